// A scene as read from its file, and as a run records it in /parameters.
#pragma once
#include <string>

#include "common/trajectory/run_parameters.h"
#include "simulate/scene/scene.h"

namespace coolgas {

// The scene file's text; throws InputError naming the file if it cannot be
// read (a directory, a missing file).
std::string read_scene_file(const std::string& path);

// The /parameters of a run of this scene (and what its ETA is made from).
RunParameters parameters_of(const Scene& s);

}  // namespace coolgas
