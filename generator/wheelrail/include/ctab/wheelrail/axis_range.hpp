// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Validated uniform axes {start, stop, step} (lateral shifts, loads, approaches): the one builder shared by the
//! table config ([axes]) and `ctab geometry --dy-min/--dy-max/--dy-step`.
//!
//! Every check runs before any allocation, in double: finite start/stop/step, step > 0, stop >= start, at most
//! `max_points` points (the count floor((stop - start)/step + 1e-9) + 1 is formed in double, so a step of 1e-21
//! is an error, never an overflowed size_t), and consecutive values that stay distinct in floating point.
//! A range symmetric about zero is made exactly antisymmetric (values[n-1-i] = -values[i], 0 in the middle), so
//! that mirroring one wheel onto the other is exact.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ctab::gen {

//! Most points on one axis. Chosen: 10^6 shifts at 0.1 mm would span 100 m; any real sweep is far below.
inline constexpr std::size_t kMaxAxisPoints = 1'000'000;

enum class AxisProblem : std::int8_t {
  None = 0,
  NonFinite = 1,        //!< start, stop or step is NaN or infinite
  NonPositiveStep = 2,  //!< step <= 0
  StopBelowStart = 3,   //!< empty axis
  TooManyPoints = 4,    //!< more than max_points values
  StepTooSmall = 5,     //!< consecutive values coincide in floating point
};

struct UniformAxis {
  std::vector<double> values;  //!< the axis (empty unless problem == None)
  AxisProblem problem = AxisProblem::None;
  std::string part;     //!< "start", "stop", "step" or "" (the whole range) at fault
  std::string message;  //!< what was expected, e.g. "must be positive"
  [[nodiscard]] bool ok() const noexcept { return problem == AxisProblem::None; }
};

//! Number of points of {start, stop, step}, computed in double (NaN or huge for bad input; no allocation).
[[nodiscard]] inline double uniform_axis_point_count(double start, double stop, double step) noexcept {
  return std::floor((stop - start) / step + 1e-9) + 1.0;  // 1e-9: a stop reached up to rounding is included
}

//! Builds a validated uniform axis; never throws except std::bad_alloc.
[[nodiscard]] inline UniformAxis make_uniform_axis(double start, double stop, double step,
                                                   std::size_t max_points = kMaxAxisPoints) {
  UniformAxis axis;
  auto fail = [&](AxisProblem problem, const char* part, std::string message) {
    axis.problem = problem;
    axis.part = part;
    axis.message = std::move(message);
    return axis;
  };
  if (!std::isfinite(start)) return fail(AxisProblem::NonFinite, "start", "must be finite");
  if (!std::isfinite(stop)) return fail(AxisProblem::NonFinite, "stop", "must be finite");
  if (!std::isfinite(step)) return fail(AxisProblem::NonFinite, "step", "must be finite");
  if (!(step > 0.0)) return fail(AxisProblem::NonPositiveStep, "step", "must be positive");
  if (stop < start) return fail(AxisProblem::StopBelowStart, "stop", "must not be below start (empty axis)");
  const double count = uniform_axis_point_count(start, stop, step);
  if (!(count <= static_cast<double>(max_points)))
    return fail(AxisProblem::TooManyPoints, "",
                "more than " + std::to_string(max_points) + " values (" + std::to_string(count) +
                    "): reduce the range or increase the step");
  const auto n = static_cast<std::size_t>(count);
  axis.values.reserve(n);
  for (std::size_t i = 0; i < n; ++i) axis.values.push_back(start + step * static_cast<double>(i));
  for (std::size_t i = 1; i < n; ++i)
    if (!(axis.values[i] > axis.values[i - 1])) {
      axis.values.clear();
      return fail(AxisProblem::StepTooSmall, "step", "too small for the values (consecutive points coincide)");
    }
  if (n > 1 && std::abs(start + axis.values.back()) <= 1e-9 * step)
    for (std::size_t i = 0; i < n / 2; ++i) {
      axis.values[n - 1 - i] = -axis.values[i];
      if (n % 2 == 1) axis.values[n / 2] = 0.0;
    }
  return axis;
}

}  // namespace ctab::gen
