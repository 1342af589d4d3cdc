// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Carlson symmetric elliptic integrals and the complete elliptic integrals built on them.
//!
//! Convention: every complete integral takes the PARAMETER m = k^2 (not the modulus k), as DLMF §19.2.
//! K(m) = R_F(0, 1-m, 1), E(m) = K(m) - (m/3) R_D(0, 1-m, 1), D(m) = (K - E)/m = R_D(0, 1-m, 1)/3
//! (DLMF 19.25.1). D is computed directly, without the K - E cancellation at small m.
//! Algorithm: Carlson's duplication with the fifth-order series (DLMF 19.36.1-2; Carlson, Numer. Algorithms
//! 10 (1995) 13-26), relative error below 1e-15.

namespace ctab::gen {

//! Carlson's R_F(x, y, z); x, y, z >= 0, at most one of them zero.
[[nodiscard]] double carlson_rf(double x, double y, double z) noexcept;
//! Carlson's R_D(x, y, z); x, y >= 0 (not both zero), z > 0.
[[nodiscard]] double carlson_rd(double x, double y, double z) noexcept;

//! Complete elliptic integral of the first kind K(m), parameter m in [0, 1).
[[nodiscard]] double elliptic_k(double m) noexcept;
//! Complete elliptic integral of the second kind E(m), parameter m in [0, 1].
[[nodiscard]] double elliptic_e(double m) noexcept;
//! D(m) = (K(m) - E(m))/m, parameter m in [0, 1); D(0) = pi/4.
[[nodiscard]] double elliptic_d(double m) noexcept;

//! K, E and D at once from the complementary parameter mc = 1 - m (two Carlson evaluations).
struct CompleteElliptic {
  double K;  //!< first kind
  double E;  //!< second kind
  double D;  //!< (K - E)/m
};
[[nodiscard]] CompleteElliptic complete_elliptic_from_complement(double mc) noexcept;

}  // namespace ctab::gen
