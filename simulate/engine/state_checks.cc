#include "simulate/engine/state_checks.h"

#include <sstream>

namespace coolgas {

namespace {
std::string text(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}
std::string text(const Vec3& v) { return "(" + text(v.x) + ", " + text(v.y) + ", " + text(v.z) + ")"; }
}  // namespace

void check_scalars(const StateReader& in, const std::string& prefix, double L, double now, const EngineCounters& c) {
  if (!(std::isfinite(L) && L > 0)) in.fail(prefix + "scalars: box side L = " + text(L) + "; must be finite and > 0");
  if (!(std::isfinite(now) && now >= 0)) in.fail(prefix + "scalars: time " + text(now) + "; must be finite and >= 0");
  if (c.collisions < 0 || c.events < 0 || c.below_delta < 0 || c.stale < 0 || c.below_delta > c.collisions ||
      c.stale > c.events)
    in.fail(prefix + "scalars: counters " + std::to_string(c.collisions) + ", " + std::to_string(c.below_delta) + ", " +
            std::to_string(c.events) + ", " + std::to_string(c.stale) +
            "; must be >= 0 with below_delta <= collisions and stale <= events");
}

void check_motion(const StateReader& in, const std::string& prefix, std::size_t i, const Motion& m, double now,
                  double L) {
  if (!finite(m.r) || !finite(m.v) || !std::isfinite(dot(m.v, m.v)))
    in.fail(prefix + "motion[" + std::to_string(i) + "]: position " + text(m.r) + ", velocity " + text(m.v) +
            "; both must be finite");
  if (!(std::isfinite(m.t) && m.t >= 0 && m.t <= now))
    in.fail(prefix + "motion[" + std::to_string(i) + "]: own time " + text(m.t) + "; must be finite and in [0, now = " +
            text(now) + "]");
  // Moving it to now wraps the position back into the box one side at a
  // time: a displacement of 1e300 would never end. Between two of its
  // events a particle crosses at most one cell, so never a whole box side.
  for (int d = 0; d < 3; ++d)
    if (!(std::fabs(m.v[d]) * (now - m.t) <= L))
      in.fail(prefix + "motion[" + std::to_string(i) + "]: velocity " + text(m.v) + " since its own time " + text(m.t) +
              " moves it " + text(std::fabs(m.v[d]) * (now - m.t)) + " by now = " + text(now) +
              "; a particle moves less than the box side L = " + text(L) + " between its events");
}

void check_in_cell(const StateReader& in, const std::string& prefix, std::size_t i, const Vec3& r,
                   const CellGrid& grid, int cell) {
  const CellCoord c = grid.coord(cell);
  const int cc[3] = {c.x, c.y, c.z};
  const double w = grid.width();
  for (int d = 0; d < 3; ++d)
    if (!(r[d] >= (cc[d] - 0.5) * w && r[d] <= (cc[d] + 1.5) * w))
      in.fail(prefix + "motion[" + std::to_string(i) + "]: position " + text(r) + " is not in its cell " +
              std::to_string(cell) + " (cells " + text(w) + " wide)");
}

void check_grid_size(const StateReader& in, const std::string& heads, std::int64_t cells) {
  const std::size_t found = in.count(heads, sizeof(std::int32_t));
  if (cells <= 0 || found != std::size_t(cells))
    in.fail(heads + " holds " + std::to_string(found) + " cells; the box and cell width stored give " +
            (cells > 0 ? std::to_string(cells) : std::string("no valid grid")));
}

}  // namespace coolgas
