// Checkpoints: the exact state of a run in a file beside its trajectory
// (FILE.h5 -> FILE.h5.checkpoint), so that a resumed run replays the same
// events as the uninterrupted one, from any stop. The layout is
// data-schema/checkpoint.md.
//
// A checkpoint holds the engine's exact state (state_archive.h), the physics
// it belongs to, the time of the trajectory's last complete dump when it was
// written and the observable rows computed since that dump (the trajectory
// writer buffers them until the next dump). It is written beside the old one,
// flushed to disk and renamed into place, so a crash while writing leaves the
// previous checkpoint whole.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/trajectory/h5md_writer.h"
#include "simulate/engine/engine_base.h"
#include "simulate/scene/scene.h"

namespace coolgas {

std::string checkpoint_path(const std::string& trajectory);

struct RunCheckpoint {
  std::unique_ptr<EngineBase> engine;
  double last_dump = 0;                // the trajectory's last complete dump when it was written
  std::vector<ObservableRow> pending;  // observables after last_dump, at times <= engine->now()
};

// Writes the checkpoint of `trajectory` (replacing the old one atomically).
// Throws WriteError (exit code 5) naming the file if writing fails (a full
// disk); the previous checkpoint is then still in place.
void write_checkpoint(const std::string& trajectory, const Scene& scene, const EngineBase& engine, double last_dump,
                      const std::vector<ObservableRow>& pending);

// The checkpoint of `trajectory`, or nothing if it has none. Throws
// InputError naming it if it is not a regular file, larger than the memory,
// damaged (a section longer than the file, a wrong hash) or belongs to other
// physics than `scene`.
std::optional<RunCheckpoint> read_checkpoint(const std::string& trajectory, const Scene& scene);

// Removes a checkpoint left by an earlier run of that name (a new run).
void remove_checkpoint(const std::string& trajectory);

}  // namespace coolgas
