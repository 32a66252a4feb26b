#include "analyze/smoluchowski/method.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "analyze/smoluchowski/direct.h"
#include "analyze/smoluchowski/geometric.h"
#include "common/error.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

Method parse_method(const std::string& name) {
  if (name == "direct") return Method::Direct;
  if (name == "fft") return Method::Fft;
  if (name == "geometric") return Method::Geometric;
  throw InputError("method '" + name + "' is not known; use direct, fft or geometric");
}

std::string method_name(Method m) {
  switch (m) {
    case Method::Direct: return "direct";
    case Method::Fft: return "fft";
    case Method::Geometric: return "geometric";
  }
  return "?";
}

void validate(const MethodOptions& o) {
  // Upper bound: the FFT length 2M must fit an int, and memory stays sane.
  constexpr std::int64_t kMaxM = std::int64_t(1) << 28;
  if (o.M < 2 || o.M > kMaxM)
    throw InputError("cut-off mass M must be between 2 and 2^28, got " + std::to_string(o.M));
  // Each method's own knobs only: the others are not used.
  if (o.method == Method::Geometric && (!(o.grid_ratio > 1) || !std::isfinite(o.grid_ratio)))
    throw InputError("grid ratio must be a number > 1, got " + format_number(o.grid_ratio));
  if (o.method == Method::Fft && !(o.fft_floor >= 0 && o.fft_floor < 1))
    throw InputError("fft floor must be in [0, 1), got " + format_number(o.fft_floor));
}

std::unique_ptr<CoagulationRhs> make_rhs(const Kernel& kernel, const MethodOptions& o) {
  validate(o);
  switch (o.method) {
    case Method::Direct: return std::make_unique<DirectRhs>(kernel, o.M);
    case Method::Fft: return std::make_unique<FftRhs>(kernel, o.M, o.fft_floor);
    case Method::Geometric: return std::make_unique<GeometricRhs>(kernel, o.M, o.grid_ratio);
  }
  return nullptr;
}

double grid_cells(const MethodOptions& o) {
  const double M = double(o.M);
  if (o.method != Method::Geometric) return M;
  // Pivots 1, 2, 3, ... while x (r - 1) < 1, then growing by r: at most
  // 1/(r - 1) of the first kind and log(M)/log(r) of the second.
  return std::min(M, 1 / (o.grid_ratio - 1) + std::log(M) / std::log(o.grid_ratio) + 2);
}

double method_bytes(const Kernel& kernel, const MethodOptions& o) {
  const double cells = grid_cells(o), exponents = double(kernel.exponents().size());
  double doubles = (2 * cells + 1) + exponents * cells;  // MassGrid (pivots, edges), KernelPowers
  switch (o.method) {
    case Method::Direct:
      if (o.M <= DirectRhs::kTableLimit) doubles += cells * cells;
      break;
    case Method::Fft: {
      const double length = 2 * double(std::bit_ceil(static_cast<std::uint64_t>(o.M)));
      doubles += length + (exponents + 1) * (length / 2 + 1) * 2;  // real buffer, complex spectra
      break;
    }
    case Method::Geometric: doubles += cells; break;  // the losses of an evaluation
  }
  return doubles * sizeof(double);
}

}  // namespace coolgas::smoluchowski
