// The collision models a run can use, one row each. Everything that differs
// between models on the simulator's side follows from its row: the scene's
// choice (collision.model), the engine made at the start or restored from a
// checkpoint, and the progress line's ETA rule; the engine contract test
// runs every row. The file side (the /parameters a model has, its schema
// version and layout) is the row of the same name in
// common/trajectory/collision_models.cc; a test checks that the two tables
// name the same models. Adding a model: ARCHITECTURE.md.
#pragma once
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "simulate/run/scene.h"

namespace coolgas {

class EngineBase;
class StateReader;
class RunEta;
struct Particles;
struct EngineCounters;
struct AggregateState;
struct RunParameters;

struct ModelRow {
  CollisionModel model;  // the rows are in the enum's order
  const char* name;      // collision.model and /parameters/model
  // The engine with this model's rule at time `now`; `aggregates`: the
  // slots of a resumed aggregation run (else every particle is a unit sphere).
  std::unique_ptr<EngineBase> (*make)(const Scene&, Particles, double now, const EngineCounters&,
                                      const AggregateState* aggregates);
  // The engine with the exact state a checkpoint holds.
  std::unique_ptr<EngineBase> (*restore)(const Scene&, const StateReader&);
  // The progress line's estimate of the time left (simulate/run/run_eta.h).
  RunEta (*eta)(const RunParameters&);
};

const std::vector<ModelRow>& model_rows();
const ModelRow& model_row(CollisionModel model);
// The row named `name`, or nullptr.
const ModelRow* find_model_row(std::string_view name);

}  // namespace coolgas
