// coolgas-energy: kinetic energy per particle E(t) of one run, or the mean
// over runs that differ only in their seed, as a TSV table on stdout.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/energy/table.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-energy", [&] {
    coolgas::watch_interrupts();  // its loop over the runs stops at SIGINT/SIGTERM: exit code 3
    coolgas::EnergyOptions o;
    CLI::App app{
        "Kinetic energy per particle E(t) from coolgas trajectories (H5MD). One file: that run; several files\n"
        "with equal parameters (different seeds): the ensemble mean with standard errors, interpolated\n"
        "(ln E vs ln t) onto a common log-spaced grid over the overlap of the runs' times.\n"
        "Columns: t [1/omega0, initial mean collision times], E and E_err [m sigma^2 omega0^2 per particle],\n"
        "E_over_E0 and E_over_E0_err [dimensionless; E0 = the run's first row, t = 0], runs [count]."};
    app.add_option("runs", o.inputs, "trajectory files RUN.h5 written by coolgas-simulate")->required();
    app.add_option("--per-decade", o.per_decade, "grid points per decade of t (>= 1)")->capture_default_str();
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    coolgas::write_energy_table(o, std::cout);
    return 0;
  });
}
