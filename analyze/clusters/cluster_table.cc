#include "analyze/clusters/cluster_table.h"

#include <cmath>

namespace coolgas {

const std::vector<std::string>& cluster_columns(ClusterTable table) {
  static const std::vector<std::string> distribution = {"t", "m", "dm", "N", "x", "y"};
  static const std::vector<std::string> scaled = {"t", "x", "y"};
  static const std::vector<std::string> series = {"t", "M0", "M1", "M2", "M_avg", "M_max", "largest_fraction"};
  switch (table) {
    case ClusterTable::kScaled:
      return scaled;
    case ClusterTable::kSeries:
      return series;
    case ClusterTable::kDistribution:
      break;
  }
  return distribution;
}

void fill_cluster_masses(MassHistogram& hist, Labellers& labellers, const ClusterDefinition& definition, double L,
                         std::span<const double> positions, std::span<const double> aggregate_mass, Geometry g,
                         std::span<const double> diameter) {
  hist.clear();
  if (!aggregate_mass.empty()) {
    for (double m : aggregate_mass) hist.add(std::llround(m));
    return;
  }
  auto add = [&](std::int64_t m) { hist.add(m); };
  if (definition.contact()) {
    labellers.contact.label(L, positions, definition.cutoff, g, diameter);
    labellers.contact.for_each_mass(add);
    return;
  }
  labellers.cells.label(ClusterGrid(L, g), positions);
  labellers.cells.for_each_mass(add);
}

TableBlock cluster_block(ClusterTable table, double t, double L, const MassHistogram& h, Geometry g) {
  const double volume = g.box_measure(L);
  const ClusterMoments& mo = h.moments();
  TableBlock b;
  if (table == ClusterTable::kSeries) {
    b.rows.push_back({t, double(mo.clusters) / volume, double(mo.mass) / volume, mo.mass2 / volume, mo.mean(),
                      double(mo.largest), double(mo.largest) / double(mo.mass)});
    return b;
  }
  // N = count / (V dm), x = m / M_avg, y = N M_avg².
  const double m_avg = mo.mean();
  b.comment = "t = " + format_number(t) + "; M_avg = " + format_number(m_avg) + "; M_max = " +
              std::to_string(mo.largest) + "; largest_fraction = " + format_number(double(mo.largest) / double(mo.mass));
  const LogBins& bins = h.bins();
  for (int k = 0; k < bins.size(); ++k) {
    if (h.count(k) == 0) continue;
    const double dm = double(bins.width(k));
    const double n = double(h.count(k)) / (volume * dm);
    const double x = bins.center(k) / m_avg, y = n * m_avg * m_avg;
    if (table == ClusterTable::kScaled) b.rows.push_back({t, x, y});
    else b.rows.push_back({t, bins.center(k), dm, n, x, y});
  }
  return b;
}

}  // namespace coolgas
