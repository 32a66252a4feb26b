// Coagulation kernels K(i,j) for the Smoluchowski solver, all written as a sum
// of symmetric separable terms  K(i,j) = sum_t c_t (i^p_t j^q_t + i^q_t j^p_t).
//
// This one form serves every method: the direct sum evaluates it pair by
// pair, the FFT method turns each term into one convolution (gain) and two
// moments (loss), and the geometric grid evaluates it at the pivots.
//
// Kernel strings accepted by parse_kernel (masses i, j in units of one particle):
//   constant        K = 1                      exact solution known
//   additive        K = i + j                  exact solution known
//   product         K = i j                    exact, gels at t_g = 1 (½-gain time, c_k(0)=δ_k1)
//   ballistic       K = (i^-1/2 + j^-1/2)(i^1/3 + j^1/3)^2, the paper's Eq. (4)
//                   (alias eq4); prefactor 1, homogeneity 1/6
//   ballistic2d     the same in d = 2 (disks, cross-section ~ diameter ~ m^1/2):
//                   K = (i^-1/2 + j^-1/2)(i^1/2 + j^1/2), homogeneity 0
//   ballistic1d     d = 1 (rods, cross-section 1): K = i^-1/2 + j^-1/2, homogeneity -1/2
//                   In d dimensions K = (i^-1/2 + j^-1/2)(i^1/d + j^1/d)^(d-1):
//                   relative speed ~ m^-1/2 (equipartition) times the
//                   cross-section (r_i + r_j)^(d-1), r ~ m^1/d; homogeneity
//                   lambda = (d-2)/(2d), mean mass ~ t^(1/(1-lambda)) = t^(2d/(d+2)),
//                   the mean-field theta of ballistic aggregation (t^6/5, t, t^2/3)
//   separable:c,p,q[;c,p,q...]   the general sum above; c > 0, numbers may be
//                   fractions such as 1/6 or -1/2
#pragma once
#include <string>
#include <vector>

namespace coolgas::smoluchowski {

struct KernelTerm {
  double c = 1;  // coefficient (> 0, so that K > 0 and N stays non-negative)
  double p = 0;  // exponent of i in the first product
  double q = 0;  // exponent of j in the first product
};

enum class KernelKind { Constant, Additive, Product, Ballistic, Separable };

// The ballistic kernel's terms in dimension d = 1, 2, 3 (3: the paper's Eq. 4).
std::vector<KernelTerm> ballistic_terms(int dimension);

struct Kernel {
  KernelKind kind = KernelKind::Separable;
  std::string text;  // the string it was parsed from, for provenance
  std::vector<KernelTerm> terms;

  double operator()(double i, double j) const;
  // Distinct exponents among all p and q, in first-seen order: one power
  // table (and one forward FFT per right-hand side) each.
  std::vector<double> exponents() const;
  // Index into exponents() of a given exponent.
  int exponent_index(double e) const;
  // Homogeneity λ (K(a i, a j) = a^λ K(i,j)) when all terms share p+q; else NaN.
  double homogeneity() const;
  // Written back in the general separable syntax (provenance).
  std::string as_separable() const;
};

// Parses a kernel string (see the list above). Throws InputError with one line
// naming the string and the accepted forms.
Kernel parse_kernel(const std::string& text);

}  // namespace coolgas::smoluchowski
