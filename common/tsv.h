// TSV tables: the format every analysis tool writes to stdout and reads from
// a path or "-" (see data-schema/tsv-tables.md).
//
//   t<TAB>E<TAB>E_over_E0             <- the column names, the first line, bare
//   # format: coolgas-table 2         <- provenance: "# key: value" lines
//   # tool: coolgas-energy
//   # version: 0.1.0 (abc123)
//   # input: run.h5
//   0.01<TAB>1.5<TAB>1
//
// Blank lines separate blocks (gnuplot's "index"); a comment line after the
// first row is ignored by the reader. The reader also takes format 1 tables,
// whose column line was the first comment without ':'. Numbers are written in the shortest form
// that reads back to the same double.
#pragma once
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/text_line.h"

namespace coolgas {

// The table format version written (data-schema/tsv-tables.md).
inline constexpr int kTableFormat = 2;

using Provenance = std::vector<std::pair<std::string, std::string>>;

// One block of a table as a tool computes it for one dump: its comment
// (without "# ") and rows. The tool writes it (TsvWriter::write); the Python
// module (analyze/python/) hands the same rows out, so both see one result.
struct TableBlock {
  std::string comment;
  std::vector<std::vector<double>> rows;
};

class TsvWriter {
 public:
  // Writes the provenance block (tool and program version first) and the
  // column line at once.
  TsvWriter(std::ostream& out, const std::string& tool, const Provenance& provenance,
            const std::vector<std::string>& columns);
  void row(const std::vector<double>& values);
  // Starts a new block (two blank lines, gnuplot's index separator) with an
  // optional comment such as "# t = 10".
  void block(const std::string& comment = "");
  // block(b.comment), then its rows.
  void write(const TableBlock& b);
  // Its rows only, in the current block: a series, one row per dump.
  void append(const TableBlock& b);
  std::size_t columns() const { return ncol_; }

 private:
  std::ostream& out_;
  std::size_t ncol_;
  bool rows_in_block_ = false;
};

// Formats a double in its shortest round-trip form.
std::string format_number(double x);

struct Table {
  std::string source;           // the path, or "stdin"
  Provenance provenance;        // "# key: value" header lines, in order
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::vector<int> row_block;   // block index of each row (0-based)

  // Index of a column by name; InputError naming the available columns if absent.
  std::size_t column(const std::string& name) const;
  std::vector<double> column_values(const std::string& name) const;
  // First value of a provenance key, if present.
  std::optional<std::string> get(const std::string& key) const;
};

// What a table may hold, so that no reader grows without bound on a device
// (/dev/zero: one endless line), an endless pipe or a hostile file. Past a
// bound the reader stops with an InputError naming the file, the line and
// the bound, before it allocates more (data-schema/tsv-tables.md, "Bounds").
// At the defaults a table takes at most about 1.2 GB in memory; no table a
// coolgas tool writes comes near them.
struct TableLimits {
  std::size_t line_bytes = kMaxLineBytes;  // bytes of one line, its newline not counted (1 MiB, common/text_line.h)
  std::size_t rows = 10'000'000;                  // data rows (10^7)
  std::size_t numbers = 100'000'000;              // data rows x columns (10^8)
};

// Reads a table from a path, or from stdin when path is "-". Rejects, with
// an InputError naming the line: an empty table, ragged rows, non-numbers,
// NaN and infinities, and a table beyond `limits`. Stops with Interrupted
// (common/interrupt.h) once SIGINT/SIGTERM/SIGHUP arrived in a tool that
// watches them (looked at every few thousand lines).
Table read_table(const std::string& path, const TableLimits& limits = {});
Table read_table(std::istream& in, const std::string& source, const TableLimits& limits = {});

}  // namespace coolgas
