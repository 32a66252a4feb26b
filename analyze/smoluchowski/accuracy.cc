#include "analyze/smoluchowski/accuracy.h"

#include <chrono>
#include <cmath>
#include <ostream>
#include <vector>

#include "analyze/smoluchowski/exact.h"
#include "analyze/smoluchowski/initial.h"
#include "analyze/smoluchowski/observables.h"
#include "analyze/smoluchowski/solve.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

namespace {

constexpr int kBinsPerDecade = 10;

struct Case {
  const char* kernel;
  double t;                    // ½-gain time
  std::vector<std::int64_t> M; // cut-offs to try, the last one large enough
};

struct Setting {
  MethodOptions method;
  IntegratorOptions integrator;
};

struct Reference {
  MassGrid grid;
  std::vector<double> c;
  double mean;
};

Reference reference(const Kernel& k, const Case& cs) {
  const std::int64_t M = 2 * cs.M.back();
  if (has_exact_solution(k)) {
    Reference r{uniform_grid(M), std::vector<double>(M), 0};
    for (std::int64_t m = 1; m <= M; ++m) r.c[m - 1] = exact_concentration(k, m, cs.t);
    r.mean = moments(r.grid, r.c).mean();
    return r;
  }
  MethodOptions mo{Method::Fft, M};
  IntegratorOptions io{1e-12, 1e-20, Stepper::Rk8pd};
  auto s = solve(k, mo, io, initial_masses("mono", M), cs.t);
  return {s.grid, s.c, moments(s.grid, s.c).mean()};
}

void row(TsvWriter& w, const Kernel& k, const Case& cs, const Reference& ref, const Setting& st) {
  const auto start = std::chrono::steady_clock::now();
  const auto s = solve(k, st.method, st.integrator, initial_masses("mono", st.method.M), cs.t);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double err = binned_distance(s.grid, s.c, ref.grid, ref.c, kBinsPerDecade);
  const double mean_err = std::abs(moments(s.grid, s.c).mean() / ref.mean - 1);
  const double ratio = st.method.method == Method::Geometric ? st.method.grid_ratio : 1;
  w.row({double(st.method.M), st.integrator.rtol, st.integrator.atol, ratio, wall, double(s.evaluations), err,
         mean_err});
}

// The curves of one kernel: each a list of settings varying one knob.
std::vector<std::pair<std::string, std::vector<Setting>>> curves(const Case& cs, AccuracyScope scope) {
  const bool quick = scope == AccuracyScope::Quick;
  const std::int64_t Mbig = cs.M.back();
  const IntegratorOptions tight{1e-10, 1e-18, Stepper::Rkck};
  std::vector<double> rtols = quick ? std::vector<double>{1e-4, 1e-7, 1e-10}
                                    : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  std::vector<double> ratios = quick ? std::vector<double>{2, 1.25, 1.05}
                                     : std::vector<double>{2, 1.5, 1.25, 1.1, 1.05, 1.02};
  std::vector<std::pair<std::string, std::vector<Setting>>> out;
  for (Method m : {Method::Direct, Method::Fft}) {
    std::vector<Setting> byM, byTol;
    for (auto M : cs.M) byM.push_back({{m, M}, tight});
    for (double r : rtols) byTol.push_back({{m, Mbig}, {r, r / 1e8, Stepper::Rkck}});
    out.push_back({method_name(m) + "/M", byM});
    out.push_back({method_name(m) + "/rtol", byTol});
  }
  std::vector<Setting> byRatio;
  for (double r : ratios) byRatio.push_back({{Method::Geometric, Mbig, r}, tight});
  out.push_back({"geometric/ratio", byRatio});
  return out;
}

std::vector<Case> cases(AccuracyScope scope) {
  if (scope == AccuracyScope::Quick) return {{"constant", 20, {64, 128, 256}}, {"ballistic", 2, {64, 128, 256}}};
  return {{"constant", 20, {64, 128, 256, 512}},
          {"additive", 1.5, {128, 256, 512, 1024}},
          {"product", 0.8, {128, 256, 512, 1024}},
          {"ballistic", 2, {64, 128, 256, 512}}};
}

}  // namespace

void write_accuracy_table(std::ostream& out, AccuracyScope scope) {
  const auto all = cases(scope);
  Provenance prov{{"study", scope == AccuracyScope::Quick ? "quick" : "full"},
                  {"convention", "half (dc/dt = 1/2 sum K c c - c sum K c), monodisperse start"},
                  {"error", "mass-weighted relative L1 distance of log-binned N(m) from the reference"},
                  {"stepper", "rkck"}};
  for (const auto& cs : all)
    for (const auto& [name, settings] : curves(cs, scope))
      prov.push_back({"block", std::string(cs.kernel) + "/" + name});
  TsvWriter w(out, "coolgas-smoluchowski", prov,
              {"M", "rtol", "atol", "ratio", "wall_s", "rhs_evaluations", "error", "mean_mass_error"});
  for (const auto& cs : all) {
    const Kernel k = parse_kernel(cs.kernel);
    const Reference ref = reference(k, cs);
    for (const auto& [name, settings] : curves(cs, scope)) {
      w.block(std::string(cs.kernel) + "/" + name + " (t = " + format_number(cs.t) + ")");
      for (const auto& st : settings) row(w, k, cs, ref, st);
    }
  }
}

}  // namespace coolgas::smoluchowski
