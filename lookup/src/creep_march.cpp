// SPDX-License-Identifier: Apache-2.0
// The FASTSIM march (Kalker 1982, "A fast algorithm for the simplified theory of rolling contact", VSD 11:1-13):
// traction p = -(displacement difference) / L grows from zero at the leading edge x = +a with the rigid slip
// (xi - phi s, eta + phi x) and is cut back to the bound mu q0 (1 - x^2/a^2) where it would exceed it (slip).
// Cells: `cells` per strip, evenly spread over [-a, a], evaluated at their centres (the first step, from the
// leading edge, is half a cell, so that the small-creepage traction is exact at every centre).
#include "creep_march.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

// As the queries: x86-64-v3 and baseline clones picked once by the loader (GCC on x86-64 Linux).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(CTAB_LOOKUP_NO_CLONES)
#define CTAB_CREEP_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define CTAB_CREEP_CLONES
#endif

namespace ctab::lookup::detail {

Flexibility flexibility(double a_m, double b_m, double shear_modulus_Pa, const KalkerCoefficients& c) noexcept {
  Flexibility f;
  f.l1 = 8.0 * a_m / (3.0 * c.c11 * shear_modulus_Pa);
  f.l2 = 8.0 * a_m / (3.0 * c.c22 * shear_modulus_Pa);
  f.l3 = std::numbers::pi * a_m * std::sqrt(a_m / b_m) / (4.0 * c.c23 * shear_modulus_Pa);
  return f;
}

// With the traction growing by w per unit length in stick and the bound mu q0 (1 - x^2/a^2), a strip's march gives
// mu Q (1 - (1 - k)^3), k = w a / (2 mu q0) (stick zone 2a (1 - k)); Carter's strip of the same initial slope gives
// mu Q (1 - (1 - 3k/2)^2). The march with its growth scaled by k'/k, 1 - (1 - k')^3 = 1 - (1 - 3k/2)^2, gives
// Carter's force; 3/2 from full slip (3k/2 >= 1) on. Carter's strip has a uniform rigid slip: the factor is that of
// the creepages xi, eta and scales their terms only; the spin's terms keep Kalker's L3. The cube root of
// t = 1 - 3k/2: a quadratic first guess exact at t = 1 and one Halley step (one division, vectorises): k'/k within
// 1e-9 for k < 0.1, the strip's force within 3e-5 of mu Q everywhere.
CTAB_CREEP_CLONES void carter_stiffness(MarchStrips& strips, const Flexibility& flex,
                                        const ctab_creep_input& in) noexcept {
  const double xi_l1 = in.xi / flex.l1, eta_l2 = in.eta / flex.l2, w = std::sqrt(xi_l1 * xi_l1 + eta_l2 * eta_l2);
  for (std::uint32_t i = 0; i < strips.n; ++i) {
    const double k = w * strips.a[i] / std::max(2.0 * in.friction * strips.q0[i], 1e-300);
    const double t = std::max(0.0, 1.0 - 1.5 * k);
    const double guess = 1.0 - (1.0 - t) * ((0.49833973 * t - 0.82725272) * t + 0.69269587);
    const double cube = guess * guess * guess, root = guess * (cube + 2.0 * t) / (2.0 * cube + t);
    const double carter = (1.0 - root * root) / std::max(k, 1e-300);
    strips.stiffness[i] = k < 1e-9 ? 1.0 : t <= 0.0 ? 1.5 : carter;
  }
}

namespace {

// Per-strip state and sums of one march; the loop over strips is the inner one so that it vectorises.
struct MarchState {
  double px[kMaxCreepStrips], py[kMaxCreepStrips];
  double fx[kMaxCreepStrips], fy[kMaxCreepStrips], mz[kMaxCreepStrips], slip[kMaxCreepStrips];
  double dpx[kMaxCreepStrips], dx[kMaxCreepStrips], g0[kMaxCreepStrips];
};

CTAB_CREEP_CLONES void march_cells(const MarchStrips& strips, const Flexibility& flex, const ctab_creep_input& in,
                                   std::int32_t cells, MarchState& st) noexcept {
  const std::uint32_t n = strips.n;
  const double inv_cells = 1.0 / cells;
  const double xi_l1 = in.xi / flex.l1, phi_l3 = in.phi_per_m / flex.l3, eta_l2 = in.eta / flex.l2;
  for (std::uint32_t i = 0; i < n; ++i) {
    st.px[i] = st.py[i] = st.fx[i] = st.fy[i] = st.mz[i] = st.slip[i] = 0.0;
    st.dx[i] = 2.0 * strips.a[i] * inv_cells;
    st.dpx[i] = -st.dx[i] * (strips.stiffness[i] * xi_l1 - phi_l3 * strips.s[i]);
    st.g0[i] = in.friction * strips.q0[i];
  }
  for (std::int32_t k = 0; k < cells; ++k) {
    const double u = 1.0 - (2.0 * k + 1.0) * inv_cells;  // x / a at the cell centre
    const double bound = 1.0 - u * u;
    // The step from the previous centre (from the leading edge for the first cell) and x / a at its middle.
    const double step = k == 0 ? 0.5 : 1.0, u_step = k == 0 ? 1.0 - 0.5 * inv_cells : 1.0 - 2.0 * k * inv_cells;
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = strips.a[i] * u;
      double px = st.px[i] + step * st.dpx[i];
      double py = st.py[i] - step * st.dx[i] * (strips.stiffness[i] * eta_l2 + phi_l3 * strips.a[i] * u_step);
      const double g = st.g0[i] * bound, t2 = px * px + py * py;
      // Branch-free (the loop vectorises): scale < 1 exactly where the traction exceeds its bound (slip).
      const double scale = std::min(1.0, g / std::sqrt(std::max(t2, 1e-300)));
      px *= scale;
      py *= scale;
      st.px[i] = px;
      st.py[i] = py;
      st.fx[i] += px * st.dx[i];
      st.fy[i] += py * st.dx[i];
      st.mz[i] += (x * py - strips.s[i] * px) * st.dx[i];
      st.slip[i] += scale < 1.0 ? st.dx[i] : 0.0;
    }
  }
}

}  // namespace

void march(const MarchStrips& strips, const Flexibility& flex, const ctab_creep_input& input, std::int32_t cells,
           ctab_creep_patch& out, StripForces* field) noexcept {
  MarchState st;
  march_cells(strips, flex, input, cells, st);
  double fx = 0.0, fy = 0.0, mz = 0.0, slip = 0.0, length = 0.0;
  for (std::uint32_t i = 0; field != nullptr && i < strips.n; ++i) {
    field->fx_per_m[i] = st.fx[i];
    field->fs_per_m[i] = st.fy[i];
    field->slip_fraction[i] = strips.a[i] > 0.0 ? st.slip[i] / (2.0 * strips.a[i]) : 0.0;
  }
  for (std::uint32_t i = 0; i < strips.n; ++i) {
    fx += st.fx[i];
    fy += st.fy[i];
    mz += st.mz[i];
    slip += st.slip[i];
    length += 2.0 * strips.a[i];
  }
  out.fx_N = fx * strips.ds;
  out.fs_N = fy * strips.ds;
  out.mz_Nm = mz * strips.ds;
  out.slip_fraction = length > 0.0 ? slip / length : 0.0;
}

}  // namespace ctab::lookup::detail
