// SPDX-License-Identifier: Apache-2.0
// Synthetic tables for the lookup tests (see synthetic_table.hpp).
#include "synthetic_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace ctab::lookup::test {

double synthetic_value(std::size_t q, std::size_t s, std::size_t w, double dy_m, double second) {
  const double k = static_cast<double>(q + 1) + 10.0 * static_cast<double>(s) + 100.0 * static_cast<double>(w);
  return k * (1.0 + 50.0 * dy_m) + 1e-5 * k * second;
}

TableData make_synthetic(const SyntheticOptions& o) {
  TableData data;
  const auto n_uniform = static_cast<std::size_t>(std::lround((o.dy_max_m - o.dy_min_m) / o.dy_step_m)) + 1;
  for (std::size_t i = 0; i < n_uniform; ++i) data.dy_m.push_back(o.dy_min_m + o.dy_step_m * static_cast<double>(i));
  if (o.refine_step_m > 0.0) {
    for (double dy = o.refine_from_m; dy <= o.refine_to_m + 1e-12; dy += o.refine_step_m) data.dy_m.push_back(dy);
    std::sort(data.dy_m.begin(), data.dy_m.end());
    data.dy_m.erase(std::unique(data.dy_m.begin(), data.dy_m.end(),
                                [](double a, double b) { return std::abs(a - b) < 1e-12; }),
                    data.dy_m.end());
  }
  if (!o.extra_dy_m.empty()) {
    data.dy_m.insert(data.dy_m.end(), o.extra_dy_m.begin(), o.extra_dy_m.end());
    std::sort(data.dy_m.begin(), data.dy_m.end());
    data.dy_m.erase(std::unique(data.dy_m.begin(), data.dy_m.end(), [](double a, double b) { return b - a < 0.2e-6; }),
                    data.dy_m.end());
  }
  const std::size_t n_dy = data.dy_m.size();
  for (std::size_t j = 0; j < o.n_second; ++j) data.second.push_back(60e3 + 20e3 * static_cast<double>(j));
  data.second_axis = SecondAxis::VerticalLoad;
  data.n_slots = 3;
  data.strip_samples = o.strip_samples;
  data.allocate();
  for (std::size_t i = 0; i < n_dy; ++i)
    for (std::size_t j = 0; j < o.n_second; ++j) {
      const double dy = data.dy_m[i], second = data.second[j];
      data.roll_rad[i * o.n_second + j] = 1e-3 * dy + 1e-9 * second;
      data.rolling_radius_difference_m[i * o.n_second + j] = 0.1 * dy;
      for (std::size_t w = 0; w < kWheels; ++w) {
        const double flange_from = o.flange_from_m + (o.second_row_flange_later && j >= 1 ? 1e-3 : 0.0);
        const bool present[3] = {true, dy >= flange_from, true};
        for (std::size_t s = 0; s < 3; ++s) {
          const std::size_t p = data.patch_index(i, j, w, s);
          data.present[p] = present[s] ? 1 : 0;
          if (!present[s]) continue;
          for (std::size_t q = 0; q < kQuantities; ++q)
            data.quantities[p * kQuantities + q] = synthetic_value(q, s, w, dy, second);
          if (s == 2 && dy >= o.moves_at_m) data.quantities[p * kQuantities + 11] += 5e-3;  // y_rail_m moves
          for (std::size_t k = 0; k < o.strip_samples; ++k) {
            data.strip_half_length_m[p * o.strip_samples + k] = 1e-3 * (1.0 + static_cast<double>(k)) * (1.0 + dy);
            data.strip_peak_pressure_Pa[p * o.strip_samples + k] = 1e9 * (1.0 + static_cast<double>(k) + 10.0 * dy);
          }
        }
        // Jumps: the flange appears, the spare slot moves (in the cells containing those points).
        const double next = i + 1 < n_dy ? data.dy_m[i + 1] : dy;
        if (i + 1 < n_dy && dy < flange_from && next >= flange_from)
          data.jumps.push_back({static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i),
                                static_cast<std::uint8_t>(w), 1, JumpKind::Appears});
        if (i + 1 < n_dy && dy < o.moves_at_m && next >= o.moves_at_m)
          data.jumps.push_back({static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i),
                                static_cast<std::uint8_t>(w), 2, JumpKind::Moves});
      }
    }
  if (o.failed_case) {
    std::size_t i = 0;  // the node at -8 mm
    while (i + 1 < n_dy && data.dy_m[i] < -8e-3 - 1e-12) ++i;
    data.case_status[data.case_index(i, 0, 0)] = -1;
    for (std::size_t s = 0; s < 3; ++s) {
      const std::size_t p = data.patch_index(i, 0, 0, s);
      data.present[p] = 0;
      for (std::size_t q = 0; q < kQuantities; ++q) data.quantities[p * kQuantities + q] = 0.0;
    }
  }
  return data;
}

double located_value(std::size_t q, std::size_t s, std::size_t w, double dy, double second, bool after,
                     bool& present) {
  present = s == 0 ? !after : s == 1 ? after : true;
  if (!present) return 0.0;
  const double weight = static_cast<double>(q + 1) + 10.0 * static_cast<double>(s) + 100.0 * static_cast<double>(w);
  return synthetic_value(q, s, w, dy, second) + (s == 2 && after ? kLocatedMove * weight : 0.0);
}

double located_jump(const LocatedOptions& o, std::size_t slot, std::size_t row) {
  return slot == 0 ? o.disappears_at_m[row] : slot == 1 ? o.appears_at_m[row] : o.moves_at_m[row];
}

namespace {

// The adaptive axis of make_located: the coarse nodes and, graded around every row's jumps, nodes down to the
// jump's 1 um cell.
std::vector<double> located_axis(const LocatedOptions& o) {
  std::vector<double> dy;
  const auto n = static_cast<std::size_t>(std::lround((o.dy_max_m - o.dy_min_m) / o.coarse_step_m));
  for (std::size_t i = 0; i <= n; ++i) dy.push_back(o.dy_min_m + o.coarse_step_m * static_cast<double>(i));
  for (std::size_t row = 0; row < o.appears_at_m.size(); ++row)
    for (std::size_t slot = 0; slot < 3; ++slot)
      for (const double offset : {kLocatedHalfCell, 3e-6, 20e-6, 100e-6}) {
        dy.push_back(located_jump(o, slot, row) - offset);
        dy.push_back(located_jump(o, slot, row) + offset);
      }
  std::sort(dy.begin(), dy.end());
  dy.erase(std::unique(dy.begin(), dy.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }), dy.end());
  return dy;
}

}  // namespace

TableData make_located(const LocatedOptions& o) {
  TableData data;
  data.dy_m = located_axis(o);
  const std::size_t n_dy = data.dy_m.size(), n_2 = o.appears_at_m.size();
  for (std::size_t j = 0; j < n_2; ++j) data.second.push_back(60e3 + 20e3 * static_cast<double>(j));
  data.n_slots = 3;
  data.strip_samples = 2;
  data.allocate();
  for (std::size_t i = 0; i < n_dy; ++i)
    for (std::size_t j = 0; j < n_2; ++j) {
      const double dy = data.dy_m[i], second = data.second[j];
      data.roll_rad[i * n_2 + j] = 1e-3 * dy;
      for (std::size_t w = 0; w < kWheels; ++w)
        for (std::size_t s = 0; s < 3; ++s) {
          const std::size_t p = data.patch_index(i, j, w, s);
          const double x = located_jump(o, s, j);
          bool present = false;
          for (std::size_t q = 0; q < kQuantities; ++q)
            data.quantities[p * kQuantities + q] = located_value(q, s, w, dy, second, dy > x, present);
          data.present[p] = present ? 1 : 0;
          for (std::size_t k = 0; present && k < 2; ++k) {
            data.strip_half_length_m[p * 2 + k] = data.quantities[p * kQuantities + CTAB_AREA_M2] * (1.0 + static_cast<double>(k));
            data.strip_peak_pressure_Pa[p * 2 + k] = data.quantities[p * kQuantities + CTAB_MAX_PRESSURE_PA];
          }
          if (i + 1 < n_dy && dy < x && data.dy_m[i + 1] > x) {
            const JumpKind kind = s == 0 ? JumpKind::Disappears : s == 1 ? JumpKind::Appears : JumpKind::Moves;
            data.jumps.push_back({static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i),
                                  static_cast<std::uint8_t>(w), static_cast<std::uint8_t>(s), kind});
          }
        }
    }
  return data;
}

SyntheticOptions adaptive_options() {
  SyntheticOptions o{.dy_step_m = 0.5e-3, .strip_samples = 32};
  for (std::size_t k = 0; k < 34; ++k) {
    const double centre = -11.62e-3 + 0.7e-3 * static_cast<double>(k);
    for (const double offset : {0.5e-6, 1.5e-6, 4e-6, 10e-6, 25e-6, 60e-6, 150e-6, 300e-6})
      o.extra_dy_m.insert(o.extra_dy_m.end(), {centre - offset, centre + offset});
  }
  return o;
}

bool identical(const std::vector<ctab_result>& a, const std::vector<ctab_result>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(ctab_result)) == 0;
}

std::vector<unsigned char> parse_c_header(const std::string& text) {
  std::vector<unsigned char> bytes;
  const std::size_t open = text.find("] = {"), close = text.find("};");
  std::istringstream in(text.substr(open + 5, close - open - 5));
  std::string token;
  while (std::getline(in, token, ','))
    if (token.find("0x") != std::string::npos)
      bytes.push_back(static_cast<unsigned char>(std::stoul(token, nullptr, 16)));
  return bytes;
}

}  // namespace ctab::lookup::test
