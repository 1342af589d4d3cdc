// SPDX-License-Identifier: Apache-2.0
// MIM-1D solver (mim1d.hpp): the influence matrix and the Jacobian of the compatibility equations on the active
// set, the displacement they give, the strips' compliances and the system's right-hand side.
#include <algorithm>
#include <cmath>

#include "ctab/contact/mim1d.hpp"
#include "ctab/contact/strip_kernel.hpp"
#include "mim1d_constants.hpp"

namespace ctab::gen {

using namespace mim1d_detail;

// The influence matrix of the loads, G_ij = C_ij / (pi a_j b) (Eqs. A2-A3 with C_ij of Eq. 10 in the closed form
// of strip_kernel.hpp, Eqs. 11-12), the displacement u = G N (Eq. A2) and the Newton Jacobian of
// R = G(a(N)) N - (delta - h), a_j from Eq. A4.
void Mim1dSolver::build_matrices(MatrixKind kind, bool with_displacement) {
  const StripKernel& kernel = StripKernel::instance();
  const auto n = static_cast<Eigen::Index>(active_.size());
  const bool jacobian = kind == MatrixKind::Jacobian;
  matrix_entries_ += static_cast<double>(n) * static_cast<double>(n);
  influence_.resize(n, n);
  if (jacobian) jacobian_.resize(n, n);
  displacement_.setZero(n);
  const std::size_t first = active_.front(), last = active_.back();
  // One run of neighbouring strips (the usual case): row r is strip first + r, so entry (r, c) depends on |r - c|
  // alone and a column is two straight copies of its lag arrays.
  const bool contiguous = last - first + 1 == active_.size();
  double* g_lag = column_g_.data();  // G_ij by lag k = |i - j|
  double* j_lag = column_j_.data();  // J_ij by lag
  const double* h_lag = column_h_.data();
  const double* q_lag = column_q_.data();
  const double half_scale = 0.5 * kernel_scale_;
  for (Eigen::Index c = 0; c < n; ++c) {
    const std::size_t j = active_[static_cast<std::size_t>(c)];
    const std::size_t reach = std::max(j - first, last - j);
    // H_k = h((2k+1) b/a_j), Q_k = t h'(t) there; entries are differences of neighbours:
    // G = scale (H_k - H_{k-1}) (2 H_0 at k = 0), and d(G_ij N_j)/dN_j = G_ij + (a_j/2) dG_ij/da_j with
    // dh(c/a)/da = -t h'(t)/a, so J = G - scale/2 (Q_k - Q_{k-1}). The lookups first, then the differences (a
    // loop the compiler vectorises).
    kernel.at_odd_multiples(b_ / length_[j], reach + 1, column_h_.data(), column_q_.data());
    g_lag[0] = kernel_scale_ * (2.0 * h_lag[0]);
    j_lag[0] = g_lag[0] - half_scale * (2.0 * q_lag[0]);
    for (std::size_t k = 1; k <= reach; ++k) {
      g_lag[k] = kernel_scale_ * (h_lag[k] - h_lag[k - 1]);
      j_lag[k] = g_lag[k] - half_scale * (q_lag[k] - q_lag[k - 1]);
    }
    const double load = with_displacement ? load_[j] : 0.0;
    double* column = influence_.col(c).data();
    double* jacobian_column = jacobian ? jacobian_.col(c).data() : nullptr;
    double* u = displacement_.data();
    if (contiguous) {
      const auto cc = static_cast<std::size_t>(c), rows = static_cast<std::size_t>(n);
      for (std::size_t r = 0; r < cc; ++r) column[r] = g_lag[cc - r];
      for (std::size_t r = cc; r < rows; ++r) column[r] = g_lag[r - cc];
      if (jacobian) {
        for (std::size_t r = 0; r < cc; ++r) jacobian_column[r] = j_lag[cc - r];
        for (std::size_t r = cc; r < rows; ++r) jacobian_column[r] = j_lag[r - cc];
      }
      for (std::size_t r = 0; r < rows; ++r) u[r] += column[r] * load;  // u = G N, accumulated column by column
      continue;
    }
    for (Eigen::Index r = 0; r < n; ++r) {
      const std::size_t i = active_[static_cast<std::size_t>(r)];
      const std::size_t k = i > j ? i - j : j - i;
      column[r] = g_lag[k];
      u[r] += g_lag[k] * load;
      if (jacobian) jacobian_column[r] = j_lag[k];
    }
  }
}

// u_i = sum_j G_ij N_j (Eqs. 8 and A2) at one strip, inside or outside the active set (the Eq. 4 check).
double Mim1dSolver::displacement_at(std::size_t strip) const {
  const StripKernel& kernel = StripKernel::instance();
  double u = 0.0;
  for (const std::size_t j : active_) {
    const double d = grid_.y_m[strip] - grid_.y_m[j];
    const double dh = kernel.value((d + b_) / length_[j]) - kernel.value((d - b_) / length_[j]);
    u += kernel_scale_ * dh * load_[j];
  }
  return u;
}

void Mim1dSolver::refresh_compliances(double approach_m) {
  // c_i of Eq. 26 (a_i = c_i p0_i) per strip. Pointwise compliances do not depend on the approach; smoothed ones do
  // (their weights).
  if (approach_m == compliance_approach_ ||
      (options_.curvature.treatment == CurvatureTreatment::Pointwise && !std::isnan(compliance_approach_)))
    return;
  strip_compliances(grid_, E_star_Pa_, approach_m, options_.curvature, compliance_, scratch_);
  compliance_approach_ = approach_m;
}

void Mim1dSolver::fill_approach_column(double approach_m, double h_min) {
  approach_column_ = ones_;
  if (options_.curvature.treatment == CurvatureTreatment::Pointwise) return;
  // Smoothed compliances c_j depend on the approach (their weights, the virtual half-widths and the merge factor of
  // two runs): a_j = sqrt(c_j N_j / (pi b)), so d(G_ij N_j)/dc_j = (N_j / c_j) (a_j/2) dG_ij/da_j = (N_j / c_j)
  // (J_ij - G_ij). Without this term the bordered Newton step is only a fixed-point step along delta, which
  // alternates and does not converge at a two-point contact. dc_j/d(delta) by a forward difference.
  const double step = kComplianceApproachStep * (approach_m - h_min);
  strip_compliances(grid_, E_star_Pa_, approach_m + step, options_.curvature, shifted_compliance_, scratch_);
  for (Eigen::Index c = 0; c < approach_column_.size(); ++c) {
    const std::size_t j = active_[static_cast<std::size_t>(c)];
    const double compliance = compliance_[j].compliance_m_per_Pa;
    const double rate = (shifted_compliance_[j].compliance_m_per_Pa - compliance) / (step * compliance);
    if (rate == 0.0 || !std::isfinite(rate)) continue;
    approach_column_ -= (rate * load_[j]) * (jacobian_.col(c) - influence_.col(c));
  }
}

// The compatibility equations' right-hand side delta - h_i (Eq. 9) and the loads on the active set.
void Mim1dSolver::gather_active_system(double approach_m) {
  const auto n = static_cast<Eigen::Index>(active_.size());
  rhs_.resize(n);
  active_loads_.resize(n);
  ones_.setOnes(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const std::size_t i = active_[static_cast<std::size_t>(r)];
    rhs_(r) = approach_m - grid_.h_m[i];
    active_loads_(r) = load_[i];
  }
}

}  // namespace ctab::gen
