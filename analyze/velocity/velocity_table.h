// One dump's velocity statistics and its rows of the coolgas-velocity
// tables, from the frame's velocities. The tool writes them; the Python
// module (analyze/python/) returns them.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "analyze/velocity/distribution.h"
#include "analyze/velocity/tail.h"
#include "analyze/velocity/tool.h"
#include "common/tsv.h"

namespace coolgas {

struct VelocityStats {
  SpeedMoments moments;
  std::vector<TailPoint> tail;  // the folded tail bins that qualify for the fit
  std::optional<TailFit> fit;   // nothing when fewer than 3 qualify
};

// InputError unless tail_from > 0 and min_count >= 1 (the tool's options).
void check_tail_options(double tail_from, double min_count);

const std::vector<std::string>& velocity_columns(VelocityTable table);

// The statistics of `velocities` (vx0 vy0 vz0 vx1 ..., N >= 2; vz = 0 in
// 2D, vy = vz = 0 in 1D) in `dimension` d; `hist` is filled with their d components scaled by v_rms.
VelocityStats velocity_stats(std::span<const double> velocities, ComponentHistogram& hist, double tail_from,
                             double min_count, Geometry g);

// The rows of one dump at time t: a block (Phi, tail) with its summary
// comment, or the series' one row (no comment; beta NaN without a fit).
// The tail table needs the fit (std::logic_error without: callers refuse first).
TableBlock velocity_block(VelocityTable table, double t, const ComponentHistogram& hist, const VelocityStats& s,
                          double tail_from);

}  // namespace coolgas
