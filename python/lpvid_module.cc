// The extension module lpvid._lpvid: the two command lines, run in-process
// (run_lpvid: output to the process's stdout and stderr; run_lpvid_captured:
// output returned as text, progress lines through take_progress).
// The Python package (python/lpvid/) writes the input files, builds the
// arguments and reads the reports; this file only runs the programs' code.
#include <cstdio>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "cli/command_line.h"
#include "core/progress_sink.h"
#include "core/stop_request.h"
#include "plot/gnuplot.h"
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

/// The progress lines of the running call (core/progress_sink.h), waiting
/// for the caller's thread to take them (take_progress): the lines reach
/// Python's logging in that thread, in order, each once, and never through
/// the process's file descriptors.
struct ProgressQueue {
  std::mutex mutex;
  std::vector<std::string> lines;
};

ProgressQueue& progress_queue() {
  static ProgressQueue q;
  return q;
}

/// For one run: std::cout and std::cerr written into strings, and the
/// progress lines into the queue; both restored when the run ends.
class RunCapture {
 public:
  RunCapture() : out_before_(std::cout.rdbuf(out.rdbuf())), err_before_(std::cerr.rdbuf(err.rdbuf())) {
    lpvid::set_progress_sink([](const std::string& line) {
      ProgressQueue& q = progress_queue();
      const std::lock_guard<std::mutex> lock(q.mutex);
      q.lines.push_back(line);
    });
  }
  ~RunCapture() {
    lpvid::set_progress_sink({});
    std::cout.rdbuf(out_before_);
    std::cerr.rdbuf(err_before_);
  }
  RunCapture(const RunCapture&) = delete;
  RunCapture& operator=(const RunCapture&) = delete;
  std::ostringstream out, err;

 private:
  std::streambuf* out_before_;
  std::streambuf* err_before_;
};

template <class Run>
py::tuple run_captured(Run run) {
  int code = 0;
  std::string out, err;
  {
    py::gil_scoped_release released;
    std::lock_guard<std::mutex> lock(run_mutex());
    RunCapture capture;
    code = run();
    out = capture.out.str();
    err = capture.err.str();
  }
  return py::make_tuple(code, out, err);
}

py::list take_progress() {
  std::vector<std::string> lines;
  {
    ProgressQueue& q = progress_queue();
    const std::lock_guard<std::mutex> lock(q.mutex);
    lines.swap(q.lines);
  }
  py::list out;
  for (const std::string& line : lines) out.append(py::str(line));
  return out;
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
  m.def(
      "run_lpvid_captured",
      [](const std::vector<std::string>& args) { return run_captured([&] { return lpvid::cli::run_lpvid(args); }); },
      py::arg("args"),
      "Runs `lpvid args...` in this process; returns (exit code, stdout text, stderr text). Progress lines wait "
      "in a queue for take_progress(); nothing is written to the process's stdout or stderr.");
  m.def(
      "run_lpvid_verify_captured",
      [](const std::vector<std::string>& args) { return run_captured([&] { return lpvid::run_lpvid_verify(args); }); },
      py::arg("args"), "Runs `lpvid-verify args...` as run_lpvid_captured does.");
  m.def("set_png_drawing", &lpvid::set_png_drawing, py::arg("on"),
        "Whether the commands' --plots draw PNG files with gnuplot (default) or write only the figure "
        "descriptions (.plot.json) that lpvid.plots draws from.");
  m.def("take_progress", &take_progress,
        "The progress lines of the running captured call written since the last take_progress(), in order.");
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
