#include "analyze/structure/growing_length.h"

#include <cmath>

namespace coolgas {

PeakLength peak_length(const std::vector<Shell>& shells, double shot, double fraction) {
  PeakLength p;
  if (shells.empty()) return p;
  std::size_t peak = 0;
  for (std::size_t i = 1; i < shells.size(); ++i)
    if (shells[i].S > shells[peak].S) peak = i;
  p.k_peak = shells[peak].k;
  p.S_peak = shells[peak].S;
  const double threshold = shot + fraction * (p.S_peak - shot);
  std::size_t cut = peak + 1;
  while (cut < shells.size() && shells[cut].S > threshold) ++cut;
  double sk = 0, s = 0;
  for (std::size_t i = 0; i < cut; ++i) sk += shells[i].k * shells[i].S, s += shells[i].S;
  p.k_cut = cut < shells.size() ? shells[cut].k : shells.back().k + (shells.size() > 1 ? shells.back().k - shells[shells.size() - 2].k : shells.back().k);
  p.shells = int(cut);
  if (s > 0 && sk > 0) {
    p.k_mean = sk / s;
    p.L = 2 * M_PI / p.k_mean;
  }
  return p;
}

}  // namespace coolgas
