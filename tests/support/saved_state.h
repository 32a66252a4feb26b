// An engine's (or one part's) exact state written to memory and read back (as a checkpoint
// does, without the file beside a trajectory).
#pragma once
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "simulate/engine/engine_base.h"
#include "simulate/engine/state_archive.h"

namespace coolgas::test {

// Whatever `save(StateWriter&)` writes, read back from memory.
template <class Save>
StateReader saved_state_of(Save save) {
  std::FILE* f = std::tmpfile();
  if (!f) {  // fails the test (StateReader throws on no bytes) rather than writing to no file
    ADD_FAILURE() << "no temporary file for the saved state";
    return StateReader({}, "memory");
  }
  StateWriter out(f);
  save(out);
  out.finish();
  std::vector<char> bytes(std::size_t(std::ftell(f)));
  std::rewind(f);
  EXPECT_EQ(std::fread(bytes.data(), 1, bytes.size(), f), bytes.size());
  std::fclose(f);
  return StateReader(std::move(bytes), "memory");
}

inline StateReader saved_state(const EngineBase& e) {
  return saved_state_of([&](StateWriter& out) { e.save(out); });
}

// Whether two frames are equal bit for bit (positions, velocities, images, ids, masses, diameters).
inline void expect_same_frame(const EngineFrame& a, const EngineFrame& b) {
  ASSERT_EQ(a.time, b.time);
  ASSERT_EQ(a.collisions, b.collisions);
  ASSERT_EQ(a.position.size(), b.position.size());
  for (std::size_t i = 0; i < a.position.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(a.position[i][d], b.position[i][d]) << "particle " << i;
      ASSERT_EQ(a.velocity[i][d], b.velocity[i][d]) << "particle " << i;
      ASSERT_EQ(a.image[i][d], b.image[i][d]) << "particle " << i;
    }
  ASSERT_EQ(a.angular_velocity.size(), b.angular_velocity.size());
  for (std::size_t i = 0; i < a.angular_velocity.size(); ++i)
    for (int d = 0; d < 3; ++d) ASSERT_EQ(a.angular_velocity[i][d], b.angular_velocity[i][d]) << "particle " << i;
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.diameter, b.diameter);
  EXPECT_EQ(a.species, b.species);
}

}  // namespace coolgas::test
