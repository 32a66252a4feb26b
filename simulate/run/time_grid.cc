#include "simulate/run/time_grid.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace coolgas {

std::vector<double> log_grid(double t_min, double t_end, int per_decade) {
  std::vector<double> out;
  // Start one step early and filter: std::log10 may round k just below.
  for (auto k = static_cast<long>(std::floor(std::log10(t_min) * per_decade)) - 1;; ++k) {
    const double t = std::pow(10.0, double(k) / per_decade);
    if (t >= t_end) break;
    if (t >= t_min) out.push_back(t);
  }
  return out;
}

std::vector<StopTime> stop_times(const Scene& s) {
  std::map<double, StopTime> stops;  // ordered by time, merged when equal
  auto add = [&](double t, bool observe, bool dump) {
    if (t <= 0 || t > s.t_end) return;
    auto [it, fresh] = stops.try_emplace(t, StopTime{t, false, false});
    it->second.observe |= observe;
    it->second.dump |= dump;
  };
  for (double t : log_grid(s.t_min, s.t_end, s.observables_per_decade)) add(t, true, false);
  for (double t : log_grid(s.t_min, s.t_end, s.dumps_per_decade)) add(t, true, true);
  for (double t : s.dump_times) add(t, true, true);
  add(s.t_end, true, true);
  std::vector<StopTime> out;
  for (const auto& [t, stop] : stops) out.push_back(stop);
  return out;
}

}  // namespace coolgas
