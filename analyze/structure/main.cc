// coolgas-structure: S(k, t), the growing length L_t, the correlation
// lengths and g(r) of a trajectory. All logic is in analyze/structure/tool.h.
#include <CLI/CLI.hpp>
#include <iostream>

#include "analyze/structure/tool.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-structure", [&] {
    coolgas::watch_interrupts();  // its loops stop at SIGINT/SIGTERM: exit code 3
    coolgas::StructureOptions opt;
    bool series = false, correlation = false, rdf = false;
    CLI::App app{
        "Structure factor and growing length of a coolgas trajectory.\n"
        "The particle density (ballistic aggregation: the aggregates weighted by their mass, i.e. their\n"
        "particles at the aggregates' centres) is assigned to a periodic grid by cloud in cell and Fourier\n"
        "transformed (FFTW). Per mode S(k) = s + (|rho_grid(k)|^2/M - s C1(k))/W(k)^2 corrects the CIC window\n"
        "W = prod sinc^2(pi k_a h/2pi) and subtracts the aliased shot noise s C1, C1 = prod (1 - 2/3 sin^2(pi k_a h/2pi))\n"
        "(Jing 2005, ApJ 620, 559); M = sum m_j, s = sum m_j^2 / M (1 for particles). Shells of |k| in units of\n"
        "2 pi/L (shell s: s - 1/2 <= |k| L/2pi < s + 1/2), up to half the grid's Nyquist wave number (shell grid/4).\n"
        "A 2D file (disks): an n^2 grid and its 2D transform, circular shells, y = S / L_t^2 [sigma^-2].\n"
        "A 1D file (rods): n points on the ring and its 1D transform; shell s is k = 2 pi s/L alone (one\n"
        "independent mode: S_err = S), y = S / L_t [sigma^-1]; C(r) and C_v(r) along the ring.\n\n"
        "Output (TSV on stdout), one block per dump:\n"
        "  t [1/omega0]; shell [2 pi/L]; k [1/sigma] mean |k| of the shell's modes; S [1] mean over its modes;\n"
        "  S_err [1] standard error over its independent modes; modes [1] independent modes (k, -k once);\n"
        "  x = k L_t [1]; y = S / L_t^3 [sigma^-3] (the dynamic-scaling collapse).\n"
        "  Each block starts with '# t = ...; L_t = ...; k_cut = ...; shell 1: S_direct = ..., S = ...' (the exact sum\n"
        "  over particles for the lowest --direct-shells shells beside the grid estimate).\n"
        "L_t = 2 pi/<k> [sigma], <k> = sum k S / sum S over the shells from the first up to the first shell beyond\n"
        "the maximum of S where S - s <= peak_fraction (S_max - s) (that shell left out).\n"
        "With --series, one row per dump:\n"
        "  t [1/omega0]; L_t [sigma]; k_mean, k_cut, k_peak [1/sigma]; S_peak [1];\n"
        "  L_C [sigma] first zero of the pair correlation C(r) of the CIC density;\n"
        "  L_v [sigma] first zero of the correlation C_v(r) of the CIC momentum field sum m v.\n"
        "With --correlation, one block per dump: t [1/omega0]; r [sigma] mean separation in the bin (bins one\n"
        "  grid spacing wide, up to L/2); C, C_v [1] normalised to 1 at r = 0; points [1] grid separations in the bin.\n\n"
        "With --rdf, the radial distribution function g(r) of the particles (diameter sigma; not for ballistic-\n"
        "aggregation files) from all pairs closer than --r-max (cell list, periodic minimum images), in bins\n"
        "[i, i + 1)/b sigma, b = --bins-per-sigma; g = pairs / (N (N - 1)/2 * shell measure / L^d), the pairs of\n"
        "an ideal gas of the same N (shell measure: 4 pi r^2 dr in 3D, 2 pi r dr in 2D, 2 dr in 1D, exact for each bin).\n"
        "g(sigma+) is the maximum-likelihood fit of g(sigma+) exp(-kappa (r - sigma)) to the pair counts (Poisson)\n"
        "of the --contact-bins bins above sigma. One block per dump: t [1/omega0]; r [sigma] bin centre; g [1];\n"
        "  g_err [1] g/sqrt(pairs); pairs [1] pairs in the bin. Each block starts with\n"
        "  '# t = ...; g_contact = ... +- ...; g_equilibrium = ...'.\n"
        "With --rdf --series, one row per dump: t [1/omega0]; g_contact [1] g(sigma+); g_contact_err [1] its\n"
        "  standard error from the fit; kappa [1/sigma] -d ln g/dr at sigma+; contact_pairs [1] pairs in the fit;\n"
        "  g_equilibrium [1] the equilibrium contact value at the dump's phi (Carnahan-Starling; 2D: Henderson;\n"
        "  1D: Tonks, exact)."};
    app.add_option("trajectory", opt.input, "trajectory file (H5MD, written by coolgas-simulate)")->required();
    app.add_option("--grid", opt.grid,
                   "grid points per side, even, 8..1024 (default: the even number nearest below L/sigma, spacing ~ sigma)");
    app.add_option("--peak-fraction", opt.peak_fraction, "cut of the low-k peak for L_t, in (0, 1)")
        ->capture_default_str();
    app.add_option("--direct-shells", opt.direct_shells,
                   "shells (from k = 2 pi/L) also summed exactly over particles, 0..8; cost grows as shells^3")
        ->capture_default_str();
    app.add_flag("--series", series, "one row per dump: t L_t k_mean k_cut k_peak S_peak L_C L_v");
    app.add_flag("--correlation", correlation, "blocks of C(r) and C_v(r)");
    CLI::Option* rdf_flag = app.add_flag("--rdf", rdf, "blocks of g(r); with --series one row per dump of g(sigma+)");
    app.add_option("--r-max", opt.r_max, "g(r) up to this distance [sigma], at most L/2 (default: min(5, L/2))")
        ->needs(rdf_flag);
    app.add_option("--bins-per-sigma", opt.bins_per_sigma, "g(r) bins per sigma, 1..1000 (bin width sigma/b)")
        ->capture_default_str()
        ->needs(rdf_flag);
    app.add_option("--contact-bins", opt.contact_bins,
                   "bins above sigma fitted for g(sigma+), 2..bins-per-sigma (default: the range sigma..1.1 sigma)")
        ->capture_default_str()
        ->needs(rdf_flag);
    coolgas::add_dump_selection(app, opt.times, opt.exact_time, "analyse only the dump nearest this time");
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    if (series && correlation) throw coolgas::InputError("--series and --correlation exclude each other: choose one table");
    if (rdf && correlation) throw coolgas::InputError("--rdf and --correlation exclude each other: choose one table");
    if (series) opt.table = coolgas::StructureTable::kSeries;
    if (correlation) opt.table = coolgas::StructureTable::kCorrelation;
    if (rdf) opt.table = series ? coolgas::StructureTable::kRdfSeries : coolgas::StructureTable::kRdf;
    coolgas::run_structure(opt, std::cout);
    return 0;
  });
}
