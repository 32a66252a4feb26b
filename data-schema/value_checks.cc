#include "data-schema/value_checks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "common/close_pairs.h"
#include "common/hdf5_file.h"
#include "common/interrupt.h"
#include "data-schema/hdf5_inspect.h"

namespace coolgas::schema {
namespace {

hsize_t product(std::vector<hsize_t>::const_iterator first, std::vector<hsize_t>::const_iterator last) {
  return std::accumulate(first, last, hsize_t{1}, std::multiplies<>());
}

// Reads the hyperslab start/count of `dataset` into out (resized to fit).
void read_slab(hid_t dataset, const std::vector<hsize_t>& start, const std::vector<hsize_t>& count,
               std::vector<double>& out) {
  out.resize(static_cast<std::size_t>(product(count.begin(), count.end())));
  h5::Handle fspace(H5Dget_space(dataset));
  h5::Handle mspace(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr));
  if (H5Sselect_hyperslab(fspace.id(), H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr) < 0 ||
      H5Dread(dataset, H5T_NATIVE_DOUBLE, mspace.id(), fspace.id(), H5P_DEFAULT, out.data()) < 0)
    throw std::runtime_error("cannot read rows " + std::to_string(start[0]) + ".." +
                             std::to_string(start[0] + count[0]) + " (corrupt data?)");
}

// Remembers the first offending element and counts the others.
class Offences {
 public:
  void add(const std::function<std::string()>& describe) {
    if (count_++ == 0) first_ = describe();
  }
  Finding result() const {
    if (count_ == 0) return std::nullopt;
    return count_ == 1 ? first_ : first_ + " (and " + std::to_string(count_ - 1) + " more)";
  }

 private:
  std::string first_;
  std::size_t count_ = 0;
};

std::string at(const std::vector<hsize_t>& dims, hsize_t flat, double v) {
  return index_text(dims, flat) + " = " + number_text(v);
}

// "[i] = v" for a one-dimensional dataset (built by appending: GCC 12 gives
// a false -Wrestrict for "literal" + std::string&&).
std::string at(hsize_t i, double v) {
  std::string s = "[";
  s.append(std::to_string(i)).append("] = ").append(number_text(v));
  return s;
}

}  // namespace

void for_each_block(hid_t dataset, const Scan& scan,
                    const std::function<void(hsize_t first, std::span<const double> values)>& visit) {
  std::vector<hsize_t> dims = h5::shape(dataset);
  if (!dims.empty()) dims[0] = std::min(dims[0], scan.rows);
  const std::size_t block_values = scan.block_values;
  std::vector<double> buf;
  if (dims.empty()) {  // scalar
    read_slab(dataset, {}, {}, buf);
    visit(0, buf);
    return;
  }
  const hsize_t row = product(dims.begin() + 1, dims.end());
  const auto block = static_cast<hsize_t>(std::max<std::size_t>(block_values, 1));
  std::vector<hsize_t> start(dims.size(), 0), count = dims;
  if (row <= block || dims.size() == 1) {  // whole rows at a time
    const hsize_t rows = std::max<hsize_t>(1, block / std::max<hsize_t>(row, 1));
    for (hsize_t r = 0; r < dims[0]; r += rows) {
      start[0] = r;
      count[0] = std::min(rows, dims[0] - r);
      throw_if_interrupted(kInterruptedCheck);
      read_slab(dataset, start, count, buf);
      visit(r * row, buf);
    }
    return;
  }
  // A row too large for one block: slices along the second dimension.
  const hsize_t inner = product(dims.begin() + 2, dims.end());
  const hsize_t step = std::max<hsize_t>(1, block / std::max<hsize_t>(inner, 1));
  count[0] = 1;
  for (hsize_t r = 0; r < dims[0]; ++r) {
    for (hsize_t j = 0; j < dims[1]; j += step) {
      start[0] = r;
      start[1] = j;
      count[1] = std::min(step, dims[1] - j);
      throw_if_interrupted(kInterruptedCheck);
      read_slab(dataset, start, count, buf);
      visit(r * row + j * inner, buf);
    }
  }
}

Finding check_finite(hid_t dataset, const Scan& scan) {
  const auto dims = h5::shape(dataset);
  Offences bad;
  for_each_block(dataset, scan, [&](hsize_t first, std::span<const double> v) {
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!std::isfinite(v[i])) bad.add([&] { return at(dims, first + i, v[i]) + " is not finite"; });
  });
  return bad.result();
}

Finding check_inside_box(hid_t dataset, double L, std::string_view L_source, const Scan& scan) {
  const auto dims = h5::shape(dataset);
  Offences bad;
  for_each_block(dataset, scan, [&](hsize_t first, std::span<const double> v) {
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!(v[i] >= 0 && v[i] < L))  // also catches NaN
        bad.add([&] {
          return at(dims, first + i, v[i]) + " is outside [0, L) with L = " + number_text(L) + " from " +
                 std::string(L_source);
        });
  });
  return bad.result();
}

Finding check_indices_below(hid_t dataset, std::size_t count, std::string_view table, const Scan& scan) {
  const auto dims = h5::shape(dataset);
  Offences bad;
  for_each_block(dataset, scan, [&](hsize_t first, std::span<const double> v) {
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!(v[i] >= 0 && v[i] < double(count)))
        bad.add([&] { return at(dims, first + i, v[i]) + " is not one of the " + std::to_string(count) + " " +
                             std::string(table); });
  });
  return bad.result();
}

namespace {

// "(L)", "diag(L, L)" or "diag(L, L, L)": the box matrix of a d-dimensional box.
std::string diagonal_text(int d) {
  if (d == 1) return "(L)";
  std::string s = "diag(L";
  for (int k = 1; k < d; ++k) s += ", L";
  return s + ")";
}

}  // namespace

Finding check_box_matrix(hid_t dataset, double L, std::string_view L_source, const Scan& scan) {
  const auto dims = h5::shape(dataset);
  Offences bad;
  for_each_block(dataset, scan, [&](hsize_t first, std::span<const double> v) {
    const hsize_t d = dims.back();  // 3, or 2 for a 2D box, 1 for a ring
    for (std::size_t i = 0; i < v.size(); ++i) {
      const hsize_t k = (first + i) % (d * d);
      const double want = k % (d + 1) == 0 ? L : 0.0;  // the diagonal of a row-major 3x3 is 0, 4, 8 (2x2: 0, 3)
      if (v[i] != want)
        bad.add([&] {
          return at(dims, first + i, v[i]) + " but the box is " +
                 diagonal_text(int(d)) +
                 " with L = " + number_text(L) + " from " + std::string(L_source);
        });
    }
  });
  return bad.result();
}

Finding check_nondecreasing(hid_t dataset, const Scan& scan) {
  Offences bad;
  double previous = -INFINITY;
  for_each_block(dataset, scan, [&](hsize_t first, std::span<const double> v) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (std::isnan(v[i])) {
        bad.add([&] { return at(first + i, v[i]) + " is not a number"; });
        continue;  // compare the next row with the last real one
      }
      if (v[i] < previous)
        bad.add([&] {
          return at(first + i, v[i]) + " is less than an earlier " + number_text(previous) +
                 ": rows must not go back in time";
        });
      previous = std::max(previous, v[i]);
    }
  });
  return bad.result();
}

Finding check_equal(hid_t dataset, hid_t reference, std::string_view reference_path, const Scan& scan) {
  Offences bad;
  std::vector<double> ref;
  for_each_block(dataset, scan, [&](hsize_t first, std::span<const double> v) {
    read_slab(reference, {first}, {v.size()}, ref);
    for (std::size_t i = 0; i < v.size(); ++i)
      if (v[i] != ref[i])
        bad.add([&] { return at(first + i, v[i]) + " but " + std::string(reference_path) + at(first + i, ref[i]); });
  });
  return bad.result();
}

namespace {

// The spheres of one frame and the pair test.
struct Spheres {
  std::span<const double> r, d;
  std::span<const std::int32_t> id;
  double L;
  std::size_t size() const { return r.size() / 3; }
  double diameter(std::size_t i) const { return d.empty() ? 1.0 : d[i]; }
  std::int64_t name(std::size_t i) const { return id.empty() ? std::int64_t(i) : std::int64_t(id[i]); }
  double distance(std::size_t i, std::size_t j) const {
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      double x = r[3 * j + std::size_t(k)] - r[3 * i + std::size_t(k)];
      x -= L * std::round(x / L);
      s += x * x;
    }
    return std::sqrt(s);
  }
};

void test_pair(const Spheres& s, std::size_t i, std::size_t j, Offences& found) {
  const double contact = 0.5 * (s.diameter(i) + s.diameter(j)), r = s.distance(i, j);
  if (!(r < contact * (1 - kOverlapTolerance))) return;
  found.add([&] {
    return "particles " + std::to_string(std::min(s.name(i), s.name(j))) + " and " +
           std::to_string(std::max(s.name(i), s.name(j))) + " overlap: centres " + number_text(r) +
           " apart, contact at " + number_text(contact) + " (" + number_text(r / contact) + " of it)";
  });
}

}  // namespace

Finding check_no_overlaps(std::span<const double> position, std::span<const double> diameter,
                          std::span<const std::int32_t> id, double L, Geometry g) {
  const Spheres s{position, diameter, id, L};
  std::vector<std::size_t> small, large;
  double width = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.diameter(i) > L / 4) {
      large.push_back(i);
    } else {
      small.push_back(i);
      width = std::max(width, s.diameter(i));
    }
  }
  Offences found;
  if (!small.empty())
    for_each_close_pair(
        small, [&](std::size_t i) { return &position[3 * i]; }, std::max(width, L * 1e-6), L, g,
        [&](std::size_t i, std::size_t j) { test_pair(s, i, j, found); });
  // Spheres wider than L/4 fill a sixtieth of the box each: there are few.
  for (std::size_t a = 0; a < large.size(); ++a)
    for (std::size_t j = 0; j < s.size(); ++j)
      if (j != large[a] && (s.diameter(j) <= L / 4 || j > large[a])) test_pair(s, large[a], j, found);
  return found.result();
}

}  // namespace coolgas::schema
