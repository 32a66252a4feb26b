// The picture of a 1D trajectory (rods on a ring): a space-time diagram, x
// across and one row per dump up the picture, from the first dump to the one
// drawn last, as Ben-Naim et al. (PRL 83, 4069 (1999), Fig. 1) show the 1D
// cooling gas. Each rod is a segment of its true length (1 sigma; an
// aggregate of mass m, m sigma: lengths add) coloured by its velocity over
// the dump's v_rms, blue (left) through grey to red (right), so that the
// colours mean the same in every row while the gas cools. The dumps of a run
// are log-spaced in time, so rows of equal height make the vertical axis
// close to log t; each row is labelled by its time.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "analyze/snapshot/plot.h"

namespace coolgas {

// Colours saturate at |v| = this many v_rms.
inline constexpr double kSpaceTimeVelocityRange = 2;

struct SpaceTimeRod {
  double x = 0, length = 1;
  double v = 0;  // velocity / the row's v_rms (0 in a row at rest)
};

struct SpaceTimeRow {
  double t = 0;
  double v_rms = 0;  // sqrt(sum m v^2 / sum m): the rods' (unit masses) or the aggregates' (their masses)
  std::vector<SpaceTimeRod> rods;
};

// One dump's row: positions and velocities as the frame reader gives them
// (3 numbers per entry; only x is used), masses empty for a gas (unit rods)
// or the aggregates' masses.
SpaceTimeRow space_time_row(double t, std::span<const double> positions, std::span<const double> velocities,
                            std::span<const double> mass);

// The gnuplot script drawing `rows` on a ring of length L from `data` (lines
// "x_left row length v") into `picture`; opt.view is not used.
std::string space_time_script(const std::vector<SpaceTimeRow>& rows, const PlotOptions& opt, const std::string& data,
                              const std::string& picture);

// Draws the diagram into `output` (the format from opt.format), as
// render_picture does a 2D or 3D scene.
void render_space_time(const std::vector<SpaceTimeRow>& rows, const PlotOptions& opt, const std::string& output);

}  // namespace coolgas
