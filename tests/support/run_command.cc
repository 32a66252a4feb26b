#include "tests/support/run_command.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>
#include <stdexcept>

namespace coolgas::test {

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

CommandResult run_command(const std::string& command) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() / ("coolgas-test-" + std::to_string(::getpid()));
  // Every test process made one of these and left it behind, empty; the
  // guard removes it when the process ends (a killed test may still leave it).
  struct RemoveAtExit {
    std::filesystem::path dir;
    ~RemoveAtExit() {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  };
  static const RemoveAtExit guard{dir};
  std::filesystem::create_directories(dir);
  const std::string base = (dir / std::to_string(counter++)).string();
  const std::string full = "(" + command + ") >" + base + ".out 2>" + base + ".err";
  const int status = std::system(full.c_str());
  CommandResult r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) r.exit_code = 128 + WTERMSIG(status);
  r.out = read_text(base + ".out");
  r.err = read_text(base + ".err");
  std::filesystem::remove(base + ".out");
  std::filesystem::remove(base + ".err");
  return r;
}

std::string bin(const std::string& program) { return std::string(COOLGAS_BIN_DIR) + "/" + program; }

std::string source(const std::string& relative) { return std::string(COOLGAS_SOURCE_DIR) + "/" + relative; }

std::string scratch_dir(const std::string& name) {
  // ctest runs every test case as its own process, in parallel: a folder per
  // test case keeps them from wiping each other's files.
  // Fixtures set up outside any test case get a folder per process, removed at exit.
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const bool in_test = info != nullptr;
  const std::string test = in_test ? std::string(info->test_suite_name()) + "." + info->name()
                                   : "setup-" + std::to_string(::getpid());
  const auto dir = std::filesystem::current_path() / "test-scratch" / name / test;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  if (!in_test) {
    static std::vector<std::filesystem::path> setup_dirs;
    if (setup_dirs.empty()) std::atexit([] {
        for (const auto& d : setup_dirs) std::filesystem::remove_all(d);
      });
    setup_dirs.push_back(dir);
  }
  return dir.string();
}

int line_count(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  if (!s.empty() && s.back() != '\n') ++n;
  return n;
}

}  // namespace coolgas::test
