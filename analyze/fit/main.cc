// coolgas-fit: power-law fit, smoothed local slope or Haff fit of E(t) from a
// TSV table (a path or "-" for stdin); the result is a TSV table on stdout.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/fit/table.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-fit", [&] {
    coolgas::watch_interrupts();  // reading 10^7 rows, a local slope or Haff fit of them: exit code 3
    coolgas::FitOptions o;
    bool power = false, slope = false, haff = false, no_weights = false;
    std::string window = ":", err;
    CLI::App app{
        "Fits to E(t) read from a table (e.g. coolgas-energy output). Exactly one mode:\n"
        "  --power        E = A t^-theta, weighted least squares of ln E vs ln t. One row:\n"
        "                 theta theta_err [1], A A_err [E units x time^theta], t_min t_max [time], points, chi2_dof\n"
        "  --haff         E = E0/(1 + t/t0)^2, nonlinear least squares of ln E. One row:\n"
        "                 E0 E0_err [E units], t0 t0_err [time], t_min t_max [time], points, chi2_dof\n"
        "  --local-slope  -d ln E/d ln t [1], smoothed over +-SMOOTH decades. Rows: t [time], slope\n"
        "Time in initial mean collision times 1/omega0, E in m sigma^2 omega0^2 per particle (as the input).\n"
        "Weights 1/err^2 come from the column <E>_err when all its values are > 0 (or --err-column)."};
    app.add_option("table", o.input, "input table, or - for stdin")->capture_default_str();
    auto* modes = app.add_option_group("mode");
    modes->add_flag("--power", power, "power-law fit");
    modes->add_flag("--local-slope", slope, "smoothed local slope");
    modes->add_flag("--haff", haff, "Haff-law fit");
    modes->require_option(1);
    auto* window_opt = app.add_option("--t-window,--window", window,
                                      "fit only rows with TMIN <= t <= TMAX, as TMIN:TMAX [time]; a side may be empty.\n"
                                      "--power without it: E past Haff's law (from where it falls as t^-1, or back to\n"
                                      "t^-3/2 if it fell faster) to the finite-size crossover t = 0.1 L^(5/2) (L from\n"
                                      "the table; 0.1 L^2 and 0.1 L^(3/2) for a 2D and a 1D run's table); other columns: t > 0; stderr says which");
    app.add_option("--t-column", o.columns.t, "name of the time column")->capture_default_str();
    app.add_option("--e-column", o.columns.E, "name of the energy column")->capture_default_str();
    app.add_option("--err-column", err, "name of the column of standard errors of E (default: <E>_err if usable)");
    app.add_flag("--no-weights", no_weights, "unweighted fit even if an error column exists");
    app.add_option("--smooth", o.smooth_decades, "local slope: half width of the fit window [decades of t]")
        ->capture_default_str();
    app.add_flag("--curve", o.curve, "power/haff: write rows t, E, E_fit over the window, results as '# key: value' lines");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    coolgas::note_old_spelling(argc, argv, "--window", "--t-window");
    o.mode = power ? coolgas::FitMode::kPowerLaw : haff ? coolgas::FitMode::kHaff : coolgas::FitMode::kLocalSlope;
    o.window = coolgas::parse_window(window, "--t-window");
    o.auto_window = window_opt->count() == 0;
    if (!err.empty()) o.columns.err = err;
    o.columns.weights = !no_weights;
    coolgas::write_fit_table(o, std::cout);
    return 0;
  });
}
