#pragma once
/// Where the progress lines of a long command go ("[diagnose   4.0 s] …"):
/// standard error by default, or a sink the embedding program installs (the
/// Python module hands them to the caller's thread, which logs them). One
/// call is one whole line, so lines written from several threads never mix.

#include <functional>
#include <string>

namespace lpvid {

/// Writes one progress line (without its newline) to the sink.
void progress_line(const std::string& line);

/// Formats like printf and writes the result as one progress line.
[[gnu::format(printf, 1, 2)]] void progress_printf(const char* format, ...);

/// Installs `sink` for every later progress line (an empty function: back to
/// standard error). Calls to the sink are serialised.
void set_progress_sink(std::function<void(const std::string&)> sink);

}  // namespace lpvid
