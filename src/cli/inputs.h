#pragma once
/// What every lpvid command reads: the data file (both as doubles and as
/// exact rationals, from the same text), the model, the data window, and the
/// common options of docs/design.md §11.2. Defaults live here, in one place (docs/design.md §13.7).

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "data/experiment.h"
#include "certify/certify.h"
#include "data/data_reference.h"
#include "lmi/bound_objective.h"
#include "model/load_problem.h"
#include "model/lpv_model.h"
#include "model/problem.h"
#include "solvers/sdp_solver.h"
#include "toeplitz/uncertainty_toeplitz.h"

namespace lpvid::cli {

/// One record of the command line: a --data file and the --rows window
/// that follows it (empty: all rows) and its --x0 (empty: the model's x0).
struct RecordOption {
  std::string path, rows_text, x0_text;
};

struct CommonOptions {
  std::string data_path, model_path;     ///< data_path: the first --data
  std::vector<std::string> data_paths;   ///< every --data, in order (several: several records)
  std::vector<std::string> rows_texts;   ///< every --rows, in order
  std::vector<std::string> x0_texts;     ///< every --x0, in order (each record's own initial state)
  std::string data_rows_order;           ///< 'd' per --data, 'r' per --rows, 'x' per --x0, in the order given
  std::vector<std::string> names;        ///< --names for headerless data files (every record)
  long row_begin = 0, row_end = -1;      ///< --rows B:E window (one record)
  std::string rows_text;                 ///< the --rows of one record
  std::string toeplitz = "signal";       ///< --toeplitz signal|paper
  std::string solver = "csdp";           ///< --solver
  std::string certificate_path;          ///< --certificate (default: <report stem>.cert.json or lpvid.cert.json)
  std::string report_path;               ///< --report
  std::string delta_text, dmax_text;     ///< --delta / --dmax as typed (exact)
  std::optional<double> lambda;          ///< --lambda
  long max_taps = CertifyOptions{}.max_taps;                    ///< --max-taps (Δ form; 0 = full horizon)
  bool dense_dual = false;                                      ///< --dense-dual
  std::string delta_norm = "toeplitz";   ///< --delta-norm toeplitz|kyp (how the certificate's Δ is solved for)
  std::string write_sdpa;                ///< --write-sdpa F.dat-s
  bool verbose = false;
  bool quiet = false;       ///< --quiet: no progress lines on stderr
  std::string command;      ///< the subcommand's name (progress lines)
};

/// --delta-norm as the enum of certify.h.
DeltaNorm delta_norm_of(const CommonOptions& o);


/// Registers the common options on a subcommand.
void add_common_options(CLI::App& app, CommonOptions& o, bool needs_bounds);

/// The model and the data (Problem: model_q, model_d, exp_q, exp_d, each
/// view read from the text), passed on as `const Problem&`, where each
/// record's rows came from (LoadedProblem::records: file, sha256, --names,
/// --rows, one per record in order, at least one), and the options read
/// beside them.
struct Inputs : LoadedProblem {
  ToeplitzMode mode = ToeplitzMode::kSignal;
  BoundObjective objective;
};

/// Registers --data and --rows, both repeatable, on `app`; after parsing,
/// `order` holds 'd' per --data and 'r' per --rows in the order given and
/// `then` (if set) runs.
void add_data_and_rows(CLI::App& app, std::vector<std::string>& paths, std::vector<std::string>& rows, std::string& order,
                       const std::string& data_help, const std::string& rows_help, std::function<void()> then = {});

/// Each --data with the --rows and --x0 after it (`order` as
/// add_data_and_rows records it, 'x' per --x0). One --data: its --rows and
/// --x0 anywhere (at most one each). `x0s` empty: the command's --x0 is not
/// per record (compare's model|fit) and its place is ignored. Throws InputError for a --rows or --x0
/// before the first --data or two of them for one --data.
std::vector<RecordOption> pair_data_and_rows(const std::vector<std::string>& paths, const std::vector<std::string>& rows,
                                             const std::string& order, const std::vector<std::string>& x0s = {});

/// The exact initial state of --x0 `text` ("V1,V2,..."), `nx` values;
/// throws InputError naming --x0 and the text otherwise.
Vec<Rational> parse_x0(const std::string& text, Eigen::Index nx);

/// The records of the command line: each --data with the --rows after it
/// (before the next --data). One --data: today's single window, its --rows
/// anywhere (pair_data_and_rows).
std::vector<RecordOption> data_records(const CommonOptions& o);

/// The certification options every command takes from the common options and
/// its inputs: objective, solver verbosity, --max-taps, --delta-norm, the data
/// reference and the fixed bounds' exact text.
CertifyOptions certify_options(const CommonOptions& o, const Inputs& in);

/// Reads and checks everything (throws InputError with file/line/field):
/// the output files can be written, then the model and the records
/// (model/load_problem.h), then the objective.
Inputs load_inputs(const CommonOptions& o);

/// Parses a row window "B:E" (0-based, E exclusive, 0 <= B < E) given to
/// option `flag` (--rows, --window, --test-rows, ...); throws InputError
/// naming the flag and the text otherwise.
std::pair<long, long> parse_row_range(const std::string& text, const std::string& flag);

/// The printed data line(s): the file and its --rows, or one line per record.
std::string data_lines(const CommonOptions& o, const Inputs& in);

/// Prints the options a command ran with (docs/design.md §13.7).
void print_options(const CommonOptions& o, const Inputs& in, const std::string& command);

/// The certificate path of diagnose: as named_certificate_path, else lpvid.cert.json.
std::string certificate_path(const CommonOptions& o);
/// The certificate file the user named: --certificate, or <report stem>.cert.json
/// when --report is given; "" when neither (then no certificate file is written).
std::string named_certificate_path(const CommonOptions& o);

/// `path` without the first of `extensions` it ends with ("a.cert.json" →
/// "a"); unchanged when it ends with none of them.
std::string stem_of(const std::string& path, const std::vector<std::string>& extensions);

/// The correction basis of --basis: each text parsed as a monomial of
/// `scheduling`; an unknown name or a function given twice is an InputError
/// naming --basis.
std::vector<Monomial> parse_basis(const std::vector<std::string>& texts, const std::vector<std::string>& scheduling);

}  // namespace lpvid::cli
