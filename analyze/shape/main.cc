// coolgas-shape: cluster shapes and the mass-radius relation of a trajectory.
// All logic is in analyze/shape/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/shape/tool.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-shape", [&] {
    coolgas::watch_interrupts();  // its loops stop at SIGINT/SIGTERM: exit code 3
    coolgas::ShapeOptions opt;
    bool series = false, clusters = false;
    CLI::App app{
        "Shapes of the clusters of a coolgas trajectory. Clusters as in coolgas-clusters (Pathak et al. 2014):\n"
        "floor(L)^3 cubic cells of side L/floor(L) (about one diameter sigma), a cell holding a particle centre is\n"
        "occupied, occupied cells sharing a face, across the periodic boundaries, form a cluster. Each cluster is\n"
        "unwrapped along its own face contacts (a cluster that meets itself in another periodic image winds around\n"
        "the box: 'wraps', no shape). Gyration tensor G of its particle centres, eigenvalues l1 <= l2 <= l3:\n"
        "R_g^2 = l1 + l2 + l3; asphericity (3/2) sum (l - lbar)^2 / (sum l)^2 in [0, 1] (0 sphere, 1 rod);\n"
        "prolateness 27 prod (l - lbar) / (sum l)^3 in [-1/4, 2] (-1/4 disc, 2 rod).\n"
        "Ballistic aggregation files record no particles inside an aggregate: each aggregate is the solid sphere\n"
        "of diameter m^(1/3) sigma it is in the simulation (R_g^2 = 3 d^2/20, d_f = 3 by construction).\n"
        "d_f: straight line <ln R_g> = <ln m>/d_f + c through the mass bins in --fit-mass (unweighted; error from\n"
        "the scatter about the line).\n"
        "A 2D file (disks): floor(L)^2 unit squares sharing an edge, a 2 x 2 tensor, l1 <= l2, R_g^2 = l1 + l2,\n"
        "asphericity ((l2 - l1)/(l1 + l2))^2 (0 disc, 1 rod); no lambda3 and no prolateness columns; aggregates are\n"
        "solid discs of diameter m^(1/2) (d_f = 2).\n"
        "A 1D file (rods): floor(L) unit segments, neighbours left and right; the 1 x 1 tensor is R_g^2 itself:\n"
        "no lambda2, lambda3, asphericity or prolateness columns; aggregates are solid rods of length m (d_f = 1).\n\n"
        "Output (TSV on stdout), one block per dump, starting '# t = ...; d_f = ... +- ... (bins); wrapping_fraction = ...':\n"
        "  t [1/omega0]; m [particles] exp<ln m> of the bin; dm [particles] integer masses in the bin;\n"
        "  clusters [1]; Rg [sigma] exp<ln R_g>; Rg_err [sigma]; asphericity, prolateness [1] means over the bin.\n"
        "With --series, one row per dump: t [1/omega0]; d_f [1]; d_f_err [1]; fit_bins [1]; fitted_clusters [1];\n"
        "  asphericity, prolateness [1] mass-weighted over the fitted clusters; wrapping_fraction [1] share of\n"
        "  all particles in clusters that wrap.\n"
        "With --clusters, one block per dump, one row per cluster of at least --min-mass particles, largest first:\n"
        "  t [1/omega0]; mass [particles]; Rg [sigma]; lambda1..3 [sigma^2]; asphericity; prolateness; wraps (0/1)."};
    app.add_option("trajectory", opt.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    app.add_option("--bins-per-decade", opt.bins_per_decade, "logarithmic mass bins per decade (>= 1)")
        ->capture_default_str();
    app.add_option("--fit-mass", opt.fit_mass, "mass window LO:HI [particles] of the d_f fit (either side may be empty)")
        ->capture_default_str();
    app.add_option("--min-mass", opt.min_mass, "--clusters: smallest cluster listed [particles]")->capture_default_str();
    app.add_flag("--series", series, "one row per dump: d_f, its error, mean shape");
    app.add_flag("--clusters", clusters, "one row per cluster: mass, R_g, eigenvalues, shape");
    coolgas::add_dump_selection(app, opt.times, opt.exact_time, "analyse only the dump nearest this time");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    if (series && clusters) throw coolgas::InputError("--series and --clusters exclude each other: choose one table");
    if (series) opt.table = coolgas::ShapeTable::kSeries;
    if (clusters) opt.table = coolgas::ShapeTable::kClusters;
    coolgas::run_shape(opt, std::cout);
    return 0;
  });
}
