// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Safeguarded scalar root finding (Illinois variant of regula falsi): superlinear, never leaves its bracket.
#include <cmath>
#include <utility>

namespace ctab::gen {

struct RootResult {
  double x = 0.0;         //!< the root estimate
  double residual = 0.0;  //!< f(x)
  int iterations = 0;     //!< evaluations of f after the bracket
  bool converged = false;
};

//! Finds x in [lo, hi] with f(x) = 0, given f(lo) and f(hi) of opposite signs (or one of them zero).
//! Stops when |f(x)| <= f_tolerance or the bracket is narrower than x_tolerance.
template <class Function>
RootResult find_root_bracketed(Function&& f, double lo, double f_lo, double hi, double f_hi, double x_tolerance,
                               double f_tolerance, int max_iterations) {
  RootResult result;
  if (f_lo == 0.0) return {lo, 0.0, 0, true};
  if (f_hi == 0.0) return {hi, 0.0, 0, true};
  if ((f_lo > 0.0) == (f_hi > 0.0) || !std::isfinite(f_lo) || !std::isfinite(f_hi)) return result;
  int side = 0;
  for (int iteration = 1; iteration <= max_iterations; ++iteration) {
    double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(x > std::min(lo, hi) && x < std::max(lo, hi))) x = 0.5 * (lo + hi);
    const double fx = f(x);
    result = {x, fx, iteration, false};
    if (!std::isfinite(fx)) return result;
    if (std::abs(fx) <= f_tolerance || std::abs(hi - lo) <= x_tolerance) {
      result.converged = true;
      return result;
    }
    if ((fx > 0.0) == (f_hi > 0.0)) {
      hi = x;
      f_hi = fx;
      if (side == -1) f_lo *= 0.5;  // Illinois: halve the stale end point's value
      side = -1;
    } else {
      lo = x;
      f_lo = fx;
      if (side == +1) f_hi *= 0.5;
      side = +1;
    }
  }
  return result;
}

}  // namespace ctab::gen
