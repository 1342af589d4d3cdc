// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The least model (`--method auto --tolerance T`, docs/method.md): per wheel case the coarsest MIM-1D
//! strip width whose estimated error in area and max pressure stays within T against MIM-1D at a fine width.
//!
//! Estimator (least_model_test):
//! 1. First solve: MIM-1D at 0.4 mm (kAutoFirstRung), the gap correction of solve_wheel_contact included. Its
//!    smallest loaded patch (>= 5 % of the force, resolution.hpp) is W wide.
//! 2. Start: the coarsest ladder width w >= 0.4 mm with at least kMinResolvedStrips (8) strips across W (solved
//!    afresh when finer than the first solve): the widths below 8 strips are those where the stability matrix
//!    measured MIM-1D up to 38 % off.
//! 3. Richardson-type check: the case's final gap samples and patch loads are solved again at 2w
//!    (resolve_at_strip_width: geometry and load held, the strip width alone changed, no second gap correction),
//!    and the error of the solution at w is estimated as e(w) = max(|A_w - A_2w| / A_w, |p_w - p_2w| / p_w), the
//!    estimate for a first-order method (error proportional to w: err(w) = err(2w) - err(w)); MIM-1D's measured
//!    error on the S1002/UIC60 sweep falls about as 1/n (0.8 mm: up to 27 % at n = 2 and 1.8 % at n = 24). The
//!    solution at w is taken when kAutoSafetyFactor * e(w) <= T and it is not under-resolved (every patch with
//!    >= 5 % of the force on >= 8 strips); else w is halved, down to the finest ladder width, which is taken
//!    whatever its estimate.
//!    Each patch problem carrying >= 5 % of the normal force is checked as well as the totals (per-patch bound);
//!    at the finest width an estimate above T gives UnderResolved, never Converged.
//! 4. Escalation (docs/design/knee-indicator.md): the steps above bound MIM-1D's discretisation error, not the strip
//!    model's own, which against bem2d reaches 16 % in area and 6 % of F_z in lateral force where the contact
//!    climbs from the flange root onto the flank, and 3-6 % in area where tread and flange root share the load.
//!    The case is solved with bem2d (rows kEscalationRowWidth_m wide, elements kEscalationElementLength_m long,
//!    each halved until the smallest such patch has kEscalationElementsAcross across it, rows down to 0.1 mm and
//!    elements to 0.2 mm)
//!    when a patch carrying >= 5 % of the normal force is a flange patch whose surface turns by
//!    kEscalationAngleSpread_rad or more across its strips (patch_shape.hpp), or when two patches each carry
//!    >= 5 %. On the S1002/UIC60 sweep dy 4-9 mm (3 loads) this flags 44 % of the cases and misses 3.3 % of the
//!    patches off the targets. When bem2d fails the MIM-1D solution is returned as UnderResolved.
//! A case the first solve cannot solve is solved once at kAutoFallbackWidth_m (as `--method mim1d` would); a
//! first solve without contact is the answer.
#include <array>

#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen {

//! Strip widths of the least model, coarsest first [m]: it chooses from kAutoFirstRung on; 0.8 mm only checks 0.4.
inline constexpr std::array<double, 5> kAutoStripWidths_m{0.8e-3, 0.4e-3, 0.2e-3, 0.1e-3, 0.05e-3};
//! The ladder index of the first solve (0.4 mm).
inline constexpr std::size_t kAutoFirstRung = 1;
//! Margin on the estimate: the check takes e(w) <= T / kAutoSafetyFactor [-].
inline constexpr double kAutoSafetyFactor = 1.0;
//! Width after a failed first solve (the default strip width) [m].
inline constexpr double kAutoFallbackWidth_m = 0.2e-3;
//! Inclination spread across a flange patch from which the case escalates to bem2d [rad] (knee-indicator.md).
inline constexpr double kEscalationAngleSpread_rad = 0.10;
//! bem2d of an escalated case: row width [m] and element length along the rolling direction [m]. Chosen for the
//! cost (the default table with auto 3.2x MIM-1D's, against 16x at 0.1 x 0.4 mm): on the knee (dy 6.3-7.5 mm) it
//! holds the targets per patch against bem2d at 0.05 x 0.4 mm (least_model_knee_test), and CONTACT's conformal
//! flange cases within 2.5 % in area; on the knee's 14-30 mm long patches 0.4 mm elements change area and
//! pressure by < 0.1 % against 0.1 mm squares, 0.8 mm by < 0.4 %.
inline constexpr double kEscalationRowWidth_m = 0.2e-3;
inline constexpr double kEscalationElementLength_m = 0.8e-3;
//! Elements across the width and the length of the smallest loaded patch that the escalation's grid aims for [-].
inline constexpr double kEscalationElementsAcross = 24.0;
//! Default tolerance of `--method auto` [-].
inline constexpr double kAutoDefaultTolerance = 0.02;

//! The ladder index at which the check starts for a smallest loaded patch `patch_width_m` wide (step 2 above).
[[nodiscard]] std::size_t auto_start_rung(double patch_width_m) noexcept;

//! e(w) of step 3: the larger relative change of total area and max pressure from `coarse` (the same case's samples
//! at 2w) to `fine` [-] (+inf when either has no loaded patch or the coarse solve failed).
[[nodiscard]] double richardson_error(const WheelContact& fine, const StripWidthTotals& coarse) noexcept;

//! Step 4's rule: a flange patch carrying >= kResolvedForceShare of the normal force with an inclination spread of
//! kEscalationAngleSpread_rad or more, or two patches carrying >= kResolvedForceShare each.
[[nodiscard]] bool strip_model_at_risk(const WheelContact& contact) noexcept;

//! What the least model chose for a case.
struct AutoChoice {
  ContactMethod method = ContactMethod::Mim1d;  //!< Bem2d when the case escalated (step 4)
  double strip_width_m = 0.0;    //!< chosen strip width (bem2d: row width) [m]
  double patch_width_m = 0.0;    //!< W of the first solve [m] (0 when it failed or found no contact)
  double estimated_error = 0.0;  //!< e(w) at the chosen width [-] (0 when no check was made)
  int solves = 0;                //!< wheel solves made (the checks at 2w re-solve strips only: not counted)
  //! Influence-matrix entries MIM-1D built, every iteration of the solves and the checks [-] (WheelContact): the
  //! cost measure of the tests (the LU grows faster still; wall time is measured by the bench, not the tests).
  double matrix_entries = 0.0;
};

//! Solves one wheel case with the least model (options.method and options.mim1d.strip_width_m are overridden).
//! Never throws. `choice` (optional) receives the choice.
[[nodiscard]] WheelContact solve_wheel_contact_auto(const SideGeometry& side, double dy_m, double roll_rad,
                                                    double E_star_Pa, LoadKind load, double load_value,
                                                    const WheelRailOptions& options, double tolerance,
                                                    WheelContactWorkspace& workspace, AutoChoice* choice = nullptr);

}  // namespace ctab::gen
