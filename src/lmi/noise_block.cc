#include "lmi/noise_block.h"

#include "core/rms.h"
#include "core/input_error.h"
#include "toeplitz/fir.h"

namespace lpvid {

Eigen::Index check_uncertainty_excited(const Mat<double>& z) {
  const Eigen::Index m = leading_zero_samples(z);
  if (m == z.rows() || z.cols() == 0)
    throw InputError(
        "ill-posed data: the uncertainty channel z is identically zero along the experiment (for example u = 0 "
        "with x0 = 0), so the data says nothing about the uncertainty and delta is undetermined");
  return m;
}

SignalScaling signal_scaling(const Mat<double>& z, const Mat<double>& r) {
  SignalScaling s;
  s.n = z.rows();
  s.nz = z.cols();
  s.ny = r.cols();
  s.m = check_uncertainty_excited(z);
  s.L = s.n - s.m;
  s.sigma_z = rms(z.bottomRows(s.L));
  s.sigma_r = rms(r);
  if (!(s.sigma_r > 0.0)) s.sigma_r = 1.0;
  return s;
}

int add_noise_block(LmiProgram& p, int s_var, double fixed_s, const Mat<double>& r_scaled) {
  const Eigen::Index n = r_scaled.rows(), ny = r_scaled.cols();
  const double N = static_cast<double>(n * ny);
  const int B = p.add_block("C2_noise", static_cast<int>(n * ny + 1));
  if (s_var >= 0)
    p.add_entry(B, s_var, 0, 0, N);
  else
    p.add_entry(B, -1, 0, 0, N * fixed_s);
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index i = 0; i < ny; ++i) {
      const int row = static_cast<int>(1 + k * ny + i);
      p.add_entry(B, -1, row, row, 1.0);
      if (r_scaled(k, i) != 0.0) p.add_entry(B, -1, 0, row, r_scaled(k, i));
    }
  return B;
}

}  // namespace lpvid
