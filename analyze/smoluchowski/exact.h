// Exact solutions of the Smoluchowski equation for the classic kernels, from a
// monodisperse start c_k(0) = δ_k1, in the ½-gain convention
//   dc_k/dt = ½ Σ_{i+j=k} K(i,j) c_i c_j − c_k Σ_j K(k,j) c_j.
// Sources: Leyvraz, Phys. Rep. 383, 95 (2003), Sec. 2; Aldous, Bernoulli 5, 3
// (1999), Sec. 2.1 (tests check them against the direct method as well).
//   constant K = 1:    c_k = (t/2)^(k-1) / (1 + t/2)^(k+1)
//   additive K = i+j:  c_k = e^-t (k τ)^(k-1) e^(-k τ) / k!,  τ = 1 − e^-t
//   product  K = i j:  c_k = k^(k-3) t^(k-1) e^(-k t) / (k-1)!,  valid for t <= 1:
//                      the second moment 1/(1−t) diverges at the gelation time
//                      t_g = 1 (t_g = 1/2 in the paper's time, Eq. 3); after it
//                      the formula no longer describes the sol and is refused.
#pragma once
#include "analyze/smoluchowski/kernel.h"

namespace coolgas::smoluchowski {

// True for the constant, additive and product kernels.
bool has_exact_solution(const Kernel& kernel);

// c_k(t) for mass k >= 1 at time t >= 0 (½-gain convention). Throws
// InputError for a kernel without an exact solution or the product kernel
// past t_g = 1.
double exact_concentration(const Kernel& kernel, long k, double t);

// Gelation time of the product kernel from c_k(0) = δ_k1, ½-gain convention.
inline constexpr double kProductGelationTime = 1.0;

}  // namespace coolgas::smoluchowski
