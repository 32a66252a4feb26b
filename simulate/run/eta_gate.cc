#include "simulate/run/eta_gate.h"

#include <algorithm>
#include <cmath>

namespace coolgas {

bool EtaGate::show(double elapsed, double left) {
  if (!std::isfinite(left)) return false;
  if (open_) return true;
  const double whole = elapsed + left;
  if (elapsed >= kSeenFraction * whole) return open_ = true;
  recent_.push_back({elapsed, whole});
  const double window = std::max(kSteadySeconds, 0.25 * elapsed);
  while (recent_.size() > 1 && recent_[1].elapsed <= elapsed - window) recent_.pop_front();
  if (recent_.front().elapsed > elapsed - window) return false;  // not yet a whole window seen
  const auto [lo, hi] = std::minmax_element(recent_.begin(), recent_.end(),
                                            [](const Guess& a, const Guess& b) { return a.whole < b.whole; });
  return open_ = hi->whole <= kSteadyFactor * lo->whole;
}

}  // namespace coolgas
