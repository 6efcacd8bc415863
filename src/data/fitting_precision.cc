#include "data/fitting_precision.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace lpvid {

double at_fitting_precision(double x) {
  if (x == 0.0 || !std::isfinite(x)) return x;
  // to_chars with a precision rounds the exact binary value correctly (no
  // locale, no libm), and from_chars reads the decimal back correctly
  // rounded: the same bits on every machine.
  char text[64];
  const std::to_chars_result w = std::to_chars(text, text + sizeof text, x, std::chars_format::scientific, kFittingDigits - 1);
  if (w.ec != std::errc()) return x;
  double back = x;
  const std::from_chars_result r = std::from_chars(text, w.ptr, back, std::chars_format::scientific);
  return r.ec == std::errc() ? back : x;
}

namespace {

Mat<double> rounded(const Mat<double>& m) { return m.unaryExpr([](double v) { return at_fitting_precision(v); }); }

}  // namespace

Experiment<double> at_fitting_precision(const Experiment<double>& e) {
  Experiment<double> out = e;
  out.u = rounded(e.u);
  out.y = rounded(e.y);
  out.rho = rounded(e.rho);
  for (Vec<double>& x0 : out.record_x0) x0 = rounded(x0).col(0);
  return out;
}

}  // namespace lpvid
