// The window of t a power-law fit of E(t) uses when the user gives none
// (coolgas-fit --power, coolgas-collapse --optimize), by a stated rule:
//   start: E(t) starts flat (local slope 0) and steepens: the first t at
//          which it falls as t^-1 or faster over the next quarter decade; if
//          it then falls faster than t^-3/2 (Haff's t^-2 regime of a weakly
//          inelastic gas), the first t after that from which it falls no
//          faster than t^-3/2 — past the crossover from Haff's law (3/2,
//          Burgers', is the largest exponent any theory proposes; the test
//          pipelines/exponents.sh judges a window's start by);
//   end:   t = 0.1 L^z, the paper's finite-size crossover x = t/L^z ~ 0.1
//          (Pathak et al. 2014, Fig. 1), when the table's provenance gives L;
//          else the last row. z = d/theta with the mean-field theta =
//          2d/(d+2): z = (d+2)/2, 5/2 in 3D (the paper's), 2 in 2D, 3/2 in 1D, d from
//          the table's dimension line (common/dimension_line.h).
//   In 2D the start's rule is the same: Haff's t^-2 holds in every
//   dimension, and 3/2 lies between it and the 2D theories' theta = 1.
#pragma once
#include <optional>
#include <string>

#include "analyze/curves/fit_data.h"
#include "common/tsv.h"

namespace coolgas {

// The start of the rule, looking at t <= t_end only; nothing if there is none.
std::optional<double> past_haff(const Table& table, const FitColumns& columns, double t_end);

// The end of the rule: 0.1 L^z if the provenance gives L, else infinity.
double finite_size_crossover(const Table& table);
// The mean-field z = (d+2)/2 of that crossover in dimension d.
double crossover_z(int dimension);
// "0.1 L^(5/2)" (3D), "0.1 L^2" (2D) or "0.1 L^(3/2)" (1D), for messages.
std::string crossover_text(const Table& table);

struct ChosenWindow {
  Window window;
  std::string rule;  // what was chosen and why, for a note on stderr
};

// The whole rule. InputError naming --t-window if there is no such region
// (E(t) still in Haff's regime at its end, or past the finite-size crossover
// before it leaves it).
ChosenWindow scaling_window(const Table& table, const FitColumns& columns);

}  // namespace coolgas
