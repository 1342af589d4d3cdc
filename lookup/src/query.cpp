// SPDX-License-Identifier: Apache-2.0
// Table::prelookup and Table::query: index search (dy: arithmetic on a uniform axis, on an adaptive one an index of
// bounded size and a fixed-step binary search within an entry's cells; fixed-step binary search on the second axis) and interpolation of
// every slot's record, with the blending rules of docs/method.md "Tables: sweep, slots, jumps, refined axis". No allocation; one
// branch on the table's values (a cell in a jump band: lookup/README.md), bounded work either way; loops bounded by
// the table's sizes only.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "blend.hpp"
#include "ctab/lookup/table.hpp"
#include "ctab/tables/limits.hpp"

// On x86-64 Linux with GCC the query is compiled twice, for baseline x86-64 and for x86-64-v3 (AVX2, FMA), and
// the loader picks one once (ifunc); elsewhere it is compiled for the build's target only.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(CTAB_LOOKUP_NO_CLONES)
#define CTAB_LOOKUP_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define CTAB_LOOKUP_CLONES
#endif

namespace ctab::lookup {

namespace {

constexpr double kClampTolerance = 1e-9;  // in (end) cells: points this close outside the range count as inside

static_assert(sizeof(ctab_patch) == (kQuantities + 1) * sizeof(double), "ctab_patch: no padding (ctypes, memcmp)");

void zero_result(ctab_result& out, std::uint32_t slots, ctab_status status) noexcept {
  out.status = status;
  out.n_slots = static_cast<std::int32_t>(slots);
  out.worst_case_status = 0;
  std::memset(out.neighbour_status, 0, sizeof out.neighbour_status);
  out.dy_m = out.second = out.roll_rad = out.rolling_radius_difference_m = 0.0;
  std::memset(out.patch, 0, sizeof(ctab_patch) * slots);
  for (std::size_t s = slots; s < kMaxSlots; ++s) out.patch[s].present = 0;
}

void set_presence(ctab_patch& patch, double presence) noexcept {
  patch.present = presence > 0.5 ? 1 : 0;
  patch.reserved = 0;
}

}  // namespace

void fill_not_loaded(ctab_result& out) noexcept { zero_result(out, 0, CTAB_NOT_LOADED); }

void Table::prelookup(double dy_m, double second, ctab_location& out) const noexcept {
  out = ctab_location{};
  if (!loaded()) {
    out.status = CTAB_NOT_LOADED;
    return;
  }
  const std::size_t n_2 = second_.size();
  const bool finite = std::isfinite(dy_m) && (n_2 == 1 || std::isfinite(second));
  // dy: arithmetic on a uniform axis; on an adaptive one the index entry of the point, then a binary search of a
  // fixed number of steps among the cells that entry can hold (Table::dy_search_length_ from its cell less one).
  const double first = dy_.front(), last = dy_.back();
  const double d = finite ? dy_m : first;
  bool clamped = false;
  if (uniform_dy_) {
    const double n_cells = static_cast<double>(n_dy_ - 1);
    const double x = (d - first) * inv_mean_step_;
    const double x_clamped = std::min(std::max(x, 0.0), n_cells);
    const std::uint32_t i = std::min(static_cast<std::uint32_t>(x_clamped), n_dy_ - 2);
    clamped = x < -kClampTolerance || x > n_cells + kClampTolerance;
    out.i_dy = i;
    out.f_dy = x_clamped - static_cast<double>(i);
    out.dy_m = first + cell_width_.front() * x_clamped;
  } else {
    const double d_clamped = std::min(std::max(d, first), last);
    clamped = d < first - kClampTolerance * cell_width_.front() || d > last + kClampTolerance * cell_width_.back();
    const auto k = std::min(static_cast<std::size_t>((d_clamped - first) * inv_index_step_), dy_index_.size() - 1);
    const std::uint32_t n_cells = n_dy_ - 1;
    std::uint32_t i = std::min(dy_index_[k] - (dy_index_[k] > 0 ? 1u : 0u), n_cells - dy_search_length_);
    for (std::uint32_t length = dy_search_length_; length > 1;) {  // the largest i with dy_[i] <= d, or the first
      const std::uint32_t half = length / 2;
      i = dy_[i + half] <= d_clamped ? i + half : i;
      length -= half;
    }
    out.i_dy = i;
    out.f_dy = std::min(std::max((d_clamped - dy_[i]) * inv_cell_width_[i], 0.0), 1.0);
    out.dy_m = d_clamped;
  }
  // Second axis: binary search with a fixed number of steps (ceil(log2 n)), independent of the value.
  if (n_2 > 1) {
    const double s = finite ? second : second_.front();
    const double s_clamped = std::min(std::max(s, second_.front()), second_.back());
    clamped = clamped || s < second_.front() || s > second_.back();
    std::size_t base = 0, length = n_2;
    while (length > 1) {
      const std::size_t half = length / 2;
      base = second_[base + half] <= s_clamped ? base + half : base;
      length -= half;
    }
    const std::size_t j = std::min(base, n_2 - 2);
    out.i_second = static_cast<std::uint32_t>(j);
    out.f_second = std::min(1.0, (s_clamped - second_[j]) / (second_[j + 1] - second_[j]));
    out.second = s_clamped;
  } else {
    out.second = second_.front();
  }
  out.status = !finite ? CTAB_INVALID_INPUT : clamped ? CTAB_CLAMPED : CTAB_OK;
  if (!finite) {
    out.i_dy = out.i_second = 0;
    out.f_dy = out.f_second = out.dy_m = out.second = 0.0;
  }
}

bool Table::valid_location(const ctab_location& where) const noexcept {
  const std::size_t n_2 = second_.size();
  const bool second_ok = n_2 == 1 ? where.i_second == 0 : tables::cell_in_range(where.i_second, n_2);
  return (where.status == CTAB_OK || where.status == CTAB_CLAMPED) && where.reserved == 0 &&
         tables::cell_in_range(where.i_dy, n_dy_) && second_ok && where.f_dy >= 0.0 && where.f_dy <= 1.0 &&
         where.f_second >= 0.0 && where.f_second <= 1.0 && std::isfinite(where.dy_m) && std::isfinite(where.second);
}

template <typename T, bool kCubic>
[[gnu::always_inline]] inline double Table::dy_slot(const T* __restrict lo, const T* __restrict hi,
                                                    const T* __restrict slope_lo, const T* __restrict slope_hi,
                                                    std::size_t slot, const DyBasis& basis,
                                                    double* __restrict v) const noexcept {
  const std::uint8_t rule = detail::rule_of(lo[off_rule_ + slot]);
  const double w_hi = detail::upper_weight(rule, basis.f, basis.step), w_lo = 1.0 - w_hi;
  const T* __restrict a = lo + slot * kQuantities;
  const T* __restrict b = hi + slot * kQuantities;
  if constexpr (kCubic) {
    const double cubic = detail::kF[rule];  // 1 where the cell interpolates
    const double a0 = cubic * basis.h00 + (1.0 - cubic) * w_lo, a1 = cubic * basis.h01 + (1.0 - cubic) * w_hi;
    const double b0 = cubic * basis.h10, b1 = cubic * basis.h11;
    const T* __restrict da = slope_lo + slot * kQuantities;
    const T* __restrict db = slope_hi + slot * kQuantities;
    for (std::size_t q = 0; q < kQuantities; ++q)
      v[q] = a0 * static_cast<double>(a[q]) + a1 * static_cast<double>(b[q]) + b0 * static_cast<double>(da[q]) +
             b1 * static_cast<double>(db[q]);
  } else {
    for (std::size_t q = 0; q < kQuantities; ++q)
      v[q] = w_lo * static_cast<double>(a[q]) + w_hi * static_cast<double>(b[q]);
  }
  return w_lo * static_cast<double>(lo[off_present_ + slot]) + w_hi * static_cast<double>(hi[off_present_ + slot]);
}

void Table::band_nodes(const ctab_location& where, std::uint32_t band, std::uint32_t node[2]) const noexcept {
  const JumpBand& b = bands_[band];
  const double g = where.f_second;
  const bool after = where.dy_m >= (1.0 - g) * b.x_lo + g * b.x_hi;  // the query's side of the interpolated jump
  const std::uint32_t cells[2] = {b.cell_lo, b.cell_hi};
  for (std::size_t r = 0; r < 2; ++r) {
    // The row's own side at this point: past its jump cell, or in it at or past the midpoint (CellRule::Nearest).
    const bool own_after = where.i_dy > cells[r] || (where.i_dy == cells[r] && where.f_dy >= 0.5);
    node[r] = own_after == after ? kNoNode : cells[r] + (after ? 1u : 0u);
  }
}

template <typename T>
[[gnu::always_inline]] inline double Table::node_slot(std::size_t c, std::size_t slot, double* v) const noexcept {
  const T* record = records<T>() + c * stride_;
  for (std::size_t q = 0; q < kQuantities; ++q) v[q] = static_cast<double>(record[slot * kQuantities + q]);
  return static_cast<double>(record[off_present_ + slot]);
}

template <typename T>
[[gnu::noinline]] void Table::band_rows(const ctab_location& where, std::uint32_t wheel, std::size_t slot,
                                       std::uint32_t band, double* v0, double& p0, double* v1,
                                       double& p1) const noexcept {
  std::uint32_t node[2];
  band_nodes(where, band, node);
  if (node[0] != kNoNode) p0 = node_slot<T>(case_(node[0], where.i_second, wheel), slot, v0);
  if (node[1] != kNoNode) p1 = node_slot<T>(case_(node[1], where.i_second + 1, wheel), slot, v1);
}

template <typename T, bool kCubic>
[[gnu::always_inline]] inline void Table::wheelset(const ctab_location& where, std::uint32_t wheel,
                                                   const DyBasis& basis, ctab_result& out) const noexcept {
  const T* records_ = records<T>();
  const T* slopes = slope_records<T>();
  const std::size_t n_2 = second_.size();
  const std::size_t i2_hi = n_2 > 1 ? where.i_second + 1 : where.i_second;
  const double g = n_2 > 1 ? where.f_second : 0.0;
  const double a0 = kCubic ? basis.h00 : 1.0 - basis.f, a1 = kCubic ? basis.h01 : basis.f;
  const std::size_t cases[4] = {case_(where.i_dy, where.i_second, wheel), case_(where.i_dy + 1, where.i_second, wheel),
                                case_(where.i_dy, i2_hi, wheel), case_(where.i_dy + 1, i2_hi, wheel)};
  double row[2][2];
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t k = 0; k < 2; ++k) {
      const std::size_t lo = cases[2 * r] * stride_ + off_roll_ + k, hi = cases[2 * r + 1] * stride_ + off_roll_ + k;
      row[r][k] = a0 * static_cast<double>(records_[lo]) + a1 * static_cast<double>(records_[hi]);
      if constexpr (kCubic)
        row[r][k] += basis.h10 * static_cast<double>(slopes[lo]) + basis.h11 * static_cast<double>(slopes[hi]);
    }
  out.roll_rad = (1.0 - g) * row[0][0] + g * row[1][0];
  out.rolling_radius_difference_m = (1.0 - g) * row[0][1] + g * row[1][1];
  std::int8_t statuses[4];
  for (std::size_t k = 0; k < 4; ++k)
    statuses[k] = static_cast<std::int8_t>(records_[cases[k] * stride_ + off_status_]);
  std::memcpy(out.neighbour_status, statuses, sizeof statuses);
  out.worst_case_status = std::min(std::min(statuses[0], statuses[1]), std::min(statuses[2], statuses[3]));
}

template <typename T, bool kCubic>
[[gnu::always_inline]] inline void Table::query_rows(const ctab_location& where, std::uint32_t wheel,
                                                     ctab_result& out) const noexcept {
  const T* records_ = records<T>();
  const T* slopes = slope_records<T>();
  // Hermite basis on the unit cell (slopes are per metre, hence the factor of the cell's width).
  DyBasis basis;
  const double width = cell_width_[where.i_dy];
  const double f = where.f_dy, f2 = f * f, f3 = f2 * f;
  basis.f = f;
  basis.step = f >= 0.5 ? 1.0 : 0.0;
  basis.h00 = 2.0 * f3 - 3.0 * f2 + 1.0;
  basis.h01 = -2.0 * f3 + 3.0 * f2;
  basis.h10 = (f3 - 2.0 * f2 + f) * width;
  basis.h11 = (f3 - f2) * width;
  const std::size_t lo0 = case_(where.i_dy, where.i_second, wheel) * stride_;
  const std::size_t hi0 = case_(where.i_dy + 1, where.i_second, wheel) * stride_;
  const T* slope_lo0 = kCubic ? slopes + lo0 : nullptr;
  const T* slope_hi0 = kCubic ? slopes + hi0 : nullptr;
  if (second_.size() == 1) {  // straight into the result
    for (std::size_t s = 0; s < n_slots_; ++s)
      set_presence(out.patch[s],
                   dy_slot<T, kCubic>(records_ + lo0, records_ + hi0, slope_lo0, slope_hi0, s, basis, out.patch[s].q));
  } else {
    const std::size_t lo1 = case_(where.i_dy, where.i_second + 1, wheel) * stride_;
    const std::size_t hi1 = case_(where.i_dy + 1, where.i_second + 1, wheel) * stride_;
    const T* slope_lo1 = kCubic ? slopes + lo1 : nullptr;
    const T* slope_hi1 = kCubic ? slopes + hi1 : nullptr;
    const double g = where.f_second;
    double v1[kQuantities];
    for (std::size_t s = 0; s < n_slots_; ++s) {
      double* v0 = out.patch[s].q;
      double p0 = dy_slot<T, kCubic>(records_ + lo0, records_ + hi0, slope_lo0, slope_hi0, s, basis, v0);
      double p1 = dy_slot<T, kCubic>(records_ + lo1, records_ + hi1, slope_lo1, slope_hi1, s, basis, v1);
      // In a jump band a row whose own jump lies on the other side of the query gives its one-sided value.
      if (const std::uint32_t band = detail::band_of(records_[lo0 + off_rule_ + s]); band != 0) [[unlikely]]
        band_rows<T>(where, wheel, s, band, v0, p0, v1, p1);
      const double w1 = detail::row_weight(p0, p1, g), w0 = 1.0 - w1;
      for (std::size_t q = 0; q < kQuantities; ++q) v0[q] = w0 * v0[q] + w1 * v1[q];
      set_presence(out.patch[s], w0 * p0 + w1 * p1);
    }
  }
  wheelset<T, kCubic>(where, wheel, basis, out);
}

CTAB_LOOKUP_CLONES void Table::query(const ctab_location& where, std::int32_t wheel, ctab_result& out) const noexcept {
  if (!loaded()) {
    zero_result(out, 0, CTAB_NOT_LOADED);
    return;
  }
  if (!valid_location(where) || (wheel != 0 && wheel != 1)) {
    zero_result(out, n_slots_, where.status == CTAB_NOT_LOADED ? CTAB_NOT_LOADED : CTAB_INVALID_INPUT);
    return;
  }
  const auto w = static_cast<std::uint32_t>(wheel);
  const bool single = single_precision();
  if (interpolation_ == CTAB_PCHIP) {
    if (single) query_rows<float, true>(where, w, out);
    else query_rows<double, true>(where, w, out);
  } else {
    if (single) query_rows<float, false>(where, w, out);
    else query_rows<double, false>(where, w, out);
  }
  for (std::size_t s = n_slots_; s < kMaxSlots; ++s) out.patch[s].present = 0;
  out.status = where.status;
  out.n_slots = static_cast<std::int32_t>(n_slots_);
  out.dy_m = where.dy_m;
  out.second = where.second;
}

}  // namespace ctab::lookup
