// coolgas-collapse: finite-size scaling of E(t) tables of several system
// sizes L (the paper's Eq. 2), with fixed or optimised exponents.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/collapse/table.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-collapse", [&] {
    coolgas::watch_interrupts();  // its loops stop at SIGINT/SIGTERM: exit code 3
    coolgas::CollapseOptions o;
    std::string t_window = ":", eta_window, weights = "none";
    CLI::App app{
        "Finite-size scaling E(t) = L^(-z theta) f(t/L^z) of E(t) tables (coolgas-energy output; L is read from\n"
        "each table's '# L:' line). Several tables of one L are its runs (seeds) and are averaged at their common\n"
        "times. Writes one block per L (ascending) with columns x = t/L^z [1/omega0 / sigma^z],\n"
        "y = E L^(z theta) [m sigma^2 omega0^2 x sigma^(z theta)], L [sigma], t [1/omega0], E [m sigma^2 omega0^2];\n"
        "theta, z [dimensionless] and the results as '# key: value' lines. --optimize finds the theta, z that\n"
        "minimise the collapse quality Q (mean over pairs of curves of the mean squared difference of ln y on\n"
        "their overlap) by Nelder-Mead. theta_err, z_err are one standard error: with two or more tables (runs)\n"
        "per L, from the jackknife over whole runs (resampling the seeds, which keeps each run's correlation in\n"
        "time); with one table per L, from a bootstrap over its E errors or rows, which treats the times as\n"
        "independent and so comes out too small. --summary: one row instead."};
    app.add_option("tables", o.inputs, "E(t) tables: one per L, or one per run (seed) of each L (- for stdin, once)")->required();
    app.add_option("--theta", o.theta, "energy exponent theta (with --optimize: the starting value)")->capture_default_str();
    app.add_option("--z", o.z, "dynamical exponent z (with --optimize: the starting value)")->capture_default_str();
    auto* optimize_opt = app.add_flag("--optimize", o.optimize, "find the theta and z that collapse the curves best");
    app.add_option("--z-theta", o.z_theta,
                   "with --optimize: hold the product z theta at this value (mean field: z theta = d, the dimension;\n"
                   "the paper's E L^3 against t/L^(5/2) is 3) and find the z that collapses best, theta = z_theta / z;\n"
                   "errors from the jackknife over\n"
                   "runs (two or more tables of every L, or --bootstrap 0). Compare its quality with the free fit's")
        ->needs(optimize_opt);
    app.add_option("--bootstrap", o.search.bootstrap, "bootstrap replicas with one table per L (0: no uncertainties at all)")
        ->capture_default_str();
    app.add_option("--seed", o.search.seed, "random seed of the bootstrap")->capture_default_str();
    app.add_option("--min-overlap", o.search.min_overlap_decades,
                   "pairs of curves overlapping by less than this many decades of x are penalised")
        ->capture_default_str();
    auto* window_opt = app.add_option("--t-window", t_window,
                                      "use only rows with TMIN <= t <= TMAX [1/omega0], as TMIN:TMAX. --optimize\n"
                                      "without it: t from where every table is past Haff's law (falls as t^-1, or\n"
                                      "back to t^-3/2 if it fell faster); stderr says which");
    app.add_option("--eta-window", eta_window, "fit f(x) ~ x^-eta over XMIN <= x <= XMAX, as XMIN:XMAX\n"
                   "(eta = nan, with a note, if fewer than 3 scaled points lie there)");
    app.add_option("--weights", weights,
                   "none: every point counts alike in Q; seeds (two or more tables per L): each squared\n"
                   "difference over the variance of ln E among that L's runs there, so Q is a chi^2 per point and\n"
                   "the late, noisy times of small boxes count as little as they are known. The jackknife\n"
                   "re-estimates the weights in each replica; with only 2 runs of an L it cannot, and its errors\n"
                   "then come out about 2x too small (3 or more runs per L: they cover at their stated rate)")
        ->check(CLI::IsMember({"none", "seeds"}))
        ->capture_default_str();
    app.add_option("--t-column", o.columns.t, "name of the time column")->capture_default_str();
    app.add_option("--e-column", o.columns.E, "name of the energy column")->capture_default_str();
    app.add_flag("--summary", o.summary, "write one row: theta theta_err z z_err quality [eta eta_err]");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    o.t_window = coolgas::parse_window(t_window, "--t-window");
    o.seed_weights = weights == "seeds";
    o.auto_window = o.optimize && window_opt->count() == 0;
    if (!eta_window.empty()) o.eta_window = coolgas::parse_window(eta_window, "--eta-window");
    coolgas::write_collapse_table(o, std::cout);
    return 0;
  });
}
