// The extension module lpvid._lpvid: the two command lines, run in-process.
// The Python package (python/lpvid/) writes the input files, builds the
// arguments and reads the reports; this file only runs the programs' code.
#include <cstdio>
#include <iostream>
#include <mutex>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "cli/command_line.h"
#include "verify/verify_command_line.h"

namespace py = pybind11;

namespace {

// The input limits and the record of a run's outputs are per process: two
// runs at once (from two Python threads) would share them, so one at a time.
std::mutex& run_mutex() {
  static std::mutex m;
  return m;
}

template <class Run>
int run_exclusively(Run run) {
  int code = 0;
  {
    py::gil_scoped_release released;  // minutes of solving need not hold the interpreter
    std::lock_guard<std::mutex> lock(run_mutex());
    code = run();
    // The caller may be reading what was written to stdout/stderr as soon as
    // the call returns (it redirects them to capture the messages).
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
  }
  return code;
}

}  // namespace

PYBIND11_MODULE(_lpvid, m) {
  m.doc() = "lpvid's command lines, run in-process (the Python package lpvid wraps them)";
  m.def(
      "run_lpvid",
      [](const std::vector<std::string>& args) { return run_exclusively([&] { return lpvid::cli::run_lpvid(args); }); },
      py::arg("args"),
      "Runs `lpvid args...` in this process and returns its exit code (README \"Exit codes\"); messages go to the "
      "process's stdout and stderr.");
  m.def(
      "run_lpvid_verify",
      [](const std::vector<std::string>& args) { return run_exclusively([&] { return lpvid::run_lpvid_verify(args); }); },
      py::arg("args"), "Runs `lpvid-verify args...` in this process and returns its exit code.");
  m.def("version", [] { return std::string(LPVID_VERSION); }, "the version of lpvid this module was built from");
}
