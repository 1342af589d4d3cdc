#pragma once
//! The in-memory contact table: the contract between the generator (writes) and lookup (reads).
//! Layout and units are documented in tables/README.md; every array is row-major (C order) with the shape
//! given next to it. SI units throughout.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ctab::tables {

inline constexpr int kSchemaVersion = 1;   //!< readers reject any other version
inline constexpr std::size_t kWheels = 2;  //!< index 0: right wheel, 1: left wheel
inline constexpr std::size_t kSlots = 3;   //!< patch slots: 0 tread, 1 flange, 2 spare
inline constexpr std::array<const char*, kSlots> kSlotNames = {"tread", "flange", "spare"};

//! Per-patch scalar quantities, each an array of shape (n_dy x n_second x kWheels x kSlots).
struct PatchQuantities {
  std::vector<std::uint8_t> present;          //!< 1 where the slot holds a patch
  std::vector<double> normal_force_N;         //!< [N]
  std::vector<double> area_m2;                //!< [m^2]
  std::vector<double> max_pressure_Pa;        //!< [Pa]
  std::vector<double> approach_m;             //!< normal approach of the patch [m]
  std::vector<double> contact_angle_rad;      //!< direction of the patch's resultant normal force [rad]
  std::vector<double> y_wheel_m;              //!< contact point on the wheel profile (tape circle origin) [m]
  std::vector<double> y_rail_m;               //!< contact point on the rail profile (head top origin) [m]
  std::vector<double> y_cop_rail_m;           //!< centre of pressure on the rail profile [m]
  std::vector<double> rolling_radius_m;       //!< [m]
  std::vector<double> semi_axis_a_m;          //!< equivalent ellipse, rolling direction [m]
  std::vector<double> semi_axis_b_m;          //!< equivalent ellipse, lateral [m]
  std::vector<double> s_min_m, s_max_m;       //!< lateral extent of the patch in its contact plane [m]
  //! Strip profiles resampled on n_samples points evenly spread over [s_min, s_max], shape
  //! (n_dy x n_second x kWheels x kSlots x n_samples).
  std::vector<double> strip_half_length_m;    //!< a(s) [m]
  std::vector<double> strip_peak_pressure_Pa; //!< p0(s) [Pa]
};

struct Table {
  std::vector<double> lateral_displacement_m;  //!< axis 0, uniform, strictly increasing [m] (n_dy)
  std::string second_axis_name;                //!< "vertical_load_N", "normal_load_N" or "approach_m"
  std::vector<double> second_axis;             //!< axis 1 values in the unit of its name (n_second >= 1)
  std::size_t strip_samples = 0;               //!< n_samples
  std::vector<double> roll_rad;                //!< wheelset roll (n_dy x n_second) [rad]
  std::vector<double> rolling_radius_difference_m;  //!< r_right - r_left at the first patch (n_dy x n_second) [m]
  std::vector<std::int8_t> status;             //!< solve status per wheel (n_dy x n_second x kWheels)
  PatchQuantities patch;
  std::map<std::string, std::string> text_attributes;    //!< provenance (see README)
  std::map<std::string, double> number_attributes;       //!< provenance numbers (material, threads, ...)

  [[nodiscard]] std::size_t n_dy() const noexcept { return lateral_displacement_m.size(); }
  [[nodiscard]] std::size_t n_second() const noexcept { return second_axis.size(); }
  [[nodiscard]] std::size_t cases() const noexcept { return n_dy() * n_second(); }
  //! Index of (dy, second, wheel, slot) in the patch arrays.
  [[nodiscard]] std::size_t patch_index(std::size_t i_dy, std::size_t i_second, std::size_t wheel, std::size_t slot) const noexcept {
    return ((i_dy * n_second() + i_second) * kWheels + wheel) * kSlots + slot;
  }
  //! Sizes every array for the axes and strip_samples already set (fills zeros).
  void allocate();
};

//! Outcome of reading or writing a table (no exceptions in this module).
enum class TableStatus : std::int8_t {
  Ok = 0,
  CannotOpen = -1,
  NotATable = -2,          //!< not HDF5, or truncated
  WrongSchemaVersion = -3,
  MissingDataset = -4,
  WrongShape = -5,
  InvalidContent = -6,     //!< e.g. a non-uniform or non-increasing axis
  WriteFailed = -7,
};

struct TableResult {
  TableStatus status = TableStatus::Ok;
  std::string message;  //!< names the file and the dataset or attribute concerned
  [[nodiscard]] bool ok() const noexcept { return status == TableStatus::Ok; }
};

//! Writes to `path + ".tmp-<pid>"`, then renames onto `path`: an existing table is replaced only on success,
//! and a failed or interrupted write never leaves a partial table under `path`.
[[nodiscard]] TableResult write_table(const Table& table, const std::string& path);
//! Reads and validates a table (schema version, every dataset present with the right shape, axes).
[[nodiscard]] TableResult read_table(const std::string& path, Table& table);

}  // namespace ctab::tables
