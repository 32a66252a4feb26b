// One run of coolgas-simulate: scene -> initial state (or checkpoint, or
// resume point) -> engine -> observables and dumps in an H5MD file, with
// checkpoints beside it (checkpoint.h), progress, signals and collapse
// handled. The main() only parses the command line.
#pragma once
#include <string>
#include <vector>

namespace coolgas {

struct SimulationRequest {
  std::string scene_path;              // SCENE.toml (empty when resuming)
  std::string output;                  // -o; default: the scene's name with .h5
  std::string resume;                  // --resume FILE
  std::vector<std::string> overrides;  // --set key=value
  bool force = false;                  // overwrite an existing output
  bool quiet = false;                  // no progress line
};

// Returns the process exit code: 0 done, 3 interrupted by a signal (a
// checkpoint was written: --resume continues exactly), 4 inelastic collapse
// or an aggregate too large (the state was written as the last dump).
// Throws InputError for bad input, before anything is written, and
// WriteError (exit code 5) when writing the trajectory fails.
int run_simulation(const SimulationRequest& request);

}  // namespace coolgas
