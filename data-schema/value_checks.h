// Checks on the numbers inside a dataset, streamed in bounded blocks: a frame
// of 8e6 particles (192 MB) is never read whole, let alone all frames.
// Each check returns the problem ("[1, 0, 2] = nan is not finite"), naming
// the first offending element and how many more there are, or nothing.
#pragma once
#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "common/geometry.h"

namespace coolgas::schema {

// How a check reads a dataset: at most `block_values` numbers at a time (at
// least one innermost row), and only its first `rows` rows (the rows of
// complete dumps: later ones belong to an interrupted burst).
struct Scan {
  std::size_t block_values = std::size_t{1} << 20;
  hsize_t rows = std::numeric_limits<hsize_t>::max();
};

// Where a check stops on SIGINT/SIGTERM/SIGHUP (common/interrupt.h): before
// a block or a dump, in coolgas-validate and in the check before a --resume.
inline constexpr const char* kInterruptedCheck = "while checking the file; it is unchanged";

// Reads a numeric dataset in row-major order as doubles, block by block;
// visit gets the flat index of the block's first number and the numbers.
// Stops with Interrupted between blocks once a signal arrived.
void for_each_block(hid_t dataset, const Scan& scan,
                    const std::function<void(hsize_t first, std::span<const double> values)>& visit);

using Finding = std::optional<std::string>;

Finding check_finite(hid_t dataset, const Scan& scan);
// Finite and 0 <= x < L.
Finding check_inside_box(hid_t dataset, double L, std::string_view L_source, const Scan& scan);
// Every row of a (R, 3, 3) dataset equals diag(L, L, L).
Finding check_box_matrix(hid_t dataset, double L, std::string_view L_source, const Scan& scan);
// Integers 0 <= x < count (indices into a table of `count` rows, named by `table`).
Finding check_indices_below(hid_t dataset, std::size_t count, std::string_view table, const Scan& scan);
// Values never decrease along a (R,) dataset.
Finding check_nondecreasing(hid_t dataset, const Scan& scan);
// Two (R,) datasets of equal length hold the same numbers.
Finding check_equal(hid_t dataset, hid_t reference, std::string_view reference_path, const Scan& scan);

// Pairs closer than their contact distance (d_i + d_j)/2 by more than
// kOverlapTolerance of it, at the minimum image in a periodic box of side
// L: hard spheres and aggregates never overlap (touching pairs sit at
// contact to within round-off). `position` holds 3 numbers per sphere;
// `diameter` one per sphere (empty: unit spheres); `id` names them in the
// message (empty: their index). Found with a cell list as wide as the
// widest sphere no wider than L/4 (common/close_pairs.h), the few wider
// ones against every sphere: O(n) for a gas. In 2D and 1D, disks (z = 0)
// or rods (y = z = 0), the cells then one layer or one row.
inline constexpr double kOverlapTolerance = 1e-9;
Finding check_no_overlaps(std::span<const double> position, std::span<const double> diameter,
                          std::span<const std::int32_t> id, double L, Geometry g);

}  // namespace coolgas::schema
