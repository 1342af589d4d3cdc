// SPDX-License-Identifier: Apache-2.0
// Table::strip_profile: a slot's resampled strip profile a(s), p0(s) at a prelooked point, blended sample by
// sample with the same per-slot weights as the patch quantities (always linear in dy, also in PCHIP tables).
#include <cmath>
#include <cstddef>

#include "blend.hpp"
#include "ctab/lookup/table.hpp"

namespace ctab::lookup {

ctab_status Table::strip_profile(const ctab_location& where, std::int32_t wheel, std::int32_t slot, double* s_m,
                                 double* half_length_m, double* peak_pressure_Pa, std::uint32_t capacity,
                                 std::uint32_t* count) const noexcept {
  if (count) *count = 0;
  if (!loaded()) return CTAB_NOT_LOADED;
  const std::size_t n_2 = second_.size();
  if (count == nullptr || !valid_location(where) || wheel < 0 || wheel > 1 || slot < 0 ||
      static_cast<std::uint32_t>(slot) >= n_slots_ || capacity < strip_samples_)
    return CTAB_INVALID_INPUT;
  const auto w = static_cast<std::uint32_t>(wheel), s = static_cast<std::uint32_t>(slot);
  // Weights of the four neighbouring cases: dy rule per row, then the row rule.
  const std::size_t rows[2] = {where.i_second, n_2 > 1 ? where.i_second + 1 : where.i_second};
  std::size_t cases[4];
  double weights[4], presence[2];
  const double step = where.f_dy >= 0.5 ? 1.0 : 0.0;
  for (std::size_t r = 0; r < 2; ++r) {
    cases[2 * r] = case_(where.i_dy, rows[r], w);
    cases[2 * r + 1] = case_(where.i_dy + 1, rows[r], w);
    const std::uint8_t rule = detail::rule_of(field(cases[2 * r], off_rule_ + s));
    const double w_hi = detail::upper_weight(rule, where.f_dy, step);
    weights[2 * r] = 1.0 - w_hi;
    weights[2 * r + 1] = w_hi;
  }
  // In a jump band a row whose own jump lies on the other side of the query gives its one-sided node (as query).
  if (const std::uint32_t band = n_2 > 1 ? detail::band_of(field(cases[0], off_rule_ + s)) : 0; band != 0) {
    std::uint32_t node[2];
    band_nodes(where, band, node);
    for (std::size_t r = 0; r < 2; ++r)
      if (node[r] != kNoNode) {
        cases[2 * r] = cases[2 * r + 1] = case_(node[r], rows[r], w);
        weights[2 * r] = 1.0;
        weights[2 * r + 1] = 0.0;
      }
  }
  for (std::size_t r = 0; r < 2; ++r)
    presence[r] = weights[2 * r] * field(cases[2 * r], off_present_ + s) +
                  weights[2 * r + 1] * field(cases[2 * r + 1], off_present_ + s);
  const double w1 = n_2 > 1 ? detail::row_weight(presence[0], presence[1], where.f_second) : 0.0;
  for (std::size_t k = 0; k < 4; ++k) weights[k] *= k < 2 ? 1.0 - w1 : w1;
  if ((1.0 - w1) * presence[0] + w1 * presence[1] < 0.5 || strip_samples_ == 0)
    return where.status == CTAB_CLAMPED ? CTAB_CLAMPED : CTAB_OK;

  const bool single = single_precision();
  const auto sample = [&](bool peak, std::size_t c, std::size_t i) {
    const std::size_t k = (c * n_slots_ + s) * strip_samples_ + i;  // strip arrays are per patch
    if (single) return static_cast<double>(peak ? strip_p0_f_[k] : strip_a_f_[k]);
    return peak ? strip_p0_d_[k] : strip_a_d_[k];
  };
  double s_min = 0.0, s_max = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    s_min += weights[k] * field(cases[k], s * kQuantities + CTAB_S_MIN_M);
    s_max += weights[k] * field(cases[k], s * kQuantities + CTAB_S_MAX_M);
  }
  const double spacing = (s_max - s_min) / static_cast<double>(strip_samples_ - 1);
  for (std::size_t i = 0; i < strip_samples_; ++i) {
    double a = 0.0, p0 = 0.0;
    for (std::size_t k = 0; k < 4; ++k) {
      a += weights[k] * sample(false, cases[k], i);
      p0 += weights[k] * sample(true, cases[k], i);
    }
    if (s_m) s_m[i] = s_min + spacing * static_cast<double>(i);
    if (half_length_m) half_length_m[i] = a;
    if (peak_pressure_Pa) peak_pressure_Pa[i] = p0;
  }
  *count = strip_samples_;
  return where.status == CTAB_CLAMPED ? CTAB_CLAMPED : CTAB_OK;
}

}  // namespace ctab::lookup
