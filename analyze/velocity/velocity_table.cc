#include "analyze/velocity/velocity_table.h"

#include <cmath>
#include <stdexcept>

#include "common/error.h"

namespace coolgas {

void check_tail_options(double tail_from, double min_count) {
  if (!(tail_from > 0) || !std::isfinite(tail_from))
    throw InputError("--tail-from must be a positive number, got " + format_number(tail_from));
  if (!(min_count >= 1) || !std::isfinite(min_count))
    throw InputError("--min-count must be >= 1, got " + format_number(min_count));
}

const std::vector<std::string>& velocity_columns(VelocityTable t) {
  static const std::vector<std::string> phi = {"t", "y", "Phi", "Phi_err", "minus_ln_Phi"};
  static const std::vector<std::string> tail = {"t", "y", "minus_ln_Phi", "minus_ln_Phi_err", "fit"};
  static const std::vector<std::string> series = {"t", "v_rms", "kappa", "kappa_err", "beta", "beta_err", "tail_points"};
  switch (t) {
    case VelocityTable::kTail:
      return tail;
    case VelocityTable::kSeries:
      return series;
    case VelocityTable::kPhi:
      break;
  }
  return phi;
}

VelocityStats velocity_stats(std::span<const double> velocities, ComponentHistogram& hist, double tail_from,
                             double min_count, Geometry g) {
  VelocityStats s;
  s.moments = speed_moments(velocities, g);
  hist.fill(velocities, s.moments.v_rms, g);
  s.tail = tail_points(hist, tail_from, min_count);
  s.fit = fit_tail(s.tail);
  return s;
}

namespace {

std::string summary(double t, const SpeedMoments& m, const std::optional<TailFit>& fit, double tail_from) {
  std::string s = "t = " + format_number(t) + "; v_rms = " + format_number(m.v_rms) +
                  "; kappa = " + format_number(m.kappa) + " +- " + format_number(m.kappa_err);
  if (fit)
    s += "; beta = " + format_number(fit->beta) + " +- " + format_number(fit->beta_err) + " (" +
         std::to_string(fit->points) + " bins, y >= " + format_number(tail_from) + ")";
  return s;
}

}  // namespace

TableBlock velocity_block(VelocityTable table, double t, const ComponentHistogram& h, const VelocityStats& s,
                          double tail_from) {
  TableBlock b;
  switch (table) {
    case VelocityTable::kPhi: {
      b.comment = summary(t, s.moments, s.fit, tail_from);
      const double norm = 1.0 / (double(h.samples()) * h.width());
      for (int j = 0; j < h.bins(); ++j) {
        if (h.count(j) == 0) continue;  // -ln Φ would be infinite
        const double phi = h.phi(j);
        b.rows.push_back({t, h.center(j), phi, std::sqrt(double(h.count(j))) * norm, -std::log(phi)});
      }
      break;
    }
    case VelocityTable::kTail: {
      if (!s.fit) throw std::logic_error("velocity_block: the tail table without a fit");
      b.comment = summary(t, s.moments, s.fit, tail_from);
      for (const auto& p : s.tail)
        b.rows.push_back({t, p.y, -std::log(p.phi), 1 / std::sqrt(p.count), s.fit->prefactor * std::pow(p.y, s.fit->beta)});
      break;
    }
    case VelocityTable::kSeries:
      // v_rms and kappa need no tail: a dump whose tail is too thin keeps its row, beta NaN.
      b.rows.push_back({t, s.moments.v_rms, s.moments.kappa, s.moments.kappa_err, s.fit ? s.fit->beta : NAN,
                        s.fit ? s.fit->beta_err : NAN, double(s.fit ? s.fit->points : s.tail.size())});
      break;
  }
  return b;
}

}  // namespace coolgas
