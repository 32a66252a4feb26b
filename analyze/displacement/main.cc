// coolgas-displacement: the mean-square displacement and the velocity
// autocorrelation of a trajectory. All logic is in analyze/displacement/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/displacement/tool.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-displacement", [&] {
    coolgas::watch_interrupts();  // its loop stops at SIGINT/SIGTERM: exit code 3
    coolgas::DisplacementOptions opt;
    CLI::App app{
        "Mean-square displacement and velocity autocorrelation of the particles of a coolgas trajectory,\n"
        "from one reference dump (--from; default the first). Positions are unwrapped with the periodic image\n"
        "counts the dumps hold (position + L image), so displacements are exact at any dump spacing.\n"
        "Averages are over the particles (unit masses; not for ballistic-aggregation files). In the homogeneous\n"
        "cooling state msd grows only as ln(1 + t/t0) (Brilliantov & Poeschel 2004); free flight gives\n"
        "msd = d T dt^2 exactly before the first collisions.\n\n"
        "Output (TSV on stdout), one row per dump:\n"
        "  t [1/omega0]; dt = t - t_ref [1/omega0]; msd [sigma^2] <|r(t) - r(t_ref)|^2>;\n"
        "  msd_err [sigma^2] its standard error over the particles; vacf [sigma^2 omega0^2] <v(t).v(t_ref)>;\n"
        "  vacf_norm [1] vacf/<|v(t_ref)|^2>; T [m sigma^2 omega0^2] <|v(t)|^2>/d;\n"
        "  D_apparent = msd/(2 d dt) [sigma^2 omega0] (0 at dt = 0)."};
    app.add_option("trajectory", opt.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    app.add_option("--from", opt.from, "the reference dump: the one nearest this time [1/omega0] (default: the first)");
    coolgas::add_dump_selection(app, opt.times, opt.exact_time,
                                "rows only at the dumps nearest this time (default: every dump from the reference on)");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    coolgas::run_displacement(opt, std::cout);
    return 0;
  });
}
