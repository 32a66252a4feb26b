// TSV tables (data-schema/tsv-tables.md): what a tool writes, a tool reads back exactly.
#include "common/tsv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <sstream>
#include <streambuf>

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

// The one error line of reading `text` with `limits`.
std::string refusal(const std::string& text, const TableLimits& limits = {}) {
  std::istringstream in(text);
  try {
    read_table(in, "mem", limits);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

// An endless stream of one byte, as /dev/zero is: counts what is read.
class Endless : public std::streambuf {
 public:
  explicit Endless(char c) { std::fill(std::begin(buf_), std::end(buf_), c); }
  std::size_t read = 0;

 protected:
  int_type underflow() override {
    read += sizeof buf_;
    setg(buf_, buf_, buf_ + sizeof buf_);
    return traits_type::to_int_type(buf_[0]);
  }

 private:
  char buf_[4096];
};

// Issue 52, class 4: an endless line (/dev/zero) grew the reader past a
// gigabyte; it is refused at the bound, having read little more than it.
TEST(TsvBounds, AnEndlessLineIsRefusedAtOneMebibyte) {
  for (char c : {'\0', 'x', '1', '#'}) {
    Endless zero(c);
    std::istream in(&zero);
    try {
      read_table(in, "/dev/zero");
      FAIL();
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                "/dev/zero:1: a line longer than 1048576 bytes; a table's lines are at most 1048576 bytes");
    }
    EXPECT_LE(zero.read, (std::size_t(1) << 20) + 8192);
  }
}

TEST(TsvBounds, LinesUpToTheBoundAreReadAndLongerOnesRefusedNamingTheLine) {
  const TableLimits limits{.line_bytes = 16};
  const std::string fits = "1234567890123456";  // 16 bytes
  std::istringstream in("a\n" + fits + "\n");
  EXPECT_EQ(read_table(in, "mem", limits).rows.size(), 1u);
  EXPECT_EQ(refusal("a\n1\n" + fits + "7\n", limits),
            "mem:3: a line longer than 16 bytes; a table's lines are at most 16 bytes");
  EXPECT_EQ(refusal("# " + fits + "\na\n1\n", limits),
            "mem:1: a line longer than 16 bytes; a table's lines are at most 16 bytes");
}

TEST(TsvBounds, RowsAndNumbersBeyondTheirBoundsAreRefused) {
  std::string rows = "a\tb\n";
  for (int i = 0; i < 5; ++i) rows += "1\t2\n";
  std::istringstream in(rows);
  EXPECT_EQ(read_table(in, "mem", {.rows = 5}).rows.size(), 5u);
  EXPECT_EQ(refusal(rows + "1\t2\n", {.rows = 5}), "mem:7: more than 5 rows; a table holds at most 5 rows");
  EXPECT_EQ(refusal(rows, {.numbers = 9}),
            "mem:6: more than 9 numbers (5 rows of 2 columns); a table holds at most 9 numbers");
}

TEST(TsvBounds, TheDefaultsAreTheStatedOnes) {
  const TableLimits d;
  EXPECT_EQ(d.line_bytes, 1048576u);
  EXPECT_EQ(d.rows, 10000000u);
  EXPECT_EQ(d.numbers, 100000000u);
}

}  // namespace
}  // namespace coolgas
