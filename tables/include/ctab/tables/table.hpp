// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The in-memory contact table, schema 2: the contract between the generator (writes) and lookup (reads).
//! Layout and units are documented in tables/README.md; every array is row-major (C order) with the shape
//! given next to it. SI units throughout (m, N, Pa, rad).
//!
//! Frames. Each wheel's quantities are in its own side frame (docs/method.md "Track, wheelset and rigid geometry"): y lateral, + towards
//! the field side of that rail; z vertical, + downwards. Forces are those of the wheel on the rail.
//! Identity (tested on every case of a table): for the vertical-load axis, sum over a wheel's present patches of
//! force_vertical_N equals the prescribed vertical load to 1e-9 relative; for the normal-load axis the sum of
//! normal_force_N equals the prescribed normal load.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "ctab/tables/limits.hpp"

#include "ctab/tables/case_status.hpp"

namespace ctab::tables {

inline constexpr int kSchemaVersion = 2;               //!< readers reject any other version
inline constexpr std::size_t kWheels = 2;              //!< index 0: right wheel, 1: left wheel
inline constexpr std::size_t kDefaultSlots = 3;        //!< patch slots unless the config asks for more
inline constexpr std::size_t kMaxSlots = 16;           //!< most patch slots a table may have
inline constexpr std::size_t kMaxStripSamples = 4096;  //!< most strip-profile samples per patch

//! A located jump is a cell of at most kJumpCellWidth_m whose end nodes hold the one-sided limits; the generator
//! brackets a jump to 0.1-1 um (the finest step readers and writers accept is kMinDyStep, limits.hpp).
//! Widest cell that holds a located jump [m] (tables/README.md, "Adaptive axis and located jumps").
inline constexpr double kJumpCellWidth_m = 1e-6;
//! A contact point that moves by more than this between the two nodes of a located-jump cell is a `moves` jump [m]:
//! the larger of 1 mm (the floor of detect_jumps, well above the solver's own steps of half a strip width in the
//! contact point) and 10 contact-point tolerances.
[[nodiscard]] constexpr double jump_move_threshold(double contact_point_tolerance_m) noexcept {
  return contact_point_tolerance_m * 10.0 > 1e-3 ? contact_point_tolerance_m * 10.0 : 1e-3;
}
//! Quantities of Table::cell_error, in this order.
inline constexpr std::size_t kCellErrorQuantities = 4;
enum class CellErrorQuantity : std::uint8_t { ForceRel = 0, AreaRel = 1, ContactPoint_m = 2, LateralForceRel = 3 };
//! The root number attributes with the tolerance an adaptive axis was refined to, in CellErrorQuantity order.
inline constexpr const char* kToleranceAttributes[kCellErrorQuantities] = {
    "tolerance_force_rel", "tolerance_area_rel", "tolerance_contact_point_m", "tolerance_lateral_force_rel"};
//! Table::cell_error where a cell was not measured (a jump cell, a cell narrower than the refinement's finest step).
inline constexpr double kCellNotMeasured = -1.0;

//! How a patch changes between two neighbouring lateral shifts (a cell of the dy axis).
enum class JumpKind : std::uint8_t {
  Appears = 1,     //!< the slot is empty at dy_low and holds a patch at dy_high
  Disappears = 2,  //!< the reverse
  Moves = 3,       //!< present at both, but the contact point on the rail moves by more than the jump threshold
};

//! One contact jump: between lateral_displacement_m[i_dy] and [i_dy + 1], at second-axis index i_second, for one
//! wheel and slot. Lookup never interpolates a patch quantity across such a cell.
struct Jump {
  std::uint32_t i_second = 0;
  std::uint8_t wheel = 0;
  std::uint8_t slot = 0;
  std::uint32_t i_dy = 0;  //!< the jump lies in (dy[i_dy], dy[i_dy + 1])
  JumpKind kind = JumpKind::Moves;
};

//! Per-patch scalar quantities, each an array of shape (n_dy x n_second x kWheels x n_slots).
//! Every value is 0 where `present` is 0.
struct PatchQuantities {
  std::vector<std::uint8_t> present;     //!< 1 where the slot holds a patch, else 0
  std::vector<double> normal_force_N;    //!< resultant normal force [N]
  std::vector<double> force_lateral_N;   //!< lateral component on the rail in the side frame, + to the field side [N]
  std::vector<double> force_vertical_N;  //!< vertical component on the rail, + downwards [N]
  std::vector<double> area_m2;           //!< [m^2]
  std::vector<double> max_pressure_Pa;   //!< [Pa]
  std::vector<double> approach_m;        //!< normal approach of the patch [m]
  //! Direction of the patch's resultant normal force, atan2(-force_lateral_N, force_vertical_N) (< 0 on the gauge
  //! side): on a planar surface equal to plane_angle_rad, on a conformal one the strips' normals summed [rad]
  std::vector<double> contact_angle_rad;
  std::vector<double> plane_angle_rad;    //!< inclination of the contact plane in which s is measured [rad]
  std::vector<double> s_origin_y_rail_m;  //!< rail point where s = 0 (lateral) [m]
  std::vector<double> s_origin_z_rail_m;  //!< rail point where s = 0 (vertical, + down) [m]
  std::vector<double> y_wheel_m;          //!< contact point on the wheel profile (tape circle origin) [m]
  std::vector<double> y_rail_m;           //!< contact point on the rail profile (head top origin) [m]
  std::vector<double> y_cop_rail_m;       //!< centre of pressure on the rail profile [m]
  std::vector<double> rolling_radius_m;   //!< [m]
  std::vector<double> semi_axis_a_m;      //!< equivalent ellipse, rolling direction [m]
  std::vector<double> semi_axis_b_m;      //!< equivalent ellipse, lateral [m]
  std::vector<double> s_min_m, s_max_m;   //!< lateral extent of the patch in its contact plane [m]
  //! Strip profiles resampled on strip_samples points evenly spread over [s_min, s_max], shape
  //! (n_dy x n_second x kWheels x n_slots x strip_samples).
  std::vector<double> strip_half_length_m;     //!< a(s) [m]
  std::vector<double> strip_peak_pressure_Pa;  //!< p0(s) [Pa]
};

struct Table {
  std::vector<double> lateral_displacement_m;  //!< axis 0, strictly increasing, uniform or refined [m] (n_dy)
  std::string second_axis_name;                //!< "vertical_load_N", "normal_load_N" or "approach_m"
  std::string second_axis_units;               //!< "N" or "m"
  std::vector<double> second_axis;             //!< axis 1, strictly increasing, in second_axis_units (n_second >= 1)
  std::size_t n_slots = kDefaultSlots;         //!< patch slots per wheel (1..kMaxSlots)
  std::size_t strip_samples = 0;               //!< samples per strip profile (2..kMaxStripSamples)
  std::vector<double> roll_rad;                //!< wheelset roll (n_dy x n_second) [rad]
  std::vector<double>
      rolling_radius_difference_m;  //!< r_right - r_left at the rigid contact points (n_dy x n_second) [m]
  std::vector<CaseStatus> status;   //!< per wheel (n_dy x n_second x kWheels)
  //! Per wheel: the normal-contact method that solved the case (ContactMethod value: 0 mim1d, 1 hertz, 2 kp,
  //! 3 analyn, 4 bem2d) and its strip width [m]; with `--method auto` the least model's choice. Optional on read:
  //! tables written before these datasets read as kMethodNotRecorded and 0 m.
  std::vector<std::int8_t> method;
  std::vector<double> strip_width_m;
  PatchQuantities patch;
  std::vector<Jump> jumps;                                 //!< sorted by (i_second, wheel, slot, i_dy)
  //! Adaptive axis only (empty otherwise, and in tables written without it): the interpolation error measured in
  //! each dy cell, shape (n_dy - 1, n_second, kCellErrorQuantities), kCellNotMeasured where not measured.
  std::vector<double> cell_error;
  std::map<std::string, std::string> text_attributes;      //!< provenance, UTF-8 (see README)
  std::map<std::string, double> number_attributes;         //!< provenance numbers (material, ...)
  std::map<std::string, std::int64_t> integer_attributes;  //!< provenance integers (threads, ...)

  [[nodiscard]] std::size_t n_dy() const noexcept { return lateral_displacement_m.size(); }
  [[nodiscard]] std::size_t n_second() const noexcept { return second_axis.size(); }
  [[nodiscard]] std::size_t cases() const noexcept { return n_dy() * n_second(); }
  //! Index of (dy, second, wheel) in `status`.
  [[nodiscard]] std::size_t wheel_index(std::size_t i_dy, std::size_t i_second, std::size_t wheel) const noexcept {
    return (i_dy * n_second() + i_second) * kWheels + wheel;
  }
  //! Index of (dy, second, wheel, slot) in the patch arrays.
  [[nodiscard]] std::size_t patch_index(std::size_t i_dy, std::size_t i_second, std::size_t wheel,
                                        std::size_t slot) const noexcept {
    return wheel_index(i_dy, i_second, wheel) * n_slots + slot;
  }
  //! Sizes every array for the axes, n_slots and strip_samples already set (fills zeros, status Converged).
  void allocate();
};

//! `Table::method` of a table written before the dataset existed.
inline constexpr std::int8_t kMethodNotRecorded = -1;
//! Largest ContactMethod value (bem2d).
inline constexpr std::int8_t kMaxMethodValue = 4;

//! Finds the jumps of a table from its presence flags and rail contact points: a slot that appears or
//! disappears between neighbours, or whose y_rail_m moves by more than max(1 mm, 10 of the axis's largest dy steps).
[[nodiscard]] std::vector<Jump> detect_jumps(const Table& table);

//! The jumps of a table: for a table with cell_error (an adaptive axis), the located jumps: in every cell of width
//! <= kJumpCellWidth_m not measured, each slot that appears, disappears or whose y_rail_m moves by more than
//! jump_move_threshold(tolerance_contact_point_m attribute); otherwise detect_jumps.
[[nodiscard]] std::vector<Jump> table_jumps(const Table& table);

//! Outcome of reading or writing a table (no exceptions in this module).
enum class TableStatus : std::int8_t {
  Ok = 0,
  CannotOpen = -1,
  NotATable = -2,           //!< not HDF5, or truncated
  WrongSchemaVersion = -3,  //!< includes schema 1 (the message says how to regenerate)
  MissingDataset = -4,
  WrongShape = -5,
  InvalidContent = -6,  //!< non-finite or out-of-range values, bad axes, unknown status, bad attributes
  WriteFailed = -7,
  OutOfMemory = -8,  //!< an allocation failed while reading (the table fits the size limit, this process's memory not)
};

struct TableResult {
  TableStatus status = TableStatus::Ok;
  std::string message;  //!< names the file and the dataset or attribute concerned
  [[nodiscard]] bool ok() const noexcept { return status == TableStatus::Ok; }
};

//! Root integer attribute that sets the deflate level of the file's datasets (0: no compression filters, 1..9 zlib
//! levels), written like any provenance attribute so that shards and merges keep it. Absent: kDefaultCompressionLevel.
inline constexpr const char* kCompressionLevelAttribute = "compression_level";
inline constexpr std::int64_t kMinCompressionLevel = 0;
inline constexpr std::int64_t kMaxCompressionLevel = 9;
//! Chosen from a measurement of write time against file size (tables/README.md, "Compression").
inline constexpr std::int64_t kDefaultCompressionLevel = 1;
//! The deflate level write_table uses for `table` (the attribute clamped to 0..9, or the default).
[[nodiscard]] std::int64_t compression_level(const Table& table) noexcept;

//! Runs task(0) ... task(count - 1), in any order and on any threads, and returns when all have run (the caller's
//! thread pool: the generator passes an OpenMP loop; the tables library starts no threads of its own).
using ParallelFor = std::function<void(std::size_t count, const std::function<void(std::size_t)>& task)>;

//! Writes to `temporary_path(path)`, then renames onto `path`: an existing table is replaced only on success,
//! and a failed or interrupted write never leaves a partial table under `path`. Deflated datasets' chunks are
//! shuffled and deflated by the writer (as HDF5's filters would) and stored in order (H5Dwrite_chunk); with
//! `parallel_for` on its threads. The file's bytes are the same with or without it.
[[nodiscard]] TableResult write_table(const Table& table, const std::string& path,
                                      const ParallelFor& parallel_for = {});
//! Starts the HDF5 library (once per process; its first call would otherwise, 0.3-0.4 ms), for a caller that can
//! overlap it with other set-up work. Not beside another thread's call into HDF5 (the library is not thread-safe).
void start_hdf5() noexcept;
//! The temporary file write_table uses for `path` in this process: `path + ".tmp-<pid>"`.
[[nodiscard]] std::string temporary_path(const std::string& path);
//! Reads and validates a table: schema version, every dataset present with the right shape, axes, attributes and
//! the size limit (kMaxTableBytes, checked before anything is allocated from them), and contents (finite values,
//! status values, presence 0/1). A failed allocation gives OutOfMemory; nothing is thrown.
[[nodiscard]] TableResult read_table(const std::string& path, Table& table);

}  // namespace ctab::tables
