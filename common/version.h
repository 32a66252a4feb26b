// Program version for provenance: the project version plus the git commit the
// binary was built from (stamped at build time by cmake/stamp_version.cmake).
#pragma once
#include <string>

namespace coolgas {
const std::string& program_version();
}
