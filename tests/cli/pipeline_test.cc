// The figure pipeline end to end, at SCALE = tiny (seconds): make runs every
// recipe of pipelines/common.mk, the tables parse and hold sane values, a
// finished pipeline has nothing left to do, a changed analysis knob reruns
// only the step that uses it, and 'reanalyze' redraws every figure from the
// archived runs without simulating. And the accuracy pipeline's collapse
// study (QUICK=1): runs cut at their own end give the whole runs' collapse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>
#include <string>

#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

using test::run_command;
namespace fs = std::filesystem;

std::string make_command(const std::string& out, const std::string& extra) {
  std::string bin_dir = test::bin("coolgas-simulate");
  bin_dir.erase(bin_dir.rfind('/'));
  return "make -C " + test::source("pipelines/demo") + " SCALE=tiny BIN=" + bin_dir + " OUT=" + out + " " + extra;
}

bool is_png(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  char magic[8] = {};
  f.read(magic, 8);
  return f.gcount() == 8 && std::string(magic + 1, 3) == "PNG";
}

// The data rows of a TSV table (string cells), after its column line, which
// goes into *columns when asked for.
std::vector<std::vector<std::string>> tsv_rows(const std::string& path, std::string* columns = nullptr) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(in, line);
  if (columns) *columns = line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, '\t');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// The exponent table (pipelines/exponents.sh): one row per quantity,
// "quantity figure measured error paper paper_error tolerance deviation
// regime verdict note"; the cells as written, the two numbers parsed.
constexpr const char* kExponentColumns =
    "quantity\tfigure\tmeasured\terror\tpaper\tpaper_error\ttolerance\tdeviation\tregime\tverdict\tnote";
struct Judged {
  double measured = NAN, error = NAN;
  std::string regime, verdict, note;
  std::vector<std::string> cells;
};
std::vector<std::pair<std::string, Judged>> read_exponent_rows(const std::string& path) {
  std::vector<std::pair<std::string, Judged>> rows;
  std::string columns;  // the column line (data-schema/tsv-tables.md)
  const auto cells_of_rows = tsv_rows(path, &columns);
  EXPECT_EQ(columns, kExponentColumns);
  for (const auto& cells : cells_of_rows) {
    EXPECT_EQ(cells.size(), 11u) << cells.at(0);
    if (cells.size() != 11) continue;
    const auto number = [](const std::string& c) { return c == "-" ? NAN : std::stod(c); };
    rows.emplace_back(cells[0], Judged{number(cells[2]), number(cells[3]), cells[8], cells[9], cells[10], cells});
  }
  return rows;
}
std::map<std::string, Judged> read_exponents(const std::string& path) {
  std::map<std::string, Judged> rows;
  for (auto& [name, row] : read_exponent_rows(path)) rows[name] = row;
  return rows;
}

// A row's verdict by the rules pipelines/row-verdict.sh states (its RULES
// text), written out again here from that statement: outside the paper's
// regime or without a number, not decided; no value of the paper, "-"; a
// value p with tolerance tol, agrees when |m - p| <= tol and the combined
// error s <= tol, differs when |m - p| - tol > 3 s, else not decided; a
// bound "> b" / "< b", agrees beyond it on its side by more than 3 s,
// differs on the other side by more than 3 s, else not decided.
std::string verdict_by_the_rules(const std::vector<std::string>& cells) {
  const std::string &measured = cells[2], &error = cells[3], &paper = cells[4], &paper_error = cells[5],
                    &tolerance = cells[6], &regime = cells[8];
  if (regime.rfind("no", 0) == 0 || measured == "nan") return "not decided";
  if (paper == "-") return "-";
  const auto or_zero = [](const std::string& c) { return c == "-" || c == "nan" ? 0.0 : std::stod(c); };
  const double m = std::stod(measured), e = or_zero(error), pe = or_zero(paper_error);
  const double s = std::sqrt(e * e + pe * pe);
  if (paper.rfind("> ", 0) == 0 || paper.rfind("< ", 0) == 0) {
    const double b = std::stod(paper.substr(2)), d = paper[0] == '>' ? m - b : b - m;
    return d > 3 * s ? "agrees" : -d > 3 * s ? "differs" : "not decided";
  }
  const double d = std::fabs(m - std::stod(paper)), tol = std::stod(tolerance);
  return d <= tol && s <= tol ? "agrees" : d - tol > 3 * s ? "differs" : "not decided";
}

// No row's words contradict its numbers: its verdict is the rules' verdict
// of its own cells; its name is short; the verdict words stand in the
// verdict column only (neither name nor note says "agrees", "differs", ...);
// and a cause ("because ...") is given only for a row that differs.
void expect_words_match_numbers(const std::string& path) {
  for (const auto& [name, row] : read_exponent_rows(path)) {
    EXPECT_EQ(row.verdict, verdict_by_the_rules(row.cells)) << name;
    EXPECT_LE(name.size(), 50u) << name;
    EXPECT_EQ(name.find(':'), std::string::npos) << name;
    for (const char* word : {"agree", "differ", "support", "not decided"}) {
      EXPECT_EQ(name.find(word), std::string::npos) << name;
      EXPECT_EQ(row.note.find(word), std::string::npos) << name << ": " << row.note;
    }
    if (row.note.find("because") != std::string::npos) {
      EXPECT_EQ(row.verdict, "differs") << name;
    }
  }
}

// The dimensions the dimension study runs in the test, and its table's rows:
// theta of the gas (twice in 3D, once per theory) and of BA in each d, the
// gas's kappa against BA's in each d, and 2D's against the Gaussian.
constexpr const char* kStudiedDimensions = "1 2 3";
constexpr std::size_t kStudiedRows = 4 + 3 + 3 + 1;

const char* kFigures[] = {"fig1_energy_size.png", "fig2_energy_parameters.png", "fig3_clusters.png",
                          "fig4_largest_mass.png", "fig5_velocity.png", "smoluchowski.png",
                          "structure.png", "fields.png"};

TEST(Pipeline, TinyPipelineRunsEndToEndAndIsIncremental) {
  const std::string dir = test::scratch_dir("pipeline");
  const std::string out = dir + "/tiny";

  auto run = run_command(make_command(out, "-j2"));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;

  for (const char* figure : kFigures) {
    EXPECT_TRUE(is_png(out + "/" + figure)) << figure;
    EXPECT_TRUE(fs::exists(out + "/" + fs::path(figure).replace_extension(".pdf").string())) << figure;
  }

  // The exponents, one row per quantity, each with a finite value and a
  // judgement of its regime; the sane ranges of a tiny run.
  const auto exponents = read_exponents(out + "/exponents.tsv");
  for (const auto& [name, row] : exponents) {
    EXPECT_TRUE(std::isfinite(row.measured)) << name;
    EXPECT_TRUE(row.regime == "yes" || row.regime.rfind("no: ", 0) == 0) << name << ": " << row.regime;
  }
  expect_words_match_numbers(out + "/exponents.tsv");
  const auto row = [&](const std::string& prefix) {  // the first quantity that starts with prefix
    const auto it = exponents.lower_bound(prefix);
    EXPECT_TRUE(it != exponents.end() && it->first.rfind(prefix, 0) == 0) << prefix;
    return it == exponents.end() ? Judged{} : it->second;
  };
  const auto value = [&](const std::string& prefix) { return row(prefix).measured; };
  // Past the homogeneous regime: Haff cooling gives E ~ t^-2 at late times, the
  // clustered gas of the paper t^-6/5 (Pathak et al. 2014); a run stuck in
  // Haff's regime would give theta near 2.
  EXPECT_GT(value("theta, collapse"), 0.8);
  EXPECT_LT(value("theta, collapse"), 1.7);
  EXPECT_LT(value("theta, power-law fit"), 1.7);
  EXPECT_GT(row("theta, collapse").error, 0.0);
  EXPECT_GT(value("z, free collapse"), 0.5);
  // The product row is the same fit's theta z (identity), with an error of its own.
  EXPECT_NEAR(value("z theta, free collapse"), value("theta, collapse") * value("z, free collapse"),
              1e-12 * value("z theta, free collapse"));
  EXPECT_GT(row("z theta, free collapse").error, 0.0);
  // The paper's method (tables/collapse_z_theta.tsv): z theta held at 3, so
  // theta z = 3 (identity); its quality, the minimum of the same Q over a line
  // of the free fit's plane, is not below the free fit's; its z and eta are
  // the table's rows.
  {
    const Table fixed = read_table(out + "/tables/collapse_z_theta.tsv"), free = read_table(out + "/tables/collapse.tsv");
    const auto meta = [](const Table& t, const char* key) { return std::stod(t.get(key).value_or("nan")); };
    EXPECT_NEAR(meta(fixed, "theta") * meta(fixed, "z"), 3.0, 1e-12);
    EXPECT_GE(meta(fixed, "quality"), meta(free, "quality") * (1 - 1e-9));
    EXPECT_DOUBLE_EQ(value("z, collapse with z theta = 3"), meta(fixed, "z"));
    EXPECT_DOUBLE_EQ(value("eta, f(x)"), meta(fixed, "eta"));
  }
  EXPECT_GT(value("theta, power-law fit"), 0.5);
  EXPECT_GT(value("largest cluster"), 0.0);
  EXPECT_LE(value("largest cluster"), 1.0);
  EXPECT_GT(value("tau,"), 0.0);
  // The Smoluchowski equation with the paper's kernel (homogeneity 1/6): mean mass ~ t^(6/5).
  EXPECT_NEAR(value("Smoluchowski M_avg"), 1.2, 0.1);
  // The tiny boxes are far from the paper's late-time regime, and the table says so.
  EXPECT_EQ(row("beta,").regime.rfind("no: ", 0), 0u);
  // The growing length (pipelines/structure.mk): z from L_t and L_C with fit
  // errors, each beside the collapse's z as a difference with its combined
  // error. A growing length has 1/z > 0; in the 16^3 box (scales/tiny.mk)
  // L_t is above L/4 = 4 from the first dump on, and the table says box-limited.
  for (const char* length : {"z from L_t at", "z from L_C at"}) {
    EXPECT_GT(value(length), 0.0) << length;
    EXPECT_GT(row(length).error, 0.0) << length;
  }
  EXPECT_NE(row("z from L_t at").regime.find("box-limited"), std::string::npos) << row("z from L_t at").regime;
  const Judged difference = row("z from L_t minus the free collapse's z");
  EXPECT_NEAR(difference.measured, value("z from L_t at") - value("z, free collapse"), 1e-4);
  EXPECT_GT(difference.error, row("z, free collapse").error);
  EXPECT_TRUE(std::isfinite(row("z from L_C minus the free collapse's z").measured));
  // Fig. 4 (pipelines/mmax-jump.sh): at phi = 0.208 a third of the unit cells
  // are occupied, above the site-percolation threshold 0.3116, so the largest
  // cluster spans the box from t = 0 and the table says so instead of
  // measuring a jump. BA's largest aggregate grows as a power law (paper:
  // t^0.94 ... t^1.03; mean field t^(6/5)), so its steepest rise stays below
  // the rule's jump threshold 2.
  const Judged percolating = row("M_max's steepest rise, gas phi = 0.208, L = 16");
  EXPECT_NE(percolating.regime.find("site-percolation"), std::string::npos) << percolating.regime;
  // So is tau by the unit cells, with their occupancy N/L^3 = 6 phi/pi =
  // 0.397 particles per cell; by contact (pipelines/contact-clusters.mk) the
  // same run starts far from spanning the box, and its rows are measured:
  // tau as the contact table's fit, and M_max's rise from its own series.
  const Judged cells_tau = row("tau, N(m) ~ m^-tau, unit cells");
  EXPECT_NE(cells_tau.regime.find("n = 0.397 particles per cell"), std::string::npos) << cells_tau.regime;
  const Judged contact_tau = row("tau, N(m) ~ m^-tau, contact clusters");
  EXPECT_EQ(contact_tau.regime.find("percolate"), std::string::npos) << contact_tau.regime;
  EXPECT_DOUBLE_EQ(contact_tau.measured, std::stod(tsv_rows(out + "/tables/contact/fit_nm_gas.tsv").at(0).at(0)));
  const Judged contact_rise = row("M_max rise, contact, phi = 0.208, L = 16");
  EXPECT_EQ(contact_rise.regime.find("percolate"), std::string::npos) << contact_rise.regime;
  EXPECT_GT(contact_rise.measured, 0.0);
  const double ba_rise = value("M_max's steepest rise, BA phi = 0.208");
  EXPECT_GT(ba_rise, 0.5);
  EXPECT_LT(ba_rise, 2.0);
  // The comparison row is the log of the two times' ratio (rounded to 3 digits).
  // (the first of each kind by name is the same run's: phi = 0.104); by
  // contact, its own t_jump against the run's t_inhom.
  EXPECT_NEAR(value("log10(t_jump/t_inhom)"), std::log10(value("t_jump, gas") / value("t_inhom, gas")), 0.01);
  EXPECT_NEAR(value("lg(t_jump/t_inhom), contact"), std::log10(value("t_jump, contact") / value("t_inhom, gas")), 0.01);

  // exponents.md: the table's rows in order, each with the TSV's verdict in
  // its own column (the seventh); then the paper's claims, each with a verdict
  // of the three kinds pipelines/verdicts.sh gives.
  {
    const std::string md = test::read_text(out + "/exponents.md");
    std::vector<std::string> md_verdicts, tsv_verdicts;
    std::istringstream table(md.substr(md.find("| quantity |")));
    std::string line;
    std::getline(table, line);  // the column line
    std::getline(table, line);  // |---|
    while (std::getline(table, line) && line.rfind("| ", 0) == 0) {
      std::vector<std::string> cells;
      std::stringstream ss(line.substr(2));
      for (std::string cell; std::getline(ss, cell, '|');) cells.push_back(cell.substr(0, cell.size() - 1));
      ASSERT_EQ(cells.size(), 8u) << line;
      md_verdicts.push_back(cells[6].substr(1));
    }
    for (const auto& [name, r] : read_exponent_rows(out + "/exponents.tsv")) tsv_verdicts.push_back(r.verdict);
    EXPECT_EQ(md_verdicts, tsv_verdicts);
    const auto at = md.find("| the paper's claim | evidence | verdict |");
    ASSERT_NE(at, std::string::npos);
    std::istringstream lines(md.substr(at));
    int claims = 0;
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("| ", 0) != 0 || line.rfind("| the paper's claim", 0) == 0) continue;
      ++claims;
      const std::string verdict = line.substr(line.rfind(" | ", line.size() - 3) + 3);
      EXPECT_TRUE(verdict.rfind("supported", 0) == 0 || verdict.rfind("not supported", 0) == 0 ||
                  verdict.rfind("not decided at this scale", 0) == 0)
          << line;
    }
    EXPECT_EQ(claims, 9);
  }

  // The robustness block (pipelines/robustness.mk, robustness.sh): the
  // pipeline's collapse and one row per other analysis choice. Identity:
  // the eta window changes only eta (the same search on the same data gives
  // theta and z bit for bit).
  {
    std::string columns;
    const auto rows = tsv_rows(out + "/robustness.tsv", &columns);
    EXPECT_EQ(columns, "choice\tchange\ttheta\ttheta_err\tz\tz_err\teta\teta_err\tquality\tverdict");
    std::map<std::string, std::vector<std::string>> by_choice;
    for (const auto& r : rows) by_choice[r.at(0)] = r;
    for (const char* choice : {"pipeline", "start", "weights", "eta", "drop"})
      EXPECT_EQ(by_choice.count(choice), 1u) << choice;
    EXPECT_EQ(rows.size(), 5u);
    EXPECT_EQ(by_choice["eta"].at(2), by_choice["pipeline"].at(2));  // theta
    EXPECT_EQ(by_choice["eta"].at(4), by_choice["pipeline"].at(4));  // z
    EXPECT_DOUBLE_EQ(std::stod(by_choice["pipeline"].at(2)), value("theta, collapse"));
    for (const auto& r : rows) EXPECT_FALSE(r.at(9).empty()) << r.at(0);  // every row has a verdict
  }

  // Every table of the figures parses, and each fitted theta of Fig. 2 is finite.
  int fits = 0;
  for (const auto& entry : fs::directory_iterator(out + "/tables")) {
    if (entry.path().extension() != ".tsv") continue;
    const Table t = read_table(entry.path().string());
    EXPECT_FALSE(t.rows.empty()) << entry.path();
    if (entry.path().filename().string().rfind("fit_param_", 0) == 0) {
      EXPECT_TRUE(std::isfinite(t.column_values("theta").at(0))) << entry.path();
      ++fits;
    }
  }
  EXPECT_EQ(fits, 4);  // scales/tiny.mk: phi 0.104, r0 0.5, delta 1e-3, and the reference

  // Each run's scene, seed included, is recorded beside it.
  std::ifstream scene(out + "/scenes/snap_s1.toml");
  std::string scene_text((std::istreambuf_iterator<char>(scene)), std::istreambuf_iterator<char>());
  EXPECT_NE(scene_text.find("seed = 1"), std::string::npos) << scene_text;

  // A finished pipeline has nothing left to do.
  auto question = run_command(make_command(out, "-q"));
  EXPECT_EQ(question.exit_code, 0) << question.out << question.err;

  // A changed fit window reruns that fit and what uses it, and no simulation.
  auto dry = run_command(make_command(out, "-n THETA_WINDOW=20:200"));
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_NE(dry.out.find("coolgas-fit --power --no-weights --t-window 20:200"), std::string::npos) << dry.out;
  EXPECT_EQ(dry.out.find("coolgas-simulate"), std::string::npos) << dry.out;
  EXPECT_EQ(dry.out.find("coolgas-collapse"), std::string::npos) << dry.out;
  // So does the growing length's fit window: both length fits, the figure and
  // the table, and neither a simulation nor coolgas-structure.
  auto lt_dry = run_command(make_command(out, "-n LT_FIT_WINDOW=20:800"));
  ASSERT_EQ(lt_dry.exit_code, 0) << lt_dry.err;
  EXPECT_NE(lt_dry.out.find("--t-window 20:800 --e-column L_t"), std::string::npos) << lt_dry.out;
  EXPECT_NE(lt_dry.out.find("--t-window 20:800 --e-column L_C"), std::string::npos) << lt_dry.out;
  EXPECT_EQ(lt_dry.out.find("coolgas-structure"), std::string::npos) << lt_dry.out;
  EXPECT_EQ(lt_dry.out.find("coolgas-simulate"), std::string::npos) << lt_dry.out;
  // (make -n recorded the new windows; the default ones come back with a refit.)
  ASSERT_EQ(run_command(make_command(out, "")).exit_code, 0);
  EXPECT_EQ(run_command(make_command(out, "-q")).exit_code, 0);

  // Reanalysis: every figure again from the archived runs, without simulating.
  const std::string again = dir + "/reanalysis";
  auto re = run_command(make_command(again, "reanalyze ARCHIVE=" + out + "/runs"));
  ASSERT_EQ(re.exit_code, 0) << re.out << re.err;
  EXPECT_EQ(re.out.find("coolgas-simulate"), std::string::npos) << re.out;
  for (const char* figure : kFigures) EXPECT_TRUE(is_png(again + "/" + figure)) << figure;
  EXPECT_FALSE(fs::exists(again + "/runs"));
  const auto re_exponents = read_exponents(again + "/exponents.tsv");
  EXPECT_DOUBLE_EQ(re_exponents.lower_bound("theta, collapse")->second.measured, value("theta, collapse"));
}

TEST(AccuracyPipeline, CollapseOfRunsCutAtTheirEndIsTheCollapseOfTheWholeRuns) {
  // QUICK=1: L = 16, 20, 27, 4 seeds each, run to x = t/L^(5/2) = 3, and the
  // collapse against t_end cuts them at x = 1 and 3. Cut at 3 the tables are
  // whole, so that row must equal the 4-seed row of the seeds study, digit
  // for digit, cost included (an exact identity); cut at 1 costs less.
  std::string bin_dir = test::bin("coolgas-simulate");
  bin_dir.erase(bin_dir.rfind('/'));
  const std::string out = test::scratch_dir("accuracy_pipeline") + "/out";
  const auto r = run_command("make -C " + test::source("pipelines/accuracy") + " -j2 QUICK=1 BIN=" + bin_dir +
                             " OUT=" + out + " collapse-accuracy");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(is_png(out + "/collapse_accuracy.png"));
  const auto seeds = tsv_rows(out + "/collapse_accuracy.tsv"), tend = tsv_rows(out + "/collapse_tend.tsv");
  ASSERT_EQ(tend.size(), 2u);
  const auto full = std::find_if(seeds.begin(), seeds.end(), [](const auto& row) { return row.at(1) == "4"; });
  ASSERT_NE(full, seeds.end());
  EXPECT_EQ(tend[1].at(0), "3");
  // columns from the third on: theta theta_err z z_err quality cpu_s in both
  EXPECT_EQ(std::vector<std::string>(tend[1].begin() + 2, tend[1].end()),
            std::vector<std::string>(full->begin() + 2, full->end()));
  EXPECT_EQ(tend[0].at(0), "1");
  EXPECT_LT(std::stod(tend[0].at(7)), std::stod(tend[1].at(7)));
  EXPECT_GT(std::stod(tend[0].at(7)), 0);
}

TEST(DimensionsPipeline, TinyRunsGiveEveryRowBothFiguresAndNothingLeftToDo) {
  // pipelines/dimensions with PARAMETERS=tiny.mk (boxes of seconds): every
  // row of the table, judged against the two theories' exact values, and the
  // figures; then make has nothing left to do, and a new fit window refits
  // without simulating.
  std::string bin_dir = test::bin("coolgas-simulate");
  bin_dir.erase(bin_dir.rfind('/'));
  const std::string out = test::scratch_dir("dimensions_pipeline") + "/out";
  const std::string make = "make -C " + test::source("pipelines/dimensions") + " PARAMETERS=tiny.mk BIN=" + bin_dir +
                           " OUT=" + out + " DIMS='" + kStudiedDimensions + "' ";
  const auto r = run_command(make + "-j2");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(is_png(out + "/figures/theta_dimension.png"));
  EXPECT_TRUE(is_png(out + "/figures/energy_dimension.png"));
  std::string columns;
  const auto rows = tsv_rows(out + "/dimensions.tsv", &columns);
  EXPECT_EQ(columns, "quantity\td\tmeasured\terror\treference\treference_error\tsource\tdeviation\tregime");
  std::map<std::string, double> reference;  // "quantity d source" -> reference value
  for (const auto& cells : rows) {
    ASSERT_EQ(cells.size(), 9u) << cells.at(0);
    EXPECT_TRUE(std::isfinite(std::stod(cells[2]))) << cells[0];
    EXPECT_GT(std::stod(cells[3]), 0) << cells[0];
    EXPECT_TRUE(std::isfinite(std::stod(cells[7]))) << cells[0];
    reference[cells[0] + " d=" + cells[1] + " " + cells[6].substr(0, 5)] = std::stod(cells[4]);
  }
  // Both theories in 3D: 2d/(d+2) = 6/5 and Burgers' d/2 = 3/2; in 2D both are 1.
  EXPECT_DOUBLE_EQ(reference.at("theta, inelastic gas d=3 balli"), 1.2);
  EXPECT_DOUBLE_EQ(reference.at("theta, inelastic gas d=3 Burge"), 1.5);
  EXPECT_DOUBLE_EQ(reference.at("theta, inelastic gas d=2 2d/(d"), 1.0);
  EXPECT_DOUBLE_EQ(reference.at("theta, ballistic aggregation d=3 mean "), 1.2);
  EXPECT_EQ(rows.size(), kStudiedRows);
  EXPECT_EQ(run_command(make + "-q").exit_code, 0);
  const auto dry = run_command(make + "-n GAS_WINDOW_D2=10:50");
  ASSERT_EQ(dry.exit_code, 0) << dry.err;
  EXPECT_NE(dry.out.find("coolgas-fit --power --t-window 10:50"), std::string::npos) << dry.out;
  EXPECT_EQ(dry.out.find("coolgas-simulate"), std::string::npos) << dry.out;
}

TEST(EffectsPipeline, TinyRunsGiveEveryRowJudgedAndTheFigures) {
  // pipelines/effects with PARAMETERS=tiny.mk (seconds): each row of the
  // effects table judged by pipelines/row-verdict.sh against its theory's
  // exact value, and the figures; then make has nothing left to do.
  std::string bin_dir = test::bin("coolgas-simulate");
  bin_dir.erase(bin_dir.rfind('/'));
  const std::string out = test::scratch_dir("effects_pipeline") + "/out";
  const std::string make =
      "make -C " + test::source("pipelines/effects") + " PARAMETERS=tiny.mk BIN=" + bin_dir + " OUT=" + out + " ";
  const auto r = run_command(make + "-j2");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(is_png(out + "/figures/driven.png"));
  std::string columns;
  const auto rows = tsv_rows(out + "/effects.tsv", &columns);
  EXPECT_EQ(columns, "effect\tquantity\tmeasured\terror\ttheory\ttheory_error\ttolerance\tdeviation\tverdict\tsource");
  std::map<std::string, double> theory;  // quantity -> theory
  for (const auto& cells : rows) {
    ASSERT_EQ(cells.size(), 10u) << cells.at(1);
    EXPECT_TRUE(std::isfinite(std::stod(cells[2]))) << cells[1];
    EXPECT_TRUE(std::isfinite(std::stod(cells[3]))) << cells[1];
    EXPECT_TRUE(cells[8] == "agrees" || cells[8] == "differs" || cells[8] == "not decided") << cells[8];
    theory[cells[1]] = std::stod(cells[4]);
  }
  ASSERT_EQ(rows.size(), 5u);  // tiny.mk: the driven gas's three, rough spheres at one beta, the mixture
  // T ~ P^(2/3): 8 times the power, 4 times the temperature, exactly.
  EXPECT_DOUBLE_EQ(theory.at("T(8P)/T(P)"), 4.0);
  // van Noije & Ernst's a2 at r0 = 0.5 in 3D: 16 (1/2)(1/2) / (73 + 168 - 36 - 52.5 + 3.75) = 4/156.25.
  EXPECT_NEAR(theory.at("a2, steady"), 0.0256, 1e-6);
  // Enskog's balance at P = (1 - r0^2)/2: T/T0 = (1 + 3 a2/16)^(-2/3).
  EXPECT_NEAR(theory.at("T/T0, steady"), std::pow(1 + 3 * 0.0256 / 16, -2.0 / 3.0), 1e-5);
  // The two-temperature theory's T_rot/T_tr at r0 = 0.9, beta = 0.5, q = 2/5
  // (tests/physics/rough_spheres_test.cc: 0.867).
  EXPECT_NEAR(theory.at("T_rot/T_tr, r0 = 0.9, beta = 0.5"), 0.867077, 1e-5);
  EXPECT_TRUE(is_png(out + "/figures/rough.png"));
  // Garzo & Dufty's T_1/T_2 of the 1 : 1.5 mixture at r0 = 0.8, phi = 0.02
  // (tests/physics/mixture_test.cc: 0.8771).
  EXPECT_NEAR(theory.at("T_1/T_2, r0 = 0.8, diameters 1,1.5"), 0.877136, 1e-5);
  EXPECT_TRUE(is_png(out + "/figures/mixture.png"));
  EXPECT_EQ(run_command(make + "-q").exit_code, 0);
}

}  // namespace
}  // namespace coolgas
