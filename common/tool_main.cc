#include "common/tool_main.h"

#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <hdf5.h>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <streambuf>
#include <string>
#include <vector>

#include "common/did_you_mean.h"
#include "common/error.h"
#include "common/fault_point.h"
#include "common/interrupt.h"
#include "common/version.h"

namespace coolgas {

namespace {

// std::cout's buffer: writes straight to file descriptor 1 and keeps the
// errno of the first failed write, which the iostream state alone loses.
class StdoutBuffer : public std::streambuf {
 public:
  StdoutBuffer() {
    setp(buf_, buf_ + sizeof buf_);
    // A stdout closed by the caller (`>&-`): keep fd 1 taken, so that no file
    // the tool opens becomes fd 1 and receives the table, and report EBADF.
    if (::fcntl(1, F_GETFD) == -1 && errno == EBADF) {
      error_ = EBADF;
      const int fd = ::open("/dev/null", O_WRONLY);
      if (fd > 1) ::dup2(fd, 1), ::close(fd);
    }
  }
  ~StdoutBuffer() override { StdoutBuffer::sync(); }
  int error() const { return error_; }
  // Flushes and closes fd 1, so that an error reported only at close (NFS,
  // quota) is not lost either. Returns the first error, or 0.
  int close() {
    sync();
    if (::close(1) != 0 && error_ == 0 && errno != EINTR) error_ = errno;
    closed_ = true;
    return error_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    const char* p = pbase();
    while (p < pptr() && error_ == 0 && !closed_) {
      const ssize_t n = ::write(1, p, std::size_t(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) error_ = n < 0 ? errno : EIO;
      else p += n;
    }
    setp(buf_, buf_ + sizeof buf_);  // what failed is dropped, once
    return error_ == 0 ? 0 : -1;
  }

 private:
  char buf_[1 << 16];
  int error_ = 0;
  bool closed_ = false;
};

void report(const std::string& tool, const std::string& kind, const std::string& what) {
  std::cerr << one_line(tool + ": " + kind + ": " + what) << "\n";
}

int run_body(const std::string& tool, const std::function<int()>& body) {
  try {
    arm_fault_from_environment();  // a test's fault at a named point (common/fault_point.h)
    return body();
  } catch (const InputError& e) {
    report(tool, "error", e.what());
    return kExitInput;
  } catch (const WriteError& e) {
    report(tool, "error", e.what());
    return kExitWrite;
  } catch (const Interrupted& e) {
    std::cerr << one_line(tool + ": " + e.what()) << "\n";
    return kExitInterrupted;
  } catch (const std::bad_alloc&) {
    report(tool, "error", "out of memory (the input asks for more than this machine has)");
    return kExitFailure;
  } catch (const std::exception& e) {
    report(tool, "internal error", e.what());
    return kExitFailure;
  }
}

}  // namespace

std::vector<std::string>& old_spelling_notes() {
  static std::vector<std::string> notes;
  return notes;
}

// The running tool's name, for notes and the usage line (set by run_tool).
std::string& tool_name() {
  static std::string name = "coolgas";
  return name;
}

int run_tool(const std::string& tool, const std::function<int()>& body) {
  // HDF5's clean-up at exit closes whatever is still open; a file whose close
  // failed (the disk filled while the file was being set up) is still open
  // there, and closing it again crashes inside HDF5 (exit 139 after the
  // right message). Every file is closed by its handle (common/hdf5_file.h)
  // before exit, so the clean-up is left out. (Before any other HDF5 call.)
  H5dont_atexit();
  tool_name() = tool;
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGPIPE, SIG_DFL);
  // Never destroyed: std::cout is flushed at exit after function-local
  // statics are gone (ios_base::Init runs first, so is torn down last), and
  // a destroyed buffer there is a use after free (AddressSanitizer's lane
  // found it).
  static StdoutBuffer& buffer = *new StdoutBuffer;
  std::cout.rdbuf(&buffer);
  int code = run_body(tool, body);
  std::cout.flush();
  if (const int err = buffer.close(); err != 0) {
    report(tool, "error", std::string("cannot write stdout: ") + std::strerror(err));
    if (code == kExitOk) code = kExitFailure;
  }
  // Old spellings are noted only when the run worked: an error stays one line.
  if (code == kExitOk)
    for (const auto& text : old_spelling_notes()) report(tool, "note", text);
  return code;
}

namespace {

// "nan", "inf", "-Infinity", ...: what strtod reads as a number that is not finite.
bool names_non_finite(std::string token) {
  const auto space = [](char c) { return c == ' ' || c == '\t'; };
  while (!token.empty() && space(token.back())) token.pop_back();
  std::size_t i = 0;
  while (i < token.size() && space(token[i])) ++i;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  std::string word;
  for (; i < token.size(); ++i) word += char(std::tolower(static_cast<unsigned char>(token[i])));
  return word == "nan" || word == "inf" || word == "infinity";
}

// Every time, number, list (1,2) or window (LO:HI) given to an option must be
// finite: CLI11 reads "nan" and "inf" as doubles, and a NaN time or bound
// would otherwise pass every comparison unnoticed. (Scene keys given with
// --set are checked by the scene itself.)
void refuse_non_finite(const CLI::App& app) {
  for (const CLI::Option* opt : app.get_options()) {
    if (!opt->nonpositional()) continue;
    for (const std::string& value : opt->results()) {
      std::size_t start = 0;
      while (true) {
        const std::size_t end = value.find_first_of(",:", start);
        if (names_non_finite(value.substr(start, end == std::string::npos ? end : end - start)))
          throw InputError(opt->get_name() + " " + value + ": not a finite number (give finite values only)");
        if (end == std::string::npos) break;
        start = end + 1;
      }
    }
  }
}

}  // namespace

namespace {

// For the first option on the command line that the tool does not have,
// the closest one it has.
std::string suggestion(CLI::App& app, int argc, char** argv) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.size() < 3 || a.rfind("--", 0) != 0) continue;
    const std::string name = a.substr(0, a.find('='));
    if (std::find(names.begin(), names.end(), name) == names.end()) return did_you_mean(name, names);
  }
  return "";
}

}  // namespace

bool parse_command_line(CLI::App& app, int argc, char** argv) {
  app.name(tool_name());
  app.set_version_flag("--version", tool_name() + " " + program_version(), "print the program version and commit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    app.exit(e);
    return true;
  } catch (const CLI::ParseError& e) {
    throw InputError(std::string(e.what()) + suggestion(app, argc, argv) + " (see --help)");
  }
  refuse_non_finite(app);
  return false;
}

void note_old_spelling(int argc, char** argv, const std::string& old_name, const std::string& new_name) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == old_name || a.rfind(old_name + "=", 0) == 0) {
      old_spelling_notes().push_back(old_name + " is the old spelling of " + new_name +
                                     " and goes away in the next version");
      return;
    }
  }
}

CLI::Option* add_dump_selection(CLI::App& app, std::vector<double>& times, bool& exact_time, const std::string& what) {
  CLI::Option* time = app.add_option("--time", times,
                                     what + " [1/omega0] (repeatable, or a comma-separated list;\n"
                                            "a time no dump has is snapped to the nearest, with a note on stderr)")
                          ->delimiter(',');
  app.add_flag("--exact-time", exact_time, "refuse a --time that no dump has instead of snapping it");
  return time;
}

void note(const std::string& text) { report(tool_name(), "note", text); }

}  // namespace coolgas
