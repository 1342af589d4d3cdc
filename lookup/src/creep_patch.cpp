// SPDX-License-Identifier: Apache-2.0
// One patch's creep forces: the patch's strips as given (CTAB_CREEP_STRIPS; CTAB_CREEP_STRIPS_CARTER with each
// strip's march following Carter's strip), its equivalent ellipse marched the same way (CTAB_CREEP_FASTSIM_ELLIPSE),
// or Kalker's linear theory on that ellipse (CTAB_CREEP_LINEAR).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "creep_march.hpp"

namespace ctab::lookup {

namespace {

using detail::MarchStrips;

// What every method needs of the patch: its strips (pressure scaled to the normal force), equivalent ellipse,
// load centre and shear modulus.
struct PatchShape {
  double ds = 0.0, load_N = 0.0, normal_force_N = 0.0, a = 0.0, b = 0.0, s_centre = 0.0, shear_modulus = 0.0, nu = 0.0;
};

bool finite_strips(const StripPatch& p) noexcept {
  if (p.s_m == nullptr || p.half_length_m == nullptr || p.peak_pressure_Pa == nullptr || p.n < 2 ||
      p.n > kMaxCreepStrips || !std::isfinite(p.normal_force_N) || p.normal_force_N < 0.0 ||
      !std::isfinite(p.plane_angle_rad))
    return false;
  for (std::uint32_t i = 0; i < p.n; ++i)
    if (!std::isfinite(p.s_m[i]) || !(p.half_length_m[i] >= 0.0) || !(p.peak_pressure_Pa[i] >= 0.0) ||
        !std::isfinite(p.half_length_m[i]) || !std::isfinite(p.peak_pressure_Pa[i]))
      return false;
  return p.s_m[p.n - 1] > p.s_m[0];
}

// The equivalent ellipse as the generator stores it: the area, the longest strip and the width give a and b.
bool shape_of(const StripPatch& p, const ctab_creep_input& in, PatchShape& shape) noexcept {
  shape.ds = (p.s_m[p.n - 1] - p.s_m[0]) / (p.n - 1);
  double area = 0.0, load = 0.0, moment = 0.0, longest = 0.0;
  for (std::uint32_t i = 0; i < p.n; ++i) {
    area += 2.0 * p.half_length_m[i] * shape.ds;
    const double strip_load = 0.5 * std::numbers::pi * p.half_length_m[i] * p.peak_pressure_Pa[i] * shape.ds;
    load += strip_load;
    moment += strip_load * p.s_m[i];
    longest = std::max(longest, 2.0 * p.half_length_m[i]);
  }
  if (!(area > 0.0 && load > 0.0)) return false;
  const double radius = std::sqrt(area / std::numbers::pi), ratio = std::sqrt(longest / (p.s_m[p.n - 1] - p.s_m[0]));
  shape.a = radius * ratio;
  shape.b = radius / ratio;
  shape.s_centre = moment / load;
  shape.load_N = load;
  shape.normal_force_N = p.normal_force_N > 0.0 ? p.normal_force_N : load;
  const double E = in.youngs_modulus_Pa > 0.0 ? in.youngs_modulus_Pa : kDefaultYoungsModulus_Pa;
  shape.nu = in.youngs_modulus_Pa > 0.0 ? in.poisson_ratio : kDefaultPoissonRatio;
  shape.shear_modulus = E / (2.0 * (1.0 + shape.nu));
  return true;
}

// The patch's own strips; semi-elliptic pressure p0 sqrt(1 - x^2/a^2) bounded by the parabola of the same strip
// load, q0 = 3 pi p0 / 8 (a semi-elliptic bound leaves a sticking zone at the leading edge at any creepage).
void own_strips(const StripPatch& p, const PatchShape& shape, MarchStrips& m) noexcept {
  const double scale = 3.0 * std::numbers::pi / 8.0 * shape.normal_force_N / shape.load_N;
  m.n = p.n;
  m.ds = shape.ds;
  for (std::uint32_t i = 0; i < p.n; ++i) {
    m.s[i] = p.s_m[i];
    m.a[i] = p.half_length_m[i];
    m.q0[i] = scale * p.peak_pressure_Pa[i];
    m.stiffness[i] = 1.0;
  }
}

// The equivalent ellipse centred on the patch's load centre in `n` strips, parabolic pressure of the patch's force
// (Kalker's FASTSIM: p = 2N / (pi a b) (1 - x^2/a^2 - y^2/b^2)).
void ellipse_strips(const PatchShape& shape, std::uint32_t n, MarchStrips& m) noexcept {
  m.n = n;
  m.ds = 2.0 * shape.b / n;
  const double peak = 2.0 * shape.normal_force_N / (std::numbers::pi * shape.a * shape.b);
  for (std::uint32_t i = 0; i < n; ++i) {
    const double v = -1.0 + (2.0 * i + 1.0) / n, w = 1.0 - v * v;
    m.s[i] = shape.s_centre + shape.b * v;
    m.a[i] = shape.a * std::sqrt(w);
    m.q0[i] = peak * w;
    m.stiffness[i] = 1.0;
  }
}

// Kalker's linear theory at the load centre, moved to s = 0.
void linear(const PatchShape& shape, const ctab_creep_input& in, ctab_creep_patch& out) noexcept {
  const KalkerCoefficients k = kalker_coefficients(shape.a, shape.b, shape.nu);
  const double c = std::sqrt(shape.a * shape.b), gc2 = shape.shear_modulus * c * c;
  const double xi_centre = in.xi - in.phi_per_m * shape.s_centre;
  out.fx_N = -gc2 * k.c11 * xi_centre;
  out.fs_N = -gc2 * (k.c22 * in.eta + c * k.c23 * in.phi_per_m);
  out.mz_Nm = -gc2 * c * (-k.c23 * in.eta + c * k.c33 * in.phi_per_m) - shape.s_centre * out.fx_N;
  out.slip_fraction = 0.0;
}

}  // namespace

bool valid_creep_input(const ctab_creep_input& in) noexcept {
  const bool creepages = std::isfinite(in.xi) && std::isfinite(in.eta) && std::isfinite(in.phi_per_m);
  const bool friction = std::isfinite(in.friction) && in.friction > 0.0;
  const bool material = in.youngs_modulus_Pa == 0.0 || (std::isfinite(in.youngs_modulus_Pa) &&
                                                        in.youngs_modulus_Pa > 0.0 && in.poisson_ratio >= 0.0 &&
                                                        in.poisson_ratio < 0.5);
  const bool method = in.method >= CTAB_CREEP_STRIPS_CARTER && in.method <= CTAB_CREEP_STRIPS;
  const bool cells = in.cells == 0 || (in.cells >= kMinCreepCells && in.cells <= kMaxCreepCells);
  return creepages && friction && material && method && cells;
}

ctab_status creep_patch(const StripPatch& p, const ctab_creep_input& in, ctab_creep_patch& out,
                        StripForces* field) noexcept {
  std::memset(&out, 0, sizeof out);
  PatchShape shape;
  if (!valid_creep_input(in) || !finite_strips(p) || !shape_of(p, in, shape)) {
    out.status = CTAB_INVALID_INPUT;
    return CTAB_INVALID_INPUT;
  }
  const std::int32_t cells = in.cells == 0 ? kDefaultCreepCells : in.cells;
  if (in.method == CTAB_CREEP_LINEAR) {
    linear(shape, in, out);
  } else {
    const KalkerCoefficients k = kalker_coefficients(shape.a, shape.b, shape.nu);
    const detail::Flexibility flex = detail::flexibility(shape.a, shape.b, shape.shear_modulus, k);
    MarchStrips strips;
    const bool own = in.method != CTAB_CREEP_FASTSIM_ELLIPSE;
    if (own) own_strips(p, shape, strips);
    else ellipse_strips(shape, static_cast<std::uint32_t>(cells), strips);
    if (in.method == CTAB_CREEP_STRIPS_CARTER) detail::carter_stiffness(strips, flex, in);
    detail::march(strips, flex, in, cells, out, own ? field : nullptr);
  }
  out.force_lateral_N = out.fs_N * std::cos(p.plane_angle_rad);
  out.force_vertical_N = out.fs_N * std::sin(p.plane_angle_rad);
  out.normal_force_N = shape.normal_force_N;
  out.present = 1;
  out.status = CTAB_OK;
  return CTAB_OK;
}

}  // namespace ctab::lookup
