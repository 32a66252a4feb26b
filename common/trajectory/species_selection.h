// One species of a mixture picked out of a frame: the tools' --species K
// (coolgas-velocity, coolgas-clusters). K is the species' index in the file
// (0 for the first [[species]] table of the scene); the file refuses it, in
// one line, when it has no species or fewer than K + 1.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "common/trajectory/frame_reader.h"

namespace coolgas {

// InputError unless --species K (when given) names one of the species of the
// trajectory, which was opened for kSpecies.
void check_species_option(const Trajectory& traj, std::optional<int> species);

// The values of the particles of species k, `per` numbers each (3 for a
// vector, 1 for a diameter), in the particles' order, packed into `packed`.
std::span<const double> species_values(std::span<const double> values, std::size_t per,
                                       std::span<const std::int32_t> species, int k, std::vector<double>& packed);

}  // namespace coolgas
