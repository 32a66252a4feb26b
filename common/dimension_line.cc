#include "common/dimension_line.h"

#include "common/error.h"

namespace coolgas {

void add_dimension_line(Provenance& p, int dimension) {
  if (dimension != 3) p.emplace_back("dimension", std::to_string(dimension));
}

int dimension_of(const Table& table) {
  const auto d = table.get("dimension");
  if (!d) return 3;
  if (*d == "1") return 1;
  if (*d == "2") return 2;
  if (*d == "3") return 3;
  throw InputError(table.source + ": '# dimension: " + *d + "' is not a dimension coolgas writes (1, 2 or 3)");
}

}  // namespace coolgas
