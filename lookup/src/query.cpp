// Table::prelookup and Table::query: index search (arithmetic on the uniform dy axis, fixed-step binary search on
// the second axis) and interpolation of every slot's record, with the blending rules of README "Jumps".
// No allocation, no branch on the table's values, loops bounded by the table's sizes only.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "blend.hpp"
#include "ctab/lookup/table.hpp"

namespace ctab::lookup {

namespace {

constexpr double kClampTolerance = 1e-9;  // in cells: points this close outside the range count as inside

static_assert(sizeof(ctab_patch) == (kQuantities + 1) * sizeof(double), "ctab_patch: quantities then flags");

void zero_result(ctab_result& out, std::uint32_t slots, ctab_status status) noexcept {
  out.status = status;
  out.n_slots = static_cast<std::int32_t>(slots);
  out.worst_case_status = 0;
  std::memset(out.neighbour_status, 0, sizeof out.neighbour_status);
  out.dy_m = out.second = out.roll_rad = out.rolling_radius_difference_m = 0.0;
  std::memset(out.patch, 0, sizeof(ctab_patch) * slots);
  for (std::size_t s = slots; s < kMaxSlots; ++s) out.patch[s].present = 0;
}

void write_patch(ctab_patch& patch, const double* values, double presence) noexcept {
  std::memcpy(&patch, values, kQuantities * sizeof(double));
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
  // dy: arithmetic index on the uniform axis.
  const double last = static_cast<double>(n_dy_ - 1);
  const double x = finite ? (dy_m - dy0_) * inv_ddy_ : 0.0;
  const double x_clamped = std::min(std::max(x, 0.0), last);
  const std::uint32_t i = std::min(static_cast<std::uint32_t>(x_clamped), n_dy_ - 2);
  bool clamped = x < -kClampTolerance || x > last + kClampTolerance;
  out.i_dy = i;
  out.f_dy = x_clamped - static_cast<double>(i);
  out.dy_m = dy0_ + ddy_ * x_clamped;
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

template <typename T, bool kCubic>
void Table::dy_row(const T* values, const T* slopes, std::size_t lo_case, std::size_t hi_case, std::size_t rule_index,
                   double f, double* row, double* presence) const noexcept {
  const double step = f >= 0.5 ? 1.0 : 0.0;
  // Hermite basis on the unit cell (slopes are per metre, hence the factor ddy).
  const double f2 = f * f, f3 = f2 * f;
  const double h00 = 2.0 * f3 - 3.0 * f2 + 1.0, h01 = -2.0 * f3 + 3.0 * f2;
  const double h10 = (f3 - 2.0 * f2 + f) * ddy_, h11 = (f3 - f2) * ddy_;
  for (std::size_t s = 0; s < n_slots_; ++s) {
    const std::uint8_t rule = rules_[rule_index + s];
    const double w_hi = detail::upper_weight(rule, f, step);
    const double w_lo = 1.0 - w_hi;
    presence[s] = w_lo * present_[lo_case + s] + w_hi * present_[hi_case + s];
    const T* lo = values + (lo_case + s) * kQuantities;
    const T* hi = values + (hi_case + s) * kQuantities;
    double* v = row + s * kQuantities;
    if constexpr (kCubic) {
      const double cubic = detail::kF[rule];  // 1 where the cell interpolates
      const double a0 = cubic * h00 + (1.0 - cubic) * w_lo, a1 = cubic * h01 + (1.0 - cubic) * w_hi;
      const double b0 = cubic * h10, b1 = cubic * h11;
      const T* d_lo = slopes + (lo_case + s) * kQuantities;
      const T* d_hi = slopes + (hi_case + s) * kQuantities;
      for (std::size_t q = 0; q < kQuantities; ++q)
        v[q] = a0 * static_cast<double>(lo[q]) + a1 * static_cast<double>(hi[q]) + b0 * static_cast<double>(d_lo[q]) +
               b1 * static_cast<double>(d_hi[q]);
    } else {
      for (std::size_t q = 0; q < kQuantities; ++q)
        v[q] = w_lo * static_cast<double>(lo[q]) + w_hi * static_cast<double>(hi[q]);
    }
  }
}

template <typename T, bool kCubic>
void Table::query_rows(const ctab_location& where, std::uint32_t wheel, ctab_result& out) const noexcept {
  const T* values = nullptr;
  const T* slopes = nullptr;
  if constexpr (sizeof(T) == sizeof(float)) {
    values = values_f_.data();
    slopes = slopes_f_.data();
  } else {
    values = values_d_.data();
    slopes = slopes_d_.data();
  }
  double row0[kMaxSlots * kQuantities], presence0[kMaxSlots];
  const std::size_t lo0 = patch_(where.i_dy, where.i_second, wheel), hi0 = patch_(where.i_dy + 1, where.i_second, wheel);
  dy_row<T, kCubic>(values, slopes, lo0, hi0, lo0, where.f_dy, row0, presence0);
  if (second_.size() == 1) {
    for (std::size_t s = 0; s < n_slots_; ++s) write_patch(out.patch[s], row0 + s * kQuantities, presence0[s]);
    return;
  }
  double row1[kMaxSlots * kQuantities], presence1[kMaxSlots];
  const std::size_t lo1 = patch_(where.i_dy, where.i_second + 1, wheel);
  const std::size_t hi1 = patch_(where.i_dy + 1, where.i_second + 1, wheel);
  dy_row<T, kCubic>(values, slopes, lo1, hi1, lo1, where.f_dy, row1, presence1);
  const double g = where.f_second;
  for (std::size_t s = 0; s < n_slots_; ++s) {
    const double w1 = detail::row_weight(presence0[s], presence1[s], g), w0 = 1.0 - w1;
    double v[kQuantities];
    for (std::size_t q = 0; q < kQuantities; ++q) v[q] = w0 * row0[s * kQuantities + q] + w1 * row1[s * kQuantities + q];
    write_patch(out.patch[s], v, w0 * presence0[s] + w1 * presence1[s]);
  }
}

void Table::wheelset(const ctab_location& where, ctab_result& out) const noexcept {
  const std::size_t n_2 = second_.size();
  const std::size_t i2_hi = n_2 > 1 ? where.i_second + 1 : where.i_second;
  const double f = where.f_dy, g = n_2 > 1 ? where.f_second : 0.0;
  const bool cubic = interpolation_ == CTAB_PCHIP;
  const double f2 = f * f, f3 = f2 * f;
  const double a0 = cubic ? 2.0 * f3 - 3.0 * f2 + 1.0 : 1.0 - f, a1 = 1.0 - a0;
  const double b0 = cubic ? (f3 - 2.0 * f2 + f) * ddy_ : 0.0, b1 = cubic ? (f3 - f2) * ddy_ : 0.0;
  double result[2] = {0.0, 0.0};
  const std::size_t rows[2] = {where.i_second, i2_hi};
  const double row_weights[2] = {1.0 - g, g};
  for (std::size_t r = 0; r < 2; ++r) {
    const std::size_t lo = (where.i_dy * n_2 + rows[r]) * 2, hi = ((where.i_dy + 1) * n_2 + rows[r]) * 2;
    for (std::size_t k = 0; k < 2; ++k) {
      double v = a0 * wheelset_[lo + k] + a1 * wheelset_[hi + k];
      if (cubic) v += b0 * wheelset_slopes_[lo + k] + b1 * wheelset_slopes_[hi + k];
      result[k] += row_weights[r] * v;
    }
  }
  out.roll_rad = result[0];
  out.rolling_radius_difference_m = result[1];
}

void Table::query(const ctab_location& where, std::int32_t wheel, ctab_result& out) const noexcept {
  if (!loaded()) {
    zero_result(out, 0, CTAB_NOT_LOADED);
    return;
  }
  const bool valid = where.status >= 0 && (wheel == 0 || wheel == 1) && where.i_dy + 1 < n_dy_ &&
                     where.i_second < second_.size() && (second_.size() == 1 || where.i_second + 1 < second_.size()) &&
                     where.f_dy >= 0.0 && where.f_dy <= 1.0 && where.f_second >= 0.0 && where.f_second <= 1.0;
  if (!valid) {
    zero_result(out, n_slots_, where.status == CTAB_NOT_LOADED ? CTAB_NOT_LOADED : CTAB_INVALID_INPUT);
    return;
  }
  const auto w = static_cast<std::uint32_t>(wheel);
  const bool single = !values_f_.empty();
  if (interpolation_ == CTAB_PCHIP) {
    if (single) query_rows<float, true>(where, w, out);
    else query_rows<double, true>(where, w, out);
  } else {
    if (single) query_rows<float, false>(where, w, out);
    else query_rows<double, false>(where, w, out);
  }
  for (std::size_t s = n_slots_; s < kMaxSlots; ++s) out.patch[s].present = 0;
  wheelset(where, out);
  const std::size_t n_2 = second_.size();
  const std::size_t i2_hi = n_2 > 1 ? where.i_second + 1 : where.i_second;
  const std::int8_t statuses[4] = {status_[(where.i_dy * n_2 + where.i_second) * kWheels + w],
                                   status_[((where.i_dy + 1) * n_2 + where.i_second) * kWheels + w],
                                   status_[(where.i_dy * n_2 + i2_hi) * kWheels + w],
                                   status_[((where.i_dy + 1) * n_2 + i2_hi) * kWheels + w]};
  std::memcpy(out.neighbour_status, statuses, sizeof statuses);
  out.worst_case_status = std::min(std::min(statuses[0], statuses[1]), std::min(statuses[2], statuses[3]));
  out.status = where.status;
  out.n_slots = static_cast<std::int32_t>(n_slots_);
  out.dy_m = where.dy_m;
  out.second = where.second;
}

}  // namespace ctab::lookup
