// coolgas-clusters --definition contact[:CUTOFF] as a user runs it, on runs
// of coolgas-simulate: at the paper's phi = 0.208 the equilibrium start that
// the unit cells already join into one box-spanning cluster (issue 55: the
// cells' occupancy 0.397 is above site percolation's 0.3116) is many small
// contact clusters; both definitions give the same columns and count every
// particle; bad definitions are one error line.
#include <gtest/gtest.h>

#include <sstream>

#include "common/tsv.h"
#include "tests/support/cli_checks.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::expect_one_error_line;
using test::run_command;

class ContactClustersCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new std::string(test::scratch_dir("contact_clusters_cli"));
    // The paper's density in a box of side 20 (3178 spheres), elastic: the start's equilibrium fluid.
    const std::string gas = test::write_file(*dir, "gas.toml",
                                             "[system]\nL = 20\nphi = 0.208\nseed = 1\n[run]\nt_end = 1\n");
    ASSERT_EQ(run_command(test::simulate(gas + " --force -o " + *dir + "/gas.h5")).exit_code, 0);
    const std::string ba = test::write_file(
        *dir, "ba.toml", "[system]\nL = 12\nphi = 0.1\nseed = 1\n[collision]\nmodel = \"aggregation\"\n[run]\nt_end = 1\n");
    ASSERT_EQ(run_command(test::simulate(ba + " --force -o " + *dir + "/ba.h5")).exit_code, 0);
  }
  static inline std::string* dir = nullptr;

  static Table series(const std::string& args) {
    const auto r = run_command(bin("coolgas-clusters") + " " + *dir + "/gas.h5 --series " + args + " --time 0");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::istringstream in(r.out);
    return read_table(in, args);
  }
};

// Unit cells: the largest cluster holds most particles from t = 0; contacts
// at 1.1 sigma: under 2 % (pipelines/contact-percolation.sh measures 0.7 %
// at this size, and a share falling as the box grows).
TEST_F(ContactClustersCli, AtThePapersDensityContactClustersStartFarFromPercolation) {
  const Table cells = series("");
  const Table contact = series("--definition contact");
  ASSERT_EQ(cells.columns, contact.columns);
  ASSERT_EQ(contact.rows.size(), 1u);
  EXPECT_GT(cells.rows[0][cells.column("largest_fraction")], 0.5);
  EXPECT_LT(contact.rows[0][contact.column("largest_fraction")], 0.02);
  EXPECT_GT(contact.rows[0][contact.column("M_max")], 2);  // there are contacts
  EXPECT_DOUBLE_EQ(contact.rows[0][contact.column("M1")], cells.rows[0][cells.column("M1")]);  // every particle
  EXPECT_EQ(*contact.get("definition"), "contact:1.1");
  EXPECT_EQ(*series("--definition contact:1.1").get("definition"), "contact:1.1");
  EXPECT_EQ(*cells.get("definition"), "cells");
  // A longer bond joins more: at 1.3 sigma the contact clusters percolate too.
  EXPECT_GT(series("--definition contact:1.3").rows[0][contact.column("largest_fraction")], 0.5);
}

TEST_F(ContactClustersCli, BadDefinitionsAreOneErrorLine) {
  const std::string c = bin("coolgas-clusters") + " " + *dir + "/gas.h5 --definition ";
  expect_one_error_line(run_command(c + "contacts"), "not a cluster definition");
  expect_one_error_line(run_command(c + "contact:"), "not a number");
  expect_one_error_line(run_command(c + "contact:1.1x"), "not a number");
  expect_one_error_line(run_command(c + "contact:0.9"), "below 1");
  expect_one_error_line(run_command(c + "contact:nan"), "finite");
  expect_one_error_line(run_command(c + "contact:10.5"), "L/2 = 10");
  expect_one_error_line(run_command(bin("coolgas-clusters") + " " + *dir + "/ba.h5 --definition contact"),
                        "ballistic-aggregation");
}

}  // namespace
}  // namespace coolgas
