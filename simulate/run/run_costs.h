// What each kind of run costs on this project's machine, per CPU second of
// whole runs (set-up and dumps included), as --estimate prices a plan
// (run_plan.h). Each collision model's row (models.h) names its costs; the
// runs that measured them are in run_costs.cc and the table of current
// figures in tests/bench/README.md.
#pragma once

namespace coolgas {

struct Scene;

struct ModelCosts {
  double bytes_per_particle;       // the run's memory at its peak, per particle
  double dump_bytes_per_particle;  // a dump's compressed size, per particle
  // The CPU seconds of a run of `scene` doing `work` (collisions; for
  // aggregation, merges), its set-up included.
  double (*cpu_seconds)(const Scene& scene, double work);
};

// A gas of hard particles (elastic, inelastic, viscoelastic): collisions at
// the measured rate of its size and dimension, equilibration included.
extern const ModelCosts kGasCosts;
// Ballistic aggregation: merges at the measured rate of its density, and
// its set-up.
extern const ModelCosts kAggregationCosts;

}  // namespace coolgas
