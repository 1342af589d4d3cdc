// SPDX-License-Identifier: Apache-2.0
// Table::load: copies a validated TableData into one aligned record per case (lookup/include/ctab/lookup/table.hpp)
// and precomputes, per dy cell and slot, the blending rule (docs/method.md "Tables: sweep, slots, jumps, refined axis"), the dy index, and with PCHIP the
// Fritsch-Carlson slopes at every node.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "blend.hpp"
#include "ctab/lookup/table.hpp"
#include "load_guard.hpp"

namespace ctab::lookup {

namespace {

constexpr std::size_t kAlignBytes = 64;     // a cache line
constexpr double kUniformTolerance = 1e-9;  // relative to the dy span
// Largest PCHIP slope times a cell's width: with values within kMaxTableValue, a cubic's four terms stay finite.
constexpr double kMaxSlopeTerm = 1e306;
// The adaptive axis's index: up to this many entries per cell and this many in all (its size stays bounded while the
// search within an entry's cells stays short where nodes cluster, as at located jumps).
constexpr double kIndexEntriesPerCell = 8.0;
constexpr double kMaxIndexEntries = 65536.0;

bool succeeded(std::int8_t case_status) noexcept { return case_status >= 0; }  // converged, no contact, under-resolved

//! Fritsch-Carlson slope at a node from the secants of its interpolable neighbouring cells (widths h_left, h_right:
//! Fritsch and Butland's weighted harmonic mean, which is the plain harmonic mean on a uniform axis; 0 at an
//! extremum; one-sided: that cell's secant, which keeps the cubic monotone).
double node_slope(bool has_left, double left, double h_left, bool has_right, double right, double h_right) noexcept {
  if (has_left && has_right) {
    if (left * right <= 0.0) return 0.0;
    const double w_left = 2.0 * h_right + h_left, w_right = h_right + 2.0 * h_left;
    return (w_left + w_right) / (w_left / left + w_right / right);
  }
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

//! Sizes `to` for `count` values of T starting at a 64-byte boundary (zeros) and returns that start.
template <typename T, typename Storage>
T* allocate_aligned(Storage& to, std::size_t count) {
  if (count == 0) return nullptr;
  constexpr std::size_t pad = kAlignBytes / sizeof(T);
  to.storage.assign(count + pad, T{});
  const auto address = reinterpret_cast<std::uintptr_t>(to.storage.data());
  to.skip = (kAlignBytes - address % kAlignBytes) % kAlignBytes / sizeof(T);
  return to.storage.data() + to.skip;
}

template <typename T>
void store(const std::vector<double>& from, std::vector<T>& to) {
  to.resize(from.size());
  std::transform(from.begin(), from.end(), to.begin(), [](double v) { return static_cast<T>(v); });
}

// Offsets of a case record's parts (Table's stride_ and off_*_ members): the quantities of every slot, the slots'
// presence flags and cell rules, the case status, the roll and delta r; padded to whole cache lines of the storage
// type.
struct RecordLayout {
  std::size_t present = 0, rule = 0, status = 0, roll = 0, stride = 0;
};

RecordLayout record_layout(std::size_t n_slots, bool single_precision) noexcept {
  const std::size_t per_line = kAlignBytes / (single_precision ? sizeof(float) : sizeof(double));
  RecordLayout layout;
  layout.present = n_slots * kQuantities;
  layout.rule = layout.present + n_slots;
  layout.status = layout.rule + n_slots;
  layout.roll = layout.status + 1;
  layout.stride = (layout.roll + 2 + per_line - 1) / per_line * per_line;
  return layout;
}

// The dy cells' widths; `uniform` when every node lies on the mean step (to kUniformTolerance of the span): one width
// for every cell and arithmetic search, so that an axis without refinement gives the answers of a uniform grid.
std::vector<double> cell_widths(const std::vector<double>& dy_m, bool& uniform) {
  const std::size_t n_dy = dy_m.size();
  const double span = dy_m.back() - dy_m.front(), mean_step = span / static_cast<double>(n_dy - 1);
  uniform = true;
  for (std::size_t i = 0; i < n_dy; ++i)
    uniform =
        uniform && std::fabs(dy_m[i] - (dy_m.front() + mean_step * static_cast<double>(i))) <= kUniformTolerance * span;
  std::vector<double> width(n_dy - 1, mean_step);
  if (!uniform)
    for (std::size_t i = 0; i + 1 < n_dy; ++i) width[i] = dy_m[i + 1] - dy_m[i];
  return width;
}

// The value at offset k of case c's record, in double, from the description: a slot's quantity (zero where the
// patch is absent), the roll or delta r.
double record_value(const TableData& data, const RecordLayout& layout, std::size_t c, std::size_t k) noexcept {
  if (k == layout.roll) return data.roll_rad[c / kWheels];
  if (k == layout.roll + 1) return data.rolling_radius_difference_m[c / kWheels];
  const std::size_t p = c * data.n_slots + k / kQuantities;
  return data.present[p] ? data.quantities[p * kQuantities + k % kQuantities] : 0.0;
}

// The jump bands (Table::JumpBand; [0] unused) and, per patch index (i_dy, i_second, wheel, slot), the band its
// cell (i_dy, i_dy + 1) lies in between rows i_second and i_second + 1 (0: none). Per wheel and slot, the jumps of
// two neighbouring rows pair up in dy order where both rows list the same kinds in the same order (else the rows
// blend as without jumps bands); a pair in different cells gives a band over the cells from one to the other, unless
// one of those cells lies in an earlier band of the slot already.
struct JumpBands {
  std::vector<JumpBand> bands;
  std::vector<std::uint32_t> of_patch;
};

JumpBands plan_jump_bands(const TableData& data) {
  const std::size_t n_2 = data.n_second(), n_slots = data.n_slots;
  JumpBands out;
  out.bands.resize(1);
  out.of_patch.assign(data.present.size(), 0);
  if (n_2 < 2) return out;
  std::vector<std::vector<Jump>> by_row(n_2 * kWheels * n_slots);  // (i_second, wheel, slot), sorted by i_dy
  for (const Jump& j : data.jumps) by_row[(j.i_second * kWheels + j.wheel) * n_slots + j.slot].push_back(j);
  for (auto& jumps : by_row)
    std::sort(jumps.begin(), jumps.end(), [](const Jump& a, const Jump& b) { return a.i_dy < b.i_dy; });
  const auto mid = [&](std::uint32_t i) { return 0.5 * (data.dy_m[i] + data.dy_m[i + 1]); };
  for (std::size_t i2 = 0; i2 + 1 < n_2; ++i2)
    for (std::size_t w = 0; w < kWheels; ++w)
      for (std::size_t s = 0; s < n_slots; ++s) {
        const auto& lo = by_row[(i2 * kWheels + w) * n_slots + s];
        const auto& hi = by_row[((i2 + 1) * kWheels + w) * n_slots + s];
        if (lo.size() != hi.size() || !std::equal(lo.begin(), lo.end(), hi.begin(), [](const Jump& a, const Jump& b) {
              return a.kind == b.kind;
            }))
          continue;
        for (std::size_t k = 0; k < lo.size(); ++k) {
          const std::uint32_t a = lo[k].i_dy, b = hi[k].i_dy;
          const std::uint32_t first = std::min(a, b), last = std::max(a, b);
          bool free = a != b;
          for (std::uint32_t i = first; free && i <= last; ++i) free = out.of_patch[data.patch_index(i, i2, w, s)] == 0;
          if (!free) continue;
          const auto band = static_cast<std::uint32_t>(out.bands.size());
          out.bands.push_back({mid(a), mid(b), a, b});
          for (std::uint32_t i = first; i <= last; ++i) out.of_patch[data.patch_index(i, i2, w, s)] = band;
        }
      }
  return out;
}

// One record per case, in T, into `records` (zeroed): quantities (zero for absent patches), presence, the rule of the
// cell that starts at the case, status, roll and delta r.
template <typename T>
void case_records(const TableData& data, const RecordLayout& layout, const std::vector<std::uint32_t>& band_of_patch,
                  T* records) {
  const std::size_t n_dy = data.n_dy(), n_2 = data.n_second(), n_slots = data.n_slots;
  std::vector<std::uint8_t> jump(data.present.size(), 0);  // by the patch index of the cell's lower end
  for (const Jump& j : data.jumps) jump[data.patch_index(j.i_dy, j.i_second, j.wheel, j.slot)] = 1;
  for (std::size_t i = 0; i < n_dy; ++i)
    for (std::size_t i2 = 0; i2 < n_2; ++i2)
      for (std::size_t w = 0; w < kWheels; ++w) {
        const std::size_t c = data.case_index(i, i2, w);
        T* record = records + c * layout.stride;
        for (std::size_t s = 0; s < n_slots; ++s) {
          const std::size_t p = data.patch_index(i, i2, w, s);
          for (std::size_t q = 0; q < kQuantities; ++q)
            record[s * kQuantities + q] = static_cast<T>(record_value(data, layout, c, s * kQuantities + q));
          record[layout.present + s] = data.present[p] ? T{1} : T{0};
          CellRule rule = CellRule::Nearest;  // the last dy value starts no cell
          if (i + 1 < n_dy)
            rule = cell_rule(data.case_status[c], data.case_status[data.case_index(i + 1, i2, w)], data.present[p] != 0,
                             data.present[data.patch_index(i + 1, i2, w, s)] != 0, jump[p] != 0);
          record[layout.rule + s] = static_cast<T>(static_cast<std::uint32_t>(rule) + detail::kBandFactor * band_of_patch[p]);
        }
        record[layout.status] = static_cast<T>(data.case_status[c]);
        record[layout.roll] = static_cast<T>(record_value(data, layout, c, layout.roll));
        record[layout.roll + 1] = static_cast<T>(record_value(data, layout, c, layout.roll + 1));
      }
}

// The PCHIP dy-slopes of every record value that is interpolated (node_slope, from the description's double
// values), into `slopes` laid out as the records: a slot's quantities where the neighbouring cells interpolate it,
// the roll and delta r always. False when a slope times the widest cell exceeds kMaxSlopeTerm (or, in single
// precision, the float range): the table's values change too fast for the cubic to stay finite.
template <typename T>
bool pchip_slopes(const TableData& data, const T* records, const RecordLayout& layout,
                  const std::vector<double>& width, T* slopes) {
  const std::size_t stride = layout.stride, n_dy = data.n_dy(), n_slots = data.n_slots;
  const std::size_t row = data.n_second() * kWheels;  // cases per dy value
  const double widest = *std::max_element(width.begin(), width.end());
  const double largest = std::min(kMaxSlopeTerm / widest, static_cast<double>(std::numeric_limits<T>::max()));
  bool finite = true;
  const auto interpolable = [&](std::size_t c, std::size_t s) {
    return detail::rule_of(records[c * stride + layout.rule + s]) == static_cast<std::uint8_t>(CellRule::Interpolate);
  };
  const auto put = [&](std::size_t c, std::size_t k, bool has_left, bool has_right) {
    const double v = record_value(data, layout, c, k);
    const std::size_t i = c / row;
    const double h_left = has_left ? width[i - 1] : 0.0, h_right = has_right ? width[i] : 0.0;
    const double left = has_left ? (v - record_value(data, layout, c - row, k)) / h_left : 0.0;
    const double right = has_right ? (record_value(data, layout, c + row, k) - v) / h_right : 0.0;
    const double slope = node_slope(has_left, left, h_left, has_right, right, h_right);
    finite = finite && std::fabs(slope) <= largest;
    slopes[c * stride + k] = finite ? static_cast<T>(slope) : T{0};
  };
  for (std::size_t i = 0; i < n_dy; ++i)
    for (std::size_t k = 0; k < row; ++k) {
      const std::size_t c = i * row + k;
      for (std::size_t s = 0; s < n_slots; ++s) {
        const bool has_left = i >= 1 && interpolable(c - row, s), has_right = i + 1 < n_dy && interpolable(c, s);
        for (std::size_t q = 0; q < kQuantities; ++q) put(c, s * kQuantities + q, has_left, has_right);
      }
      for (std::size_t k2 = layout.roll; k2 < layout.roll + 2; ++k2)  // roll and delta r: always interpolable
        put(c, k2, i >= 1, i + 1 < n_dy);
    }
  return finite;
}

}  // namespace

LoadResult Table::load(const TableData& data, const LoadOptions& options) {
  return detail::guard_allocation([&] { return build(data, nullptr, options); });
}

LoadResult Table::load(TableData&& data, const LoadOptions& options) {
  return detail::guard_allocation([&] { return build(data, &data, options); });
}

LoadResult Table::build(const TableData& data, TableData* consumed, const LoadOptions& options) {
  *this = Table{};
  LoadResult result = validate(data);
  if (result.ok() && options.single_precision) result = check_float_range(data);
  if (!result.ok()) return result;

  bool uniform = true;
  const std::vector<double> width = cell_widths(data.dy_m, uniform);
  const RecordLayout layout = record_layout(data.n_slots, options.single_precision);
  off_present_ = layout.present;
  off_rule_ = layout.rule;
  off_status_ = layout.status;
  off_roll_ = layout.roll;
  stride_ = layout.stride;
  JumpBands bands = plan_jump_bands(data);
  if (bands.bands.size() >= detail::kMaxBands) {
    *this = Table{};
    return {CTAB_ERR_CONTENT, "more jumps move between second-axis rows than the lookup can hold (4194303)"};
  }
  const bool slopes_ok =
      options.single_precision ? build_records<float>(data, width, bands.of_patch, options, records_f_, slopes_f_)
                               : build_records<double>(data, width, bands.of_patch, options, records_d_, slopes_d_);
  bands_ = std::move(bands.bands);
  if (!slopes_ok) {
    *this = Table{};
    return {CTAB_ERR_CONTENT, "a value changes too fast between neighbouring dy rows for PCHIP slopes to stay finite"};
  }
  if (consumed != nullptr) consumed->quantities = std::vector<double>{};  // in the records now: its memory back
  if (options.single_precision) {
    store(data.strip_half_length_m, strip_a_f_);
    store(data.strip_peak_pressure_Pa, strip_p0_f_);
  } else if (consumed != nullptr) {
    strip_a_d_ = std::move(consumed->strip_half_length_m);
    strip_p0_d_ = std::move(consumed->strip_peak_pressure_Pa);
  } else {
    strip_a_d_ = data.strip_half_length_m;
    strip_p0_d_ = data.strip_peak_pressure_Pa;
  }
  second_ = data.second;
  second_kind_ = data.second_axis;
  interpolation_ = options.interpolation;
  n_slots_ = static_cast<std::uint32_t>(data.n_slots);
  strip_samples_ = static_cast<std::uint32_t>(data.strip_samples);
  build_dy_index(data.dy_m, width, uniform);
  n_dy_ = static_cast<std::uint32_t>(data.n_dy());
  return result;
}

template <typename T, typename Storage>
bool Table::build_records(const TableData& data, const std::vector<double>& width,
                          const std::vector<std::uint32_t>& band_of_patch, const LoadOptions& options,
                          Storage& records, Storage& slopes) {
  const std::size_t count = data.n_dy() * data.n_second() * kWheels * stride_;
  T* at = allocate_aligned<T>(records, count);
  case_records<T>(data, RecordLayout{off_present_, off_rule_, off_status_, off_roll_, stride_}, band_of_patch, at);
  if (options.interpolation != CTAB_PCHIP) return true;
  return pchip_slopes<T>(data, at, RecordLayout{off_present_, off_rule_, off_status_, off_roll_, stride_}, width,
                         allocate_aligned<T>(slopes, count));
}

template <>
const double* Table::records<double>() const noexcept {
  return records_d_.data();
}
template <>
const float* Table::records<float>() const noexcept {
  return records_f_.data();
}
template <>
const double* Table::slope_records<double>() const noexcept {
  return slopes_d_.data();
}
template <>
const float* Table::slope_records<float>() const noexcept {
  return slopes_f_.data();
}

void Table::build_dy_index(const std::vector<double>& dy_m, const std::vector<double>& width, bool uniform) {
  uniform_dy_ = uniform;
  inv_mean_step_ = static_cast<double>(dy_m.size() - 1) / (dy_m.back() - dy_m.front());
  dy_ = dy_m;
  cell_width_ = width;
  inv_cell_width_.resize(width.size());
  std::transform(width.begin(), width.end(), inv_cell_width_.begin(), [](double h) { return 1.0 / h; });
  dy_index_.clear();
  dy_search_length_ = 0;
  if (uniform) return;  // arithmetic search (prelookup)
  // Entries on a step of the smallest cell's width where that is few, else kIndexEntriesPerCell per cell (at most
  // kMaxIndexEntries): entry k is the cell holding dy_front + k x step, the last the last cell.
  const std::size_t n_dy = dy_m.size(), n_cells = n_dy - 1;
  const double span = dy_m.back() - dy_m.front();
  const double smallest = *std::min_element(width.begin(), width.end());
  const double wanted = std::min({std::ceil(span / smallest), kIndexEntriesPerCell * static_cast<double>(n_cells),
                                  kMaxIndexEntries});
  const auto entries = static_cast<std::size_t>(std::max(wanted, 1.0));
  const double step = span / static_cast<double>(entries);
  dy_index_.resize(entries + 1);
  std::uint32_t i = 0;
  for (std::size_t k = 0; k <= entries; ++k) {
    const double at = k == entries ? dy_m.back() : dy_m.front() + step * static_cast<double>(k);
    while (i + 2 < n_dy && dy_m[i + 1] <= at) ++i;
    dy_index_[k] = i;
  }
  // A point in entry k's interval lies in a cell from dy_index_[k] to dy_index_[k + 1]; one more either way covers
  // a point that rounding puts across an entry's boundary.
  std::size_t length = 1;
  for (std::size_t k = 0; k < entries; ++k)
    length = std::max<std::size_t>(length, dy_index_[k + 1] - dy_index_[k] + 3);
  dy_search_length_ = static_cast<std::uint32_t>(std::min(length, n_cells));
  inv_index_step_ = 1.0 / step;
}

double Table::field(std::size_t c, std::size_t offset) const noexcept {
  return single_precision() ? static_cast<double>(records<float>()[c * stride_ + offset])
                            : records<double>()[c * stride_ + offset];
}

std::size_t Table::memory_bytes() const noexcept {
  return sizeof(*this) +
         (records_d_.storage.size() + slopes_d_.storage.size() + second_.size() + strip_a_d_.size() +
          strip_p0_d_.size() + dy_.size() + cell_width_.size() + inv_cell_width_.size()) *
             sizeof(double) +
         dy_index_.size() * sizeof(std::uint32_t) + bands_.size() * sizeof(JumpBand) +
         (records_f_.storage.size() + slopes_f_.storage.size() + strip_a_f_.size() + strip_p0_f_.size()) *
             sizeof(float);
}

}  // namespace ctab::lookup
