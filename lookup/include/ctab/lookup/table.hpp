#pragma once
//! ctab::lookup::Table: a loaded contact table, immutable after load, queried in bounded time.
//! Built once from a TableData (which it copies into its own layout): per case (i_dy, i_second, wheel) one
//! contiguous record of every slot's quantities, per dy cell and slot a rule code saying how to blend the two
//! neighbours (interpolate, nearest, lower only, upper only), and PCHIP slopes when asked for.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/lookup/table_data.hpp"

namespace ctab::lookup {

//! How a patch quantity is taken in one dy cell (chosen at load from presence, jumps and case status).
enum class CellRule : std::uint8_t {
  Interpolate = 0,  //!< present at both ends, no jump, both cases succeeded
  Nearest = 1,      //!< jump or presence change: the neighbour the query point is nearer to (lower if f < 0.5)
  LowerOnly = 2,    //!< the upper case failed: always the lower neighbour
  UpperOnly = 3,    //!< the lower case failed: always the upper neighbour
};

struct LoadOptions {
  ctab_interpolation interpolation = CTAB_LINEAR;
  bool single_precision = false;
};

class Table {
 public:
  Table() = default;
  //! Validates `data` and builds the table; on failure the table stays empty (loaded() false).
  [[nodiscard]] LoadResult load(const TableData& data, const LoadOptions& options);
  [[nodiscard]] bool loaded() const noexcept { return n_dy_ >= 2; }

  [[nodiscard]] std::uint32_t n_dy() const noexcept { return n_dy_; }
  [[nodiscard]] std::uint32_t n_second() const noexcept { return static_cast<std::uint32_t>(second_.size()); }
  [[nodiscard]] std::uint32_t n_slots() const noexcept { return n_slots_; }
  [[nodiscard]] std::uint32_t strip_samples() const noexcept { return strip_samples_; }
  [[nodiscard]] double dy_min() const noexcept { return dy0_; }
  [[nodiscard]] double dy_max() const noexcept { return dy0_ + ddy_ * static_cast<double>(n_dy_ - 1); }
  [[nodiscard]] const std::vector<double>& second_axis() const noexcept { return second_; }
  [[nodiscard]] SecondAxis second_axis_kind() const noexcept { return second_kind_; }
  [[nodiscard]] ctab_interpolation interpolation() const noexcept { return interpolation_; }
  [[nodiscard]] bool single_precision() const noexcept { return !values_f_.empty(); }
  [[nodiscard]] CellRule rule(std::size_t i_dy, std::size_t i_second, std::size_t wheel, std::size_t slot) const noexcept {
    return static_cast<CellRule>(rules_[patch_(i_dy, i_second, wheel) + slot]);
  }
  //! Bytes held by this table (all arrays).
  [[nodiscard]] std::size_t memory_bytes() const noexcept;

  //! Where (dy_m, second) lies: cells and fractions, clamped; status ok / clamped / invalid input.
  void prelookup(double dy_m, double second, ctab_location& out) const noexcept;
  //! Every slot and wheelset quantity of one wheel at a prelooked point.
  void query(const ctab_location& where, std::int32_t wheel, ctab_result& out) const noexcept;
  //! Strip profile of one slot (see ctab_strip_profile).
  ctab_status strip_profile(const ctab_location& where, std::int32_t wheel, std::int32_t slot, double* s_m,
                            double* half_length_m, double* peak_pressure_Pa, std::uint32_t capacity,
                            std::uint32_t* count) const noexcept;

 private:
  template <typename T, bool kCubic>
  void query_rows(const ctab_location& where, std::uint32_t wheel, ctab_result& out) const noexcept;
  template <typename T, bool kCubic>
  void dy_row(const T* values, const T* slopes, std::size_t lo_case, std::size_t hi_case, std::size_t rule_index,
              double f, double* row, double* presence) const noexcept;
  void wheelset(const ctab_location& where, ctab_result& out) const noexcept;
  //! First index of case (i_dy, i_second, wheel)'s slots in the per-slot arrays.
  [[nodiscard]] std::size_t patch_(std::size_t i_dy, std::size_t i_second, std::size_t wheel) const noexcept {
    return ((i_dy * second_.size() + i_second) * kWheels + wheel) * n_slots_;
  }

  std::uint32_t n_dy_ = 0;
  std::uint32_t n_slots_ = 0;
  std::uint32_t strip_samples_ = 0;
  double dy0_ = 0.0, ddy_ = 0.0, inv_ddy_ = 0.0;
  std::vector<double> second_;
  SecondAxis second_kind_ = SecondAxis::VerticalLoad;
  ctab_interpolation interpolation_ = CTAB_LINEAR;
  // Per case (i_dy, i_second, wheel): n_slots x kQuantities values, in double or (single precision) float, and
  // with PCHIP the dy-slopes [unit/m] in the same layout.
  std::vector<double> values_d_, slopes_d_;
  std::vector<float> values_f_, slopes_f_;
  std::vector<double> present_;        //!< per case and slot, 0.0 or 1.0
  std::vector<std::uint8_t> rules_;    //!< per dy cell (indexed by its lower case) and slot: CellRule
  std::vector<std::int8_t> status_;    //!< per case
  std::vector<double> wheelset_;       //!< per (i_dy, i_second): roll, delta r
  std::vector<double> wheelset_slopes_;
  std::vector<double> strip_a_d_, strip_p0_d_;  //!< per case, slot, sample (double or float as the values)
  std::vector<float> strip_a_f_, strip_p0_f_;
};

//! The result of a query without a table: status CTAB_NOT_LOADED, every slot absent, values zero.
void fill_not_loaded(ctab_result& out) noexcept;

}  // namespace ctab::lookup
