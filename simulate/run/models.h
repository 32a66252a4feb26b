// The collision models a run can use, one row each. Everything that differs
// between models on the simulator's side follows from its row: the engine
// made at the start or restored from a checkpoint, the progress line's ETA
// rule and what --estimate prices; the engine contract test runs every row.
// The model's name, the /parameters it has, its schema version and layout
// are the file side's row at the same place in
// common/trajectory/collision_models.cc (the scene's collision.model offers
// those names); a test checks that the two tables have the same rows.
// Adding a model: ARCHITECTURE.md.
#pragma once
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "simulate/run/run_costs.h"
#include "simulate/scene/scene.h"

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
  std::string name() const { return model_name(model); }  // collision.model and /parameters/model
  // The engine with this model's rule at time `now`; `aggregates`: the
  // slots of a resumed aggregation run (else every particle is a unit sphere).
  std::unique_ptr<EngineBase> (*make)(const Scene&, Particles, double now, const EngineCounters&,
                                      const AggregateState* aggregates);
  // The engine with the exact state a checkpoint holds.
  std::unique_ptr<EngineBase> (*restore)(const Scene&, const StateReader&);
  // The progress line's estimate of the time left (simulate/run/run_eta.h).
  RunEta (*eta)(const RunParameters&);
  // What its runs cost, for --estimate (simulate/run/run_costs.h).
  const ModelCosts* costs;
};

const std::vector<ModelRow>& model_rows();
// The ETA of a run of these parameters in geometry g, by its model's row:
// an elastic gas has no finite-size regime, aggregation at most N - 1
// merges, the inelastic gas its own clustering floor and its crossings
// modelled; other cooling gases (viscoelastic) the floor 0.5; a driven gas,
// whatever its model, its steady state (eta_of_driven_gas).
RunEta run_eta_for(const RunParameters& p, Geometry g);
const ModelRow& model_row(CollisionModel model);
// The row named `name`, or nullptr.
const ModelRow* find_model_row(std::string_view name);

}  // namespace coolgas
