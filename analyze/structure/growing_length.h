// The growing length of a coarsening density field from its structure factor
// (Pathak et al. 2014 mention L_t ~ t^{1/z}; the definition is the usual one
// of coarsening studies, the inverse first moment of S(k); Bray, Adv. Phys.
// 43, 357 (1994), Sec. 2):
//   L_t = 2 pi / <k>,   <k> = sum_s k_s S_s / sum_s S_s
// over the low-k peak: the shells from the first (k = 2 pi/L) up to, not
// including, the first shell beyond the maximum of S at which S - s has
// fallen to `fraction` of its maximum S_max - s (s: the shot-noise level,
// 1 for particles). Shells are equally spaced, so the sums are the integrals
// int k S dk / int S dk of the literature on the shell grid. The cut scales
// with the peak, so L_t keeps the scaling of S(k, t) = L_t^3 f(k L_t).
#pragma once
#include <vector>

#include "analyze/structure/structure_factor.h"

namespace coolgas {

struct PeakLength {
  double L = 0;       // 2 pi / <k> [sigma]
  double k_mean = 0;  // <k> [1/sigma]
  double k_cut = 0;   // k of the first shell left out (the last shell's k + dk if none is) [1/sigma]
  double k_peak = 0;  // k of the maximum of S [1/sigma]
  double S_peak = 0;  // the maximum of S
  int shells = 0;     // shells summed
};

// All zeros when there are no shells or the sums vanish.
PeakLength peak_length(const std::vector<Shell>& shells, double shot, double fraction);

}  // namespace coolgas
