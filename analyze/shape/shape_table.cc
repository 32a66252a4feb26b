#include "analyze/shape/shape_table.h"

#include "common/error.h"

namespace coolgas {

namespace {

const std::vector<std::string>& all_columns(ShapeTable table) {
  static const std::vector<std::string> mass_radius{"t", "m", "dm", "clusters", "Rg", "Rg_err", "asphericity", "prolateness"},
      series{"t", "d_f", "d_f_err", "fit_bins", "fitted_clusters", "asphericity", "prolateness", "wrapping_fraction"},
      clusters{"t", "mass", "Rg", "lambda1", "lambda2", "lambda3", "asphericity", "prolateness", "wraps"};
  switch (table) {
    case ShapeTable::kMassRadius:
      return mass_radius;
    case ShapeTable::kSeries:
      return series;
    case ShapeTable::kClusters:
      break;
  }
  return clusters;
}

// A 2D table leaves out the columns of 3D invariants; a 1D table those of
// any shape (its 1 x 1 tensor is R_g^2 itself).
bool in_dimension(const std::string& column, int dimension) {
  if (dimension == 1) return column != "lambda2" && column != "lambda3" && column != "asphericity" && column != "prolateness";
  return dimension == 3 || (column != "lambda3" && column != "prolateness");
}

// The entries of a full row (all_columns order) that the dimension's table has.
std::vector<double> row_of(ShapeTable table, int dimension, const std::vector<double>& full) {
  if (dimension == 3) return full;
  std::vector<double> row;
  const auto& names = all_columns(table);
  for (std::size_t i = 0; i < names.size(); ++i)
    if (in_dimension(names[i], dimension)) row.push_back(full[i]);
  return row;
}

}  // namespace

std::vector<std::string> shape_columns(ShapeTable table, Geometry g) {
  const int dimension = g.d();
  std::vector<std::string> out;
  for (const auto& c : all_columns(table))
    if (in_dimension(c, dimension)) out.push_back(c);
  return out;
}

void check_shape_options(int bins_per_decade, std::int64_t min_mass) {
  if (bins_per_decade < 1) throw InputError("--bins-per-decade must be >= 1, got " + std::to_string(bins_per_decade));
  if (min_mass < 1) throw InputError("--min-mass must be >= 1, got " + std::to_string(min_mass));
}

TableBlock shape_block(ShapeTable table, double t, const std::vector<ClusterShape>& shapes, const MassRadius& mr,
                       std::int64_t min_mass, Geometry g) {
  const int dimension = g.d();
  TableBlock b;
  const auto add = [&](const std::vector<double>& full) { b.rows.push_back(row_of(table, dimension, full)); };
  if (table == ShapeTable::kSeries) {
    add({t, mr.d_f, mr.d_f_err, double(mr.fit_bins), double(mr.fitted_clusters), mr.asphericity, mr.prolateness,
         mr.wrapping_fraction});
    return b;
  }
  b.comment = "t = " + format_number(t) + "; d_f = " + format_number(mr.d_f) + " +- " + format_number(mr.d_f_err) +
              " (" + std::to_string(mr.fit_bins) + " bins); wrapping_fraction = " + format_number(mr.wrapping_fraction);
  if (table == ShapeTable::kMassRadius) {
    for (const MassRadiusBin& m : mr.bins)
      add({t, m.m, double(m.dm), double(m.clusters), m.Rg, m.Rg_err, m.asphericity, m.prolateness});
    return b;
  }
  for (const ClusterShape& c : shapes) {
    if (c.shape.mass < min_mass) break;  // ranked by mass
    const Shape& s = c.shape;
    add({t, double(s.mass), s.Rg, s.lambda[0], s.lambda[1], s.lambda[2], s.asphericity, s.prolateness,
         c.wraps ? 1.0 : 0.0});
  }
  return b;
}

}  // namespace coolgas
