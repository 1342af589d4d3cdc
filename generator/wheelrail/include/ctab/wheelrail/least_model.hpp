#pragma once
//! The least model (`--method auto --tolerance T`, README "The least model"): per wheel case the coarsest MIM-1D
//! strip width whose estimated error in area and max pressure stays within T against MIM-1D at a fine width.
//!
//! Estimator (stated, tested in least_model_test):
//! 1. First look: MIM-1D at the coarsest width of the ladder (kAutoStripWidths_m[0], 0.8 mm; about 1/16 of the
//!    cost of 0.2 mm on a tread patch). Its smallest loaded patch (>= 5 % of the force, resolution.hpp) has
//!    width W.
//! 2. Error law: with n = W / w strips across that patch, the relative error of MIM-1D at width w (larger of area
//!    and max pressure, against MIM-1D at 0.05 mm) is at most kAutoErrorCoefficient / n. The coefficient is the
//!    envelope max(e * n) measured on the S1002/UIC60 sweep (dy -6 ... +8 mm in 0.25 mm, 78.5 kN, widths 0.8,
//!    0.4, 0.2, 0.1 mm): 0.53 (tread dy 0.5 mm at 0.8 mm: n = 24, 1.8 %; flank dy 8 mm at 0.8 mm: n = 2, 27 %);
//!    a pure 1/n^2 law does not bound the tread (the error there follows the gap's curvature, not only n).
//! 3. Choice: the coarsest ladder width with kAutoSafetyFactor * C / n <= T; the finest rung when none is. The
//!    first look is the answer when it is chosen; otherwise the case is solved once more at the chosen width.
//! A case the first look cannot solve is solved at the default width (kAutoFallbackWidth_m), as `--method mim1d`
//! would.
#include <array>

#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen {

//! Strip widths the least model chooses from, coarsest first [m].
inline constexpr std::array<double, 5> kAutoStripWidths_m{0.8e-3, 0.4e-3, 0.2e-3, 0.1e-3, 0.05e-3};
//! C of the error law e(n) <= C / n (measured envelope, see above) [-].
inline constexpr double kAutoErrorCoefficient = 0.55;
//! Margin on the estimate [-].
inline constexpr double kAutoSafetyFactor = 1.0;
//! Width after a failed first look (the default strip width) [m].
inline constexpr double kAutoFallbackWidth_m = 0.2e-3;
//! Default tolerance of `--method auto` [-].
inline constexpr double kAutoDefaultTolerance = 0.02;

//! Estimated relative error of MIM-1D with `strips` strips across the smallest loaded patch [-].
[[nodiscard]] double auto_error_estimate(double strips) noexcept;

//! The coarsest ladder width whose estimated error on a patch `patch_width_m` wide is within `tolerance`; the
//! finest ladder width when none is [m].
[[nodiscard]] double auto_strip_width(double patch_width_m, double tolerance) noexcept;

//! What the least model chose for a case.
struct AutoChoice {
  ContactMethod method = ContactMethod::Mim1d;
  double strip_width_m = 0.0;      //!< chosen strip width [m]
  double patch_width_m = 0.0;      //!< W of the first look [m] (0 when it failed or found no contact)
  double estimated_error = 0.0;    //!< auto_error_estimate at the chosen width [-]
  int solves = 0;                  //!< wheel solves made (1: the first look was chosen, 2: solved again)
  double strips_solved = 0.0;      //!< strips across all patches, summed over the solves [-] (a cost measure)
};

//! Solves one wheel case with the least model (options.method and options.mim1d.strip_width_m are overridden).
//! Never throws. `choice` (optional) receives the choice.
[[nodiscard]] WheelContact solve_wheel_contact_auto(const SideGeometry& side, double dy_m, double roll_rad,
                                                    double E_star_Pa, LoadKind load, double load_value,
                                                    const WheelRailOptions& options, double tolerance,
                                                    WheelContactWorkspace& workspace, AutoChoice* choice = nullptr);

}  // namespace ctab::gen
