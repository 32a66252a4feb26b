// TSV tables (data-schema/tsv-tables.md): what a tool writes, a tool reads back exactly.
#include "common/tsv.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

#include "common/error.h"

namespace coolgas {
namespace {

TEST(Tsv, RoundTripKeepsEveryBitAndTheProvenance) {
  std::ostringstream out;
  {
    TsvWriter w(out, "coolgas-test", {{"input", "a.h5"}, {"L", "32"}}, {"t", "E"});
    w.row({0.1, 1.0 / 3.0});
    w.block("t = 10");
    w.row({1e-300, -2.5e17});
  }
  std::istringstream in(out.str());
  Table t = read_table(in, "mem");
  ASSERT_EQ(t.columns, (std::vector<std::string>{"t", "E"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0][1], 1.0 / 3.0);  // shortest round-trip form is exact
  EXPECT_EQ(t.rows[1][0], 1e-300);
  EXPECT_EQ(t.row_block, (std::vector<int>{0, 1}));
  EXPECT_EQ(t.get("L").value(), "32");
  EXPECT_EQ(t.get("tool").value(), "coolgas-test");
  EXPECT_FALSE(t.get("absent").has_value());
}

TEST(Tsv, ABlockCommentBeforeTheFirstRowIsNotTheColumnLine) {
  std::ostringstream out;
  {
    TsvWriter w(out, "coolgas-test", {{"L", "16"}}, {"t", "m", "N"});
    w.block("t = 10");
    w.row({10, 1, 0.5});
    w.block("t = 20");
    w.row({20, 1, 0.25});
  }
  std::istringstream in(out.str());
  Table t = read_table(in, "mem");
  EXPECT_EQ(t.columns, (std::vector<std::string>{"t", "m", "N"}));
  EXPECT_EQ(t.row_block, (std::vector<int>{0, 1}));
}

// data-schema/tsv-tables.md, format 2: the bare column line first, then the
// format line, the tool and its version, then the provenance.
TEST(Tsv, TheColumnLineComesFirstThenTheFormatAndProvenance) {
  std::ostringstream out;
  TsvWriter(out, "coolgas-test", {{"L", "16"}}, {"t", "E"}).row({1, 2});
  const std::string s = out.str();
  EXPECT_EQ(s.substr(0, s.find("# tool:")), "t\tE\n# format: coolgas-table 2\n") << s;
  EXPECT_NE(s.find("# L: 16\n1\t2\n"), std::string::npos) << s;
}

// Tables written before format 2 named their columns in the first comment
// without ':'; they stay readable.
TEST(Tsv, ReadsFormatOneTables) {
  std::istringstream in("# tool: old\n# L: 16\n# t\tE\n1\t2\n\n\n# t = 10\n3\t4\n");
  Table t = read_table(in, "mem");
  EXPECT_EQ(t.columns, (std::vector<std::string>{"t", "E"}));
  EXPECT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.get("L").value(), "16");
}

TEST(Tsv, RejectsEmptyRaggedNonNumericAndNaN) {
  auto read = [](const std::string& s) {
    std::istringstream in(s);
    return read_table(in, "mem");
  };
  EXPECT_THROW(read("# a\tb\n"), InputError);
  EXPECT_THROW(read("# a\tb\n1\t2\n3\n"), InputError);
  EXPECT_THROW(read("# a\tb\n1\tx\n"), InputError);
  EXPECT_THROW(read("# a\tb\n1\tnan\n"), InputError);
  EXPECT_THROW(read("# a\tb\n1\tinf\n"), InputError);
  EXPECT_THROW(read("1\t2\n"), InputError);     // no column line
  EXPECT_THROW(read("a\tb\n1\t2\n3\n"), InputError);  // format 2, ragged
  try {
    read("# a\tb\n1\t2\n1\tnan\n");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mem:3"), std::string::npos) << e.what();
  }
}

TEST(Tsv, MissingColumnNamesTheAvailableOnes) {
  std::istringstream in("# t\tE\n1\t2\n");
  Table t = read_table(in, "mem");
  try {
    t.column("M_max");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t, E"), std::string::npos);
  }
}

}  // namespace
}  // namespace coolgas
