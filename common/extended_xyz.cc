#include "common/extended_xyz.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <istream>
#include <map>
#include <ostream>
#include <sstream>

#include "common/error.h"
#include "common/geometry.h"
#include "common/memory.h"
#include "common/text_line.h"

namespace coolgas {

namespace {

// pbc="T T T", "T T F" (disks in the plane z = 0) or "T F F" (rods on the x axis).
std::string pbc_of(Geometry g) {
  return std::string("pbc=\"") + (g.spans(0) ? "T" : "F") + (g.spans(1) ? " T" : " F") + (g.spans(2) ? " T" : " F") + "\"";
}

std::string quoted(std::string v) {
  for (char& c : v)
    if (c == '"' || c == '\n' || c == '\r') c = '\'';
  return "\"" + v + "\"";
}

std::string xyz_key(const std::string& k) {
  std::string out;
  for (char c : k) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out.empty() || std::isdigit(static_cast<unsigned char>(out[0])) ? "_" + out : out;
}

}  // namespace

void write_xyz_frame(std::ostream& out, const XyzFrame& f, const Provenance& provenance) {
  const std::size_t n = f.position.size() / 3;
  const std::string L = format_number(f.L);
  const bool spheres = !f.diameter.empty();
  // Disks: the plane z = 0, a unit third lattice vector, not periodic; rods:
  // the x axis, unit second and third vectors, periodic along x only.
  const Geometry g(f.dimension);
  const std::string b = g.spans(1) ? L : "1", c = g.spans(2) ? L : "1";
  out << n << "\nLattice=\"" << L << " 0 0 0 " << b << " 0 0 0 " << c
      << "\" Properties=species:S:1:pos:R:3" << (f.velocity.empty() ? "" : ":velo:R:3")
      << (f.angular_velocity.empty() ? "" : ":omega:R:3") << (f.id.empty() ? "" : ":id:I:1")
      << (spheres ? ":radius:R:1" : "") << (f.mass.empty() ? "" : ":mass:R:1")
      << " " << pbc_of(g);
  if (f.time) out << " Time=" << format_number(*f.time);
  if (f.step) out << " Step=" << *f.step;
  for (const auto& [k, v] : provenance) out << " " << xyz_key(k) << "=" << quoted(v);
  out << "\n";
  for (std::size_t i = 0; i < n; ++i) {
    out << "X";
    for (int d = 0; d < 3; ++d) out << " " << format_number(f.position[3 * i + d]);
    if (!f.velocity.empty())
      for (int d = 0; d < 3; ++d) out << " " << format_number(f.velocity[3 * i + d]);
    if (!f.angular_velocity.empty())
      for (int d = 0; d < 3; ++d) out << " " << format_number(f.angular_velocity[3 * i + d]);
    if (!f.id.empty()) out << " " << f.id[i];
    if (spheres) out << " " << format_number(f.diameter[i] / 2);
    if (!f.mass.empty()) out << " " << format_number(f.mass[i]);
    out << "\n";
  }
}

namespace {

struct Parser {
  std::istream& in;
  const std::string& source;
  long line_no = 0;
  std::optional<std::streamoff> size;  // the file's bytes, when the stream can tell

  [[noreturn]] void fail(const std::string& what) const { fail_at(line_no, what); }
  [[noreturn]] void fail_at(long line, const std::string& what) const {
    throw InputError(source + ": line " + std::to_string(line) + ": " + what);
  }

  bool next(std::string& line) {
    try {
      if (!next_line(in, line, kMaxLineBytes, "an extended XYZ file's")) return false;
    } catch (const LineRefused& e) {
      fail_at(line_no + 1, e.what());
    }
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }

  double number(std::string_view t, const char* what) const {
    double x = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), x);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail(std::string(what) + " '" + shown(std::string(t)) + "' is not a number");
    return x;
  }

  // key=value, key="quoted value" or key={braced value}; a bare key is "T".
  std::map<std::string, std::string> pairs(const std::string& s) const {
    std::map<std::string, std::string> kv;
    std::size_t i = 0;
    while (i < s.size()) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i == s.size()) break;
      const std::size_t k0 = i;
      while (i < s.size() && s[i] != '=' && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      const std::string key = s.substr(k0, i - k0);
      std::string value = "T";
      if (i < s.size() && s[i] == '=') {
        ++i;
        const char open = i < s.size() ? s[i] : ' ';
        if (open == '"' || open == '{') {
          const char close = open == '"' ? '"' : '}';
          const std::size_t end = s.find(close, i + 1);
          if (end == std::string::npos) fail("the comment line has an unclosed " + std::string(1, open) + " after " + shown(key) + "=");
          value = s.substr(i + 1, end - i - 1);
          i = end + 1;
        } else {
          const std::size_t v0 = i;
          while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
          value = s.substr(v0, i - v0);
        }
      }
      kv[key] = value;
    }
    return kv;
  }

  static std::vector<std::string> words(const std::string& s) {
    std::istringstream ss(s);
    std::vector<std::string> w;
    for (std::string t; ss >> t;) w.push_back(t);
    return w;
  }
};

// Where each quantity sits among the columns (-1: absent).
struct Columns {
  std::size_t count = 0;
  long pos = -1, velo = -1, omega = -1, radius = -1, diameter = -1, mass = -1;
};

Columns columns_of(const Parser& p, const std::string& properties) {
  std::vector<std::string> f;
  std::stringstream ss(properties);
  for (std::string t; std::getline(ss, t, ':');) f.push_back(t);
  if (f.size() % 3 != 0) p.fail("Properties=" + shown(properties) + " is not a list of name:type:columns");
  Columns c;
  for (std::size_t i = 0; i < f.size(); i += 3) {
    const std::string& name = f[i];
    const long at = long(c.count);
    const double cols = p.number(f[i + 2], "the column count");
    if (!(cols >= 1 && cols <= 1000 && cols == std::floor(cols))) p.fail("Properties=" + shown(properties) + " has a bad column count");
    const bool real = f[i + 1] == "R";
    auto want = [&](long* slot, double n) {
      if (!real || cols != n)
        p.fail("property " + shown(name) + " is " + f[i + 1] + ":" + f[i + 2] + "; expected R:" + format_number(n));
      *slot = at;
    };
    if (name == "pos") want(&c.pos, 3);
    else if (name == "velo" || name == "vel" || name == "velocities") want(&c.velo, 3);
    else if (name == "omega" || name == "angular_velocity") want(&c.omega, 3);
    else if (name == "radius") want(&c.radius, 1);
    else if (name == "diameter") want(&c.diameter, 1);
    else if (name == "mass" || name == "masses") want(&c.mass, 1);
    c.count += std::size_t(cols);
  }
  if (c.pos < 0) p.fail("Properties=" + shown(properties) + " has no positions (pos:R:3)");
  return c;
}

// The dimension pbc= names: "T T T" (or none) spheres, "T T F" disks in the
// xy plane, "T F F" rods on the x axis (as ASE and OVITO write them).
int periodic_dimension(const Parser& p, const std::optional<std::string>& pbc) {
  if (!pbc) return 3;
  const auto w = Parser::words(*pbc);
  const auto t = [&](std::size_t i) { return w[i] == "T" || w[i] == "True"; };
  const auto f = [&](std::size_t i) { return w[i] == "F" || w[i] == "False"; };
  if (w.size() == 3 && t(0) && t(1) && t(2)) return 3;
  if (w.size() == 3 && t(0) && t(1) && f(2)) return 2;
  if (w.size() == 3 && t(0) && f(1) && f(2)) return 1;
  p.fail("pbc=\"" + shown(*pbc) + "\"; coolgas boxes are periodic in x, y and z (pbc=\"T T T\"), in x and y "
         "(\"T T F\", disks) or in x (\"T F F\", rods)");
}

// The side of the periodic box: the Lattice's first `dimension` edges, equal;
// the others (not periodic) are only checked to be orthogonal.
double periodic_side(const Parser& p, const std::string& lattice, int dimension) {
  const auto w = Parser::words(lattice);
  if (w.size() != 9) p.fail("Lattice=\"" + shown(lattice) + "\" does not hold 9 numbers");
  double m[9];
  for (int i = 0; i < 9; ++i) m[i] = p.number(w[i], "a Lattice entry");
  for (int i : {1, 2, 3, 5, 6, 7})
    if (m[i] != 0) p.fail("Lattice=\"" + shown(lattice) + "\" is not an orthogonal box; coolgas boxes are cubes, squares or rings");
  std::string edges;
  bool equal = true;
  for (int k = 0; k < dimension; ++k) {
    edges += (k ? ", " : "") + format_number(m[4 * k]);
    equal = equal && m[4 * k] == m[0];
  }
  if (!equal)
    p.fail("Lattice=\"" + shown(lattice) + "\" is not a " + Geometry(dimension).box() + " (edges " + edges + ")");
  return m[0];
}

// A frame's Time=: a NaN, an infinity or a negative time would be taken as
// the start of the run and make every later resume fail, so it is refused here.
double frame_time(const Parser& p, const std::string& text) {
  const double t = p.number(text, "Time");
  if (!(std::isfinite(t) && t >= 0)) p.fail("Time=" + shown(text) + " is not a time; times are finite and >= 0");
  return t;
}

// A frame's T0= (the time unit's temperature): finite and > 0.
double temperature(const Parser& p, const std::string& text) {
  const double T0 = p.number(text, "T0");
  if (!(std::isfinite(T0) && T0 > 0)) p.fail("T0=" + shown(text) + " is not a temperature; T0 is finite and > 0");
  return T0;
}

// The count line is only a claim: a damaged or hostile file may say 10^9
// particles and hold a few lines. Each particle line is at least a word and
// a newline (the last may lack it), so the rest of the file bounds the count
// (shorter lines are then refused naming the line); the memory available
// bounds it too. Both before anything is allocated.
void check_count(const Parser& p, long count_line, std::size_t n) {
  if (p.size) {
    const std::streamoff at = p.in.tellg();
    const double left = at >= 0 ? double(*p.size - at) : double(*p.size);
    if (2.0 * double(n) - 1 > left)
      p.fail_at(count_line, "the count line says " + std::to_string(n) + " particles, but the " + bytes_text(left) +
                                " left in the file hold at most " + format_number(std::floor((left + 1) / 2)) +
                                " lines (a cut or damaged file?)");
  }
  const double bytes = double(n) * 8 * 8, memory = usable_memory_bytes();  // pos, velo: 3 each; diameter, mass
  if (bytes > memory)
    p.fail_at(count_line, "the count line says " + std::to_string(n) + " particles, which need " + bytes_text(bytes) +
                              "; the memory available is " + bytes_text(memory));
}

// Disks and rods have no extent across the box's periodic directions: each
// particle's other coordinates must be those of the first (`plane`: one
// plane, one line), and are set to 0; its other velocity components must be 0.
void flatten(const Parser& p, XyzFrame& f, std::size_t i, std::array<double, 3>& plane) {
  static const char* const kAxis[] = {"x", "y", "z"};
  const Geometry g(f.dimension);
  const std::string pbc = pbc_of(g);
  for (int d = f.dimension; d < 3; ++d) {
    double& x = f.position[3 * i + d];
    if (i == 0) plane[d] = x;
    if (x != plane[d])
      p.fail("particle " + std::to_string(i) + " has " + kAxis[d] + " = " + format_number(x) + ", particle 0 " +
             format_number(plane[d]) + "; in " + pbc + " the particles lie in one " +
             g.space());
    x = 0;
    if (!f.velocity.empty() && f.velocity[3 * i + d] != 0)
      p.fail("particle " + std::to_string(i) + " has v" + kAxis[d] + " = " + format_number(f.velocity[3 * i + d]) +
             "; in " + pbc + " it must be 0");
  }
}

// One frame after its count line; nothing when the input has ended.
XyzFrame read_frame(Parser& p, std::size_t n) {
  const long count_line = p.line_no;
  std::string line;
  if (!p.next(line)) p.fail("the file ends before the comment line");
  const auto kv = p.pairs(line);
  const auto get = [&](const char* k) { const auto it = kv.find(k); return it == kv.end() ? std::optional<std::string>() : it->second; };
  XyzFrame f;
  const auto lattice = get("Lattice");
  if (!lattice) p.fail("no Lattice=\"L 0 0 0 L 0 0 0 L\" (the box) on the comment line: not an extended XYZ file with a box");
  f.dimension = periodic_dimension(p, get("pbc"));
  f.L = periodic_side(p, *lattice, f.dimension);
  if (const auto t = get("Time")) f.time = frame_time(p, *t);
  if (const auto t = get("T0")) f.T0 = temperature(p, *t);
  const Columns c = columns_of(p, get("Properties").value_or("species:S:1:pos:R:3"));
  check_count(p, count_line, n);
  f.position.resize(3 * n);
  if (c.velo >= 0) f.velocity.resize(3 * n);
  if (c.omega >= 0) f.angular_velocity.resize(3 * n);
  if (c.radius >= 0 || c.diameter >= 0) f.diameter.resize(n);
  if (c.mass >= 0) f.mass.resize(n);
  std::array<double, 3> plane{};
  for (std::size_t i = 0; i < n; ++i) {
    if (!p.next(line)) p.fail("the file ends after " + std::to_string(i) + " of " + std::to_string(n) + " particles");
    const auto w = Parser::words(line);
    if (w.size() < c.count) p.fail("expected " + std::to_string(c.count) + " columns, got " + std::to_string(w.size()));
    for (int d = 0; d < 3; ++d) f.position[3 * i + d] = p.number(w[c.pos + d], "a position");
    if (c.velo >= 0)
      for (int d = 0; d < 3; ++d) f.velocity[3 * i + d] = p.number(w[c.velo + d], "a velocity");
    if (c.omega >= 0)
      for (int d = 0; d < 3; ++d) f.angular_velocity[3 * i + d] = p.number(w[c.omega + d], "an angular velocity");
    if (c.radius >= 0) f.diameter[i] = 2 * p.number(w[c.radius], "a radius");
    if (c.diameter >= 0) f.diameter[i] = p.number(w[c.diameter], "a diameter");
    if (c.mass >= 0) f.mass[i] = p.number(w[c.mass], "a mass");
    flatten(p, f, i, plane);
  }
  return f;
}

}  // namespace

namespace {

// The stream's size in bytes if it can seek (a file), else nothing (a pipe).
std::optional<std::streamoff> stream_size(std::istream& in) {
  const std::streampos here = in.tellg();
  if (here < 0 || !in.seekg(0, std::ios::end)) {
    in.clear();
    return std::nullopt;
  }
  const std::streamoff end = in.tellg();
  in.seekg(here);
  if (end < 0 || !in) {
    in.clear();
    return std::nullopt;
  }
  return end;
}

}  // namespace

XyzFrame read_xyz_frame(std::istream& in, const std::string& source, std::optional<double> time) {
  Parser p{in, source, 0, stream_size(in)};
  std::optional<XyzFrame> best;
  std::string line;
  while (p.next(line)) {
    const auto w = Parser::words(line);
    if (w.empty() && best) continue;  // blank lines after the last frame
    double n = -1;
    if (w.size() == 1) std::from_chars(w[0].data(), w[0].data() + w[0].size(), n);
    if (!(n >= 1 && n < 2147483648.0 && n == std::floor(n)))
      p.fail("expected the number of particles (an extended XYZ frame starts with it), got '" + shown(line) + "'");
    XyzFrame f = read_frame(p, std::size_t(n));
    if (time && !f.time) p.fail("a frame has no Time=, so the frame nearest t = " + format_number(*time) + " cannot be chosen");
    if (!best || !time || std::abs(*f.time - *time) < std::abs(*best->time - *time)) best = std::move(f);
  }
  if (!best) throw InputError(source + ": empty file; expected an extended XYZ frame");
  return *best;
}

}  // namespace coolgas
