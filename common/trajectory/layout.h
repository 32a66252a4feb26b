// The names of the coolgas H5MD layout (data-schema/h5md-profile.md), spelled
// once: every group, element and dataset path the writer, the readers and the
// profile use. An element is a group holding step, time and value.
//
// Two layouts share these names: the gas (a fixed set of N particles) and
// ballistic aggregation, which adds per-slot id, mass and diameter (id -1 in
// an empty slot, H5MD's convention for a varying number of particles) and the
// aggregate observables. Which one a file has is decided by layout_of().
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace coolgas::layout {

inline constexpr std::string_view kH5md = "/h5md";
inline constexpr std::string_view kAuthor = "/h5md/author";
inline constexpr std::string_view kCreator = "/h5md/creator";
inline constexpr std::string_view kParticles = "/particles";  // one group per particle group (H5MD 1.1)
inline constexpr std::string_view kAll = "/particles/all";     // coolgas writes the one group "all"
inline constexpr std::string_view kBox = "/particles/all/box";
inline constexpr std::string_view kParameters = "/parameters";
inline constexpr std::string_view kRestart = "/restart";
inline constexpr std::string_view kObservables = "/observables";

// Per-dump elements.
inline constexpr std::string_view kBoxEdges = "/particles/all/box/edges";
inline constexpr std::string_view kPosition = "/particles/all/position";
inline constexpr std::string_view kPositionTime = "/particles/all/position/time";  // the dump times
inline constexpr std::string_view kImage = "/particles/all/image";
inline constexpr std::string_view kVelocity = "/particles/all/velocity";
inline constexpr std::string_view kId = "/particles/all/id";  // aggregation layout
inline constexpr std::string_view kMass = "/particles/all/mass";
inline constexpr std::string_view kDiameter = "/particles/all/diameter";
inline constexpr std::string_view kAngularVelocity = "/particles/all/angular_velocity";  // rough runs
inline constexpr std::string_view kSpecies = "/particles/all/species";                    // mixtures

// Observable elements.
inline constexpr std::string_view kKineticEnergy = "/observables/kinetic_energy";
inline constexpr std::string_view kCollisions = "/observables/collisions";
inline constexpr std::string_view kCollisionsPerParticle = "/observables/collisions_per_particle";
inline constexpr std::string_view kCollisionsBelowDelta = "/observables/collisions_below_delta";
inline constexpr std::string_view kTotalMomentum = "/observables/total_momentum";
inline constexpr std::string_view kAggregates = "/observables/aggregates";  // aggregation layout
inline constexpr std::string_view kMeanMass = "/observables/mean_mass";
inline constexpr std::string_view kLargestMass = "/observables/largest_mass";
inline constexpr std::string_view kRotationalEnergy = "/observables/rotational_energy";  // rough runs
inline constexpr std::string_view kSpeciesKineticEnergy = "/observables/species_kinetic_energy";  // mixtures

// The /restart series: one row per complete dump. The writer appends the
// time row last, so its length is the number of complete dumps.
inline constexpr std::string_view kRestartTime = "/restart/time";
inline constexpr std::string_view kRestartCollisions = "/restart/collisions";
inline constexpr std::string_view kRestartBelowDelta = "/restart/collisions_below_delta";

// The fill value of /particles/all/id: no aggregate in this slot.
inline constexpr std::int32_t kAbsentId = -1;

std::string step_of(std::string_view element);
std::string time_of(std::string_view element);
std::string value_of(std::string_view element);
// The same element in another particle group (files of other programs):
// in_group(kPosition, "trajectory") is "/particles/trajectory/position".
std::string in_group(std::string_view element, std::string_view group);

// The completion marker: the number of complete dumps (rows of
// /restart/time; 0 if the file has none) and the time of the last one.
// Rows beyond them were written by a burst still under way or cut short by
// a crash; readers leave them out.
hsize_t complete_dumps(hid_t file);
std::optional<double> last_dump_time(hid_t file);

// A coolgas trajectory (it has /parameters and the position element), not
// an H5MD file of another program (h5md_frame.h reads those).
bool is_coolgas(hid_t file);

// The file's dimension: the H5MD box's `dimension` attribute (3 for spheres,
// 2 for disks, 1 for rods); 3 when it is absent (files before 2D). Any other
// value (an array, a string, 2.5, 0 or 4) is an InputError naming the file,
// the attribute and the value.
int dimension_of(hid_t file);

enum class Layout { kGas, kAggregation };

// The one place that tells the layouts apart: a file is of the aggregation
// layout when it holds the id element.
Layout layout_of(hid_t file);

}  // namespace coolgas::layout
