#include "common/trajectory/species_selection.h"

#include <string>

#include "common/error.h"

namespace coolgas {

void check_species_option(const Trajectory& traj, std::optional<int> species) {
  if (!species) return;
  if (!traj.has(Field::kSpecies))
    throw InputError(traj.path() + ": no species (its particles are all alike); --species needs a mixture's run "
                     "([[species]])");
  const std::size_t count = traj.species_count();
  if (*species < 0 || std::size_t(*species) >= count)
    throw InputError("--species " + std::to_string(*species) + ": " + traj.path() + " has " +
                     std::to_string(count) + " species, 0 to " + std::to_string(count - 1));
}

std::span<const double> species_values(std::span<const double> values, std::size_t per,
                                       std::span<const std::int32_t> species, int k, std::vector<double>& packed) {
  packed.clear();
  for (std::size_t i = 0; i < species.size(); ++i)
    if (species[i] == k) packed.insert(packed.end(), values.begin() + per * i, values.begin() + per * (i + 1));
  return packed;
}

}  // namespace coolgas
