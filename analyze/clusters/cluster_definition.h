// Which clusters coolgas-clusters counts (--definition): the paper's unit
// cells (analyze/labelling/cluster_labeller.h), or particles in contact
// (analyze/labelling/contact_labeller.h), whose bond length CUTOFF sigma
// defaults to 1.1 sigma.
//
// Why 1.1: in the cooling gas the particles of a cluster sit at contact (g(r)
// peaks within 0.005 sigma of it, docs/tools.md, g(r)), so any cutoff a little
// above 1 finds them; in the homogeneous gas at the paper's phi = 0.208
// a shell of 0.1 sigma holds about one neighbour per particle on average
// (n g(sigma) times the shell's volume: 0.397 x 1.80 x 0.46 = 0.99 by
// Carnahan-Starling), below the two or so a continuum percolation cluster
// needs, so the start is many small clusters, not one spanning the box as
// the unit cells make it (docs/tools.md gives the measured threshold).
#pragma once
#include <span>
#include <string>

#include "common/geometry.h"

namespace coolgas {

struct ClusterDefinition {
  enum class Kind { kCells, kContact };
  Kind kind = Kind::kCells;
  double cutoff = 1.1;  // contact: bond length [sigma]
  bool contact() const { return kind == Kind::kContact; }
};

// "cells", "contact" or "contact:CUTOFF" (CUTOFF >= 1, finite); InputError
// naming --definition and what is allowed otherwise.
ClusterDefinition parse_cluster_definition(const std::string& text);
// The definition as "cells" or "contact:1.1" (parse_cluster_definition reads it back).
std::string definition_name(const ClusterDefinition& d);
// The provenance line of a contact definition (the cells' is cluster_cells_text);
// of a mixture's (particles of several diameters), the bond's scale is each pair's contact distance.
std::string contact_text(const ClusterDefinition& d, bool mixture = false);
// InputError unless the longest contact bond, the cutoff times the largest
// of the particles' diameters `diameter` (a mixture's; none: the gas's unit
// particles), is at most L/2 (the minimum image), naming `where` (a file's dump).
void check_cutoff(const ClusterDefinition& d, double L, const std::string& where,
                  std::span<const double> diameter = {});

}  // namespace coolgas
