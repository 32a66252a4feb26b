#include "analyze/clusters/tool.h"

#include <cmath>

#include <ostream>
#include <span>
#include <sstream>

#include "analyze/labelling/cluster_labeller.h"
#include "analyze/clusters/mass_distribution.h"
#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

const std::vector<std::string> kDistributionColumns = {"t", "m", "dm", "N", "x", "y"};
const std::vector<std::string> kScaledColumns = {"t", "x", "y"};
const std::vector<std::string> kSeriesColumns = {"t", "M0", "M1", "M2", "M_avg", "M_max", "largest_fraction"};

// One block of the mass distribution: N = count / (V dm), x = m / M_avg, y = N M_avg².
void write_distribution(TsvWriter& out, double t, const MassHistogram& h, double volume, bool scaled_only) {
  const ClusterMoments& mo = h.moments();
  const double m_avg = mo.mean();
  out.block("t = " + format_number(t) + "; M_avg = " + format_number(m_avg) + "; M_max = " +
            std::to_string(mo.largest) + "; largest_fraction = " + format_number(double(mo.largest) / double(mo.mass)));
  const LogBins& b = h.bins();
  for (int k = 0; k < b.size(); ++k) {
    if (h.count(k) == 0) continue;
    const double dm = double(b.width(k));
    const double n = double(h.count(k)) / (volume * dm);
    const double x = b.center(k) / m_avg, y = n * m_avg * m_avg;
    if (scaled_only) out.row({t, x, y});
    else out.row({t, b.center(k), dm, n, x, y});
  }
}

void write_series_row(TsvWriter& out, double t, const ClusterMoments& mo, double volume) {
  out.row({t, double(mo.clusters) / volume, double(mo.mass) / volume, mo.mass2 / volume, mo.mean(), double(mo.largest),
           double(mo.largest) / double(mo.mass)});
}

}  // namespace

void run_clusters(const ClustersOptions& opt, std::ostream& final_out) {
  // The table is built in memory and written only when every dump has been
  // read: a bad dump leaves no half table behind.
  std::ostringstream os;
  if (opt.bins_per_decade < 1)
    throw InputError("--bins-per-decade must be >= 1, got " + std::to_string(opt.bins_per_decade));
  Trajectory traj(opt.input, kPosition);
  Provenance prov = traj.provenance();
  prov.emplace_back("bins_per_decade", std::to_string(opt.bins_per_decade));
  if (traj.aggregates())  // ballistic aggregation: the clusters are the aggregates themselves
    prov.emplace_back("clusters", "the aggregates of the file (ballistic aggregation); mass in particles");
  else
    prov.emplace_back("cells", "floor(L)^3 cubic cells of side L/floor(L); face neighbours; periodic");
  for (double t : opt.times) prov.emplace_back("time", format_number(t));
  if (opt.series && opt.scaled) throw InputError("--series and --scaled exclude each other: choose one table");
  prov.emplace_back("table", opt.series ? "cluster series" : (opt.scaled ? "scaled mass distribution" : "mass distribution"));
  TsvWriter out(os, "coolgas-clusters", prov,
                opt.series ? kSeriesColumns : (opt.scaled ? kScaledColumns : kDistributionColumns));

  MassHistogram hist(opt.bins_per_decade, traj.particles());
  ClusterLabeller labeller;
  Frame frame;
  const std::vector<std::size_t> dumps = traj.dumps_nearest(opt.times, opt.exact_time);
  for (std::size_t i = 0; i < dumps.size(); ++i) {
    throw_if_interrupted(i, dumps.size(), "dumps");
    traj.read(dumps[i], frame);
    hist.clear();
    if (traj.aggregates()) {
      for (double m : frame.mass) hist.add(std::llround(m));
    } else {
      labeller.label(cluster_grid_of_dump(frame.L, traj.path(), frame.dump), frame.position);
      labeller.for_each_mass([&](std::int64_t m) { hist.add(m); });
    }
    const double volume = frame.L * frame.L * frame.L;
    if (opt.series) {
      write_series_row(out, frame.time, hist.moments(), volume);
    } else {
      write_distribution(out, frame.time, hist, volume, opt.scaled);
    }
  }
  final_out << os.str();
}

}  // namespace coolgas
