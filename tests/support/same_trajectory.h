// Bit-for-bit comparison of two trajectories, for the resume tests: every
// dump and observable of one file equals that of the other, byte for byte.
#pragma once
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/hdf5_file.h"

namespace coolgas::test {

// The bytes of a whole dataset (any element type).
inline std::vector<char> dataset_bytes(hid_t file, const std::string& path) {
  h5::Handle d = h5::open_dataset(file, path);
  const hid_t type = H5Dget_type(d.id());
  const std::size_t size = H5Tget_size(type);
  hsize_t n = 1;
  for (hsize_t x : h5::shape(d.id())) n *= x;
  std::vector<char> bytes(n * size);
  if (n > 0) H5Dread(d.id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
  H5Tclose(type);
  return bytes;
}

// The datasets a resumed run must reproduce.
inline constexpr const char* kTrajectoryDatasets[] = {
    "particles/all/position/value", "particles/all/position/time", "particles/all/velocity/value",
    "particles/all/image/value",    "observables/kinetic_energy/value", "observables/kinetic_energy/time",
    "observables/collisions/value", "observables/total_momentum/value", "restart/time"};

// A rough run's too (data-schema/h5md-profile.md, version 5): its spins and
// rotational energy; a mixture's (version 6): its species and their
// energies; and aggregation's: each aggregate's id, mass and diameter.
inline constexpr const char* kModelDatasets[] = {
    "particles/all/angular_velocity/value",     "observables/rotational_energy/value",
    "particles/all/species/value",              "observables/species_kinetic_energy/value",
    "particles/all/id/value",                   "particles/all/mass/value",
    "particles/all/diameter/value",             "observables/largest_mass/value"};

// Every dump and observable of `b` equals that of `a`, bit for bit.
inline void expect_same_trajectory(const std::string& a, const std::string& b) {
  h5::Handle fa = h5::open_file(a, h5::Mode::kReadOnly), fb = h5::open_file(b, h5::Mode::kReadOnly);
  for (const char* ds : kModelDatasets) {
    if (!h5::exists(fa.id(), ds)) continue;
    ASSERT_TRUE(h5::exists(fb.id(), ds)) << ds << " of " << b;
    EXPECT_TRUE(dataset_bytes(fa.id(), ds) == dataset_bytes(fb.id(), ds)) << ds << " of " << b << " differs";
  }
  for (const char* ds : kTrajectoryDatasets) {
    const auto x = dataset_bytes(fa.id(), ds), y = dataset_bytes(fb.id(), ds);
    ASSERT_EQ(x.size(), y.size()) << ds << " of " << b;
    EXPECT_TRUE(x == y) << ds << " of " << b << " differs from the uninterrupted run";
  }
}

}  // namespace coolgas::test
