// Reading a trajectory's /parameters and observables back (common/trajectory/run_info.h): what
// the writer stored comes back exactly, and every defect is one InputError
// naming the file and what is missing.
#include "common/trajectory/run_info.h"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "common/trajectory/layout.h"
#include "tests/support/run_command.h"
#include "tests/support/energy_test_runs.h"

namespace coolgas {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TEST(RunInfo, ParametersAndObservablesReadBackExactly) {
  const std::string path = test::scratch_dir("run_info_roundtrip") + "/run.h5";
  test::write_energy_run(path, test::paper_parameters(32, 7), {0, 1, 2.5}, [](double t) { return 1 / (1 + t); }, Geometry(3));
  const RunInfo info = read_run_info(path);
  EXPECT_EQ(info.params.N, 1000);
  EXPECT_EQ(info.params.L, 32.0);
  EXPECT_EQ(info.params.phi, 0.208);
  EXPECT_EQ(info.params.model, "inelastic");
  EXPECT_EQ(info.params.collision.at("r0"), 0.1);
  EXPECT_EQ(info.params.collision.at("delta"), 1e-4);
  EXPECT_EQ(info.params.seed, 7);
  EXPECT_EQ(info.params.scene_toml, test::paper_parameters(32, 7).scene_toml);
  const ObservableSeries e = read_observable(path, layout::kKineticEnergy);
  EXPECT_EQ(e.time, (std::vector<double>{0, 1, 2.5}));
  EXPECT_EQ(e.value, (std::vector<double>{1, 0.5, 1 / 3.5}));
}

TEST(RunInfo, MissingObservableIsNamedWithTheFile) {
  const std::string path = test::scratch_dir("run_info_missing") + "/bare.h5";
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
    h5::create_group(f.id(), "observables");
  }
  EXPECT_EQ(message_of([&] { read_observable(path, layout::kKineticEnergy); }),
            path + ": not a coolgas trajectory: missing /observables/kinetic_energy");
  EXPECT_EQ(message_of([&] { read_run_info(path); }), path + ": not a coolgas trajectory: missing /parameters");
}

TEST(RunInfo, FileThatIsNotHdf5IsAnInputError) {
  const std::string path = test::scratch_dir("run_info_text") + "/table.tsv";
  std::ofstream(path) << "# t\tE\n1\t2\n";
  EXPECT_NE(message_of([&] { read_run_info(path); }).find("not HDF5"), std::string::npos);
}

TEST(RunInfo, NonFiniteEnergyIsRejected) {
  const std::string path = test::scratch_dir("run_info_nan") + "/run.h5";
  test::write_energy_run(path, test::paper_parameters(32, 1), {0, 1}, [](double t) { return t > 0 ? std::numeric_limits<double>::quiet_NaN() : 1.0; }, Geometry(3));
  EXPECT_NE(message_of([&] { read_observable(path, layout::kKineticEnergy); }).find("row 1 is not finite"), std::string::npos);
}

TEST(RunInfo, PhysicsDifferenceIgnoresSeedAndSceneOnly) {
  const RunParameters a = test::paper_parameters(32, 1);
  EXPECT_FALSE(physics_difference(a, test::paper_parameters(32, 2)));  // scene text differs in its seed line
  EXPECT_EQ(physics_difference(a, test::paper_parameters(48, 1)), "L = 32 vs 48");
  RunParameters b = a;
  b.collision["r0"] = 0.5;
  EXPECT_EQ(physics_difference(a, b), "r0 = 0.1 vs 0.5");
  b = a;
  b.model = "elastic";
  EXPECT_EQ(physics_difference(a, b), "model = inelastic vs elastic");
}

}  // namespace
}  // namespace coolgas
