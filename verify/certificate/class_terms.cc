#include "verify/certificate/class_terms.h"

#include <algorithm>
#include <cmath>

#include "core/decimal_rounding.h"
#include "core/integer_form.h"
#include "core/number_text.h"
#include "toeplitz/record_segments.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {
namespace {

/// Leading samples of the record [first, first + count) where z0 and every
/// column of Jz vanish (z(p)_k = 0 for every p).
Eigen::Index common_leading_zeros(const AffineResidual<Rational>& a, Eigen::Index first, Eigen::Index count) {
  const Eigen::Index nz = a.nz;
  for (Eigen::Index k = 0; k < count; ++k)
    for (Eigen::Index j = 0; j < nz; ++j) {
      const Eigen::Index row = (first + k) * nz + j;
      if (a.z0(row) != 0) return k;
      for (Eigen::Index c = 0; c < a.Jz.cols(); ++c)
        if (a.Jz(row, c) != 0) return k;
    }
  return count;
}

/// The class's horizon: the longest record's samples from the first one where
/// some parameter makes z non-zero (one record: n − common leading zeros).
Eigen::Index class_horizon(const AffineResidual<Rational>& a) {
  const RecordLengths lengths = record_lengths_of(a.records, a.n);
  const std::vector<Eigen::Index> start = record_starts(lengths);
  Eigen::Index L = 0;
  for (size_t k = 0; k < lengths.size(); ++k)
    L = std::max(L, lengths[k] - common_leading_zeros(a, start[k], lengths[k]));
  return L;
}

/// A solution x of the consistent system G x = b (G symmetric PSD, possibly
/// singular) by exact Gauss–Jordan elimination; free unknowns set to 0.
Vec<Rational> solve_consistent(Mat<Rational> G, Vec<Rational> b) {
  const Eigen::Index m = G.rows();
  std::vector<Eigen::Index> pivot_col;
  Eigen::Index row = 0;
  for (Eigen::Index col = 0; col < m && row < m; ++col) {
    Eigen::Index p = row;
    while (p < m && G(p, col) == 0) ++p;
    if (p == m) continue;
    G.row(p).swap(G.row(row));
    std::swap(b(p), b(row));
    for (Eigen::Index i = 0; i < m; ++i) {
      if (i == row || G(i, col) == 0) continue;
      const Rational f = G(i, col) / G(row, col);
      G.row(i) -= f * G.row(row);
      b(i) -= f * b(row);
    }
    pivot_col.push_back(col);
    ++row;
  }
  Vec<Rational> x = Vec<Rational>::Zero(m);
  for (size_t i = 0; i < pivot_col.size(); ++i) {
    const Eigen::Index r = static_cast<Eigen::Index>(i);
    x(pivot_col[i]) = b(r) / G(r, pivot_col[i]);
  }
  return x;
}

}  // namespace

std::string class_signals(AffineResidual<Rational> a, const std::vector<long>& free, ClassSignals& out) {
  const long P = static_cast<long>(a.num_params());
  std::vector<char> is_free(static_cast<size_t>(P), 0);
  for (const long i : free) {
    if (i < 0 || i >= P) return "free parameter index " + std::to_string(i) + " is out of range";
    if (!a.Jz.col(i).isZero()) return "parameter " + a.names[static_cast<size_t>(i)] + " moves z, so it cannot be free";
    is_free[static_cast<size_t>(i)] = 1;
  }
  out.free = free;
  out.boxed.clear();
  for (long i = 0; i < P; ++i)
    if (!is_free[static_cast<size_t>(i)]) out.boxed.push_back(i);
  out.free_columns = Mat<Rational>(a.Jr.rows(), static_cast<Eigen::Index>(free.size()));
  for (size_t c = 0; c < free.size(); ++c) out.free_columns.col(static_cast<Eigen::Index>(c)) = a.Jr.col(free[c]);
  out.horizon = class_horizon(a);
  out.a = std::move(a);
  if (out.horizon == 0 || out.a.nz == 0) return "z is identically zero for every parameter: the Delta form has no horizon";
  return "";
}

Mat<Rational> project_out_free(const Mat<Rational>& g, const Mat<Rational>& F) {
  if (F.cols() == 0) return g;
  const Vec<Rational> gv = stack_rows(g);
  const Mat<Rational> G = exact_transpose_product(F, F);
  const Vec<Rational> x = solve_consistent(G, exact_transpose_product(F, Mat<Rational>(gv)).col(0));
  return unstack_rows(exact_minus_product(gv, F, x), g.cols());
}

Mat<Rational> class_z(const ClassSignals& s, const Vec<Rational>& center) { return unstack_rows(s.a.z(center), s.a.nz); }
Mat<Rational> class_r(const ClassSignals& s, const Vec<Rational>& center) { return unstack_rows(s.a.r(center), s.a.ny); }

ClassPenalty class_penalty(const ClassSignals& s, const Vec<Rational>& radius, const Mat<Rational>& g) {
  ClassPenalty p;
  const Vec<Rational> gv = stack_rows(g);
  Rational kappa(0);
  for (const long i : s.boxed) {
    if (radius(i) == 0) continue;
    const Rational gj = gv.dot(s.a.Jr.col(i));
    p.linear += Rational(2) * radius(i) * (gj < 0 ? Rational(-gj) : gj);
    const Rational jz2 = s.a.Jz.col(i).squaredNorm();
    if (jz2 == 0) continue;
    if (!std::isfinite(nearest_double(jz2))) {
      p.problem = "the column of Jz of " + s.a.names[static_cast<size_t>(i)] + " is too large";
      return p;
    }
    kappa += radius(i) * Rational(sqrt_up(jz2));
  }
  if (kappa == 0) return p;
  const Rational gg = gv.squaredNorm();
  if (!std::isfinite(nearest_double(gg))) {
    p.problem = "||g||^2 leaves the range of a double";
    return p;
  }
  p.bilinear = Rational(2) * Rational(sqrt_up(gg)) * kappa;
  return p;
}

DualTerms<Rational> leaf_terms(DualTerms<Rational> terms, const ClassPenalty& p, const Rational& epsilon) {
  terms.beta -= p.linear;
  if (p.bilinear > 0) {
    terms.trace_U += p.bilinear / (Rational(2) * epsilon);
    terms.beta -= p.bilinear * epsilon / Rational(2);
  }
  return terms;
}

}  // namespace lpvid
