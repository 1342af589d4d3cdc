// Table::load: copies a validated TableData into the query layout and precomputes, per dy cell and slot, the
// blending rule (README "Jumps"), and with PCHIP the Fritsch-Carlson slopes at every node.
#include <algorithm>
#include <cmath>

#include "ctab/lookup/table.hpp"

namespace ctab::lookup {

namespace {

bool succeeded(std::int8_t case_status) noexcept { return case_status >= 0; }  // converged or no contact

//! Fritsch-Carlson slope at a node from the secants of its interpolable neighbouring cells (uniform spacing:
//! the harmonic mean, 0 at an extremum; one-sided: that cell's secant, which keeps the cubic monotone).
double node_slope(bool has_left, double left, bool has_right, double right) noexcept {
  if (has_left && has_right) return left * right <= 0.0 ? 0.0 : 2.0 / (1.0 / left + 1.0 / right);
  if (has_left) return left;
  if (has_right) return right;
  return 0.0;
}

CellRule cell_rule(std::int8_t status_lo, std::int8_t status_hi, bool present_lo, bool present_hi, bool jump) noexcept {
  const bool ok_lo = succeeded(status_lo), ok_hi = succeeded(status_hi);
  if (ok_lo && ok_hi) return present_lo && present_hi && !jump ? CellRule::Interpolate : CellRule::Nearest;
  if (ok_lo) return CellRule::LowerOnly;
  if (ok_hi) return CellRule::UpperOnly;
  return CellRule::Nearest;
}

template <typename T>
void store(const std::vector<double>& from, std::vector<T>& to) {
  to.resize(from.size());
  std::transform(from.begin(), from.end(), to.begin(), [](double v) { return static_cast<T>(v); });
}

}  // namespace

LoadResult Table::load(const TableData& data, const LoadOptions& options) {
  *this = Table{};
  LoadResult result = validate(data);
  if (!result.ok()) return result;

  const std::size_t n_dy = data.n_dy(), n_2 = data.n_second(), n_slots = data.n_slots;
  const std::size_t patches = n_dy * n_2 * kWheels * n_slots;
  const double ddy = (data.dy_m.back() - data.dy_m.front()) / static_cast<double>(n_dy - 1);

  // Values (zero where absent), presence, rules.
  std::vector<double> values(data.quantities);
  present_.resize(patches);
  for (std::size_t p = 0; p < patches; ++p) {
    present_[p] = data.present[p] ? 1.0 : 0.0;
    if (!data.present[p]) std::fill_n(values.begin() + static_cast<std::ptrdiff_t>(p * kQuantities), kQuantities, 0.0);
  }
  std::vector<std::uint8_t> jump(patches, 0);  // by the patch index of the cell's lower end
  for (const Jump& j : data.jumps) jump[data.patch_index(j.i_dy, j.i_second, j.wheel, j.slot)] = 1;
  rules_.assign(patches, static_cast<std::uint8_t>(CellRule::Nearest));
  for (std::size_t i = 0; i + 1 < n_dy; ++i)
    for (std::size_t i2 = 0; i2 < n_2; ++i2)
      for (std::size_t w = 0; w < kWheels; ++w)
        for (std::size_t s = 0; s < n_slots; ++s) {
          const std::size_t lo = data.patch_index(i, i2, w, s), hi = data.patch_index(i + 1, i2, w, s);
          rules_[lo] = static_cast<std::uint8_t>(cell_rule(data.case_status[data.case_index(i, i2, w)],
                                                           data.case_status[data.case_index(i + 1, i2, w)],
                                                           data.present[lo] != 0, data.present[hi] != 0, jump[lo] != 0));
        }

  // Wheelset quantities: roll and delta r per (i_dy, i_second), always interpolable.
  wheelset_.resize(n_dy * n_2 * 2);
  for (std::size_t c = 0; c < n_dy * n_2; ++c) {
    wheelset_[2 * c] = data.roll_rad[c];
    wheelset_[2 * c + 1] = data.rolling_radius_difference_m[c];
  }

  std::vector<double> slopes;
  if (options.interpolation == CTAB_PCHIP) {
    const std::size_t row = n_2 * kWheels * n_slots;  // patches per dy value
    slopes.assign(values.size(), 0.0);
    for (std::size_t i = 0; i < n_dy; ++i)
      for (std::size_t k = 0; k < row; ++k) {
        const std::size_t p = i * row + k;
        const bool has_left = i >= 1 && rules_[p - row] == static_cast<std::uint8_t>(CellRule::Interpolate);
        const bool has_right = i + 1 < n_dy && rules_[p] == static_cast<std::uint8_t>(CellRule::Interpolate);
        for (std::size_t q = 0; q < kQuantities; ++q) {
          const double v = values[p * kQuantities + q];
          const double left = has_left ? (v - values[(p - row) * kQuantities + q]) / ddy : 0.0;
          const double right = has_right ? (values[(p + row) * kQuantities + q] - v) / ddy : 0.0;
          slopes[p * kQuantities + q] = node_slope(has_left, left, has_right, right);
        }
      }
    const std::size_t ws_row = n_2 * 2;
    wheelset_slopes_.assign(wheelset_.size(), 0.0);
    for (std::size_t i = 0; i < n_dy; ++i)
      for (std::size_t k = 0; k < ws_row; ++k) {
        const std::size_t p = i * ws_row + k;
        const double left = i >= 1 ? (wheelset_[p] - wheelset_[p - ws_row]) / ddy : 0.0;
        const double right = i + 1 < n_dy ? (wheelset_[p + ws_row] - wheelset_[p]) / ddy : 0.0;
        wheelset_slopes_[p] = node_slope(i >= 1, left, i + 1 < n_dy, right);
      }
  }

  if (options.single_precision) {
    store(values, values_f_);
    store(slopes, slopes_f_);
    store(data.strip_half_length_m, strip_a_f_);
    store(data.strip_peak_pressure_Pa, strip_p0_f_);
  } else {
    values_d_ = std::move(values);
    slopes_d_ = std::move(slopes);
    strip_a_d_ = data.strip_half_length_m;
    strip_p0_d_ = data.strip_peak_pressure_Pa;
  }
  status_ = data.case_status;
  second_ = data.second;
  second_kind_ = data.second_axis;
  interpolation_ = options.interpolation;
  n_slots_ = static_cast<std::uint32_t>(n_slots);
  strip_samples_ = static_cast<std::uint32_t>(data.strip_samples);
  dy0_ = data.dy_m.front();
  ddy_ = ddy;
  inv_ddy_ = 1.0 / ddy;
  n_dy_ = static_cast<std::uint32_t>(n_dy);
  return result;
}

std::size_t Table::memory_bytes() const noexcept {
  return sizeof(*this) + (values_d_.size() + slopes_d_.size() + present_.size() + wheelset_.size() +
                          wheelset_slopes_.size() + second_.size() + strip_a_d_.size() + strip_p0_d_.size()) * sizeof(double) +
         (values_f_.size() + slopes_f_.size() + strip_a_f_.size() + strip_p0_f_.size()) * sizeof(float) + rules_.size() + status_.size();
}

}  // namespace ctab::lookup
