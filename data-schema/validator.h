// Checks a trajectory file against the coolgas H5MD profile and lists every
// problem found, each naming the path and what is wrong with it.
//
// What is checked: each group, attribute, element and dataset of the profile
// tables (h5md_profile.h) exists with its type and shape; N (/parameters/N)
// matches the particle arrays; the particle elements share F rows and the
// observables K rows; times never decrease; positions lie in [0, L);
// velocities and observables are finite; box edges are diag(L, L, L);
// /restart has F rows and the dump times; no two spheres overlap in any
// dump (aggregates by their diameters). F and K count the complete dumps
// (rows of /restart/time) and the observable rows up to the last of them:
// rows after it, which a killed writer (or one still running) leaves, are
// not checked. Objects the profile does not list
// are ignored (later versions only add). Rows an element gained in a later
// schema version are required only from that version on.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "common/trajectory/h5md_profile.h"

namespace coolgas::schema {

struct Problem {
  std::string path;  // "/particles/all/position/value"
  std::string what;  // "[1, 0, 2] = 5.5 is outside [0, L) with L = 5 from /parameters/L"
};

// What the file holds, as far as it could be read.
struct Summary {
  std::int64_t particles = 0;   // N
  hsize_t frames = 0;           // F
  hsize_t observable_rows = 0;  // K
  int schema_version = 0;       // the file's /parameters/schema_version (the profile's when unreadable)
  bool interrupted = false;     // rows after the last complete dump (a burst cut short, or under way)
};

struct Report {
  std::vector<Problem> problems;  // in profile-table order
  Summary summary;
  bool valid() const { return problems.empty(); }
};

struct ValidateOptions {
  // Numbers read at once when scanning values: bounds memory for huge frames.
  std::size_t block_values = std::size_t{1} << 20;
};

// Throws InputError if `path` is missing or not an HDF5 file, and
// Interrupted (common/interrupt.h) once SIGINT/SIGTERM/SIGHUP arrived in a
// program that watches them: a large file is minutes of reading.
Report validate(const std::string& path, const Profile& profile = h5md_profile(), const ValidateOptions& options = {});

// "FILE: /path: what"
std::string problem_line(const std::string& file, const Problem& p);
// "FILE: valid (coolgas H5MD profile v1, N particles, F frames, K observable rows)"
std::string valid_line(const std::string& file, const Summary& s, int profile_version);

}  // namespace coolgas::schema
