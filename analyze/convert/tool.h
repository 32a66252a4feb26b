// coolgas-convert: frames of a coolgas trajectory as extended XYZ (ASE,
// OVITO, VMD) or a LAMMPS text dump (LAMMPS read_dump, OVITO, MDAnalysis),
// written to stdout; ballistic-aggregation files give only the aggregates
// present, with their radii and masses.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace coolgas {

enum class ExportFormat { kXyz, kLammps };

struct ConvertOptions {
  std::string input;
  ExportFormat format = ExportFormat::kXyz;
  std::vector<double> times;  // dumps nearest these times; empty = all dumps
  bool exact_time = false;    // --exact-time: refuse a time no dump has
  bool last = false;          // only the last dump
};

void run_convert(const ConvertOptions& opt, std::ostream& out);

}  // namespace coolgas
