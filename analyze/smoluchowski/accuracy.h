// What accuracy costs in time: every method run over its knobs against a
// reference, one table row per run with the wall time and the error.
//
// Cases (½-gain time, monodisperse start):
//   constant  t = 20   exact solution
//   additive  t = 1.5  exact solution
//   product   t = 0.8  exact solution (before gelation at t_g = 1)
//   ballistic t = 2    reference: fft at twice the largest M, rtol 1e-12, rk8pd
// Knobs (one block, i.e. one curve, each): direct and fft over M at tight
// tolerances, direct and fft over rtol at the largest M, geometric over the
// grid ratio. Error: the mass-weighted relative L1 distance of the log-binned
// N(m) from the reference (binned_distance), and |M_avg/M_avg,ref − 1|.
// Table shape: data-schema/tsv-tables.md, "coolgas-smoluchowski accuracy table".
#pragma once
#include <iosfwd>

namespace coolgas::smoluchowski {

enum class AccuracyScope { Quick, Full };  // Quick: constant and ballistic, fewer knobs

void write_accuracy_table(std::ostream& out, AccuracyScope scope);

}  // namespace coolgas::smoluchowski
