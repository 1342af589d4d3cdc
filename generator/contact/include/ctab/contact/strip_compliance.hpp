// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Strip half-length compliance c_i = a_i / p0_i [m/Pa] of MIM-1D (paper Eq. 26) and the treatment of the
//! lateral curvature that enters it.
//!
//! Pointwise (the paper as printed): c_i = pi m_i^2 n_i / (2 E* (A_i + B_i)) with the local curvatures.
//! A curvature jump makes c_i jump, and with it a_i: the "bottleneck" of the paper's Figure 6.
//!
//! ContactSmoothed (default): the Hertz relation a/p0 = pi m^2 n/(2E*(A+B)) holds for a whole elliptic patch,
//! its m, n set by the patch's curvature ratio: the strip length responds to the geometry over the lateral
//! extent of the contact, not at a point. So each strip takes the lateral curvature averaged over the contact
//! around it: B_eff,i = sum_j K_ij w_j B_j / sum_j K_ij w_j, with w_j = (delta_v - h_j)+ the virtual
//! interpenetration at half the approach (the Hertz contact boundary; ~ the strip load for an elliptic patch)
//! and K_ij a Gaussian of width l = lambda * W_i, W_i the half-width of the virtual-interpenetration run that
//! holds strip i (edges at the interpolated zero crossings; runs about to merge blend into one; the kernel cut
//! to zero at 4 l; the local curvature with a small weight of its own), so that B_eff, and with it the
//! force-approach curve, is continuous in the approach. Constant curvature is left unchanged (Hertz stays exact); a jump is spread over a fraction
//! of the patch width; negative local curvature is absorbed by the contact's convex parts (a floor
//! B_eff >= A/20, CONTACT's R_y <= 20 R_x rule, catches a patch that is concave as a whole).
#include <cstdint>
#include <vector>

#include "ctab/contact/strip_grid.hpp"

namespace ctab::gen {

enum class CurvatureTreatment : std::int8_t {
  Pointwise = 0,        //!< local curvature at each strip (paper Eq. 26 as printed)
  ContactSmoothed = 1,  //!< load-weighted average over the contact (default; see above)
};

struct CurvatureOptions {
  CurvatureTreatment treatment = CurvatureTreatment::ContactSmoothed;
  double smoothing_fraction = 0.2;  //!< lambda: kernel width as a fraction of the contact half-width [-]
};

//! Local Hertz data of one strip, from (A_i, B_eff,i).
struct StripHertz {
  double compliance_m_per_Pa = 0.0;  //!< c_i = a_i / p0_i = pi m^2 n / (2 E* (A + B))  (Eq. 26) [m/Pa]
  double length_factor = 0.0;        //!< 1 + alpha_i = r (1 + B/A)/m^2  (ANALYN, Eq. A7) [-]
  double depth_factor = 0.0;         //!< 1 + beta_i  = r (1 + A/B)/n^2  (ANALYN, Eq. A8) [-]
};

//! Fills `hertz` (size grid.size()) for the approach delta [m]; zeros where the curvatures are invalid.
//! E* [Pa]. Allocates only when the vectors are too small.
void strip_compliances(const StripGrid& grid, double E_star_Pa, double approach_m, const CurvatureOptions& options,
                       std::vector<StripHertz>& hertz, std::vector<double>& scratch);

}  // namespace ctab::gen
