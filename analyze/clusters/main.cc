// coolgas-clusters: cluster mass distribution N(m,t) or the cluster series of
// a trajectory. All logic is in analyze/clusters/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/clusters/tool.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-clusters", [&] {
    coolgas::watch_interrupts();  // its loops stop at SIGINT/SIGTERM: exit code 3
    coolgas::ClustersOptions opt;
    CLI::App app{
        "Clusters of a coolgas trajectory, by the definition of Pathak et al. (2014): the box of side L is cut\n"
        "into floor(L)^3 cubic cells of side L/floor(L) (about one diameter sigma); a cell holding a particle\n"
        "centre is occupied; occupied cells sharing a face, across the periodic boundaries, form a cluster;\n"
        "a cluster's mass m is its number of particles. A 2D file (disks): floor(L)^2 square cells, cells\n"
        "sharing an edge; its densities are per sigma^2 (L^2 in place of L^3 below). A 1D file (rods on a\n"
        "ring): floor(L) unit segments, neighbours left and right; densities per sigma (L in place of L^3).\n"
        "At the paper's phi = 0.208 these cells percolate from t = 0 (the largest holds most particles).\n"
        "--definition contact[:CUTOFF] counts clusters of particles in contact instead: two particles whose\n"
        "centres are closer than CUTOFF sigma (default 1.1; periodic minimum image) are bonded, bonded\n"
        "particles form a cluster (cell-list neighbour search, union-find); same columns. In a mixture\n"
        "([[species]]) the bond is CUTOFF sigma_ij, sigma_ij = (sigma_i + sigma_j)/2 the pair's contact distance.\n"
        "--species K: the clusters of a mixture's species K alone (its index in the file: 0 for the first\n"
        "[[species]] table): only its particles occupy cells or bond (CUTOFF sigma_K); the others are not\n"
        "there. Masses stay numbers of particles; N (in largest_fraction = M_max/N; the bins end at N) is\n"
        "species K's number of particles.\n\n"
        "Output (TSV on stdout), one block per dump:\n"
        "  t [1/omega0] time; m [particles] bin centre sqrt(lo*hi); dm [particles] integer masses in the bin;\n"
        "  N [sigma^-3 per particle] clusters per unit volume per unit mass, count/(L^3 dm);\n"
        "  x = m/M_avg; y = N M_avg^2 (the scaled distribution of the paper's Fig. 3).\n"
        "  Each block starts with '# t = ...; M_avg = ...; M_max = ...; largest_fraction = ...'.\n"
        "With --series, one row per dump:\n"
        "  t [1/omega0]; M0 [sigma^-3] clusters per unit volume; M1 [sigma^-3] particles per unit volume;\n"
        "  M2 [sigma^-3] sum of m^2 per unit volume; M_avg = M1/M0 [particles] mean cluster mass;\n"
        "  M_max [particles] largest cluster; largest_fraction = M_max/N."};
    app.add_option("trajectory", opt.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    app.add_option("--definition", opt.definition,
                   "cells (the paper's unit cells) or contact[:CUTOFF] (particles closer than CUTOFF sigma, default 1.1)")
        ->capture_default_str();
    app.add_option("--bins-per-decade", opt.bins_per_decade, "logarithmic mass bins per decade (>= 1)")
        ->capture_default_str();
    app.add_option("--species", opt.species, "only the particles of this species of a mixture (0 for the first)");
    app.add_flag("--series", opt.series, "one row per dump: M0, M1, M2, M_avg, M_max, largest_fraction");
    app.add_flag("--scaled", opt.scaled,
                 "N(m,t) scaled by the mean size as in the paper's Fig. 3: columns t, x = m/M_avg, y = N M_avg^2");
    coolgas::add_dump_selection(app, opt.times, opt.exact_time, "analyse only the dump nearest this time");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    coolgas::run_clusters(opt, std::cout);
    return 0;
  });
}
