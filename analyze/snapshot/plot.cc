#include "analyze/snapshot/plot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

namespace fs = std::filesystem;

namespace {

// A fresh private directory, removed with its contents when done.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "coolgas-snapshot-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary directory in " + pattern);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write_data(const SnapshotScene& scene, const fs::path& file) {
  std::ofstream out(file);
  char line[96];
  for (const auto& p : scene.points) {
    std::snprintf(line, sizeof line, "%.6g %.6g %.6g %u %.6g\n", p.x, p.y, p.z, p.rgb, p.diameter);
    out << line;
  }
  out.close();
  if (!out) throw WriteError("cannot write the snapshot data to " + file.string() + ": " + std::strerror(errno));
}

}  // namespace

std::string gnuplot_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

// The font grows with the picture (18 at 900 pixels, 14 at 700), so that it
// stays readable where the picture is shown smaller (the pipelines' Fig. 3).
std::string gnuplot_terminal(const PlotOptions& o, int width) {
  const int font = std::max(10, int(std::lround(o.size_px / 50.0)));
  std::ostringstream t;
  switch (o.format) {
    case PictureFormat::kPng: t << "pngcairo noenhanced size " << width << "," << o.size_px; break;
    case PictureFormat::kPdf:  // cairo's PDF size in inches: 72 pixels to the inch keeps the proportions
      t << "pdfcairo noenhanced size " << format_number(width / 72.0) << "in," << format_number(o.size_px / 72.0) << "in";
      break;
    case PictureFormat::kSvg: t << "svg noenhanced size " << width << "," << o.size_px; break;
  }
  t << " font '," << font << "'";
  return t.str();
}

namespace {

std::string quoted(const std::string& s) { return gnuplot_quoted(s); }

std::string hex(std::uint32_t rgb) {
  char s[16];
  std::snprintf(s, sizeof s, "#%06x", unsigned(rgb));
  return s;
}

// One key entry per coloured cluster (and one for the grey rest), drawn as
// empty plots so the key never covers a particle.
std::string key_entries(const SnapshotScene& scene, const std::string& what) {
  std::ostringstream k;
  for (const auto& c : scene.clusters)
    k << ", NaN with points pt 7 ps 2 lc rgb '" << hex(c.rgb) << "' title "
      << quoted(std::to_string(c.rank) + ": m = " + std::to_string(c.mass));
  k << ", NaN with points pt 7 ps 2 lc rgb '" << hex(kOtherClusters) << "' title " << quoted("other " + what + "s");
  return k.str();
}

std::string script(const SnapshotScene& scene, const PlotOptions& o, const fs::path& data, const fs::path& picture) {
  std::ostringstream s;
  s << "set terminal " << gnuplot_terminal(o, o.size_px + o.size_px * 3 / 10) << "\n"
    << "set output " << quoted(picture.string()) << "\n"
    << "set title " << quoted(o.title) << "\n"
    << "set key outside right top samplen 1 title " << quoted("largest " + o.what + "s") << "\n"
    << "set xrange [0:" << format_number(o.L) << "]\nset yrange [0:" << format_number(o.L) << "]\n"
    << "set xlabel 'x [sigma]'\nset ylabel 'y [sigma]'\n";
  const std::string keys = key_entries(scene, o.what);
  if (o.view != SnapshotView::k3d) {
    // Circles of radius d/2 in axis units: the particles at their true size.
    s << "set size ratio -1\n"
      << "plot " << quoted(data.string()) << " using 1:2:($5/2):4 with circles fill solid noborder lc rgb variable notitle"
      << keys << "\n";
  } else {
    s << "set zrange [0:" << format_number(o.L) << "]\nset zlabel 'z [sigma]'\n"
      << "set view 60, 35\nset view equal xyz\nset xyplane 0\n"
      << "splot " << quoted(data.string())
      << " using 1:2:3:(0.25*$5):4 with points pt 7 ps variable lc rgb variable notitle" << keys << "\n";
  }
  return s.str();
}

const char* extension(PictureFormat f) {
  switch (f) {
    case PictureFormat::kPdf: return ".pdf";
    case PictureFormat::kSvg: return ".svg";
    default: return ".png";
  }
}

// Runs `program script` with stdout and stderr into `log`; returns the exit
// status, 127 if the program could not be started.
int run_gnuplot(const std::string& program, const fs::path& script_file, const fs::path& log) {
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    if (!std::freopen(log.c_str(), "w", stdout) || dup2(fileno(stdout), 2) < 0) _exit(126);
    execlp(program.c_str(), program.c_str(), script_file.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t^") != std::string::npos) return line;
  return "(no message)";
}

// A write that failed for want of room (a full disk, a quota, a size limit)
// or an I/O error is exit code 5; anything else is the path's fault (exit 2).
[[noreturn]] void write_failed(const std::string& to, const std::error_code& ec) {
  const int e = ec.value();
  if (e == ENOSPC || e == EDQUOT || e == EFBIG || e == EIO) throw WriteError("cannot write '" + to + "': " + ec.message());
  throw InputError("cannot write '" + to + "': " + ec.message());
}

// Across file systems the picture is copied beside its place first and
// renamed over it: a copy that fails half way leaves the old picture (if
// any) whole and no cut one.
void move_into_place(const fs::path& from, const std::string& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (!ec) return;
  const std::string partial = to + ".partial";
  fs::copy_file(from, partial, fs::copy_options::overwrite_existing, ec);
  if (!ec) fs::rename(partial, to, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(partial, ignored);
    write_failed(to, ec);
  }
}

}  // namespace

PictureFormat picture_format(const std::string& output) {
  std::string ext = fs::path(output).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".png") return PictureFormat::kPng;
  if (ext == ".pdf") return PictureFormat::kPdf;
  if (ext == ".svg") return PictureFormat::kSvg;
  throw InputError("-o " + output + ": the picture type is taken from the extension, which must be .png, .pdf or .svg" +
                   (ext.empty() ? std::string(" (none given)") : ", not " + ext));
}

void render_picture(const SnapshotScene& scene, const PlotOptions& opt, const std::string& output) {
  render_with_gnuplot([&](const fs::path& data) { write_data(scene, data); },
                      [&](const fs::path& data, const fs::path& picture) { return script(scene, opt, data, picture); },
                      opt, output);
}

void render_with_gnuplot(const std::function<void(const fs::path& data)>& write,
                         const std::function<std::string(const fs::path& data, const fs::path& picture)>& make_script,
                         const PlotOptions& opt, const std::string& output) {
  const fs::path dir = fs::absolute(output).parent_path();
  if (!fs::is_directory(dir))
    throw InputError("cannot write '" + output + "': directory '" + dir.string() + "' does not exist");
  TempDir tmp;
  const fs::path data = tmp.path() / "particles.dat", png = tmp.path() / (std::string("snapshot") + extension(opt.format));
  const fs::path gp = tmp.path() / "snapshot.gp", log = tmp.path() / "gnuplot.log";
  write(data);
  {
    std::ofstream script_file(gp);
    script_file << make_script(data, png);
    script_file.close();
    if (!script_file) throw WriteError("cannot write the gnuplot script to " + gp.string() + ": " + std::strerror(errno));
  }
  const int rc = run_gnuplot(opt.gnuplot, gp, log);
  // Ctrl-C reaches gnuplot too (one process group): its exit is then no failure of its own.
  throw_if_interrupted("while gnuplot drew the picture; no picture or table written");
  if (rc == 127)
    throw InputError("cannot run gnuplot ('" + opt.gnuplot +
                     "'): not found; install the gnuplot package or pass --gnuplot PATH");
  if (rc != 0 || !fs::exists(png) || fs::file_size(png) == 0)
    throw InputError("gnuplot ('" + opt.gnuplot + "') failed with exit code " + std::to_string(rc) + ": " +
                     first_line(log));
  move_into_place(png, output);
}

}  // namespace coolgas
