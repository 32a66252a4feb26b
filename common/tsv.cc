#include "common/tsv.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/text_line.h"
#include "common/version.h"

namespace coolgas {

std::string format_number(double x) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

TsvWriter::TsvWriter(std::ostream& out, const std::string& tool, const Provenance& provenance,
                     const std::vector<std::string>& columns)
    : out_(out), ncol_(columns.size()) {
  // The column line comes first and bare, so that readers which take the
  // first line as names (numpy.genfromtxt(names=True), gnuplot's column
  // names) and those that skip '#' lines first (pandas comment='#') agree.
  for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "\t" : "") << columns[i];
  out_ << "\n# format: coolgas-table " << kTableFormat << "\n";
  out_ << "# tool: " << tool << "\n# version: " << program_version() << "\n";
  for (const auto& [k, v] : provenance) out_ << "# " << k << ": " << v << "\n";
}

void TsvWriter::row(const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "\t" : "") << format_number(values[i]);
  out_ << "\n";
  rows_in_block_ = true;
}

void TsvWriter::block(const std::string& comment) {
  if (rows_in_block_) out_ << "\n\n";
  if (!comment.empty()) out_ << "# " << comment << "\n";
  rows_in_block_ = false;
}

void TsvWriter::write(const TableBlock& b) {
  block(b.comment);
  append(b);
}

void TsvWriter::append(const TableBlock& b) {
  for (const auto& r : b.rows) row(r);
}

std::size_t Table::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  std::string have;
  for (const auto& c : columns) have += (have.empty() ? "" : ", ") + c;
  throw InputError(source + ": no column '" + name + "' (columns: " + have + ")");
}

std::vector<double> Table::column_values(const std::string& name) const {
  const std::size_t c = column(name);
  std::vector<double> v;
  v.reserve(rows.size());
  for (const auto& r : rows) v.push_back(r[c]);
  return v;
}

std::optional<std::string> Table::get(const std::string& key) const {
  for (const auto& [k, v] : provenance)
    if (k == key) return v;
  return std::nullopt;
}

namespace {

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> f;
  std::istringstream in(line);
  std::string tok;
  while (in >> tok) f.push_back(tok);
  return f;
}

double parse_field(const std::string& tok, const std::string& where) {
  double x = 0;
  auto res = std::from_chars(tok.data(), tok.data() + tok.size(), x);
  if (res.ec != std::errc() || res.ptr != tok.data() + tok.size())
    throw InputError(where + ": '" + tok + "' is not a number");
  if (!std::isfinite(x)) throw InputError(where + ": value '" + tok + "' is not finite (NaN or infinity)");
  return x;
}

}  // namespace

namespace {

std::string trim(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

// Header comments before the first data row: "key: value" lines are
// provenance; in a version 1 table the first other comment names the
// columns; later ones (such as a block's "# t = 10") are ignored.
void read_header_line(Table& t, const std::string& text) {
  const auto colon = text.find(':');
  if (colon != std::string::npos) {
    t.provenance.emplace_back(trim(text.substr(0, colon)), trim(text.substr(colon + 1)));
  } else if (t.columns.empty()) {
    t.columns = split_fields(text);
  }
}

// A column line that is a number is a table without one (the data came first).
void read_column_line(Table& t, const std::vector<std::string>& names, const std::string& where) {
  double x = 0;
  const std::string& first = names.front();
  const auto res = std::from_chars(first.data(), first.data() + first.size(), x);
  if (res.ec == std::errc() && res.ptr == first.data() + first.size())
    throw InputError(where + ": no column line (expected tab-separated column names before the data, got '" +
                     first + "')");
  t.columns = names;
}

// The next line of a table (common/text_line.h), refused naming the line.
bool next_table_line(std::istream& in, std::string& line, std::size_t limit, const std::string& source, long lineno) {
  try {
    return next_line(in, line, limit, "a table's");
  } catch (const LineRefused& e) {
    throw InputError(source + ":" + std::to_string(lineno) + ": " + e.what());
  }
}

// Lines between two looks at the interrupt flag: a few microseconds of work.
constexpr long kLinesPerInterruptCheck = 4096;

}  // namespace

Table read_table(std::istream& in, const std::string& source, const TableLimits& limits) {
  Table t;
  t.source = source;
  std::string line;
  int block = 0, blank_run = 0;
  long lineno = 0;
  while (next_table_line(in, line, limits.line_bytes, source, lineno + 1)) {
    ++lineno;
    if (lineno % kLinesPerInterruptCheck == 0 && interrupted())
      throw Interrupted(interrupt_signal(), "while reading " + source + " (at line " + std::to_string(lineno) +
                                                "); no table written");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) {
      ++blank_run;
      continue;
    }
    if (line[0] == '#') {
      if (t.rows.empty()) read_header_line(t, line.substr(1));
      continue;
    }
    const std::string where = source + ":" + std::to_string(lineno);
    auto fields = split_fields(line);
    if (t.columns.empty()) {  // format 2: the first line that is not a comment names the columns
      read_column_line(t, fields, where);
      continue;
    }
    if (!t.rows.empty() && blank_run > 0) ++block;
    blank_run = 0;
    if (fields.size() != t.columns.size())
      throw InputError(where + ": " + std::to_string(fields.size()) + " fields, expected " +
                       std::to_string(t.columns.size()) + " (one per column)");
    if (t.rows.size() == limits.rows)
      throw InputError(where + ": more than " + std::to_string(limits.rows) + " rows; a table holds at most " +
                       std::to_string(limits.rows) + " rows");
    if (double(t.rows.size() + 1) * double(fields.size()) > double(limits.numbers))
      throw InputError(where + ": more than " + std::to_string(limits.numbers) + " numbers (" +
                       std::to_string(t.rows.size() + 1) + " rows of " + std::to_string(fields.size()) +
                       " columns); a table holds at most " + std::to_string(limits.numbers) + " numbers");
    std::vector<double> row;
    row.reserve(fields.size());
    for (const auto& f : fields) row.push_back(parse_field(f, where));
    t.rows.push_back(std::move(row));
    t.row_block.push_back(block);
  }
  if (t.rows.empty()) throw InputError(source + ": empty table (no data rows)");
  return t;
}

Table read_table(const std::string& path, const TableLimits& limits) {
  if (path == "-") return read_table(std::cin, "stdin", limits);
  std::ifstream f(path);
  if (!f) throw InputError("cannot open table '" + path + "' for reading");
  return read_table(f, path, limits);
}

}  // namespace coolgas
