// Scenes: sizes derived consistently, the effective scene reads back to the
// same scene, and bad values are refused with a message naming them.
#include "simulate/scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/error.h"

namespace coolgas {
namespace {

const char* kScene = R"(
[system]
N = 1000
phi = 0.208
[collision]
model = "inelastic"
r0 = 0.1
delta = 1e-4
[run]
t_end = 100
)";

std::string error_of(const std::vector<std::string>& overrides, const std::string& text = kScene) {
  try {
    parse_scene(text, "s.toml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, BoxSideFollowsFromNAndPhi) {
  const Scene s = parse_scene(kScene, "s.toml", {});
  EXPECT_NEAR(double(s.N) * M_PI / (6 * s.L * s.L * s.L), 0.208, 1e-15);
  EXPECT_EQ(s.parameter("r0"), 0.1);
  const Scene t = parse_scene(kScene, "s.toml", {"system.N=8000"});
  EXPECT_NEAR(t.L, 2 * s.L, 1e-12);  // 8x the particles at the same phi: twice the side
}

// A --set of one of N, L, phi keeps the scene's first of the other two
// (phi before N before L) and derives the third; when the scene gave that
// third, its change is said (N pi / (6 L^3) = phi: L = (N pi / (6 phi))^(1/3)).
TEST(Scene, ASetOfNSaysTheBoxSideItChanged) {
  const std::string given = "[system]\nL = 48\nphi = 0.208\n[collision]\nmodel = \"elastic\"\n[run]\nt_end = 1\n";
  const Scene s = parse_scene(given, "t.toml", {"system.N=300000"});
  EXPECT_NEAR(s.L, std::cbrt(300000 * M_PI / (6 * 0.208)), 1e-9);
  EXPECT_NE(s.size_note.find("system.L = 91.06"), std::string::npos) << s.size_note;
  EXPECT_NE(s.size_note.find("not the scene's 48"), std::string::npos) << s.size_note;
  EXPECT_TRUE(parse_scene(given, "t.toml", {"system.L=40"}).size_note.empty());   // N derived, never given
  EXPECT_TRUE(parse_scene(given, "t.toml", {"system.phi=0.1"}).size_note.empty());
  EXPECT_TRUE(parse_scene(given, "t.toml", {}).size_note.empty());
}

TEST(Scene, EffectiveSceneReadsBackIdentically) {
  const Scene s = parse_scene(kScene, "s.toml", {"output.dump_times=[5, 10.5]", "system.seed=99"});
  const Scene t = parse_scene(s.to_toml(), "effective", {});
  EXPECT_EQ(t.to_toml(), s.to_toml());
  EXPECT_EQ(t.L, s.L);
  EXPECT_EQ(t.dump_times, (std::vector<double>{5, 10.5}));
  EXPECT_EQ(t.seed, 99);
}

TEST(Scene, UnknownKeyGetsADidYouMean) {
  EXPECT_NE(error_of({"system.phy=0.1"}).find("did you mean 'system.phi'"), std::string::npos);
  EXPECT_NE(error_of({"colision.r0=0.5"}).find("did you mean 'collision.r0'"), std::string::npos);
}

TEST(Scene, OutOfRangeValuesAreNamed) {
  EXPECT_NE(error_of({"system.phi=0"}).find("system.phi"), std::string::npos);
  EXPECT_NE(error_of({"system.phi=0.4"}).find("fcc"), std::string::npos);  // beyond RSA: suggests the lattice
  EXPECT_NE(error_of({"system.N=1"}).find("system.N"), std::string::npos);
  EXPECT_NE(error_of({"collision.r0=0"}).find("collision.r0"), std::string::npos);
  EXPECT_NE(error_of({"collision.r0=1.5"}).find("collision.r0"), std::string::npos);
  EXPECT_NE(error_of({"collision.delta=-1"}).find("collision.delta"), std::string::npos);
  EXPECT_NE(error_of({"run.t_end=0"}).find("run.t_end"), std::string::npos);
  EXPECT_NE(error_of({"system.N=3"}).find("too small"), std::string::npos);  // box below 3 cells
  EXPECT_NE(error_of({"system.N=1.5"}).find("integer"), std::string::npos);
  EXPECT_NE(error_of({"collision.model=sticky"}).find("collision.model"), std::string::npos);
  EXPECT_NE(error_of({}, "[system]\nN = 10\n[run]\nt_end = 1\n").find("two of"), std::string::npos);
  EXPECT_NE(error_of({}, "[system\n").find("not valid TOML"), std::string::npos);
}

// Rough particles: beta and the inertia where they mean something, each
// refusal one line with the value and what is allowed; a smooth scene's text
// has neither key (its files are as before they existed), a rough one's both.
TEST(Scene, RoughParticlesOnlyWhereTheyCanSpin) {
  EXPECT_EQ(error_of({"collision.beta=0.5"}), "");
  EXPECT_EQ(error_of({"collision.beta=0.5", "system.inertia=0.6666"}), "");
  const std::string viscoelastic = "[system]\nN = 1000\nphi = 0.2\n[collision]\nmodel = \"viscoelastic\"\n"
                                   "viscoelastic_b = 0.1\n[run]\nt_end = 1\n";
  EXPECT_EQ(error_of({"collision.beta=-1"}, viscoelastic), "");
  EXPECT_EQ(error_of({"collision.beta=1.5"}), "collision.beta = 1.5 is out of range: must be a finite number in [-1, 1]");
  EXPECT_EQ(error_of({"collision.beta=0.5", "system.inertia=0.7"}),
            "system.inertia = 0.7 is out of range: the moment of inertia of spheres per m a^2 is at most "
            "0.6666666666666666 (all the mass on the rim); need (0, 0.6666666666666666]");
  EXPECT_EQ(error_of({"collision.beta=0.5", "system.inertia=1", "system.dimension=2"}), "");
  EXPECT_NE(error_of({"collision.beta=0.5", "system.dimension=1"}).find("collision.beta = 0.5 is out of range: rods"),
            std::string::npos);
  EXPECT_NE(error_of({"system.inertia=0.4"}).find("system.inertia is set but the particles are smooth"),
            std::string::npos);
  EXPECT_EQ(error_of({"collision.beta=0.5"}, viscoelastic), "");
  const std::string aggregation = "[system]\nN = 1000\nphi = 0.2\n[collision]\nmodel = \"aggregation\"\n"
                                  "[run]\nt_end = 1\n";
  EXPECT_NE(error_of({"collision.beta=0.5"}, aggregation)
                .find("collision.beta is set but collision.model = \"aggregation\" does not use it"),
            std::string::npos);
  const Scene smooth = parse_scene(kScene, "s.toml", {"collision.beta=-1"});
  EXPECT_FALSE(smooth.rough());
  EXPECT_EQ(smooth.to_toml(), parse_scene(kScene, "s.toml", {}).to_toml());
  EXPECT_EQ(smooth.to_toml().find("beta"), std::string::npos);
  EXPECT_EQ(smooth.to_toml().find("inertia"), std::string::npos);
  const Scene rough = parse_scene(kScene, "s.toml", {"collision.beta=0.25", "system.dimension=2"});
  EXPECT_TRUE(rough.rough());
  EXPECT_EQ(rough.particle_inertia(), 0.5);  // a uniform disk's
  const Scene back = parse_scene(rough.to_toml(), "back", {});
  EXPECT_EQ(back.parameter("beta"), 0.25);
  EXPECT_EQ(back.inertia, 0.5);
  EXPECT_NE(physics_toml(rough).find("inertia = 0.5"), std::string::npos);
}

// Mixtures: [[species]] tables, each bad one refused in one line naming
// the table and the value; a good one reads back, its counts add up to N,
// phi is the total covered fraction, and without tables the text is as before.
TEST(Scene, MixturesFromSpeciesTables) {
  const std::string base = "[system]\nN = 1000\nphi = 0.2\n[collision]\nmodel = \"inelastic\"\nr0 = 0.9\n"
                           "[run]\nt_end = 10\n";
  const auto with = [&](const std::string& tables) { return base + tables; };
  const std::string two = "[[species]]\nfraction = 0.3\ndiameter = 1\n[[species]]\nfraction = 0.7\ndiameter = 1.5\n"
                          "mass = 2\n";
  ASSERT_EQ(error_of({}, with(two)), "");
  const Scene m = parse_scene(with(two), "s.toml", {});
  EXPECT_TRUE(m.mixture());
  EXPECT_EQ(m.species_counts(), (std::vector<std::int64_t>{300, 700}));
  EXPECT_EQ(m.species_mass(0), 1.0);  // diameter^3
  EXPECT_EQ(m.species_mass(1), 2.0);
  EXPECT_EQ(m.largest_diameter(), 1.5);
  EXPECT_NEAR(M_PI / 6 * (300 + 700 * 1.5 * 1.5 * 1.5) / std::pow(m.L, 3), 0.2, 1e-12);
  const Scene back = parse_scene(m.to_toml(), "back", {});
  EXPECT_EQ(back.to_toml(), m.to_toml());
  EXPECT_EQ(back.species.size(), 2u);
  EXPECT_NE(physics_toml(m).find("[[species]]"), std::string::npos);
  EXPECT_EQ(parse_scene(base, "s.toml", {}).to_toml().find("species"), std::string::npos);
  EXPECT_NE(scene_keys_help().find("[[species]] (array of tables, optional; every model)"),
            std::string::npos);
  // Counts by largest remainders: 1/3 each of 1000 is 334, 333, 333.
  const std::string thirds = "[[species]]\nfraction = 0.3333333333333333\ndiameter = 1\n[[species]]\n"
                             "fraction = 0.3333333333333333\ndiameter = 1.2\n[[species]]\n"
                             "fraction = 0.3333333333333334\ndiameter = 0.8\n";
  EXPECT_EQ(parse_scene(with(thirds), "s.toml", {}).species_counts(), (std::vector<std::int64_t>{333, 333, 334}));
  EXPECT_EQ(error_of({}, with("[[species]]\nfraction = 0.5\ndiameter = 1\n[[species]]\nfraction = 0.4\n"
                              "diameter = 2\n")),
            "the [[species]] fractions add up to 0.9, not 1; each is a share of the number of particles");
  EXPECT_EQ(error_of({}, with("[[species]]\nfraction = 1\ndiameter = -1\n")),
            "[[species]] 1 diameter = -1 is out of range: must be a finite number > 0");
  EXPECT_EQ(error_of({}, with("[[species]]\nfraction = 1\ndiameter = 1\nmass = 0\n")),
            "[[species]] 1 mass = 0 is out of range: must be a finite number > 0");
  EXPECT_EQ(error_of({}, with("[[species]]\nfraction = 1.5\ndiameter = 1\n")),
            "[[species]] 1 fraction = 1.5 is out of range: must be a finite number > 0 and <= 1");
  EXPECT_EQ(error_of({}, with("[[species]]\nfraction = 1\n")),
            "[[species]] 1 must give diameter (its particles' diameter)");
  EXPECT_EQ(error_of({}, with("[[species]]\nfraction = 1\ndiameter = 1\ndiamter = 2\n")),
            "unknown key 'diamter' in [[species]] 1 (did you mean 'diameter'?) (a species has fraction, diameter "
            "and mass)");
  EXPECT_EQ(error_of({}, with("[[species]]\nfraction = 0.9999\ndiameter = 1\n[[species]]\nfraction = 0.0001\n"
                              "diameter = 2\n")),
            "[[species]] 2 has fraction = 1e-04, no particle of N = 1000; raise N or its fraction");
  EXPECT_NE(error_of({"system.phi=0.35"}, with(two))
                .find("is out of range: a mixture ([[species]]) of spheres is placed by plain random trials, which "
                      "reach phi <= 0.3 here"),
            std::string::npos);
  EXPECT_EQ(error_of({"collision.beta=0.5"}, with(two)),
            "[[species]] is set with rough particles (collision.beta > -1): a rough mixture is not offered; remove "
            "collision.beta or [[species]]");
  EXPECT_EQ(error_of({"driving.power=1"}, with(two)),
            "[[species]] is set with [driving]: a driven mixture is not offered; remove [driving] or [[species]]");
  const std::string no_model = "[system]\nN = 1000\nphi = 0.2\n[run]\nt_end = 10\n" + two;  // every model takes one
  EXPECT_EQ(error_of({"collision.model=\"aggregation\""}, no_model), "");
  EXPECT_EQ(error_of({"collision.model=\"viscoelastic\"", "collision.viscoelastic_b=0.2"}, no_model), "");
  EXPECT_EQ(error_of({"system.init=\"fcc\""}, with(two)),
            "system.init = \"fcc\" is a lattice of equal spheres; a mixture ([[species]]) starts from \"random\"");
  EXPECT_EQ(error_of({"species=3"}, base), "species must be an array of tables: write one [[species]] table per "
                                         "species, with fraction = ... and diameter = ...");
}

TEST(Scene, AllowsFccUpToItsClosePacking) {
  EXPECT_EQ(error_of({"system.phi=0.45", "system.init=fcc"}), "");
  EXPECT_NE(error_of({"system.phi=0.75", "system.init=fcc"}).find("0.7404"), std::string::npos);
}

// The packing limits hold at their stated values whatever N: phi computed
// back from N and L lands an ulp or two off the phi given (0.45 for 20 000
// disks came back as 0.4500000000000001 and was refused).
TEST(Scene, PackingLimitsHoldAtTheirStatedValuesForAnyN) {
  for (const std::string n : {"1000", "4000", "20000", "123457", "999999"}) {
    EXPECT_EQ(error_of({"system.dimension=2", "system.N=" + n, "system.phi=0.45"}), "") << n;
    EXPECT_EQ(error_of({"system.N=" + n, "system.phi=0.36"}), "") << n;
    EXPECT_EQ(error_of({"system.N=" + n, "system.phi=0.7404", "system.init=fcc"}), "") << n;
  }
  EXPECT_NE(error_of({"system.dimension=2", "system.N=20000", "system.phi=0.4501"}).find("phi <= 0.45"),
            std::string::npos);
  EXPECT_NE(error_of({"system.N=20000", "system.phi=0.3601"}).find("phi <= 0.36"), std::string::npos);
}

// The box-size limit is the dimension's: floor(L)^d cells of 32-bit index.
TEST(Scene, TheGridLimitNamesTheDimensionsSide) {
  const std::string cube = error_of({"system.N=2", "system.phi=1e-10"});
  EXPECT_NE(cube.find("(L < 1291;"), std::string::npos) << cube;
  const std::string square = error_of({"system.dimension=2", "system.N=2", "system.phi=1e-10"});
  EXPECT_NE(square.find("(L < 46341;"), std::string::npos) << square;
}

TEST(Scene, IntegersAreRefusedAsGivenNeverWrapped) {
  EXPECT_NE(error_of({"output.observables_per_decade=4294967297"}).find("= 4294967297 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of({"output.dumps_per_decade=2147483648"}).find("= 2147483648 is out of range"), std::string::npos);
  EXPECT_NE(error_of({"output.dumps_per_decade=-2147483648"}).find("= -2147483648 is out of range"), std::string::npos);
}

TEST(Scene, ExactFloatsAreAcceptedForIntegerKeys) {
  const Scene s = parse_scene(kScene, "s.toml", {"system.N=1e4", "system.seed=2.0"});
  EXPECT_EQ(s.N, 10000);
  EXPECT_EQ(s.seed, 2);
  EXPECT_NE(error_of({"system.N=1e4.5"}).find("integer"), std::string::npos);
  EXPECT_NE(error_of({"system.N=1000.5"}).find("integer"), std::string::npos);
  EXPECT_NE(error_of({"system.N=1e30"}).find("integer"), std::string::npos);  // beyond 64 bits
}

// Each absurd consequence is named with what it would cost and the limit.
TEST(Scene, AbsurdCostsAreRefusedWithWhatTheyWouldCost) {
  EXPECT_NE(error_of({"system.N=1e12"}).find("180 TB of memory; the limit is N < 2^31"), std::string::npos);
  EXPECT_NE(error_of({"system.phi=1e-308"}).find("cell grid of inf cells"), std::string::npos);
  const std::string wide = error_of({}, "[system]\nN = 2\nL = 3e9\n[run]\nt_end = 1\n");
  EXPECT_NE(wide.find("cell grid of 2.7e+28 cells"), std::string::npos) << wide;
  EXPECT_NE(wide.find("the limit is 2^31 cells"), std::string::npos) << wide;
  EXPECT_NE(error_of({"system.L=inf"}).find("must be a finite number > 0"), std::string::npos);
  EXPECT_NE(error_of({"system.equilibrate=inf"}).find("finite"), std::string::npos);
  EXPECT_NE(error_of({"system.equilibrate=1e300"}).find("5e+302 collisions before t = 0; the limit is 1e12"),
            std::string::npos);
  EXPECT_NE(error_of({"output.dumps_per_decade=1000000000"}).find("4e+09 dumps (240 TB); the limit is 1e4"),
            std::string::npos);
  EXPECT_NE(error_of({"output.observables_per_decade=100000"}).find("4e+05 rows of observables; the limit is 1e5"),
            std::string::npos);
  // Within the limits a scene is accepted: check_scene_cost with this machine's memory.
  EXPECT_EQ(error_of({"system.equilibrate=1e6"}), "");
  const Scene s = parse_scene(kScene, "s.toml", {});
  EXPECT_NO_THROW(check_scene_cost(s, 1e9));
  EXPECT_THROW(check_scene_cost(s, 1e4), InputError);  // 1000 particles need about 180 kB
}

TEST(Scene, OneOfNLPhiCanBeOverriddenAndTheOthersFollow) {
  const Scene l = parse_scene(kScene, "s.toml", {"system.L=20"});  // the scene gives N and phi
  EXPECT_EQ(l.L, 20.0);
  EXPECT_EQ(l.N, std::llround(0.208 * 6 * 8000 / M_PI));  // phi kept, N follows
  const char* kNL = "[system]\nN = 1000\nL = 20\n[run]\nt_end = 1\n";
  const Scene phi = parse_scene(kNL, "s.toml", {"system.phi=0.05"});
  EXPECT_EQ(phi.N, 1000);  // N kept, L follows
  EXPECT_NEAR(phi.phi, 0.05, 1e-15);
  const Scene n = parse_scene(kNL, "s.toml", {"system.N=2000"});
  EXPECT_EQ(n.L, 20.0);  // N and L: the scene's L stays
  EXPECT_NE(error_of({"system.N=1000", "system.L=20", "system.phi=0.3"}).find("disagree"), std::string::npos);
}

TEST(Scene, TextsTheParserCannotSurviveAreRefusedBeforeParsing) {
  const std::string deep = "[run]\nt_end = 1\nx = " + std::string(100000, '[') + std::string(100000, ']') + "\n";
  EXPECT_NE(error_of({}, deep).find("nested 100000 deep; the limit is 16"), std::string::npos);
  EXPECT_NE(error_of({"output.dump_times=" + std::string(5000, '[')}).find("nested"), std::string::npos);
  const std::string big = "# " + std::string(2 << 20, 'x') + "\n" + kScene;
  EXPECT_NE(error_of({}, big).find("the limit is 1048576"), std::string::npos);
  // Brackets inside strings and comments are not nesting.
  EXPECT_NE(error_of({}, std::string(kScene) + "# " + std::string(100, '[') + "\n"), "x");
  EXPECT_EQ(error_of({"system.init=\"[[[[[[[[[[[[[[[[[[[[\""}).find("nested"), std::string::npos);
}

TEST(Scene, ValuesInMessagesAreOneShortLine) {
  const std::string e = error_of({"system.init=\"ran\\ndom" + std::string(1000, 'x') + "\""});
  EXPECT_EQ(e.find('\n'), std::string::npos);
  EXPECT_NE(e.find("ran\\ndom"), std::string::npos) << e;
  EXPECT_LT(e.size(), 200u) << e;
  EXPECT_NE(e.find("is not known: use \"random\", \"fcc\" or \"file\""), std::string::npos) << e;
}

TEST(Scene, HelpShowsEachKeysRangeAndDefaultFromTheTable) {
  const std::string help = scene_keys_help();
  EXPECT_NE(help.find("collision.r0 (float, in (0, 1], default 1.0; model inelastic)"), std::string::npos) << help;
  EXPECT_NE(help.find("run.t_end (float, > 0, required)"), std::string::npos) << help;
  EXPECT_NE(help.find("output.dumps_per_decade (integer, in [1, 2147483647], default 5)"), std::string::npos);
  EXPECT_NE(help.find("collision.viscoelastic_b (float, > 0, required; model viscoelastic)"), std::string::npos);
}

// A start from a file: its keys belong to init = "file" only, the size comes
// from the file (so the scene needs none), and a resumed run's effective
// scene, which states N, L, phi and T0, reads back without the file.
const char* kFileScene = R"(
[system]
init = "file"
from = "run.h5"
[run]
t_end = 100
)";

TEST(Scene, AStartFromAFileNeedsNoSizeAndOnlyItsOwnKeys) {
  const Scene s = parse_scene(kFileScene, "s.toml", {"system.from_time=20"});
  EXPECT_EQ(s.init, InitialPositions::kFile);
  EXPECT_EQ(s.from, "run.h5");
  EXPECT_EQ(s.from_time, 20.0);
  EXPECT_EQ(s.N, 0);  // known once the file is read (simulate/start/file_start.h)
  EXPECT_NE(error_of({"system.init=\"file\""}).find("the scene must give system.from for system.init = \"file\""),
            std::string::npos) << error_of({"system.init=\"file\""});
  EXPECT_NE(error_of({"system.from=\"x.h5\""}).find("system.from is set but system.init = \"random\" does not use it"),
            std::string::npos);
  EXPECT_NE(error_of({"system.T0=0.5"}).find("set init = \"file\""), std::string::npos);
  EXPECT_NE(error_of({"system.equilibrate=2"}, kFileScene).find("system.equilibrate is set but system.init = \"file\""),
            std::string::npos);
  EXPECT_NE(error_of({"system.from=\"\""}, kFileScene).find("system.from is empty"), std::string::npos);
  EXPECT_NE(error_of({"system.T0=0"}, kFileScene).find("system.T0"), std::string::npos);
}

TEST(Scene, TheEffectiveSceneOfAFileStartReadsBackWithoutTheFile) {
  Scene s = parse_scene(kFileScene, "s.toml", {});
  s.N = 2000, s.L = 17.364656928926813, s.phi = 0.20000000000000012, s.T0 = 0.04412881861832565;  // as read
  const std::string toml = s.to_toml();
  EXPECT_EQ(toml.find("equilibrate"), std::string::npos);  // not used by this start
  EXPECT_EQ(toml.find("from_time"), std::string::npos);    // absent: the last frame
  const Scene t = parse_scene(toml, "effective", {});
  EXPECT_EQ(t.to_toml(), toml);
  EXPECT_EQ(t.T0, s.T0);
  EXPECT_EQ(t.L, s.L);
  const std::string help = scene_keys_help();
  EXPECT_NE(help.find("system.from_time (float, >= 0, optional; init \"file\")"), std::string::npos) << help;
  EXPECT_NE(help.find("system.equilibrate (float, >= 0, default 5.0; init \"random\" or \"fcc\")"), std::string::npos);
}

}  // namespace
}  // namespace coolgas
