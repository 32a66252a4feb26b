// The coolgas H5MD profile (data-schema/h5md-profile.md) as data: every group,
// attribute, element and plain dataset a trajectory file must hold, with its
// type, shape rule and meaning. The validator walks these tables; it knows
// no path by itself.
//
// Versions only add: a later schema version appends rows (usually with
// Presence::kOptional and a higher `since`); no row is ever edited or removed.
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/trajectory/layout.h"

namespace coolgas::schema {

// Types as the profile names them. kInteger accepts any signed integer width
// (used where readers convert anyway; see the box `dimension` row).
enum class DataType { kInt32, kInt64, kFloat64, kVlenString, kInteger };
std::string_view type_name(DataType t);

// kPerModel: required when the file's model (common/trajectory/collision_models.h)
// has it: a model-specific /parameters attribute the model lists, or an
// element of the layout the model writes.
enum class Presence { kRequired, kOptional, kPerModel };

// One dimension of a dataset's shape: a fixed size, N (/parameters/N), d
// (the box's `dimension`: 3, or 2 for disks) or S (a mixture's species: the
// length of /parameters/species_fraction).
struct Extent {
  hsize_t size = 0;
  bool particles = false;  // true: the extent is N
  bool dimension = false;  // true: the extent is d
  bool species = false;    // true: the extent is S
};
inline constexpr Extent kParticles{.particles = true};
inline constexpr Extent kDimension{.dimension = true};
inline constexpr Extent kSpeciesExtent{.species = true};

// Which row count a series' first dimension shares: F (dumps) or K (observable rows).
enum class RowCount { kFrames, kObservableRows };
std::string_view row_count_symbol(RowCount r);  // "F" or "K"

// What each number of an element's value must satisfy, checked frame by frame.
enum class ValueRule {
  kAny,        // no constraint (e.g. integer image counts)
  kFinite,     // no NaN or infinity
  kInsideBox,  // finite and within [0, L), L from /parameters/L
  kBoxMatrix,  // each row is diag(L, L, L) (2D: diag(L, L))
  kSpeciesIndex,  // an index into the species table: 0 to S - 1
};

struct GroupSpec {
  std::string_view path;
  std::string_view meaning;
  Presence presence = Presence::kRequired;
  int since = 1;
};

// An attribute; `length` empty means scalar, n means shape (n,).
struct AttributeSpec {
  std::string_view group;
  std::string_view name;
  DataType type = DataType::kInt64;
  std::optional<hsize_t> length;
  std::string_view equals;               // the value as the validator prints it, e.g. "[1, 1]"; empty: any
  std::optional<std::int64_t> at_least;  // lower bound for integers
  std::optional<std::int64_t> at_most;   // upper bound for integers
  std::optional<double> above;           // floats: finite and above this
  bool per_dimension = false;            // an array of d elements, each `equals` (shown as "[x, x]")
  bool per_species = false;              // an array of S elements (a mixture's species), each above `above`
  std::string_view meaning;
  Presence presence = Presence::kRequired;
  int since = 1;
};

// An H5MD element: a group holding step (int64, (R,)), time (float64, (R,))
// and value (`type`, (R, row...)), R being F or K.
struct ElementSpec {
  std::string_view path;
  DataType type = DataType::kFloat64;
  std::vector<Extent> row;  // shape of one row of `value`
  RowCount rows = RowCount::kFrames;
  ValueRule rule = ValueRule::kAny;
  std::string_view meaning;
  Presence presence = Presence::kRequired;
  int since = 1;
  std::optional<layout::Layout> only_in;  // written only in files of this layout
  bool rough_only = false;                // written exactly in files of rough runs (/parameters/beta)
  bool mixture_only = false;              // written exactly in files of mixtures (/parameters/species_fraction)
  std::optional<std::int64_t> fill;       // the dataset's fill value (H5MD: marks absent particles)
};

// A plain time series outside H5MD elements (the /restart counters).
struct DatasetSpec {
  std::string_view path;
  DataType type = DataType::kInt64;
  RowCount rows = RowCount::kFrames;
  std::string_view same_as;  // a dataset it must equal element by element; empty: none
  std::string_view meaning;
  Presence presence = Presence::kRequired;
  int since = 1;
};

// Names an attribute, e.g. {"/parameters", "N"}.
struct AttributeRef {
  std::string_view group;
  std::string_view name;
};

struct Profile {
  int version = 0;
  std::vector<GroupSpec> groups;
  std::vector<AttributeSpec> attributes;
  std::vector<ElementSpec> elements;
  std::vector<DatasetSpec> datasets;
  // Where the file's schema version, N and L come from, and the elements
  // whose rows define F and K.
  AttributeRef schema_version;
  AttributeRef particle_count;
  AttributeRef box_side;
  std::string_view frames_from;           // element whose rows define F
  std::string_view observable_rows_from;  // element whose rows define K
};

// The profile this build of coolgas writes and checks.
const Profile& h5md_profile();

// "(F, N, d)" for an element's value; "(F, N, 3)" given the file's d = 3.
std::string shape_rule(RowCount rows, const std::vector<Extent>& row, std::optional<int> d = std::nullopt);

}  // namespace coolgas::schema
