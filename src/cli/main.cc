// lpvid: robust identification and invalidation of LPV systems (docs/design.md §11.2).
// The command line itself is cli/command_line.h (the Python module runs it
// in-process); only the interrupt handler belongs to the program.
#include <string>
#include <vector>

#include "cli/blas_kernel.h"
#include "cli/command_line.h"
#include "core/file_io.h"

int main(int argc, char** argv) {
  if (argc >= 1) lpvid::cli::pin_blas_kernel(argv);  // first: it may start the program again (cli/blas_kernel.h)
  lpvid::remove_outputs_on_interrupt("lpvid");  // before any thread: Ctrl-C leaves nothing half-done
  lpvid::end_run_after_deadline("lpvid");       // --timeout's backstop (idle until a deadline is set)
  if (argc < 1) return lpvid::cli::run_lpvid({});
  return lpvid::cli::run_lpvid(std::vector<std::string>(argv + 1, argv + argc), argv[0]);
}
