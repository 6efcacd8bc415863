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
#include "core/stop_request.h"
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

/// The options of both command lines as {command path: [option dict]}.
py::dict command_options() {
  lpvid::OptionTable table = lpvid::cli::lpvid_option_table();
  table.merge(lpvid::lpvid_verify_option_table());
  py::dict out;
  for (const auto& [path, options] : table) {
    py::list list;
    for (const lpvid::OptionInfo& o : options) {
      py::dict d;
      d["name"] = o.names.empty() ? std::string() : o.names.front();
      d["names"] = o.names;
      d["flag"] = o.flag;
      d["multi"] = o.multi;
      d["required"] = o.required;
      d["positional"] = o.positional;
      d["help"] = o.help;
      list.append(std::move(d));
    }
    out[py::str(path)] = std::move(list);
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_lpvid, m) {
  m.doc() = "lpvid's command lines, run in-process (the Python package lpvid wraps them)";
  m.def(
      "run_lpvid",
      [](const std::vector<std::string>& args) { return run_exclusively([&] { return lpvid::cli::run_lpvid(args); }); },
      py::arg("args"),
      "Runs `lpvid args...` in this process and returns its exit code (docs/exit_codes.md); messages go to the "
      "process's stdout and stderr.");
  m.def(
      "run_lpvid_verify",
      [](const std::vector<std::string>& args) { return run_exclusively([&] { return lpvid::run_lpvid_verify(args); }); },
      py::arg("args"), "Runs `lpvid-verify args...` in this process and returns its exit code.");
  // The cooperative Ctrl-C: the running call releases the GIL, so another
  // Python thread (or a signal handler on the main thread) may ask it to stop.
  // None of these takes the GIL's place or run_mutex: they only touch one atomic flag.
  m.def("request_stop", &lpvid::request_stop, py::call_guard<py::gil_scoped_release>(),
        "Asks the running call to stop at its next check (well within a second): it returns exit code 130 "
        "(interrupted) with its outputs removed. The flag stays set until clear_stop(): calls made while it is set "
        "stop at once.");
  m.def("clear_stop", &lpvid::clear_stop, "Withdraws a stop request, so that the next call runs normally.");
  m.def("stop_requested", &lpvid::stop_requested, "Whether a stop was requested and not withdrawn.");
  m.def("command_options", &command_options,
        "The options of every command, read from the command lines themselves: {command path: [{name, names, flag, "
        "multi, required, positional, help}]}. Paths: \"\" lpvid's top-level options (--timeout, the input limits), "
        "\"invalidate\", \"jobs plan\", ..., \"lpvid-verify\" the verifier's top-level options, \"lpvid-verify "
        "certificate\", \"lpvid-verify psd\". Names are long names without dashes; --help and --version are left out.");
  m.def("version", [] { return std::string(LPVID_VERSION); }, "the version of lpvid this module was built from");
}
