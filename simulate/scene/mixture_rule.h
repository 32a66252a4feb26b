// The engine's rule of a scene's mixture ([[species]]): the species'
// diameters and masses over a normal rule (simulate/engine/collision_rules.h,
// MixtureRule), for the start's melt and the run's engine alike.
#pragma once
#include <vector>

#include "simulate/engine/collision_rules.h"
#include "simulate/scene/scene.h"

namespace coolgas {

inline std::vector<double> species_diameters(const Scene& s) {
  std::vector<double> d;
  for (const Species& k : s.species) d.push_back(k.diameter);
  return d;
}

inline std::vector<double> species_masses(const Scene& s) {
  std::vector<double> m;
  for (std::size_t k = 0; k < s.species.size(); ++k) m.push_back(s.species_mass(k));
  return m;
}

template <class Normal>
MixtureRule<Normal> mixture_rule(const Scene& s, const Normal& normal) {
  return MixtureRule<Normal>(normal, species_diameters(s), species_masses(s));
}

}  // namespace coolgas
