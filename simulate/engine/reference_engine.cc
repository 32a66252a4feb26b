#include "simulate/engine/reference_engine.h"

#include <cmath>
#include <queue>
#include <tuple>

#include "simulate/engine/pair_prediction.h"

namespace coolgas {

// Named, not anonymous: reference_collisions (a template with external
// linkage) holds a queue of these, which GCC warns about when a unity build
// includes this file (-Wsubobject-linkage).
namespace reference_detail {

struct PairEvent {
  double t;
  int i, j;
  std::uint32_t ci, cj;  // collision counts of i and j when predicted
  bool operator>(const PairEvent& o) const { return std::tie(t, i, j) > std::tie(o.t, o.i, o.j); }
};

}  // namespace reference_detail

namespace {

using reference_detail::PairEvent;

Vec3 minimum_image(const Particles& p, int i, int j) {
  Vec3 d{p.r[j].x - p.r[i].x, p.r[j].y - p.r[i].y, p.r[j].z - p.r[i].z};
  for (int k = 0; k < 3; ++k) d[k] -= p.L * std::round(d[k] / p.L);
  return d;
}

}  // namespace

template <class Rule>
std::vector<CollisionRecord> reference_collisions(Particles p, const Rule& rule, double now, double t_end,
                                                  std::int64_t max_collisions) {
  const int n = int(p.size());
  if constexpr (Rule::kRough) p.omega.resize(p.size());  // spins not given: at rest
  // A mixture's pair touches at the sum of its radii (the mean of its diameters); unit spheres at 1.
  const auto contact2 = [&](int i, int j) {
    if constexpr (Rule::kMixture) {
      const double sigma = rule.radius[p.species[i]] + rule.radius[p.species[j]];
      return sigma * sigma;
    }
    return 1.0;
  };
  std::vector<std::uint32_t> count(n, 0);
  std::priority_queue<PairEvent, std::vector<PairEvent>, std::greater<>> queue;
  auto predict = [&](int i) {
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const Vec3 dv{p.v[j].x - p.v[i].x, p.v[j].y - p.v[i].y, p.v[j].z - p.v[i].z};
      const double t = time_to_contact(minimum_image(p, i, j), dv, contact2(i, j));
      if (t != kNever) queue.push({now + t, std::min(i, j), std::max(i, j), count[std::min(i, j)], count[std::max(i, j)]});
    }
  };
  for (int i = 0; i < n; ++i) predict(i);
  std::vector<CollisionRecord> out;
  while (!queue.empty() && std::int64_t(out.size()) < max_collisions) {
    const PairEvent e = queue.top();
    queue.pop();
    if (e.t > t_end) break;
    if (count[e.i] != e.ci || count[e.j] != e.cj) continue;  // one of them collided since
    for (int k = 0; k < n; ++k) {                             // everyone to the event time
      for (int d = 0; d < 3; ++d) p.r[k][d] += p.v[k][d] * (e.t - now);
    }
    now = e.t;
    Vec3 nrm = minimum_image(p, e.i, e.j);
    const double len = std::sqrt(dot(nrm, nrm));
    for (int d = 0; d < 3; ++d) nrm[d] /= len;
    const Vec3 dv{p.v[e.i].x - p.v[e.j].x, p.v[e.i].y - p.v[e.j].y, p.v[e.i].z - p.v[e.j].z};
    const double g = dot(dv, nrm);
    bool below = false;
    if (g > 0) {
      double r;
      if constexpr (Rule::kMixture) r = rule.restitution(g, p.species[e.i], p.species[e.j], below);
      else r = rule.restitution(g, below);
      if constexpr (Rule::kRough)
        apply_tangential_restitution(p.v[e.i], p.v[e.j], p.omega[e.i], p.omega[e.j], nrm, rule.eta_t, rule.spin_turn);
      if constexpr (Rule::kMixture)
        apply_restitution_with_masses(p.v[e.i], p.v[e.j], nrm, g, r, rule.mass[p.species[e.i]],
                                      rule.mass[p.species[e.j]]);
      else
        apply_restitution(p.v[e.i], p.v[e.j], nrm, g, r);
    }
    ++count[e.i];
    ++count[e.j];
    out.push_back({e.i, e.j, now});
    predict(e.i);
    predict(e.j);
  }
  return out;
}

template std::vector<CollisionRecord> reference_collisions(Particles, const ElasticRule&, double, double,
                                                           std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const ConstantRestitutionRule&, double,
                                                           double, std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const ViscoelasticRule&, double, double,
                                                           std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const RoughRule<ElasticRule>&, double, double,
                                                           std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const RoughRule<ConstantRestitutionRule>&,
                                                           double, double, std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const RoughRule<ViscoelasticRule>&, double,
                                                           double, std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const MixtureRule<ElasticRule>&, double,
                                                           double, std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const MixtureRule<ConstantRestitutionRule>&,
                                                           double, double, std::int64_t);
template std::vector<CollisionRecord> reference_collisions(Particles, const MixtureRule<ViscoelasticRule>&, double,
                                                           double, std::int64_t);

namespace {

// Merges b into a (a < b) at the common present time: a moves to the centre of mass.
void merge_into(Particles& p, AggregateState& a, int i, int j, Geometry g) {
  const Vec3 d = minimum_image(p, i, j);
  const double mi = a.mass[i], mj = a.mass[j], M = mi + mj;
  for (int k = 0; k < 3; ++k) {
    p.r[i][k] += (mj / M) * d[k];
    p.r[i][k] -= p.L * std::floor(p.r[i][k] / p.L);
    p.v[i][k] = (mi * p.v[i][k] + mj * p.v[j][k]) / M;
  }
  a.mass[i] = M;
  const double D = g.d();  // sizes add as d-th powers, computed here apart from Geometry::merged_diameter
  a.diameter[i] = std::pow(std::pow(a.diameter[i], D) + std::pow(a.diameter[j], D), 1.0 / D);
  a.mass[j] = a.diameter[j] = 0;
  a.id[j] = -1;
  p.r[j] = p.v[j] = Vec3{};
}

// The smallest id overlapping aggregate k, or -1.
int smallest_overlap(const Particles& p, const AggregateState& a, int k) {
  for (int j = 0; j < int(p.size()); ++j) {
    if (j == k || a.id[j] < 0) continue;
    const Vec3 d = minimum_image(p, k, j);
    const double sigma = 0.5 * (a.diameter[k] + a.diameter[j]);
    if (dot(d, d) < sigma * sigma) return j;
  }
  return -1;
}

// Calls f(i, j, v_j - v_i, contact distance) for every pair of live
// aggregates i < j, in index order.
template <class F>
void for_each_live_pair(const Particles& p, const AggregateState& a, F f) {
  const int n = int(p.size());
  for (int i = 0; i < n; ++i) {
    if (a.id[i] < 0) continue;
    for (int j = i + 1; j < n; ++j)
      if (a.id[j] >= 0) f(i, j, minus(p.v[j], p.v[i]), 0.5 * (a.diameter[i] + a.diameter[j]));
  }
}

// Another periodic image than the minimum one may touch first: every other
// image lies at least L/2 away (one component differs by L from one within
// ±L/2), so it matters only for a pair with L/2 - σ <= |dv| best. Those
// pairs' 26 other images are tried; best only falls, so a pair left out
// stays out.
void other_images_first(const Particles& p, const AggregateState& a, double& best, int& bi, int& bj) {
  for_each_live_pair(p, a, [&](int i, int j, const Vec3& dv, double sigma) {
    if (0.5 * p.L - sigma > std::sqrt(dot(dv, dv)) * best) return;
    const Vec3 d0 = minimum_image(p, i, j);
    for (int k = 0; k < 27; ++k) {
      if (k == 13) continue;  // the minimum image, done
      const Vec3 d{d0.x + (k % 3 - 1) * p.L, d0.y + (k / 3 % 3 - 1) * p.L, d0.z + (k / 9 - 1) * p.L};
      const double t = time_to_contact(d, dv, sigma * sigma);
      if (t < best) best = t, bi = i, bj = j;
    }
  });
}

}  // namespace

std::vector<CollisionRecord> reference_merges(Particles p, AggregateState a, double now, double t_end,
                                              std::int64_t max_merges, Geometry g) {
  const int n = int(p.size());
  std::vector<CollisionRecord> out;
  while (std::int64_t(out.size()) < max_merges) {
    double best = kNever;
    int bi = -1, bj = -1;
    for_each_live_pair(p, a, [&](int i, int j, const Vec3& dv, double sigma) {
      const double t = time_to_contact(minimum_image(p, i, j), dv, sigma * sigma);
      if (t < best) best = t, bi = i, bj = j;
    });
    other_images_first(p, a, best, bi, bj);
    if (bi < 0 || now + best > t_end) break;
    now += best;
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) p.r[k][d] += p.v[k][d] * best;
    int k = bi;
    for (int other = bj; other >= 0; other = smallest_overlap(p, a, k)) {
      const int keep = std::min(k, other), gone = std::max(k, other);
      merge_into(p, a, keep, gone, g);
      out.push_back({keep, gone, now});
      k = keep;
    }
  }
  return out;
}

}  // namespace coolgas
