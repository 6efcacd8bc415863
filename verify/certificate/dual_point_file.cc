#include "verify/certificate/dual_point_file.h"

#include <algorithm>

#include "core/input_error.h"
#include "json/json_members.h"
#include "json/json_number.h"

namespace lpvid {
namespace {

/// Form "dual_delta_path": the recipe Y1 is rebuilt from (verify/certificate/path_dual.h).
void parse_path_recipe(const JsonNode& dual, const std::string& file, const std::string& where, Eigen::Index cols,
                       DualPoint& d) {
  PathDualRecipe& p = d.path;
  const JsonNode& taps = member(dual, "taps", file, where);
  p.taps = matrix_member(taps, file, where + ".taps", cols);
  if (p.taps.rows() != d.horizon)
    throw_input_error(file, taps.line, where + ".taps", "expected " + std::to_string(d.horizon) + " rows (the horizon)");
  const auto positive = [&](const char* key, Rational& out, bool strictly) {
    const JsonNode& n = member(dual, key, file, where);
    out = number_from_json<Rational>(n, file, where + "." + key);
    if (strictly ? !(out > 0) : out < 0)
      throw_input_error(file, n.line, where + "." + key, strictly ? "must be > 0" : "must be >= 0");
  };
  positive("t", p.t, true);
  positive("mu", p.mu, true);
  positive("x", p.x, true);
  positive("u_floor", p.floor, false);
  const JsonNode& e = member(dual, "u_exponent", file, where);
  const Rational ev = number_from_json<Rational>(e, file, where + ".u_exponent");
  if (mpz_cmp_ui(mpq_denref(ev.mpq()), 1) != 0 || ev < Rational(-4000) || ev > Rational(4000))
    throw_input_error(file, e.line, where + ".u_exponent", "must be an integer in [-4000, 4000]");
  p.u_exponent = mpz_get_si(mpq_numref(ev.mpq()));
}

/// Form "dual_delta": Y1 as upper-triangle rows, row i holds columns i … P−1.
void parse_dense_y1(const JsonNode& dual, const std::string& file, const std::string& where, Eigen::Index ny,
                    Eigen::Index nz, DualPoint& d) {
  const JsonNode& y1 = member(dual, "Y1", file, where);
  const long P = d.horizon * static_cast<long>(ny + nz);
  if (!y1.is_array() || static_cast<long>(y1.items.size()) != P)
    throw_input_error(file, y1.line, where + ".Y1", "expected " + std::to_string(P) + " upper-triangle rows (horizon*(ny+nz))");
  d.Y1 = Mat<Rational>(P, P);
  for (long i = 0; i < P; ++i) {
    const JsonNode& row = y1.items[static_cast<size_t>(i)];
    const std::string rp = where + ".Y1[" + std::to_string(i) + "]";
    if (!row.is_array() || static_cast<long>(row.items.size()) != P - i)
      throw_input_error(file, row.line, rp, "expected " + std::to_string(P - i) + " numbers (columns i..P-1)");
    for (long j = i; j < P; ++j) {
      const Rational v = number_from_json<Rational>(row.items[static_cast<size_t>(j - i)], file, rp + "[" + std::to_string(j - i) + "]");
      d.Y1(i, j) = v;
      d.Y1(j, i) = v;
    }
  }
}

}  // namespace

DualPoint parse_dual_point_object(const JsonNode& dual, const std::string& file, const std::string& where, Eigen::Index ny,
                                  Eigen::Index nz, CertificateForm form, const std::vector<std::string>& extra_keys) {
  if (!dual.is_object()) throw_input_error(file, dual.line, where, "expected an object");
  const bool path = form == CertificateForm::kDualDeltaPath;
  for (const auto& [key, value] : dual.members) {
    const bool common = key == "horizon" || key == "sigma" || key == "g";
    const bool own = path ? (key == "taps" || key == "t" || key == "mu" || key == "u_exponent" || key == "x" || key == "u_floor")
                          : key == "Y1";
    const bool extra = std::find(extra_keys.begin(), extra_keys.end(), key) != extra_keys.end();
    if (!common && !own && !extra)
      throw_input_error(file, value.line, where + "." + key,
                        std::string("unknown key for form \"") + (path ? "dual_delta_path" : "dual_delta") + "\"");
  }
  DualPoint d;
  const JsonNode& horizon = member(dual, "horizon", file, where);
  d.horizon = integer_member(horizon, file, where + ".horizon");
  if (d.horizon < 1) throw_input_error(file, horizon.line, where + ".horizon", "must be at least 1");
  d.sigma = number_from_json<Rational>(member(dual, "sigma", file, where), file, where + ".sigma");
  d.g = matrix_member(member(dual, "g", file, where), file, where + ".g", ny);
  if (path) parse_path_recipe(dual, file, where, ny * nz, d);
  else parse_dense_y1(dual, file, where, ny, nz, d);
  return d;
}

nlohmann::ordered_json dual_point_json(const DualPoint& d, CertificateForm form) {
  nlohmann::ordered_json dual;
  dual["horizon"] = d.horizon;
  dual["sigma"] = rational_to_json(d.sigma);
  dual["g"] = matrix_json(d.g);
  if (form == CertificateForm::kDualDeltaPath) {
    const PathDualRecipe& p = d.path;
    dual["t"] = rational_to_json(p.t);
    dual["mu"] = rational_to_json(p.mu);
    dual["u_exponent"] = p.u_exponent;
    dual["x"] = rational_to_json(p.x);
    dual["u_floor"] = rational_to_json(p.floor);
    dual["taps"] = matrix_json(p.taps);
    return dual;
  }
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Eigen::Index i = 0; i < d.Y1.rows(); ++i) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index k = i; k < d.Y1.cols(); ++k) row.push_back(rational_to_json(d.Y1(i, k)));
    rows.push_back(row);
  }
  dual["Y1"] = rows;
  return dual;
}

}  // namespace lpvid
