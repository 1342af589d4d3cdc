// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Noise-aware smoothing of a point profile whose curvature may change fast or jump (`--smoothing auto` on noisy
//! points). Penalised least squares in summed-chord arc length s, each coordinate x in {y, z}:
//!   minimise sum_i w_i (x_i - f_i)^2 + lambda sum_j rho_j c_j (f'''_j)^2,   lambda = (L / 2 pi)^6,
//! f'''_j the third derivative of window j (3! times the divided difference over points j..j+3), c_j its length /3,
//! w_i the trapezoid weights: a discrete smoothing spline of order 3, the low-pass filter 1 / (1 + lambda omega^6)
//! (Whittaker 1923; Eilers 2003). Penalising the third derivative leaves a curvature that changes linearly
//! untouched (the cubic spline's second-derivative penalty flattens it over L). The weights rho_j follow the
//! derivative of the curvature, dkappa/ds = N . f''' (N the unit normal), by iteratively reweighted least squares
//! with Huber's weight rho = min(1, tau / |dkappa/ds|) (Huber 1964): where the profile's own curvature changes
//! faster than noise can make it (tau a multiple of the noise's dkappa/ds), the penalty gives way in proportion,
//! so jumps and fast changes keep their shape while the running surfaces keep the full length L.
//!
//! Noise hides how the curvature changes over a few mm: at 5 um on points every 0.1 mm, a 9.2 /m jump (60E1's R300 to
//! R80) and a linear change over the same 10 mm fit the points equally well (the likelihood ratio of the jump over a
//! cubic: median 5.7 against 10 at the 99th percentile of pure noise), yet a contact on the jump sees max pressures
//! 7-15 % apart. What the data cannot say the prior does. The smooth prior (the default) spreads such a jump over
//! L rho^(1/6); the arcs prior takes the profile for circular arcs and straight lines, as new rails and many wheel
//! profiles are drawn: it finds the junctions (the optimal partition of the points into arcs, quadratic_segmentation)
//! and frees the penalty of the one window that straddles each, so the curvature jumps there, then smooths the arcs
//! between the junctions with 1.5 times the length and a penalty on the departure from a circle (kArcLengthFactor). On a
//! profile that is not made of arcs (S1002's polynomial tread) the arcs prior finds a junction every few mm and is
//! worse than the smooth prior (docs/method.md "Curvature and smoothing").
#include <cstddef>
#include <vector>

namespace ctab::gen {

//! What the smoother assumes of the profile's curvature where noise hides it.
enum class CurvaturePrior {
  Smooth = 0,  //!< changes linearly but for what the data show beyond noise (worn, measured, polynomial profiles)
  Arcs = 1,    //!< constant between junctions (circular arcs and straight lines: new rails, arc-defined wheels)
};

//! Points smoothed by smooth_adaptively.
struct AdaptivelySmoothedPoints {
  std::vector<double> y_m, z_m;      //!< the smoothed points, one per input point [m]
  double length_m = 0.0;             //!< the length L used [m] (kArcLengthFactor times the one asked for, arcs prior)
  double shortest_length_m = 0.0;    //!< the shortest local smoothing length L rho^(1/6) away from junctions [m]
  std::vector<double> junction_y_m;  //!< where the arcs prior let the curvature jump [m] (none for the smooth prior)
};

//! Huber's threshold tau in standard deviations of the smoothed noise's dkappa/ds (calibrated with 5 um noise on
//! S1002 and 60E1, 10 seeds, tests/generator/profile_noise_test.cpp: 7, 10 and 14 give the worst max pressure
//! 5.1 / 4.7 / 4.3 % on the wheel and 13.9 / 14.5 / 15.7 % on the rail).
inline constexpr double kAdaptiveHuberThreshold = 10.0;
//! Passes of the reweighting. The weights still move slowly: 15, 30 and 60 passes give the rail's worst max
//! pressure 15.5 / 14.5 / 13.5 % and the wheel's worst area 4.3 / 2.8 / 2.6 % (5 um, seeds 1-3); the README's
//! figures are for 30.
inline constexpr int kAdaptiveIterations = 30;
//! Arcs prior: the penalty per piece of the partition into arcs, in noise variances (quadratic_segmentation.hpp).
//! 60E1 1:40 with 5 um noise (10 seeds): worst max pressure 8.2 / 4.8 / 4.8 % at 15, 30 and 60 (at 15 some seed
//! gains a junction noise made); chosen 30.
inline constexpr double kArcJunctionPenalty = 30.0;
//! Arcs prior: the length between the junctions, as a multiple of the one asked for. There the penalty is on the
//! departure of the third derivative from a circle's (f''' + kappa^2 T), which leaves an arc untouched, so a longer
//! length mostly lowers the noise. 60E1 1:40 with 5 um noise on points every 0.1 mm (10 seeds) reads its worst max
//! pressure 4.8 / 5.9 / 6.6 / 7.5 % at 1.5, 2, 2.5 and 3 (the plain third-derivative penalty, which bends arcs: 6.4 /
//! 5.6 / 5.5 % at 1, 1.5, 2); at 1.5 and 0.025 / 0.05 / 0.2 mm spacing (3 seeds) 2.1 / 2.5 / 4.0 %. Chosen: 1.5.
inline constexpr double kArcLengthFactor = 1.5;
//! Arcs prior: the fewest points of a piece (chosen; 1 mm at 0.1 mm spacing).
inline constexpr std::size_t kArcMinPoints = 10;

//! Smooths points (y, z) [m], ordered with increasing y, of measured noise sigma [m] normal to the profile, with
//! length L [m]. sigma and L > 0, at least 8 points.
[[nodiscard]] AdaptivelySmoothedPoints smooth_adaptively(const std::vector<double>& y, const std::vector<double>& z,
                                                         double length_m, double noise_sigma_m,
                                                         CurvaturePrior prior = CurvaturePrior::Smooth);

//! Standard deviation [1/m] of the second derivative (the curvature) that the order-3 smoother of length L [m]
//! leaves of white noise sigma [m] on points spaced h [m]:
//! Var f'' = sigma^2 h / (2 pi) int omega^4 / (1 + lambda omega^6)^2 d omega = sigma^2 h lambda^(-5/6) / 18.
[[nodiscard]] double adaptive_curvature_noise_per_m(double noise_sigma_m, double point_spacing_m,
                                                    double smoothing_length_m);
//! The inverse: the length [m] that leaves curvature noise `curvature_noise_per_m` [1/m].
[[nodiscard]] double adaptive_length_for_curvature_noise_m(double noise_sigma_m, double point_spacing_m,
                                                           double curvature_noise_per_m);
//! Standard deviation [1/m^2] of the third derivative (dkappa/ds) of the smoothed noise:
//! Var f''' = sigma^2 h / (2 pi) int omega^6 / (1 + lambda omega^6)^2 d omega = sigma^2 h lambda^(-7/6) / 18.
[[nodiscard]] double adaptive_curvature_slope_noise_per_m2(double noise_sigma_m, double point_spacing_m,
                                                           double smoothing_length_m);

}  // namespace ctab::gen
