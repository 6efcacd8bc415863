#pragma once
/// Reading and writing files: one place for the rules every command
/// follows, so that hostile or mistaken input is handled the same way everywhere.
///  - Inputs are regular files (not /dev/zero, a FIFO or a directory) no
///    larger than input_limits().max_file_bytes: otherwise InputError (exit 2).
///  - A file that exists but cannot be opened or read, and an output that
///    cannot be written, is an IoError (exit 6, distinct from bad input and
///    from solver failure).
///  - Outputs are written to a temporary name in the same directory and
///    renamed into place, so a reader never sees half a file; every output
///    of the run is recorded, and discard_outputs_of_this_run() removes them
///    when a later step fails ("nothing left behind").

#include <stdexcept>
#include <string>

namespace lpvid {

/// An input/output failure of the operating system (open, read, write, rename).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The whole content of the regular file `path` (binary).
std::string read_text_file(const std::string& path);

/// Writes `text` to `path` atomically (temporary file + rename) and records
/// `path` as an output of this run. `what` names the file in messages
/// ("report", "certificate", ...). Throws IoError.
void write_text_file(const std::string& path, const std::string& text, const std::string& what);

/// Removes every file written by write_text_file in this process (used when
/// a command fails after some outputs were written). Returns how many.
int discard_outputs_of_this_run();

/// Forgets the recorded outputs (they stay on disk): a command that
/// succeeded, or a test that runs several commands in one process.
void keep_outputs_of_this_run();

/// Before any work: throws IoError (exit 6) unless `path` can be written —
/// its directory exists, is a directory and is writable, and `path` is not
/// a directory. Empty path: nothing to check. A run that would fail at its
/// end after minutes fails at once instead.
void check_output_file(const std::string& path, const std::string& what);

/// The same for an output directory that the run creates if needed: it is a
/// writable directory, or it does not exist and its parent is one.
void check_output_directory(const std::string& dir, const std::string& what);

/// On SIGINT, SIGTERM or SIGHUP: remove every output this run wrote (and a
/// temporary being written), say so on stderr and exit with 130
/// (kExitInterrupted). Call once, at the start of main(): the handler only
/// writes the signal to a pipe; a dedicated thread reads it and does the
/// clean-up in ordinary code (not in a signal handler).
void remove_outputs_on_interrupt(const char* program);

/// The backstop of the user's --timeout (core/deadline.h): the long loops
/// stop themselves at their next check (exit 124, outputs removed, by the
/// command line's ordinary error path); a step that runs on without a check
/// (an exact check of a large certificate) is ended by a thread started here,
/// kDeadlineGraceSeconds + kDeadlineGraceShare × the timeout after the
/// deadline, with the same clean-up as an interrupt and exit code
/// kExitTimedOut. Call once, at the start of main() (it acts only once a
/// deadline is set). Not in the Python module, which must not end its process.
void end_run_after_deadline(const char* program);
constexpr double kDeadlineGraceSeconds = 2.0;
constexpr double kDeadlineGraceShare = 0.05;

}  // namespace lpvid
