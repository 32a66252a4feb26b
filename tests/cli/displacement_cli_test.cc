// coolgas-displacement as a user runs it, on runs of coolgas-simulate: its
// --help states units; a ballistic-aggregation file and a file without image
// counts are one error line; the table has a row per dump from the
// reference on, starting at msd = 0 and vacf_norm = 1.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "common/hdf5_file.h"
#include "common/tsv.h"
#include "tests/support/cli_checks.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::expect_one_error_line;
using test::run_command;

class DisplacementCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new std::string(test::scratch_dir("displacement_cli"));
    const std::string gas = test::write_file(*dir, "gas.toml", "[system]\nN = 500\nphi = 0.1\nseed = 2\n[run]\nt_end = 10\n");
    ASSERT_EQ(run_command(test::simulate(gas + " --force -o " + *dir + "/gas.h5")).exit_code, 0);
    const std::string ba = test::write_file(
        *dir, "ba.toml", "[system]\nL = 12\nphi = 0.1\nseed = 1\n[collision]\nmodel = \"aggregation\"\n[run]\nt_end = 1\n");
    ASSERT_EQ(run_command(test::simulate(ba + " --force -o " + *dir + "/ba.h5")).exit_code, 0);
  }
  static inline std::string* dir = nullptr;
};

TEST_F(DisplacementCli, HelpStatesUnits) {
  const auto r = run_command(bin("coolgas-displacement") + " --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* unit : {"[1/omega0]", "[sigma^2]", "[sigma^2 omega0^2]", "[sigma^2 omega0]"})
    EXPECT_NE(r.out.find(unit), std::string::npos) << unit;
}

TEST_F(DisplacementCli, RowsFromTheReferenceOn) {
  const auto r = run_command(bin("coolgas-displacement") + " " + *dir + "/gas.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  const Table t = read_table(in, "stdout");
  ASSERT_GT(t.rows.size(), 5u);
  EXPECT_EQ(t.rows[0][t.column("msd")], 0);
  EXPECT_NEAR(t.rows[0][t.column("vacf_norm")], 1, 1e-14);
  const auto later = run_command(bin("coolgas-displacement") + " " + *dir + "/gas.h5 --from 1");
  std::istringstream in2(later.out);
  EXPECT_EQ(read_table(in2, "stdout").rows[0][t.column("t")], 1);
}

TEST_F(DisplacementCli, FilesItCannotReadAreOneErrorLine) {
  expect_one_error_line(run_command(bin("coolgas-displacement") + " " + *dir + "/ba.h5"), "ballistic-aggregation");
  expect_one_error_line(run_command(bin("coolgas-displacement") + " " + *dir + "/absent.h5"), "cannot open");
  const std::string stripped = *dir + "/no_images.h5";  // the dumps without their image counts
  std::filesystem::copy_file(*dir + "/gas.h5", stripped, std::filesystem::copy_options::overwrite_existing);
  {
    h5::Handle f = h5::open_file(stripped, h5::Mode::kReadWrite);
    ASSERT_GE(H5Ldelete(f.id(), "/particles/all/image", H5P_DEFAULT), 0);
  }
  expect_one_error_line(run_command(bin("coolgas-displacement") + " " + stripped), "missing /particles/all/image");
}

}  // namespace
}  // namespace coolgas
