// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/material.hpp"

#include <cmath>
#include <string>

#include "ctab/core/error.hpp"

namespace ctab::gen {

bool is_valid(const ElasticMaterial& material) noexcept {
  return std::isfinite(material.youngs_modulus_Pa) && material.youngs_modulus_Pa > 0.0 &&
         std::isfinite(material.poisson_ratio) && material.poisson_ratio > -1.0 && material.poisson_ratio < 0.5;
}

double effective_modulus(const ElasticMaterial& body1, const ElasticMaterial& body2) {
  for (const ElasticMaterial* body : {&body1, &body2}) {
    if (!(std::isfinite(body->youngs_modulus_Pa) && body->youngs_modulus_Pa > 0.0))
      throw InputError("material", 0,
                       "Young's modulus must be positive and finite, got " + std::to_string(body->youngs_modulus_Pa) +
                           " Pa");
    if (!(body->poisson_ratio > -1.0 && body->poisson_ratio < 0.5))
      throw InputError("material", 0,
                       "Poisson's ratio must lie in (-1, 0.5), got " + std::to_string(body->poisson_ratio));
  }
  const double compliance = (1.0 - body1.poisson_ratio * body1.poisson_ratio) / body1.youngs_modulus_Pa +
                            (1.0 - body2.poisson_ratio * body2.poisson_ratio) / body2.youngs_modulus_Pa;
  return 1.0 / compliance;
}

}  // namespace ctab::gen
