// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Elastic materials of the two bodies and their combined (effective) modulus, paper Eq. (3).

namespace ctab::gen {

//! Linear elastic, homogeneous, isotropic material.
struct ElasticMaterial {
  double youngs_modulus_Pa = 208.0e9;  //!< Young's modulus E [Pa]
  double poisson_ratio = 0.3;          //!< Poisson's ratio nu [-], in (-1, 0.5)
};

//! Steel as in the paper and the CONTACT references: E = 208 GPa, nu = 0.3.
inline constexpr ElasticMaterial kSteel{208.0e9, 0.3};

//! True when E > 0 and finite and -1 < nu < 0.5.
[[nodiscard]] bool is_valid(const ElasticMaterial& material) noexcept;

//! Effective modulus E* [Pa]: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (paper Eq. 3). Throws InputError on invalid input.
[[nodiscard]] double effective_modulus(const ElasticMaterial& body1, const ElasticMaterial& body2);

}  // namespace ctab::gen
