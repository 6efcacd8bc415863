#pragma once
/// The model file (docs/design.md §11.1, JSON, "format": "lpvid-model/1"), read into an
/// LpvModel<T> for T = double and T = Rational, and written back with exact
/// number text so that write → read gives exactly the same model.
///
/// ## Reading
///
/// Numbers may be JSON numbers or strings holding a decimal or `p/q`
/// ("0.1", "-1/3", "2.5e-3"). The Rational reader turns the *text* into an
/// exact rational (0.1 is 1/10); the double reader gives the nearest double of
/// the same text (json/json_number.h's number_from_json). Neither goes
/// through nlohmann's double. JSON numbers that overflow a double (1e400) are
/// a syntax error: write them as strings.
/// `//` and `/* */` comments are ignored, so docs/design.md §11.1's example reads as is.
///
/// Keys (unknown keys are rejected everywhere, with the list of allowed keys,
/// because a misspelt optional key would silently change the model):
///
///   format       required, "lpvid-model/1"
///   description  optional string, ignored (free text for people)
///   states       required integer, 0..kMaxModelDimension (0: static model)
///   inputs       required integer, 1..kMaxModelDimension
///   outputs      required integer, 1..kMaxModelDimension
///   scheduling   optional list of distinct names (default []: LTI). A name
///                starts with a letter or '_' and continues with letters,
///                digits or '_' (so that basis texts like rho1^2*rho2 parse).
///   columns      required {"u": [nu names], "y": [ny names],
///                "rho": [nρ names]}; "rho" defaults to the scheduling names.
///                A rho name "@x<i>", "@abs(x<i>-c)", "@sqrt(x<i>-c)", "@sqrtpos(x<i>-c)" or
///                "@hinge(x<i>-c)" is a function of the model's own state
///                (data/column_map.h, model/state_scheduling.h); it must
///                parse and name a state 1..nx.
///   initial      required object {A, B, C, D}; each a list of terms
///                {"basis": text, "value": matrix}; absent or [] is zero.
///                Sizes: A nx×nx, B nx×nu, C ny×nx, D ny×nu. A matrix is a
///                list of rows (a 0×c or r×0 matrix: [] or [[], …]).
///                Several terms may share a basis function (they add).
///   correction   optional {"basis": [texts], "A": [terms], "B": [terms]};
///                A_i/B_i terms must use a function listed in basis, at most
///                one term per function; absent ones are zero. Basis
///                functions must be distinct.
///   uncertainty  optional {"structure": "multiplicative"|"additive"|"general",
///                "weight": W > 0 (default 1; not allowed with general),
///                general only: "nz": integer >= 1 (optional if a term fixes
///                it), "C1": [terms] (nz×nx), "D1": [terms] (nz×nu)}.
///                Default: multiplicative with weight 1.
///   offset       optional {"basis": [distinct texts], "values": [ny-vectors,
///                one per basis function]}; without values, φ_j are unknown.
///   state_offset optional {"basis": [distinct texts], "values": [nx-vectors,
///                one per basis function]} (values required): the affine term
///                E(ρ) = Σ_j h_j(ρ) e_j of x_{k+1} = A(ρ)x + B(ρ)u' + E(ρ)
///                (with a column "@sqrt(x1-c)" a term
///                ρ·e is the outflow e·√|x1 − c|). Absent: no term. Toeplitz
///                mode "paper" refuses a model with it.
///   x0           optional list of nx numbers (default zero).
///   sample_time  optional positive number: seconds between samples.
///   units        optional object {column name: unit text}; each key one of
///                the columns above. Both are descriptive (data/signal_info.h):
///                plots and reports use them, no bound depends on them.
///
/// Errors: InputError "file:line: json.path: reason", e.g.
/// `model.json:9: initial.A[1].value: expected 2x2 matrix, got 2x3`.
///
/// ## Writing
///
/// Numbers are written by json/json_number.h (number_to_json): rational
/// numbers as JSON integers when they are integers that fit in 64 bits,
/// otherwise as strings: a terminating decimal ("-0.3") when the denominator
/// is 2^a·5^b with at most 40 decimals, else "p/q". Doubles as JSON numbers in
/// the shortest text that reads back as the same double. Only non-zero
/// correction A_i/B_i are written; x0 only when non-zero; state_offset only
/// when it has a basis.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/scalar.h"
#include "json/json_tree.h"
#include "model/lpv_model.h"

namespace lpvid {

/// The format string (docs/design.md §11.1).
inline constexpr const char* kModelFormat = "lpvid-model/1";

/// Largest states/inputs/outputs/nz accepted (guards against a corrupted size
/// allocating gigabytes; an SDP-based identification is far below it).
constexpr int kMaxModelDimension = 1000;

/// Reads and checks a model file (see above). T = double or Rational.
template <typename T>
LpvModel<T> read_model_file(const std::string& path);

/// Same as read_model_file for text in memory; `name` is used in messages.
template <typename T>
LpvModel<T> parse_model_json(std::string_view text, const std::string& name);

/// The model held by an already parsed JSON object (e.g. the "model" member of
/// a certificate). `path` is the JSON path of `node` for messages ("" at the
/// top level, "model" inside a certificate).
template <typename T>
LpvModel<T> model_from_json(const JsonNode& node, const std::string& file, const std::string& path = "");

/// The model as JSON (the object written by write_model_json).
/// Throws std::invalid_argument for a model that cannot be written
/// (inconsistent sizes, non-finite double, weight != 1 with general).
nlohmann::ordered_json model_to_json(const LpvModel<Rational>& model);
nlohmann::ordered_json model_to_json(const LpvModel<double>& model);

/// Model file text (pretty printed, newline at the end).
std::string write_model_json(const LpvModel<Rational>& model);
std::string write_model_json(const LpvModel<double>& model);

/// Writes write_model_json(model) to `path`; throws InputError if the file
/// cannot be written.
void write_model_file(const std::string& path, const LpvModel<Rational>& model);
void write_model_file(const std::string& path, const LpvModel<double>& model);

extern template LpvModel<double> read_model_file<double>(const std::string&);
extern template LpvModel<Rational> read_model_file<Rational>(const std::string&);
extern template LpvModel<double> parse_model_json<double>(std::string_view, const std::string&);
extern template LpvModel<Rational> parse_model_json<Rational>(std::string_view, const std::string&);
extern template LpvModel<double> model_from_json<double>(const JsonNode&, const std::string&, const std::string&);
extern template LpvModel<Rational> model_from_json<Rational>(const JsonNode&, const std::string&,
                                                             const std::string&);

}  // namespace lpvid
