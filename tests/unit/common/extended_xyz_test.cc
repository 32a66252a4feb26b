// Extended XYZ frames: what coolgas writes reads back exactly (every double
// in its shortest round-trip form), frames are chosen by Time=, files of
// other programs (other column orders and names) are read, and a file that
// is not a periodic extended XYZ frame (a cube, a square of disks, a ring of
// rods), or has a line beyond the bound, is refused naming the line.
#include "common/extended_xyz.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/random.h"
#include "common/text_line.h"

namespace coolgas {
namespace {

XyzFrame random_frame(std::size_t n, double time, bool spheres) {
  Random rng(5);
  XyzFrame f;
  f.L = 17.364656928926813;
  f.time = time;
  f.step = 123;
  for (std::size_t i = 0; i < 3 * n; ++i) {
    f.position.push_back(f.L * rng.uniform());
    f.velocity.push_back(rng.normal() * 1e-7);
  }
  f.position[0] = 0.0;                        // the box's lower face
  f.position[1] = std::nextafter(f.L, 0.0);   // the largest position inside it
  f.position[2] = 5e-324;                     // the smallest positive double
  for (std::size_t i = 0; i < n; ++i) {
    f.id.push_back(std::int64_t(i));
    if (spheres) {
      f.mass.push_back(double(1 + i));
      f.diameter.push_back(std::cbrt(double(1 + i)));
    }
  }
  return f;
}

XyzFrame read(const std::string& text, std::optional<double> time = std::nullopt) {
  std::istringstream in(text);
  return read_xyz_frame(in, "f.xyz", time);
}

std::string error_of(const std::string& text, std::optional<double> time = std::nullopt) {
  try {
    read(text, time);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ExtendedXyz, AFrameReadsBackBitForBit) {
  for (bool spheres : {false, true}) {
    const XyzFrame f = random_frame(200, 12.5, spheres);
    std::ostringstream out;
    write_xyz_frame(out, f, {{"tool", "test"}, {"input", "a \"quoted\" name"}});
    const XyzFrame g = read(out.str());
    EXPECT_EQ(g.L, f.L);
    EXPECT_EQ(g.time, f.time);
    EXPECT_EQ(g.position, f.position);  // exact equality of every double
    EXPECT_EQ(g.velocity, f.velocity);
    EXPECT_EQ(g.diameter, f.diameter);  // radius = d/2 halves and doubles exactly
    EXPECT_EQ(g.mass, f.mass);
  }
}

// Disks (pbc="T T F", z = 0) and rods (pbc="T F F", y = z = 0) read back
// with their dimension, every coordinate exact; the non-periodic axes of
// another program's file need only be common to all particles (they are set
// to 0), and nothing may move across them.
TEST(ExtendedXyz, DisksAndRodsReadBackWithTheirDimension) {
  for (int d : {1, 2}) {
    XyzFrame f = random_frame(50, 3.5, d == 1);
    f.dimension = d;
    for (std::size_t i = 0; i < 50; ++i)
      for (int k = d; k < 3; ++k) f.position[3 * i + std::size_t(k)] = f.velocity[3 * i + std::size_t(k)] = 0;
    std::ostringstream out;
    write_xyz_frame(out, f, {});
    const XyzFrame g = read(out.str());
    EXPECT_EQ(g.dimension, d);
    EXPECT_EQ(g.L, f.L);
    EXPECT_EQ(g.position, f.position);
    EXPECT_EQ(g.velocity, f.velocity);
    EXPECT_EQ(g.diameter, f.diameter);
  }
  const XyzFrame plane = read("2\nLattice=\"6 0 0 0 6 0 0 0 2\" pbc=\"T T F\"\nX 1 2 0.5\nX 3 4 0.5\n");
  EXPECT_EQ(plane.dimension, 2);
  EXPECT_EQ(plane.position, (std::vector<double>{1, 2, 0, 3, 4, 0}));
  const std::string ring = "Lattice=\"9 0 0 0 3 0 0 0 2\" pbc=\"T F F\" Properties=species:S:1:pos:R:3:vel:R:3";
  EXPECT_EQ(read("1\n" + ring + "\nX 1 1 1 0.5 0 0\n").L, 9);  // a ring's other edges are free
  EXPECT_NE(error_of("2\n" + ring + "\nX 1 1 1 0 0 0\nX 2 1 1.5 0 0 0\n")
                .find("particle 1 has z = 1.5, particle 0 1; in pbc=\"T F F\" the particles lie in one line"),
            std::string::npos);
  EXPECT_NE(error_of("1\n" + ring + "\nX 1 1 1 0.5 0.25 0\n").find("particle 0 has vy = 0.25; in pbc=\"T F F\" it must be 0"),
            std::string::npos);
  EXPECT_NE(error_of("1\nLattice=\"6 0 0 0 5 0 0 0 1\" pbc=\"T T F\"\nX 1 2 0\n").find("is not a square (edges 6, 5)"),
            std::string::npos);
}

TEST(ExtendedXyz, TheFrameNearestTimeOrTheLastIsRead) {
  std::ostringstream out;
  for (double t : {0.0, 10.0, 100.0}) {
    XyzFrame f = random_frame(5, t, false);
    f.position[3] = t / 100;  // marks the frame
    write_xyz_frame(out, f, {});
  }
  EXPECT_EQ(read(out.str()).time, 100.0);
  EXPECT_EQ(read(out.str(), 30.0).position[3], 0.1);
  EXPECT_EQ(read(out.str(), 55.0).time, 10.0);  // a tie goes to the earlier frame
  EXPECT_EQ(read(out.str(), 1e9).time, 100.0);
}

TEST(ExtendedXyz, OtherProgramsColumnsAreRead) {
  // Columns in another order, velocities as "vel", diameters, a bare key, CRLF line ends.
  const XyzFrame f = read(
      "2\r\nProperties=id:I:1:species:S:1:vel:R:3:pos:R:3:diameter:R:1 Lattice=\"5 0 0 0 5 0 0 0 5\" "
      "flag Time=2.5\r\n7 Ar 0.1 0.2 0.3 1 2 3 1.5\r\n8 Ar -0.1 -0.2 -0.3 3.5 2.5 1.5 2\r\n");
  EXPECT_EQ(f.L, 5);
  EXPECT_EQ(f.time, 2.5);
  EXPECT_EQ(f.position, (std::vector<double>{1, 2, 3, 3.5, 2.5, 1.5}));
  EXPECT_EQ(f.velocity, (std::vector<double>{0.1, 0.2, 0.3, -0.1, -0.2, -0.3}));
  EXPECT_EQ(f.diameter, (std::vector<double>{1.5, 2}));
  // No Properties: species and positions only (the extended XYZ default).
  const XyzFrame g = read("1\nLattice=\"4 0 0 0 4 0 0 0 4\" pbc=\"T T T\"\nX 1 2 3\n");
  EXPECT_TRUE(g.velocity.empty());
  EXPECT_EQ(g.position, (std::vector<double>{1, 2, 3}));
}

TEST(ExtendedXyz, BadFilesAreRefusedNamingTheLine) {
  const std::string box = "Lattice=\"4 0 0 0 4 0 0 0 4\"";
  EXPECT_NE(error_of("").find("empty file"), std::string::npos);
  EXPECT_NE(error_of("hello\n").find("line 1: expected the number of particles"), std::string::npos);
  EXPECT_NE(error_of("1\ncomment\nX 1 2 3\n").find("line 2: no Lattice="), std::string::npos);
  EXPECT_NE(error_of("1\nLattice=\"4 0 0 0 5 0 0 0 4\"\nX 1 2 3\n").find("is not a cube (edges 4, 5, 4)"),
            std::string::npos);
  EXPECT_NE(error_of("1\nLattice=\"4 1 0 0 4 0 0 0 4\"\nX 1 2 3\n").find("not an orthogonal box"), std::string::npos);
  EXPECT_NE(error_of("1\n" + box + " pbc=\"F T T\"\nX 1 2 3\n").find("pbc=\"F T T\"; coolgas boxes are periodic"),
            std::string::npos);
  EXPECT_NE(error_of("2\n" + box + "\nX 1 2 3\n").find("line 3: the file ends after 1 of 2 particles"),
            std::string::npos);
  EXPECT_NE(error_of("1\n" + box + "\nX 1 2\n").find("line 3: expected 4 columns, got 3"), std::string::npos);
  EXPECT_NE(error_of("1\n" + box + "\nX 1 two 3\n").find("a position 'two' is not a number"), std::string::npos);
  EXPECT_NE(error_of("1\n" + box + " Properties=species:S:1:velo:R:3\nX 1 2 3\n").find("no positions"),
            std::string::npos);
  EXPECT_NE(error_of("1\n" + box + "\nX 1 2 3\n", 5.0).find("has no Time="), std::string::npos);
}

// A count line is a claim about the rest of the file: one that the file's
// bytes cannot hold is refused before the frame's arrays are allocated (a
// count of 10^9 once took 24 GB before failing).
TEST(ExtendedXyz, ACountTheFileCannotHoldIsRefusedBeforeAllocating) {
  const std::string box = "Lattice=\"4 0 0 0 4 0 0 0 4\"";
  std::string lines;
  for (int i = 0; i < 2000; ++i) lines += "X 1 2 3\n";
  const std::string e = error_of("10000000\n" + box + "\n" + lines);
  EXPECT_NE(e.find("f.xyz: line 1: the count line says 10000000 particles"), std::string::npos) << e;
  EXPECT_NE(error_of("3\n" + box + "\nX\nX\n").find("line 1: the count line says 3 particles, but the 4 B left in "
                                                    "the file hold at most 2 lines"),
            std::string::npos);
  // The shortest lines (a word each, the last without its newline) pass the
  // bound and are then refused for what they miss, naming their line.
  EXPECT_NE(error_of("2\n" + box + "\nX\nX").find("line 3: expected 4 columns, got 1"), std::string::npos);
}

// Every line is bounded as a table's are (common/text_line.h, 1 MiB): a
// line of 1 MiB + 1 is refused naming it, wherever it is, where it was once
// read whole (and, being padding, accepted); one of 1 MiB is read.
TEST(ExtendedXyz, ALineLongerThanOneMebibyteIsRefusedNamingIt) {
  const std::string box = "Lattice=\"4 0 0 0 4 0 0 0 4\"", pad(kMaxLineBytes - 7, ' ');  // "X 1 2 3" + pad: 1 MiB
  EXPECT_EQ(read("1\n" + box + "\nX 1 2 3" + pad + "\n").position.size(), 3u);
  const std::string bound = "a line longer than 1048576 bytes; an extended XYZ file's lines are at most 1048576 bytes";
  EXPECT_EQ(error_of("1" + pad + "       \n" + box + "\nX 1 2 3\n"), "f.xyz: line 1: " + bound);
  EXPECT_EQ(error_of("1\n" + box + pad + "\nX 1 2 3\n"), "f.xyz: line 2: " + bound);
  EXPECT_EQ(error_of("1\n" + box + "\nX 1 2 3" + pad + " \n"), "f.xyz: line 3: " + bound);
}

// A time that is not finite and >= 0 (then taken as the run's start, which
// every --resume refuses) and a T0 that is not finite and > 0 are refused
// naming the value.
TEST(ExtendedXyz, TimesAndTemperaturesMustBeFinite) {
  const std::string box = "Lattice=\"4 0 0 0 4 0 0 0 4\"";
  for (const std::string t : {"nan", "inf", "-inf", "-5", "-1e-300", "NaN"}) {
    const std::string e = error_of("1\n" + box + " Time=" + t + "\nX 1 2 3\n");
    EXPECT_NE(e.find("f.xyz: line 2: Time=" + t + " is not a time; times are finite and >= 0"), std::string::npos) << e;
  }
  for (const std::string T0 : {"nan", "inf", "0", "-1"}) {
    const std::string e = error_of("1\n" + box + " Time=1 T0=" + T0 + "\nX 1 2 3\n");
    EXPECT_NE(e.find("T0=" + T0 + " is not a temperature"), std::string::npos) << e;
  }
  EXPECT_EQ(*read("1\n" + box + " Time=0\nX 1 2 3\n").time, 0.0);
}

}  // namespace
}  // namespace coolgas
