// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The stability matrix (`ctab bench stability`, docs/validation.md "Stability where methods fail"): every rung of the method
//! ladder on hard scenes, each case recorded with its status, error against a reference, iterations and time.
//!
//! Scenes (strip problems unless "wheel-rail"):
//! - elongated: h = A x^2 + B y^2 with a/b = 20 and 1/20 (reference: analytic Hertz).
//! - load: an ellipsoid (A = 1/(2 * 0.46 m), B = 1/(2 * 0.3 m)) from 1 N to 1 MN (reference: analytic Hertz).
//! - barely_touching: the same ellipsoid at approaches of 1 um, 1 nm, 0 and -1 nm (reference: analytic Hertz).
//! - curvature_jump: lateral radius 40 mm / 500 mm and 10 mm / 2000 mm across y = 0 (reference: bem2d, fine).
//! - hollow_gap: a double-well gap whose lateral curvature is negative between the wells (reference: bem2d, fine).
//! - wheel-rail S1002/UIC60 1:40 at 78.5 kN: tread, two-point tread + flange, flange root and flank (60-70 deg).
//! - wheel-rail hollow-worn S1002 (cosine hollow of 1, 2, 3 mm depth, 40 mm wide, at the tape circle).
//! - wheel-rail S1002 measured with 1, 3 and 10 um noise (points every 0.1 mm, seeded), through the smoothing
//!   spline of measured profiles (L = 1 mm) and raw (L = 0, interpolated).
//! - wheel-rail loads 1 N to 1 MN at dy = 0.
//! - wheel-rail fine sweeps: dy in steps of 0.01 mm across every jump of the contact point (+-0.05 mm).
//! The wheel-rail reference is bem2d at a fine element size through the same wheel-rail pipeline.
//! Never throws once built: every outcome is a status.
#include <string>
#include <vector>

#include "ctab/contact/contact_method.hpp"
#include "ctab/contact/solve_status.hpp"

namespace ctab::gen {

struct StabilityOptions {
  bool quick = false;                 //!< the fast subset (a few cases per scene; what unlabelled tests run)
  double strip_width_m = 0.2e-3;      //!< discretisation of every rung under test [m]
  double reference_width_m = 0.1e-3;  //!< bem2d element size of the numerical references [m]
  std::vector<ContactMethod> methods = {ContactMethod::Hertz, ContactMethod::Kp, ContactMethod::Analyn,
                                        ContactMethod::Mim1d, ContactMethod::Bem2d};
  std::vector<std::string> scenes;  //!< only these scenes (empty: all)
};

//! One method on one case.
struct StabilityRow {
  std::string scene;      //!< e.g. "elongated", "wheelrail_hollow"
  std::string case_name;  //!< e.g. "a/b=20", "depth=2mm dy=3.50mm"
  std::string method;     //!< rung name (method_name)
  double strip_width_m = 0.0;
  SolveStatus status = SolveStatus::InvalidInput;
  bool finite = true;                 //!< every number of the result is finite
  double area_error_rel = 0;          //!< |A - A_ref| / A_ref [-]; NaN when the reference has no contact or failed
  double max_pressure_error_rel = 0;  //!< |pmax - pmax_ref| / pmax_ref [-]; NaN as above
  double force_error_rel = 0;         //!< |N - N_ref| / N_ref [-]; NaN as above
  std::string reference;              //!< "hertz_analytic", "bem2d_0.1mm", ...
  SolveStatus reference_status = SolveStatus::Converged;
  double reference_area_m2 = 0.0;  //!< the reference's contact area [m^2]
  double min_patch_strips = 0.0;   //!< reference patch width / strip width (resolution of the case) [-]
  //! Full-contact pressure of the profile roughness the rung cannot sample (unresolved_roughness_pressure_Pa) over
  //! the reference's mean pressure N / A [-]; 0 on profiles without measurement noise.
  double roughness_pressure_ratio = 0.0;
  int iterations = 0;
  double time_s = 0.0;  //!< wall-clock time of the solve [s]

  //! max(area, max pressure) error [-] (NaN if either is NaN).
  [[nodiscard]] double error_rel() const noexcept;
};

//! Runs the matrix (serial; cases ordered scene, case, method).
[[nodiscard]] std::vector<StabilityRow> run_stability_matrix(const StabilityOptions& options);

//! The scene names run_stability_matrix knows, in order.
[[nodiscard]] std::vector<std::string> stability_scene_names();

//! Error bound ctab claims for `method` on a converged case whose reference exists, is resolved by at least
//! `kStabilityMinResolvedStrips` strips, and lies in the method's domain (stability_claim_applies); NaN: no claim.
[[nodiscard]] double stability_error_bound(const StabilityRow& row) noexcept;
//! Whether `row` lies where ctab claims the bound of stability_error_bound (also: roughness_pressure_ratio at most
//! kStabilityMaxRoughnessPressureRatio).
[[nodiscard]] bool stability_claim_applies(const StabilityRow& row) noexcept;
inline constexpr double kStabilityMinResolvedStrips = 8.0;
//! Largest roughness_pressure_ratio with a claim: the roughness below the rung's sampling carries less than this
//! share of the mean pressure, so the rung's smooth gap misses at most about this much of the pressure.
inline constexpr double kStabilityMaxRoughnessPressureRatio = 0.1;

//! Root-mean-square height [m] of the measurement noise left on a point profile at wavelengths shorter than two
//! strip widths (what strips of width `strip_width_m` cannot sample, Nyquist): white noise of standard deviation
//! `noise_sigma_m` on points spaced `point_spacing_m` [m] through the smoothing spline of length
//! `smoothing_length_m` [m] (the low-pass filter 1 / (1 + lambda omega^4), lambda = (L / 2 pi)^4; L = 0 interpolates
//! and keeps all of it): sigma^2 h / pi * int_{pi/w}^{pi/h} d omega / (1 + lambda omega^4)^2. 0 when w <= h.
[[nodiscard]] double unresolved_roughness_rms_m(double noise_sigma_m, double point_spacing_m, double smoothing_length_m,
                                                double strip_width_m);
//! The pressure [Pa] that presses that roughness flat: Johnson (1985, section 13.2; Westergaard) p* = pi E* A / lambda
//! for a sinusoid of amplitude A = sqrt(2) rms and wavelength lambda = 2 strip widths (the longest one unresolved),
//! E* the plane-strain modulus [Pa]. Where p* is not small against the mean contact pressure the roughness shapes
//! the pressure (peaks on the asperities) below the rung's strip width: the rung cannot be held to the reference.
[[nodiscard]] double unresolved_roughness_pressure_Pa(double roughness_rms_m, double strip_width_m,
                                                      double effective_modulus_Pa);

//! CSV of the rows (header line first; SI units; empty field for NaN).
[[nodiscard]] std::string stability_csv(const std::vector<StabilityRow>& rows);

//! The summary table: one line per scene and method, in the rows' order: cases, statuses, claimed and broken
//! cases, worst error against the reference, worst time, failures by status.
[[nodiscard]] std::string stability_summary(const std::vector<StabilityRow>& rows);

//! Whether a result holds a non-finite number or a claimed case breaks its error bound.
[[nodiscard]] bool stability_claims_broken(const std::vector<StabilityRow>& rows);

}  // namespace ctab::gen
