#include "analyze/collapse/ensemble.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "analyze/collapse/seed_weights.h"
#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

bool same_time(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

// Row index of each common time in each picked run: walk all runs in step
// (times increase in every curve).
std::vector<std::vector<std::size_t>> common_rows(const SizeEnsemble& e, const std::vector<std::size_t>& picks) {
  std::vector<std::vector<std::size_t>> rows(picks.size());
  std::vector<std::size_t> at(picks.size(), 0);
  const ScalingCurve& first = e.runs[picks[0]];
  for (std::size_t i = 0; i < first.t.size(); ++i) {
    const double t = first.t[i];
    bool everywhere = true;
    for (std::size_t k = 0; k < picks.size() && everywhere; ++k) {
      const ScalingCurve& c = e.runs[picks[k]];
      while (at[k] < c.t.size() && c.t[at[k]] < t && !same_time(c.t[at[k]], t)) ++at[k];
      everywhere = at[k] < c.t.size() && same_time(c.t[at[k]], t);
    }
    if (!everywhere) continue;
    for (std::size_t k = 0; k < picks.size(); ++k) rows[k].push_back(at[k]);
  }
  return rows;
}

}  // namespace

std::vector<SizeEnsemble> group_by_size(const std::vector<ScalingCurve>& curves) {
  std::vector<SizeEnsemble> sizes;
  for (const auto& c : curves) {
    auto it = std::find_if(sizes.begin(), sizes.end(), [&](const auto& s) { return s.L == c.L; });
    if (it == sizes.end()) it = sizes.insert(sizes.end(), SizeEnsemble{c.L, {}, {}});
    it->runs.push_back(c);
  }
  std::stable_sort(sizes.begin(), sizes.end(), [](const auto& a, const auto& b) { return a.L < b.L; });
  return sizes;
}

namespace {

ScalingCurve unweighted_mean(const SizeEnsemble& e, const std::vector<std::size_t>& picks) {
  if (picks.size() == 1) return e.runs[picks[0]];
  const auto rows = common_rows(e, picks);
  const std::size_t n = picks.size(), m = rows[0].size();
  if (m < 2)
    throw InputError("the " + std::to_string(n) + " runs of L = " + format_number(e.L) + " share " + std::to_string(m) +
                     " times; averaging them needs at least 2 (make their tables with the same --per-decade)");
  ScalingCurve mean;
  mean.source = "mean of " + std::to_string(n) + " runs";
  mean.L = e.L;
  mean.ln_L = std::log(e.L);
  for (std::size_t i = 0; i < m; ++i) {
    auto E_of = [&](std::size_t k) { return e.runs[picks[k]].E[rows[k][i]]; };
    double sum = 0;
    for (std::size_t k = 0; k < n; ++k) sum += E_of(k);
    const double E = sum / double(n);
    double ss = 0;  // two passes: the spread can be far below E
    for (std::size_t k = 0; k < n; ++k) ss += (E_of(k) - E) * (E_of(k) - E);
    const double t = e.runs[picks[0]].t[rows[0][i]];
    mean.t.push_back(t);
    mean.E.push_back(E);
    mean.ln_t.push_back(std::log(t));
    mean.ln_E.push_back(std::log(E));
    mean.ln_E_err.push_back(std::sqrt(ss / double(n - 1) / double(n)) / E);
  }
  return mean;
}

}  // namespace

ScalingCurve ensemble_mean(const SizeEnsemble& e, const std::vector<std::size_t>& picks) {
  ScalingCurve mean = unweighted_mean(e, picks);
  mean.ln_E_var = mean_ln_E_variance(e, mean.ln_t, picks.size());
  return mean;
}

ScalingCurve ensemble_mean(const SizeEnsemble& e) {
  std::vector<std::size_t> all(e.runs.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  return ensemble_mean(e, all);
}

std::vector<ScalingCurve> mean_curves(const std::vector<SizeEnsemble>& sizes) {
  std::vector<ScalingCurve> out;
  for (const auto& s : sizes) out.push_back(ensemble_mean(s));
  return out;
}

SizeEnsemble without_run(const SizeEnsemble& e, std::size_t r) {
  SizeEnsemble out = e;
  out.runs.erase(out.runs.begin() + std::ptrdiff_t(r));
  if (!e.scatter.ln_t.empty() && out.runs.size() >= 2) estimate_seed_scatter(out);
  return out;
}

double sum_of_squares(const std::vector<double>& v) {
  double mean = 0, ss = 0;
  for (double x : v) mean += x;
  mean /= double(v.size());
  for (double x : v) ss += (x - mean) * (x - mean);
  return ss;
}

}  // namespace coolgas
