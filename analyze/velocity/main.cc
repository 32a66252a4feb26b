// coolgas-velocity: scaled velocity distribution Φ(y), its tail and the
// kurtosis of a trajectory. All logic is in analyze/velocity/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/velocity/tool.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-velocity", [&] {
    coolgas::watch_interrupts();  // its loops stop at SIGINT/SIGTERM: exit code 3
    coolgas::VelocityOptions o;
    bool tail = false, series = false;
    CLI::App app{
        "Velocity statistics of a coolgas trajectory, per dump (Pathak et al. 2014, Fig. 5).\n"
        "v_rms [sigma omega0] = sqrt(<vx^2+vy^2+vz^2>/3) (per component); y = v_alpha/v_rms [dimensionless],\n"
        "the three components pooled. Phi(y) [dimensionless] = count/(3N dy): a normalised histogram on --bins\n"
        "equal bins over [-ymax, ymax]. kappa = <v^4>/<v^2>^2 - 5/3 over speeds v = |v| [dimensionless; 0 for a\n"
        "Maxwellian], with its standard error (delta method). beta: weighted least-squares slope of\n"
        "ln(-ln Phi) vs ln y over bins with y >= --tail-from, both signs folded, >= --min-count samples.\n"
        "A 2D file (disks): d = 2 components, v_rms = sqrt(<vx^2+vy^2>/2), Phi = count/(2N dy), and\n"
        "kappa = <v^4>/<v^2>^2 - 2 (the 2D Maxwellian's value); Phi's Gaussian reference is the same.\n"
        "A 1D file (rods): the one component, v_rms = sqrt(<vx^2>), Phi = count/(N dy), and\n"
        "kappa = <vx^4>/<vx^2>^2 - 3 (the 1D Maxwellian's: the Gaussian's excess kurtosis).\n"
        "--spins: the same of a rough run's angular velocities (omega in place of v): the 3 axes of a sphere,\n"
        "the one (z) of a disk, kappa against the Maxwellian of that many components.\n"
        "--species K: the same of a mixture's species K alone (its index in the file: 0 for the first\n"
        "[[species]] table); v_rms is then that species' own.\n\n"
        "Tables (TSV on stdout):\n"
        "  default   one block per dump: t [1/omega0], y, Phi, Phi_err (Poisson), minus_ln_Phi = -ln Phi;\n"
        "            empty bins omitted; each block starts '# t = ...; v_rms = ...; kappa = ...; beta = ...'\n"
        "  --tail    one block per dump: the fitted points: t, y, minus_ln_Phi, minus_ln_Phi_err, fit = c y^beta\n"
        "  --series  one row per dump: t, v_rms, kappa, kappa_err, beta, beta_err, tail_points (beta and\n"
        "            beta_err nan, with a note on stderr, in a dump whose tail has too few bins to fit)"};
    app.add_option("trajectory", o.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    auto* tail_flag = app.add_flag("--tail", tail, "write the tail points and the fit instead of Phi");
    app.add_flag("--series", series, "one row per dump: v_rms, kappa, beta")->excludes(tail_flag);
    app.add_flag("--spins", o.spins, "the statistics of the angular velocities (rough runs) instead of the velocities");
    app.add_option("--species", o.species, "only the particles of this species of a mixture (0 for the first)");
    app.add_option("--bins", o.bins, "histogram bins over [-ymax, ymax] (even)")->capture_default_str();
    app.add_option("--ymax", o.ymax, "histogram range in y = v_alpha/v_rms [dimensionless]")->capture_default_str();
    app.add_option("--tail-from", o.tail_from, "fit beta over y >= this [dimensionless]")->capture_default_str();
    app.add_option("--min-count", o.min_count, "fit only bins with at least this many samples (+y and -y)")
        ->capture_default_str();
    coolgas::add_dump_selection(app, o.times, o.exact_time, "analyse only the dump nearest this time");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    o.table = tail     ? coolgas::VelocityTable::kTail
              : series ? coolgas::VelocityTable::kSeries
                       : coolgas::VelocityTable::kPhi;
    coolgas::run_velocity(o, std::cout);
    return 0;
  });
}
