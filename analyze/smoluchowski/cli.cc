#include "analyze/smoluchowski/cli.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <ostream>

#include "analyze/smoluchowski/accuracy.h"
#include "analyze/smoluchowski/run.h"
#include "common/error.h"
#include "common/tool_main.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

namespace {

const char* kDescription =
    "coolgas-smoluchowski: mean-field cluster-size distribution N(m,t), m = 1..M, from the\n"
    "Smoluchowski coagulation equation, written as the same TSV tables as coolgas-clusters.\n"
    "\n"
    "Units: mass m in particles; N(m,t) = c_m, clusters per unit volume, with c_1(0) = 1 for the\n"
    "monodisperse start; time in units of 1/(c_1(0) K0), K0 the kernel's prefactor (1 as given).\n"
    "Time convention (--convention): 'half' (default) integrates\n"
    "  dc_k/dt = 1/2 sum_{i+j=k} K(i,j) c_i c_j - c_k sum_j K(k,j) c_j;\n"
    "'paper' is the paper's Eq. (3) (no 1/2 on the gain, 2 on the loss): t_paper = t_half / 2.\n"
    "Kernels: constant (K=1), additive (i+j), product (ij; gels at t_g = 1 half-time, 1/2 paper\n"
    "time, from c_k(0) = delta_k1), ballistic or eq4 (paper's Eq. 4,\n"
    "(i^-1/2 + j^-1/2)(i^1/3 + j^1/3)^2), ballistic2d and ballistic1d (the same in d = 2, 1:\n"
    "(i^-1/2 + j^-1/2)(i^1/d + j^1/d)^(d-1), mean mass ~ t^(2d/(d+2))), separable:c,p,q[;c,p,q...] for\n"
    "K = sum c (i^p j^q + i^q j^p), c > 0, numbers may be fractions like -1/6.\n"
    "Methods: direct (O(M^2), reference), fft (O(M log M), default), geometric (grid ratio r,\n"
    "for long times; less accurate). Accuracy knobs: --M, --rtol, --atol, --stepper,\n"
    "--grid-ratio. Mass leaking past M is reported, with a warning above --leak-tolerance.";

struct Raw {
  RunOptions run;
  std::string method = "fft", stepper = "rkck", convention = "half";
  double t_end = 0, until = 0;
  CLI::Option *t_end_opt = nullptr, *until_opt = nullptr;
  bool stats = false, accuracy = false, accuracy_quick = false;
};

void define(CLI::App& app, Raw& r) {
  auto& o = r.run;
  app.add_option("--kernel", o.kernel, "kernel string (see above)")->capture_default_str();
  app.add_option("--method", r.method, "direct | fft | geometric")->capture_default_str();
  app.add_option("-M,--M", o.method.M, "cut-off: largest mass kept (>= 2)")->capture_default_str();
  app.add_option("--grid-ratio", o.method.grid_ratio, "geometric: ratio of neighbouring pivots (> 1)")
      ->capture_default_str();
  app.add_option("--fft-floor", o.method.fft_floor,
                 "fft: concentrations below this fraction of the peak do not widen the transforms")
      ->capture_default_str();
  app.add_option("--rtol", o.integrator.rtol, "relative tolerance per mass of the time stepper")
      ->capture_default_str();
  app.add_option("--atol", o.integrator.atol, "absolute tolerance, in concentration units (c_1(0) = 1)")
      ->capture_default_str();
  app.add_option("--stepper", r.stepper, "embedded Runge-Kutta pair of GSL: rk2 | rkf45 | rkck | rk8pd")
      ->capture_default_str();
  app.add_option("--convention", r.convention, "time convention: half | paper")->capture_default_str();
  app.add_option("--initial", o.initial, "mono, or a TSV (path or -) with columns m, N [, dm]")
      ->capture_default_str();
  app.add_option("--time,--times", o.times, "write N(m,t) at these times (repeatable, or comma-separated)")
      ->delimiter(',');
  r.t_end_opt = app.add_option("--t-end", r.t_end, "end time");
  r.until_opt = app.add_option("--until-mean-mass", r.until, "stop when the mean mass M1/M0 reaches this value");
  app.add_flag("--series", o.series, "write the series t M0 M1 M2 M_avg M_max largest_fraction instead");
  app.add_option("--series-file", o.series_file, "also write the series to this file");
  app.add_option("--series-t-min", o.series_t_min, "first non-zero series time")->capture_default_str();
  app.add_option("--per-decade,--series-per-decade", o.series_per_decade, "series rows per decade of time")
      ->capture_default_str();
  app.add_option("--bins-per-decade", o.bins_per_decade, "logarithmic mass bins per decade")->capture_default_str();
  app.add_option("--volume", o.volume, "system volume V for M_max (V particles at c_1(0) = 1)")
      ->capture_default_str();
  app.add_option("--leak-tolerance", o.leak_tolerance, "warn when this fraction of the mass passed M")
      ->capture_default_str();
  app.add_flag("--stats", r.stats, "print steps, right-hand sides and wall time to stderr at the end");
  app.add_flag("--accuracy-study", r.accuracy, "write the error-versus-wall-time table of all methods instead");
  app.add_flag("--quick", r.accuracy_quick, "accuracy study: fewer, cheaper settings");
}

int run_and_report(Raw& r, std::ostream& out, std::ostream& err) {
  auto& o = r.run;
  o.method.method = parse_method(r.method);
  o.integrator.stepper = parse_stepper(r.stepper);
  o.convention = parse_convention(r.convention);
  if (r.t_end_opt->count()) o.t_end = r.t_end;
  if (r.until_opt->count()) o.until_mean_mass = r.until;
  const auto start = std::chrono::steady_clock::now();
  const RunSummary s = run(o, out, err);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (r.stats)
    err << "coolgas-smoluchowski: stats: t = " << format_number(s.t) << ", mean mass = "
        << format_number(s.final_moments.mean()) << ", leaked mass fraction = " << format_number(s.leaked_fraction)
        << ", steps = " << s.steps << ", rhs evaluations = " << s.evaluations << ", wall seconds = " << wall << "\n";
  return kExitOk;
}

}  // namespace

int smoluchowski_main(int argc, char** argv, std::ostream& out, std::ostream& err) {
  CLI::App app(kDescription, "coolgas-smoluchowski");
  app.get_formatter()->column_width(34);
  Raw r;
  define(app, r);
  if (parse_command_line(app, argc, argv)) return kExitOk;
  note_old_spelling(argc, argv, "--times", "--time");
  note_old_spelling(argc, argv, "--series-per-decade", "--per-decade");
  if (r.accuracy) {
    write_accuracy_table(out, r.accuracy_quick ? AccuracyScope::Quick : AccuracyScope::Full);
    return kExitOk;
  }
  return run_and_report(r, out, err);
}

}  // namespace coolgas::smoluchowski
