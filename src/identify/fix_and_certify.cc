#include "identify/fix_and_certify.h"

namespace lpvid {

FixedParameters fix_parameters(const LpvModel<Rational>& model, const ParameterLayout& layout, const Vec<double>& p,
                               int digits) {
  FixedParameters f;
  f.exact.resize(p.size());
  f.value.resize(p.size());
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    f.exact(i) = round_to_digits(p(i), digits);
    f.value(i) = CGAL::to_double(f.exact(i));
  }
  f.model = apply_parameters(model, layout, f.exact);
  return f;
}

CertifiedBounds certify_identified(const LpvModel<Rational>& fixed, const Experiment<Rational>& exp,
                                   const Mat<double>& taps, const CertifyOptions& options, SdpSolver& solver,
                                   std::string* note) {
  if (taps.size() > 0) {
    CertifiedBounds b = certify_with_taps(fixed, exp, taps, options, solver.name());
    if (b.verified) return b;
    if (note) *note = b.reason;
  }
  return certify_fixed_model(fixed, exp, options, solver);
}

}  // namespace lpvid
