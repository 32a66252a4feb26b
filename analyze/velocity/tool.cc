#include "analyze/velocity/tool.h"

#include <cmath>
#include <ostream>
#include <sstream>

#include "common/trajectory/frame_reader.h"
#include "analyze/velocity/distribution.h"
#include "analyze/velocity/tail.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

std::vector<std::string> columns(VelocityTable t) {
  switch (t) {
    case VelocityTable::kPhi:
      return {"t", "y", "Phi", "Phi_err", "minus_ln_Phi"};
    case VelocityTable::kTail:
      return {"t", "y", "minus_ln_Phi", "minus_ln_Phi_err", "fit"};
    case VelocityTable::kSeries:
      return {"t", "v_rms", "kappa", "kappa_err", "beta", "beta_err", "tail_points"};
  }
  return {};
}

const char* table_name(VelocityTable t) {
  switch (t) {
    case VelocityTable::kPhi:
      return "Phi";
    case VelocityTable::kTail:
      return "tail";
    case VelocityTable::kSeries:
      return "series";
  }
  return "";
}

void check(const VelocityOptions& o) {
  if (!(o.tail_from > 0) || !std::isfinite(o.tail_from))
    throw InputError("--tail-from must be a positive number, got " + format_number(o.tail_from));
  if (!(o.min_count >= 1) || !std::isfinite(o.min_count))
    throw InputError("--min-count must be >= 1, got " + format_number(o.min_count));
}

Provenance provenance(const Trajectory& traj, const VelocityOptions& o) {
  Provenance p = traj.provenance();
  p.emplace_back("table", table_name(o.table));
  p.emplace_back("bins", std::to_string(o.bins));
  p.emplace_back("ymax", format_number(o.ymax));
  p.emplace_back("tail_from", format_number(o.tail_from));
  p.emplace_back("min_count", format_number(o.min_count));
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

std::string summary(double t, const SpeedMoments& m, const std::optional<TailFit>& fit, double tail_from) {
  std::string s = "t = " + format_number(t) + "; v_rms = " + format_number(m.v_rms) +
                  "; kappa = " + format_number(m.kappa) + " +- " + format_number(m.kappa_err);
  if (fit)
    s += "; beta = " + format_number(fit->beta) + " +- " + format_number(fit->beta_err) + " (" +
         std::to_string(fit->points) + " bins, y >= " + format_number(tail_from) + ")";
  return s;
}

void write_phi(TsvWriter& out, double t, const ComponentHistogram& h) {
  const double norm = 1.0 / (double(h.samples()) * h.width());
  for (int j = 0; j < h.bins(); ++j) {
    if (h.count(j) == 0) continue;  // -ln Φ would be infinite
    const double phi = h.phi(j);
    out.row({t, h.center(j), phi, std::sqrt(double(h.count(j))) * norm, -std::log(phi)});
  }
}

void write_tail(TsvWriter& out, double t, const std::vector<TailPoint>& pts, const TailFit& fit) {
  for (const auto& p : pts) {
    const double minus_ln_phi = -std::log(p.phi);
    out.row({t, p.y, minus_ln_phi, 1 / std::sqrt(p.count), fit.prefactor * std::pow(p.y, fit.beta)});
  }
}

std::string no_tail_text(const Trajectory& traj, const Frame& f, const VelocityOptions& o, std::size_t points) {
  return traj.path() + ": dump at t = " + format_number(f.time) + ": only " + std::to_string(points) +
         " tail bins with y >= " + format_number(o.tail_from) + " and >= " + format_number(o.min_count) +
         " samples (3 needed to fit beta)";
}

[[noreturn]] void no_tail(const Trajectory& traj, const Frame& f, const VelocityOptions& o, std::size_t points) {
  throw InputError(no_tail_text(traj, f, o, points) + "; lower --tail-from or --min-count, or use wider bins");
}

}  // namespace

void run_velocity(const VelocityOptions& opt, std::ostream& final_out) {
  // The table is built in memory and written only when every dump has been
  // read: a bad dump leaves no half table behind.
  std::ostringstream os;
  check(opt);
  ComponentHistogram hist(opt.bins, opt.ymax);
  Trajectory traj(opt.input, kVelocity);
  TsvWriter out(os, "coolgas-velocity", provenance(traj, opt), columns(opt.table));
  Frame frame;
  const std::vector<std::size_t> dumps = traj.dumps_nearest(opt.times, opt.exact_time);
  for (std::size_t i = 0; i < dumps.size(); ++i) {
    throw_if_interrupted(i, dumps.size(), "dumps");
    traj.read(dumps[i], frame);
    const SpeedMoments m = speed_moments(frame.velocity);
    hist.fill(frame.velocity, m.v_rms);
    const auto pts = tail_points(hist, opt.tail_from, opt.min_count);
    const auto fit = fit_tail(pts);
    if (opt.table == VelocityTable::kTail && !fit) no_tail(traj, frame, opt, pts.size());
    switch (opt.table) {
      case VelocityTable::kPhi:
        out.block(summary(frame.time, m, fit, opt.tail_from));
        write_phi(out, frame.time, hist);
        break;
      case VelocityTable::kTail:
        out.block(summary(frame.time, m, fit, opt.tail_from));
        write_tail(out, frame.time, pts, *fit);
        break;
      case VelocityTable::kSeries:
        // v_rms and kappa need no tail: a dump whose tail is too thin keeps its row, beta NaN.
        if (!fit) note(no_tail_text(traj, frame, opt, pts.size()) + "; beta is nan in that row");
        out.row({frame.time, m.v_rms, m.kappa, m.kappa_err, fit ? fit->beta : NAN, fit ? fit->beta_err : NAN,
                 double(fit ? fit->points : pts.size())});
        break;
    }
  }
  final_out << os.str();
}

}  // namespace coolgas
