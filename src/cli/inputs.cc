#include "cli/inputs.h"

#include "core/file_io.h"
#include "core/progress_sink.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <tuple>
#include <iostream>
#include <map>

#include "core/input_error.h"
#include "core/number_text.h"
#include "solvers/solver_factory.h"
#include "cli/help_text.h"

namespace lpvid::cli {

DeltaNorm delta_norm_of(const CommonOptions& o) {
  return o.delta_norm == "kyp" ? DeltaNorm::kKyp : DeltaNorm::kToeplitz;
}

void add_common_options(CLI::App& app, CommonOptions& o, bool needs_bounds) {
  add_data_and_rows(app, o.data_paths, o.rows_texts, o.data_rows_order,
                    "data file (CSV with header, or whitespace columns with --names); repeat for several records of one "
                    "system (one Delta, one noise bound for all; each --data followed by its own --rows)",
                    "window of data rows B:E (0-based, E exclusive) of the --data before it; default all", [&o] {
                      o.data_path = o.data_paths.empty() ? std::string() : o.data_paths.front();
                      if (o.data_paths.size() == 1 && o.rows_texts.size() == 1) o.rows_text = o.rows_texts.front();
                    });
  app.add_option("--x0", o.x0_texts,
                 "initial state V1,V2,... (exact numbers, one per state) of the --data before it (one --data: anywhere); "
                 "default the model's x0")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--model", o.model_path, "model file (lpvid-model/1 JSON)")->required();
  app.add_option("--names", o.names, "column names for a headerless whitespace data file (every record)")->delimiter(',');
  app.add_option("--toeplitz", o.toeplitz, "T_z mode: signal (default: T_z from the simulated z) or paper (T_G12 T_u)")
      ->check(CLI::IsMember({"signal", "paper"}));
  std::vector<std::string> solvers = available_solvers();
  solvers.push_back("csdp-command");
  app.add_option("--solver", o.solver, "SDP backend: csdp (default), sdpa, or csdp-command (the csdp program via an SDPA file)")
      ->check(CLI::IsMember(solvers));
  app.add_option("--write-sdpa", o.write_sdpa,
                 "write SDPA sparse files with a JSON sidecar F.json (scalings, variable meanings): for invalidate the "
                 "Theorem 2.1 program (solve it outside, then 'lpvid certify --solution'); for the other commands each SDP "
                 "solved (F.<k>.dat-s, the last one also to F)");
  app.add_option("--certificate", o.certificate_path, "where to write the certificate (JSON)");
  app.add_option("--report", o.report_path, "where to write the report (JSON)");
  app.add_option("--max-taps", o.max_taps,
                 "taps of the FIR Delta for --delta-norm kyp and for the SDP backends when the structured full-horizon solver "
                 "is not used (0: full horizon; default 64)")
      ->check(CLI::Range(0L, 100000L));
  app.add_option("--delta-norm", o.delta_norm,
                 "certificate's Delta solve: toeplitz (the (C1') block, exact for the horizon; default) or kyp "
                 "(||Delta||_inf by the KYP lemma: blocks independent of n, fast for long records; needs --max-taps > 0)")
      ->check(CLI::IsMember({"toeplitz", "kyp"}));
  app.add_flag("--dense-dual", o.dense_dual,
               "write lower-end and invalidation certificates with the full dual matrix Y1 (form dual_delta, quadratic "
               "in n) instead of the compact form the verifier rebuilds (dual_delta_path, linear in n)");
  app.add_flag("--verbose", o.verbose, "let the SDP backend print its iterations");
  app.add_flag("--quiet", o.quiet, "no progress lines on stderr (errors are still printed)");
  o.command = app.get_name();
  if (needs_bounds) {
    auto* d = app.add_option("--delta", o.delta_text, "fix delta (exact decimal); minimise dmax");
    auto* m = app.add_option("--dmax", o.dmax_text, "fix dmax (RMS noise bound, exact decimal); minimise delta");
    auto* l = app.add_option("--lambda", o.lambda, with_default("minimise lambda*delta^2 + (1-lambda)*dmax^2", BoundObjective{}.lambda));
    l->excludes(d)->excludes(m);
  }
}

namespace {

BoundObjective make_objective(const CommonOptions& o) {
  BoundObjective b;
  auto read = [](const std::string& text, const char* flag) {
    if (auto e = number_text_problem(text)) throw InputError(std::string(flag) + ": " + *e);
    return ExactBound::from_text(text);
  };
  const bool fd = !o.delta_text.empty(), fm = !o.dmax_text.empty();
  if (fd && fm) {
    b.kind = BoundObjective::Kind::kFeasibility;
    b.delta = read(o.delta_text, "--delta");
    b.dmax = read(o.dmax_text, "--dmax");
  } else if (fd) {
    b.kind = BoundObjective::Kind::kMinDmax;
    b.delta = read(o.delta_text, "--delta");
  } else if (fm) {
    b.kind = BoundObjective::Kind::kMinDelta;
    b.dmax = read(o.dmax_text, "--dmax");
  } else {
    b.kind = BoundObjective::Kind::kWeighted;
    b.lambda = o.lambda.value_or(b.lambda);  // BoundObjective's default
  }
  b.validate();
  return b;
}

}  // namespace

std::pair<long, long> parse_row_range(const std::string& text, const std::string& flag) {
  const size_t colon = text.find(':');
  long b = 0, e = 0;
  const auto whole_integer = [&](size_t from, size_t to, long* out) {
    const char* first = text.data() + from;
    const char* last = text.data() + to;
    const auto [ptr, ec] = std::from_chars(first, last, *out);
    return from < to && ec == std::errc() && ptr == last;
  };
  if (colon == std::string::npos || !whole_integer(0, colon, &b) || !whole_integer(colon + 1, text.size(), &e))
    throw InputError(flag + ": expected B:E (two integers, 0-based rows, E exclusive), got '" + text + "'");
  if (b < 0 || e <= b) throw InputError(flag + ": need 0 <= B < E, got '" + text + "'");
  return {b, e};
}

void add_data_and_rows(CLI::App& app, std::vector<std::string>& paths, std::vector<std::string>& rows, std::string& order,
                       const std::string& data_help, const std::string& rows_help, std::function<void()> then) {
  app.add_option("--data", paths, data_help)->required()->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--rows", rows, rows_help)->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.parse_complete_callback([&app, &order, then] {  // the order of --data, --rows and --x0 pairs them
    order.clear();
    for (const CLI::Option* opt : app.parse_order()) {
      if (opt->check_name("--data")) order += 'd';
      if (opt->check_name("--rows")) order += 'r';
      if (opt->check_name("--x0")) order += 'x';
    }
    if (then) then();
  });
}

namespace {

/// `texts` given at most once (one --data): its only entry, or "".
std::string at_most_once(const std::vector<std::string>& texts, const char* flag) {
  if (texts.size() > 1)
    throw InputError(std::string(flag) + " is given " + std::to_string(texts.size()) + " times for one --data (one per --data)");
  return texts.empty() ? std::string() : texts.front();
}

}  // namespace

std::vector<RecordOption> pair_data_and_rows(const std::vector<std::string>& paths, const std::vector<std::string>& rows,
                                             const std::string& order, const std::vector<std::string>& x0s) {
  if (paths.size() <= 1)
    return {{paths.empty() ? std::string() : paths.front(), at_most_once(rows, "--rows"), at_most_once(x0s, "--x0")}};
  std::vector<RecordOption> out;
  size_t d = 0, r = 0, x = 0;
  for (const char c : order) {
    if (c == 'x' && x0s.empty()) continue;  // this command's --x0 is not per record (compare: model|fit)
    if (c == 'd') {
      out.push_back({paths.at(d++), "", ""});
      continue;
    }
    const std::string flag = c == 'r' ? "--rows" : "--x0";
    const std::string& text = c == 'r' ? rows.at(r++) : x0s.at(x++);
    if (out.empty())
      throw InputError(flag + " " + text + ": given before the first --data (a " + flag + " belongs to the --data before it)");
    std::string& slot = c == 'r' ? out.back().rows_text : out.back().x0_text;
    if (!slot.empty())
      throw InputError(flag + " " + text + ": " + out.back().path + " has a " + flag + " already (" + slot +
                       "); give each --data at most one " + flag + ", after it");
    slot = text;
  }
  return out;
}

Vec<Rational> parse_x0(const std::string& text, Eigen::Index nx) {
  std::vector<std::string> parts(1);
  for (const char ch : text) {
    if (ch == ',') parts.emplace_back();
    else if (ch != ' ') parts.back() += ch;
  }
  if (static_cast<Eigen::Index>(parts.size()) != nx)
    throw InputError("--x0 " + text + ": " + std::to_string(parts.size()) + " value(s), the model has " + std::to_string(nx) +
                     " state(s) (give V1,V2,... one exact number per state)");
  Vec<Rational> x0(nx);
  for (Eigen::Index i = 0; i < nx; ++i) {
    const std::string& part = parts[static_cast<size_t>(i)];
    if (auto why = number_text_problem(part)) throw InputError("--x0 " + text + ": value " + std::to_string(i + 1) + " '" + part + "': " + *why);
    x0(i) = rational_from_text(part);
  }
  return x0;
}

std::vector<RecordOption> data_records(const CommonOptions& o) {
  if (o.data_paths.empty()) return {{o.data_path, o.rows_text, ""}};  // options set in code (one record)
  return pair_data_and_rows(o.data_paths, o.rows_texts, o.data_rows_order, o.x0_texts);
}

namespace {

/// The records of the command line as the loader takes them: each --rows
/// parsed here (InputError naming --rows), each --x0 read once the model's
/// number of states is known.
std::vector<RecordRequest> record_requests(const std::vector<RecordOption>& wanted) {
  std::vector<RecordRequest> out;
  for (const RecordOption& r : wanted) {
    RecordRequest q{r.path, std::nullopt, "--rows " + r.rows_text, {}};
    if (!r.rows_text.empty()) q.rows = parse_row_range(r.rows_text, "--rows");
    if (!r.x0_text.empty()) q.x0 = [text = r.x0_text](Eigen::Index nx) { return parse_x0(text, nx); };
    out.push_back(q);
  }
  return out;
}

}  // namespace

Inputs load_inputs(const CommonOptions& o) {
  // outputs first: a run that cannot write its report fails now, not at its end
  check_output_file(o.report_path, "report");
  check_output_file(o.certificate_path, "certificate");
  check_output_file(o.write_sdpa, "SDPA program");
  const std::vector<RecordOption> wanted = data_records(o);
  const std::optional<std::vector<std::string>> names =
      o.names.empty() ? std::nullopt : std::optional<std::vector<std::string>>(o.names);
  Inputs in;
  static_cast<LoadedProblem&>(in) = load_problem(o.model_path, record_requests(wanted), names, bytes_on_disk());
  if (!o.rows_text.empty() && wanted.size() == 1) {
    CommonOptions& mo = const_cast<CommonOptions&>(o);
    std::tie(mo.row_begin, mo.row_end) = parse_row_range(o.rows_text, "--rows");
  }
  in.mode = toeplitz_mode_from_string(o.toeplitz);
  in.objective = make_objective(o);
  return in;
}

std::string data_lines(const CommonOptions& o, const Inputs& in) {
  if (in.records.size() <= 1) return "  data        " + o.data_path + (o.rows_text.empty() ? "" : " rows " + o.rows_text) + "\n";
  std::string s;
  for (size_t k = 0; k < in.records.size(); ++k) {
    const DataReference& r = in.records[k];
    s += (k == 0 ? "  records     " : "              ") + r.file +
         (r.row_end >= 0 ? " rows " + std::to_string(r.row_begin) + ":" + std::to_string(r.row_end) : "") +
         " (n = " + std::to_string(in.exp_q.records.at(k)) + ")\n";
  }
  return s + "              one Delta and one noise bound for all " + std::to_string(in.records.size()) + " records\n";
}

void print_options(const CommonOptions& o, const Inputs& in, const std::string& command) {
  std::cout << "lpvid " << command << "\n" << data_lines(o, in);
  std::cout << "  model       " << o.model_path << "\n"
            << "  objective   " << in.objective.describe() << "\n"
            << "  toeplitz    " << o.toeplitz << "\n"
            << "  solver      " << o.solver << "\n"
            << "  noise       dmax is the RMS bound: ||d||_2 <= dmax*sqrt(n*ny)"
            << (in.records.size() > 1 ? ", n = all samples of all records" : "") << "\n";
}

CertifyOptions certify_options(const CommonOptions& c, const Inputs& in) {
  CertifyOptions co;
  co.objective = in.objective;
  co.records = in.records;
  co.solver.verbose = c.verbose;
  co.max_taps = c.max_taps;
  co.dense_dual = c.dense_dual;
  if (!c.quiet) {
    const auto started = std::chrono::steady_clock::now();
    co.progress = [started, name = c.command](const std::string& stage) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      progress_printf("[%s %6.1f s] %s", name.c_str(), s, stage.c_str());
    };
  }
  co.delta_norm = delta_norm_of(c);
  return co;
}

std::string certificate_path(const CommonOptions& o) {
  if (!o.certificate_path.empty()) return o.certificate_path;
  if (!o.report_path.empty()) {
    std::string p = o.report_path;
    const size_t dot = p.rfind(".json");
    if (dot != std::string::npos) p = p.substr(0, dot);
    return p + ".cert.json";
  }
  return "lpvid.cert.json";
}

std::string named_certificate_path(const CommonOptions& o) {
  return o.certificate_path.empty() && o.report_path.empty() ? "" : certificate_path(o);
}

std::string stem_of(const std::string& path, const std::vector<std::string>& extensions) {
  for (const std::string& e : extensions)
    if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0)
      return path.substr(0, path.size() - e.size());
  return path;
}

std::vector<Monomial> parse_basis(const std::vector<std::string>& texts, const std::vector<std::string>& scheduling) {
  std::vector<Monomial> basis;
  for (const std::string& t : texts) {
    Monomial f;
    try {
      f = parse_monomial(t, scheduling);
    } catch (const InputError& e) {
      throw InputError(std::string("--basis: ") + e.what());
    }
    if (std::find(basis.begin(), basis.end(), f) != basis.end()) throw InputError("--basis: '" + t + "' appears twice");
    basis.push_back(f);
  }
  return basis;
}

}  // namespace lpvid::cli
