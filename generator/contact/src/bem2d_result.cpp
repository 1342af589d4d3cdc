// SPDX-License-Identifier: Apache-2.0
// bem2d result assembly: patches of contiguous loaded element rows, one strip per row.
#include <algorithm>

#include "bem2d_internal.hpp"

namespace ctab::gen::bem2d {

namespace {

// Row j's strip, or false when no element of the row is loaded.
bool row_strip(const ElementGrid& grid, const std::vector<double>& p, std::size_t j, StripSolution& strip,
               std::size_t& loaded) {
  const double* row = &p[j * grid.nx];
  std::size_t first = grid.nx, last = 0;
  double sum = 0.0, peak = 0.0;
  loaded = 0;
  for (std::size_t i = 0; i < grid.nx; ++i)
    if (row[i] > 0.0) {
      first = std::min(first, i);
      last = i;
      sum += row[i];
      peak = std::max(peak, row[i]);
      ++loaded;
    }
  if (loaded == 0) return false;
  strip.y_m = grid.y0 + static_cast<double>(j) * grid.dy;
  strip.half_length_m = 0.5 * static_cast<double>(last - first + 1) * grid.dx;
  strip.p0_Pa = peak;
  strip.load_N = sum * grid.dx * grid.dy;
  return true;
}

void close_patch(PatchSolution& patch, double dy, NormalSolution& solution) {
  if (patch.strips.empty()) return;
  double moment = 0.0;
  for (const StripSolution& s : patch.strips) moment += s.load_N * s.y_m;
  patch.centre_of_pressure_y_m = patch.normal_force_N > 0.0 ? moment / patch.normal_force_N : patch.strips.front().y_m;
  patch.y_min_m = patch.strips.front().y_m - 0.5 * dy;
  patch.y_max_m = patch.strips.back().y_m + 0.5 * dy;
  solution.normal_load_N += patch.normal_force_N;
  solution.patches.push_back(std::move(patch));
  patch = PatchSolution{};
}

}  // namespace

void assemble_solution(const ElementGrid& grid, const std::vector<double>& pressure, NormalSolution& solution) {
  solution.patches.clear();
  solution.normal_load_N = 0.0;
  PatchSolution patch;
  for (std::size_t j = 0; j < grid.ny; ++j) {
    StripSolution strip;
    std::size_t loaded = 0;
    if (!row_strip(grid, pressure, j, strip, loaded)) {
      close_patch(patch, grid.dy, solution);
      continue;
    }
    patch.normal_force_N += strip.load_N;
    patch.area_m2 += static_cast<double>(loaded) * grid.dx * grid.dy;
    patch.max_pressure_Pa = std::max(patch.max_pressure_Pa, strip.p0_Pa);
    patch.strips.push_back(strip);
  }
  close_patch(patch, grid.dy, solution);
}

bool loaded_at_border(const ElementGrid& grid, const std::vector<double>& pressure) {
  const auto row_loaded = [&](std::size_t j) {
    return std::any_of(pressure.begin() + static_cast<std::ptrdiff_t>(j * grid.nx),
                       pressure.begin() + static_cast<std::ptrdiff_t>((j + 1) * grid.nx),
                       [](double v) { return v > 0.0; });
  };
  if (grid.first_row_at_data_end && row_loaded(0)) return true;
  if (grid.last_row_at_data_end && row_loaded(grid.ny - 1)) return true;
  for (std::size_t j = 0; j < grid.ny; ++j)
    if (pressure[j * grid.nx] > 0.0 || pressure[j * grid.nx + grid.nx - 1] > 0.0) return true;
  return false;
}

void export_field(const ElementGrid& grid, const std::vector<double>& pressure, Bem2dPressureField& field) {
  field.nx = grid.nx;
  field.ny = grid.ny;
  field.dx_m = grid.dx;
  field.dy_m = grid.dy;
  field.x0_m = grid.x0;
  field.y0_m = grid.y0;
  field.pressure_Pa = pressure;
}

}  // namespace ctab::gen::bem2d
