#include "analyze/smoluchowski/grid.h"

namespace coolgas::smoluchowski {

MassGrid uniform_grid(std::int64_t M) {
  MassGrid g;
  g.mass.resize(M);
  g.edge.resize(M + 1);
  g.edge[0] = 0.5;
  for (std::int64_t k = 1; k <= M; ++k) {
    g.mass[k - 1] = static_cast<double>(k);
    g.edge[k] = static_cast<double>(k) + 0.5;
  }
  return g;
}

}  // namespace coolgas::smoluchowski
