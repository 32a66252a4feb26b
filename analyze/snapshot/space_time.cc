#include "analyze/snapshot/space_time.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

constexpr int kLabelledRows = 10;  // at most about this many time labels up the side

void write_rows(const std::vector<SpaceTimeRow>& rows, const std::filesystem::path& file) {
  std::ofstream out(file);
  char line[96];
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const SpaceTimeRod& rod : rows[r].rods) {
      std::snprintf(line, sizeof line, "%.6g %zu %.6g %.4g\n", rod.x - rod.length / 2, r, rod.length, rod.v);
      out << line;
    }
  out.close();
  if (!out) throw WriteError("cannot write the space-time data to " + file.string() + ": " + std::strerror(errno));
}

// Every k-th row labelled with its time, k chosen for about kLabelledRows labels.
std::string time_tics(const std::vector<SpaceTimeRow>& rows) {
  const std::size_t every = std::max<std::size_t>(1, (rows.size() + kLabelledRows - 1) / kLabelledRows);
  std::ostringstream s;
  s << "set ytics (";
  for (std::size_t r = 0; r < rows.size(); r += every) {
    char t[32];
    std::snprintf(t, sizeof t, "%.3g", rows[r].t);
    s << (r > 0 ? ", " : "") << gnuplot_quoted(t) << " " << r;
  }
  s << ")\n";
  return s.str();
}

// Lines as thick as a row's share of the picture's height, so that the rows
// form bands without overlapping.
double row_width(const PlotOptions& o, std::size_t rows) {
  return std::clamp(0.6 * o.size_px / double(std::max<std::size_t>(rows, 1)), 1.0, 12.0);
}

}  // namespace

SpaceTimeRow space_time_row(double t, std::span<const double> positions, std::span<const double> velocities,
                            std::span<const double> mass) {
  SpaceTimeRow row;
  row.t = t;
  const std::size_t n = positions.size() / 3;
  double mv2 = 0, m = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = mass.empty() ? 1.0 : mass[i], v = velocities[3 * i];
    mv2 += w * v * v, m += w;
  }
  row.v_rms = m > 0 ? std::sqrt(mv2 / m) : 0.0;
  row.rods.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    row.rods.push_back({positions[3 * i], mass.empty() ? 1.0 : mass[i],
                        row.v_rms > 0 ? velocities[3 * i] / row.v_rms : 0.0});
  return row;
}

std::string space_time_script(const std::vector<SpaceTimeRow>& rows, const PlotOptions& o, const std::string& data,
                              const std::string& picture) {
  const std::string range = format_number(kSpaceTimeVelocityRange);
  std::ostringstream s;
  s << "set terminal " << gnuplot_terminal(o, o.size_px + o.size_px * 3 / 10) << "\n"
    << "set output " << gnuplot_quoted(picture) << "\n"
    << "set title " << gnuplot_quoted(o.title) << "\n"
    << "unset key\n"
    << "set xrange [0:" << format_number(o.L) << "]\n"
    << "set yrange [-0.5:" << format_number(double(rows.size()) - 0.5) << "]\n"
    << "set xlabel 'x [sigma]'\nset ylabel 't [1/omega0], one row per dump'\n"
    << time_tics(rows)
    << "set palette defined (-" << range << " '#2166ac', 0 '#bbbbbb', " << range << " '#b2182b')\n"
    << "set cbrange [-" << range << ":" << range << "]\n"
    << "set cblabel 'v / v_rms of the dump'\n"
    << "plot " << gnuplot_quoted(data) << " using 1:2:3:(0):4 with vectors nohead lw "
    << format_number(row_width(o, rows.size())) << " lc palette z notitle\n";
  return s.str();
}

void render_space_time(const std::vector<SpaceTimeRow>& rows, const PlotOptions& opt, const std::string& output) {
  render_with_gnuplot([&](const std::filesystem::path& data) { write_rows(rows, data); },
                      [&](const std::filesystem::path& data, const std::filesystem::path& picture) {
                        return space_time_script(rows, opt, data.string(), picture.string());
                      },
                      opt, output);
}

}  // namespace coolgas
