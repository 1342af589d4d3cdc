// SPDX-License-Identifier: Apache-2.0
#pragma once
//! ctab::lookup::Table: a loaded contact table, immutable after load, queried in bounded time.
//! Built once from a TableData (which it copies into its own layout): per case (i_dy, i_second, wheel) one
//! contiguous, cache-line aligned record of every slot's quantities and presence, the rule code of each slot in
//! the dy cell above the case (interpolate, nearest, lower only, upper only), the case status and the wheelset
//! quantities, so that a query reads two (or four) records; PCHIP slopes in records of the same layout.
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

//! A jump of one wheel's slot that rows i_second and i_second + 1 of the second axis place in different dy cells
//! (cell_lo in the lower row, cell_hi in the upper one; positions x_lo, x_hi the cells' midpoints [m]). Between the
//! rows the jump lies at the position interpolated in the second axis: a query takes the side of it that its dy is
//! on, from each row (a row whose own jump lies on the other side of the query gives its one-sided value at its
//! jump cell's end on the query's side).
struct JumpBand {
  double x_lo = 0.0, x_hi = 0.0;
  std::uint32_t cell_lo = 0, cell_hi = 0;
};

struct LoadOptions {
  ctab_interpolation interpolation = CTAB_LINEAR;
  bool single_precision = false;
};

class Table {
 public:
  Table() = default;
  Table(Table&&) = default;  // move-only: the records' alignment is that of their own allocation
  Table& operator=(Table&&) = default;
  Table(const Table&) = delete;
  Table& operator=(const Table&) = delete;
  //! Validates `data` and builds the table; on failure the table stays empty (loaded() false). A failed allocation
  //! gives CTAB_ERR_OUT_OF_MEMORY (no exception leaves a load).
  [[nodiscard]] LoadResult load(const TableData& data, const LoadOptions& options);
  //! The same, taking `data`'s arrays as they are used (the strip profiles are moved, the quantities released once
  //! in the records), so that a load holds little more than the table itself at its peak. `data` is left unspecified.
  [[nodiscard]] LoadResult load(TableData&& data, const LoadOptions& options);
  [[nodiscard]] bool loaded() const noexcept { return n_dy_ >= 2; }

  [[nodiscard]] std::uint32_t n_dy() const noexcept { return n_dy_; }
  [[nodiscard]] std::uint32_t n_second() const noexcept { return static_cast<std::uint32_t>(second_.size()); }
  [[nodiscard]] std::uint32_t n_slots() const noexcept { return n_slots_; }
  [[nodiscard]] std::uint32_t strip_samples() const noexcept { return strip_samples_; }
  [[nodiscard]] double dy_min() const noexcept { return dy_.front(); }
  [[nodiscard]] double dy_max() const noexcept { return dy_.back(); }
  [[nodiscard]] const std::vector<double>& dy_axis() const noexcept { return dy_; }
  [[nodiscard]] const std::vector<double>& second_axis() const noexcept { return second_; }
  [[nodiscard]] SecondAxis second_axis_kind() const noexcept { return second_kind_; }
  [[nodiscard]] ctab_interpolation interpolation() const noexcept { return interpolation_; }
  [[nodiscard]] bool single_precision() const noexcept { return !records_f_.empty(); }
  //! How slot `slot` is blended in the dy cell (i_dy, i_dy + 1).
  [[nodiscard]] CellRule rule(std::size_t i_dy, std::size_t i_second, std::size_t wheel,
                              std::size_t slot) const noexcept {
    return static_cast<CellRule>(static_cast<std::uint32_t>(field(case_(i_dy, i_second, wheel), off_rule_ + slot)) % 4);
  }
  //! The jump bands of the table (see JumpBand; band 0 is none).
  [[nodiscard]] std::size_t jump_bands() const noexcept { return bands_.empty() ? 0 : bands_.size() - 1; }
  //! Candidates of the bounded search that prelookup runs on an adaptive dy axis (0 on a uniform one): it takes
  //! ceil(log2) of this many steps.
  [[nodiscard]] std::uint32_t dy_search_length() const noexcept { return dy_search_length_; }
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
  LoadResult build(const TableData& data, TableData* consumed, const LoadOptions& options);
  //! The records (and with PCHIP the slopes) in T; false when a slope would overflow.
  template <typename T, typename Storage>
  bool build_records(const TableData& data, const std::vector<double>& width,
                     const std::vector<std::uint32_t>& band_of_patch, const LoadOptions& options, Storage& records,
                     Storage& slopes);
  //! Fraction in the dy cell, the nearest-neighbour step and the Hermite basis (slope terms times the cell's width).
  struct DyBasis {
    double f, step, h00, h01, h10, h11;
  };
  template <typename T, bool kCubic>
  void query_rows(const ctab_location& where, std::uint32_t wheel, ctab_result& out) const noexcept;
  //! One slot between two case records: values into v (kQuantities), returns the presence (0 or 1).
  template <typename T, bool kCubic>
  double dy_slot(const T* lo, const T* hi, const T* slope_lo, const T* slope_hi, std::size_t slot, const DyBasis& basis,
                 double* v) const noexcept;
  //! For slot `slot` at `where` in a cell of jump band `band`: per row (lower, upper) the dy node whose values the row
  //! gives instead of its own blend, or kNoNode where the row's own side of its jump is the query's.
  void band_nodes(const ctab_location& where, std::uint32_t band, std::uint32_t node[2]) const noexcept;
  static constexpr std::uint32_t kNoNode = 0xFFFFFFFFu;
  //! The rows' values and presence of slot `slot` in jump band `band`: replaced by the node band_nodes names.
  template <typename T>
  void band_rows(const ctab_location& where, std::uint32_t wheel, std::size_t slot, std::uint32_t band, double* v0,
                 double& p0, double* v1, double& p1) const noexcept;
  //! One slot's values (into v) and presence at one case.
  template <typename T>
  double node_slot(std::size_t c, std::size_t slot, double* v) const noexcept;
  template <typename T, bool kCubic>
  void wheelset(const ctab_location& where, std::uint32_t wheel, const DyBasis& basis, ctab_result& out) const noexcept;
  //! True when every field of a caller's location is one this table's prelookup can give (status ok or clamped,
  //! cells on the axes, fractions in [0, 1], finite point, reserved 0).
  [[nodiscard]] bool valid_location(const ctab_location& where) const noexcept;
  //! Index of case (i_dy, i_second, wheel).
  [[nodiscard]] std::size_t case_(std::size_t i_dy, std::size_t i_second, std::size_t wheel) const noexcept {
    return (i_dy * second_.size() + i_second) * kWheels + wheel;
  }
  //! The dy axis, its cells' widths and the index of prelookup.
  void build_dy_index(const std::vector<double>& dy_m, const std::vector<double>& width, bool uniform);
  //! Value at `offset` of case `c`'s record, as double, whatever the storage precision.
  [[nodiscard]] double field(std::size_t c, std::size_t offset) const noexcept;
  template <typename T>
  [[nodiscard]] const T* records() const noexcept;
  template <typename T>
  [[nodiscard]] const T* slope_records() const noexcept;

  std::uint32_t n_dy_ = 0;
  std::uint32_t n_slots_ = 0;
  std::uint32_t strip_samples_ = 0;
  // The dy axis and its bounded-time search: arithmetic on a uniform axis; on an adaptive one dy_index_[k] is the
  // cell holding dy_.front() + k x the index step (an index of bounded size), and a point's cell lies among the
  // dy_search_length_ cells from its entry's (less one): a binary search of a fixed number of steps finds it.
  std::vector<double> dy_, cell_width_, inv_cell_width_;
  std::vector<std::uint32_t> dy_index_;
  double inv_index_step_ = 0.0, inv_mean_step_ = 0.0;
  std::uint32_t dy_search_length_ = 0;
  bool uniform_dy_ = true;
  std::vector<JumpBand> bands_;  //!< [0] unused: band 0 is none
  std::vector<double> second_;
  SecondAxis second_kind_ = SecondAxis::VerticalLoad;
  ctab_interpolation interpolation_ = CTAB_LINEAR;
  // One record per case (i_dy, i_second, wheel), `stride_` values long and 64-byte aligned, in double or (single
  // precision) float: n_slots x kQuantities values, then per slot the presence (0/1) and the rule of the dy cell
  // starting at this case (CellRule + 4 x the slot's jump band between this case's row and the next), then the case status, the roll and delta r. With PCHIP, the dy-slopes
  // [unit/m] of the values, roll and delta r in records of the same layout.
  std::size_t stride_ = 0, off_present_ = 0, off_rule_ = 0, off_status_ = 0, off_roll_ = 0;
  //! Values starting at a 64-byte boundary inside their vector (`skip` elements in).
  template <typename T>
  struct Aligned {
    std::vector<T> storage;
    std::size_t skip = 0;
    [[nodiscard]] const T* data() const noexcept { return storage.empty() ? nullptr : storage.data() + skip; }
    [[nodiscard]] bool empty() const noexcept { return storage.empty(); }
  };
  Aligned<double> records_d_, slopes_d_;
  Aligned<float> records_f_, slopes_f_;
  std::vector<double> strip_a_d_, strip_p0_d_;  //!< per case, slot, sample (double or float as the values)
  std::vector<float> strip_a_f_, strip_p0_f_;
};

//! The result of a query without a table: status CTAB_NOT_LOADED, every slot absent, values zero.
void fill_not_loaded(ctab_result& out) noexcept;

}  // namespace ctab::lookup
