// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The plain description of a contact table that the lookup core loads (from a blob, or converted from an HDF5
//! table by ctab_lookup_hdf5). No HDF5, no tables/ dependency: the same indices and units as tables::Table
//! (schema 2), with the patch quantities gathered per patch (CTAB_QUANTITIES consecutive values, ctab_patch order).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ctab/lookup/ctab_lookup.h"

namespace ctab::lookup {

inline constexpr std::size_t kWheels = 2;
inline constexpr std::size_t kMaxSlots = CTAB_MAX_SLOTS;
inline constexpr std::size_t kQuantities = CTAB_QUANTITIES;
inline constexpr std::size_t kMaxStripSamples = 4096;
inline constexpr int kSchemaVersion = 2;  //!< the table schema this core understands

//! Largest magnitude of a tabulated value: any blend of a few such values (linear, PCHIP, second axis) stays finite.
//! Physical tables hold nothing near it (pressures about 1e9 Pa).
inline constexpr double kMaxTableValue = 1e300;

//! Quantity kinds of the second axis, stored as numbers in blobs.
enum class SecondAxis : std::uint32_t { VerticalLoad = 0, NormalLoad = 1, Approach = 2 };
[[nodiscard]] const char* second_axis_name(SecondAxis axis) noexcept;

//! Values of tables::JumpKind.
enum class JumpKind : std::uint8_t { Appears = 1, Disappears = 2, Moves = 3 };

//! A contact jump in the dy cell (i_dy, i_dy + 1) at second-axis row i_second, for one wheel and slot.
struct Jump {
  std::uint32_t i_second = 0;
  std::uint32_t i_dy = 0;
  std::uint8_t wheel = 0;
  std::uint8_t slot = 0;
  JumpKind kind = JumpKind::Moves;
};

struct TableData {
  std::vector<double> dy_m;    //!< lateral displacement, strictly increasing (n_dy >= 2), uniform or adaptive, steps
                               //!< >= tables::kMinDyStep [m]
  std::vector<double> second;  //!< second axis, strictly increasing (n_second >= 1)
  SecondAxis second_axis = SecondAxis::VerticalLoad;
  std::size_t n_slots = 3;                          //!< 1..kMaxSlots
  std::size_t strip_samples = 0;                    //!< 0 (none) or 2..kMaxStripSamples
  std::vector<double> roll_rad;                     //!< (n_dy x n_second)
  std::vector<double> rolling_radius_difference_m;  //!< (n_dy x n_second)
  std::vector<std::int8_t> case_status;             //!< (n_dy x n_second x kWheels), tables::CaseStatus values
  std::vector<std::uint8_t> present;                //!< (n_dy x n_second x kWheels x n_slots), 0 or 1
  std::vector<double> quantities;                   //!< (n_dy x n_second x kWheels x n_slots x kQuantities)
  std::vector<double> strip_half_length_m;          //!< (... x n_slots x strip_samples)
  std::vector<double> strip_peak_pressure_Pa;       //!< (... x n_slots x strip_samples)
  std::vector<Jump> jumps;

  [[nodiscard]] std::size_t n_dy() const noexcept { return dy_m.size(); }
  [[nodiscard]] std::size_t n_second() const noexcept { return second.size(); }
  //! Index of (dy, second, wheel) in case_status.
  [[nodiscard]] std::size_t case_index(std::size_t i_dy, std::size_t i_second, std::size_t wheel) const noexcept {
    return (i_dy * n_second() + i_second) * kWheels + wheel;
  }
  //! Index of (dy, second, wheel, slot) in present (times kQuantities or strip_samples for the other arrays).
  [[nodiscard]] std::size_t patch_index(std::size_t i_dy, std::size_t i_second, std::size_t wheel,
                                        std::size_t slot) const noexcept {
    return case_index(i_dy, i_second, wheel) * n_slots + slot;
  }
  //! Sizes every array for the axes, n_slots and strip_samples already set (zeros, status converged).
  void allocate();
};

//! Outcome of a load: a ctab_status and a sentence naming what was wrong.
struct LoadResult {
  ctab_status status = CTAB_OK;
  std::string message;
  [[nodiscard]] bool ok() const noexcept { return status == CTAB_OK; }
};

//! Checks a description: axes (steps with a finite inverse), sizes, finite values within +-kMaxTableValue, status
//! values, presence, jumps.
[[nodiscard]] LoadResult validate(const TableData& data);
//! CTAB_ERR_CONTENT, naming the array, when a value that single precision stores lies beyond the float range.
[[nodiscard]] LoadResult check_float_range(const TableData& data);

}  // namespace ctab::lookup
