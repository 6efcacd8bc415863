#pragma once
/// Runs the real `lpvid` / `lpvid-verify` binaries of the build tree from a
/// test (exit code + captured output) in a private temporary directory.
/// A test using it skips itself when the binary has not been built.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

namespace lpvid::gen {

struct CliRunner : ::testing::Test {
  std::string exe = std::string(LPVID_BINARY_DIR) + "/lpvid";
  std::string verify_exe = std::string(LPVID_BINARY_DIR) + "/lpvid-verify";
  std::filesystem::path dir;

  void SetUp() override {
    if (!std::filesystem::exists(exe)) GTEST_SKIP() << exe << " not built";
    static int counter = 0;
    dir = std::filesystem::temp_directory_path() /
          ("lpvid_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(dir);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
  }
  /// Runs `program args`, output to out.txt; returns the exit code (-1 if killed).
  int run_program(const std::string& program, const std::string& args) {
    const int s = std::system((program + " " + args + " >" + (dir / "out.txt").string() + " 2>&1").c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  }
  /// `lpvid <subcommand> args`
  int run(const std::string& subcommand, const std::string& args) { return run_program(exe, subcommand + " " + args); }
  std::string output() const {
    std::ifstream in(dir / "out.txt");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  std::string file(const std::string& name) const { return (dir / name).string(); }
  /// Whole files, by path.
  static std::string read_text(const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  static void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }
  static nlohmann::json read_json(const std::string& path) { return nlohmann::json::parse(read_text(path)); }
};

}  // namespace lpvid::gen
