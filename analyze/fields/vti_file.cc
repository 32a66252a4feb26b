#include "analyze/fields/vti_file.h"

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <vector>

#include "common/durable_file.h"
#include "common/error.h"
#include "common/tsv.h"

static_assert(std::endian::native == std::endian::little, "the .vti files are written little-endian as they lie in memory");

namespace coolgas {

namespace {

struct Array {
  std::string name;
  int components;
  std::vector<double> values;  // cells * components
};

std::vector<Array> arrays(const CellFields& f) {
  const std::int64_t cells = f.cells();
  const double volume = f.g.power(f.cell_side());
  Array density{"density", 1, {}}, velocity{"velocity", 3, {}}, temperature{"temperature", 1, {}},
      vorticity{"vorticity", 3, {}};
  for (std::int64_t c = 0; c < cells; ++c) {
    density.values.push_back(f.count[c] / volume);
    for (int a = 0; a < 3; ++a) velocity.values.push_back(f.flow(c, a));
    temperature.values.push_back(cell_temperature(f, c));
    for (double w : cell_vorticity(f, c)) vorticity.values.push_back(w);
  }
  return {density, velocity, temperature, vorticity};
}

}  // namespace

void write_vti(const std::string& path, const CellFields& f) {
  const std::vector<Array> data = arrays(f);
  std::ostringstream head;
  std::string extent;
  for (int a = 0; a < 3; ++a) extent += std::string(a ? " " : "") + "0 " + std::to_string(a < f.g.d() ? f.n : 0);
  const std::string h = format_number(f.cell_side());
  head << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       << "  <ImageData WholeExtent=\"" << extent << "\" Origin=\"0 0 0\" Spacing=\"" << h << " " << h << " " << h
       << "\">\n    <Piece Extent=\"" << extent << "\">\n      <CellData Scalars=\"density\" Vectors=\"velocity\">\n";
  std::uint64_t offset = 0;
  for (const Array& a : data) {
    head << "        <DataArray type=\"Float64\" Name=\"" << a.name << "\" NumberOfComponents=\"" << a.components
         << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
    offset += sizeof(std::uint64_t) + a.values.size() * sizeof(double);
  }
  head << "      </CellData>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n   _";
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << head.str();
    for (const Array& a : data) {
      const std::uint64_t bytes = a.values.size() * sizeof(double);
      out.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
      out.write(reinterpret_cast<const char*>(a.values.data()), std::streamsize(bytes));
    }
    out << "\n  </AppendedData>\n</VTKFile>\n";
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      throw WriteError("cannot write " + path + " (its directory must exist and be writable)");
    }
  }
  replace_file(tmp, path);
}

}  // namespace coolgas
