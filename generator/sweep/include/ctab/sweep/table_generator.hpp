// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The parallel contact-table generator: every case (lateral shift x load or approach, each wheel) solved with
//! the wheel-rail contact solver, in OpenMP over the flattened case list.
//!
//! Set-up (serial, may throw InputError): make_sweep_setup loads the profiles, places them on the track and
//! builds the process-wide kernel and Hertz tables. One table case (one lateral shift and one load value) is
//! solved by solve_table_case, which `ctab solve` uses for every wheel-rail case (--config FILE --dy X, or the
//! set-up options); generate_table runs the same steps (solve_case_roll, solve_case_wheel) over the whole grid.
//!
//! The parallel region has one task per case with a dynamic schedule (the cost varies tenfold between tread and
//! flange cases) and one WheelContactWorkspace per thread (indexed by omp_get_thread_num(); results do not
//! depend on it); every task writes only its own preallocated result slot, nothing is reduced across cases,
//! no I/O happens and no exception leaves the region (a failure becomes the case's status, SolverException for
//! an exception). The table is therefore bit-identical for any number of threads. When the two sides are mirror
//! images (one wheel and one rail profile for both) and the lateral axis is symmetric, only the right wheel is
//! solved: the left wheel at dy is the right wheel at -dy (the file says so in its `mirrored` attribute).
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ctab/core/error.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/tables/table.hpp"
#include "ctab/wheelrail/least_model.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen {

struct GeneratorInfo {
  std::string version = "unknown";  //!< generator version (provenance)
  std::string git_commit = "unknown";
  std::string compiler = "unknown";     //!< compiler id and version (CTAB_COMPILER)
  std::string build_flags = "unknown";  //!< build type and flags (CTAB_BUILD_FLAGS)
  int threads = 1;                      //!< OpenMP threads for the sweep
};

//! Everything a table case needs, built once from a config (serial; may throw InputError). Movable: the
//! profiles live behind pointers, so `side` stays valid.
struct SweepSetup {
  std::unique_ptr<const ProfileTable> wheel, rail;   //!< the profiles actually used (both sides)
  ProfileSmoothing wheel_smoothing, rail_smoothing;  //!< how point profiles were smoothed (provenance)
  std::unique_ptr<const SideGeometry> side;          //!< profiles on the track (one side frame; the left mirrored)
  double E_star_Pa = 0.0;                            //!< effective modulus of the two bodies [Pa]
  //! Method and strip width from the config, the other solver options at their defaults. A single-case caller
  //! (`ctab solve --curvature/--update`) may change them before solving; generate_table never does.
  WheelRailOptions options;
  //! The least model's tolerance (TableConfig::least_model), 0: off (options.method at its strip width) [-].
  double auto_tolerance = 0.0;
  ContactMode mode = ContactMode::Wheelset;
  LoadKind load_kind = LoadKind::VerticalForce;
  //! The config's lateral axis [m], whether the sweep is mirrored (one side solved) and whether its solves are
  //! warm-started (TableConfig::warm_start), so that solve_table_case reproduces a table entry (it replays the
  //! entry's warm-start chain).
  std::vector<double> dy_axis_m;
  bool mirrored = false;
  bool warm_start = false;
  //! Whether an under-resolved wheel is solved again at a finer strip width (solve_case_wheel); a bench that
  //! measures a rung at its own strip width turns it off.
  bool refine_under_resolved = true;
};

//! An InputError of make_sweep_setup that also tells which config key was wrong and why, so that a caller whose
//! config came from command-line options can name the option instead ("--wheel: ...").
class SweepSetupError : public InputError {
 public:
  SweepSetupError(const TableConfig& config, std::string key, std::string reason);
  [[nodiscard]] const std::string& key() const noexcept { return key_; }        //!< e.g. "profiles.wheel"
  [[nodiscard]] const std::string& reason() const noexcept { return reason_; }  //!< the message without source/key

 private:
  std::string key_, reason_;
};

//! Builds the set-up of a config; throws SweepSetupError ("FILE:LINE: 'KEY': reason") for the profiles and a strip
//! width outside [kMinStripWidth_m, kMaxStripWidth_m].
[[nodiscard]] SweepSetup make_sweep_setup(const TableConfig& config);

//! Rigid wheelset roll at a lateral shift: 0 in single-wheel mode. Never throws (an exception of the root finder
//! gives converged = false).
struct CaseRoll {
  double roll_rad = 0.0;
  bool converged = true;
  std::string detail;  //!< why the roll search failed ("" when converged)
};
//! `guess` (a neighbouring shift's roll) only speeds the search up: the roll is the same bit for bit without it
//! (rigid_wheelset_pose).
[[nodiscard]] CaseRoll solve_case_roll(const SweepSetup& setup, double dy_m, const RollGuess* guess = nullptr) noexcept;

//! One wheel of a case in its own side frame (wheel 0 right: shift +dy, roll +phi; wheel 1 left: -dy, -phi).
//! Never throws: a solver exception gives an empty contact and `exception = true`; a roll that did not converge
//! gives MaxIterations.
struct CaseWheel {
  WheelContact contact;
  bool exception = false;  //!< the solver threw (tables::CaseStatus::SolverException)
  AutoChoice choice;       //!< the method and strip width that solved it (the least model's choice, or the config's)
};
//! With `warm_start`, MIM-1D starts from it and leaves this case's solution in it (solve_wheel_contact). An
//! under-resolved result is solved again, cold, at a finer strip width (SweepSetup::refine_under_resolved; the
//! width used is in `choice`).
[[nodiscard]] CaseWheel solve_case_wheel(const SweepSetup& setup, std::size_t wheel, double dy_m, const CaseRoll& roll,
                                         double load_value, WheelContactWorkspace& workspace,
                                         Mim1dWarmStart* warm_start = nullptr) noexcept;

//! Which wheels of a case to solve: [0] right, [1] left.
using WheelSelection = std::array<bool, tables::kWheels>;
inline constexpr WheelSelection kBothWheels{true, true};

//! Exactly one table case: the roll, the selected wheels and the rolling radius difference, as generate_table
//! computes them (bit-identical to the table's values for the right wheel; for a mirrored table the left wheel of
//! the file is the right wheel at -dy).
struct CaseSolution {
  double dy_m = 0.0;
  double load_value = 0.0;  //!< in the unit of the second axis [N or m]
  CaseRoll roll;
  WheelSelection solved = kBothWheels;            //!< the wheels solved; the others are empty
  std::array<CaseWheel, tables::kWheels> wheels;  //!< 0 right, 1 left (each in its own side frame)
  double rolling_radius_difference_m = 0.0;       //!< r_right - r_left at the rigid contact points [m]; 0 unless both
};
[[nodiscard]] CaseSolution solve_table_case(const SweepSetup& setup, double dy_m, double load_value,
                                            WheelSelection wheels = kBothWheels);

//! Marks a row that starts cold (warm_start_previous_rows).
inline constexpr std::size_t kColdStart = static_cast<std::size_t>(-1);
//! For each of the n_dy rows of a sweep, the row whose solution its solves start from, or kColdStart. Chains are
//! the runs of consecutive rows inside one work unit of case_partition.hpp (8 rows, and their mirror rows in a
//! mirrored sweep), ascending; the first row of each run starts cold. A function of (n_dy, mirrored) only, so a
//! table is the same at any thread count, and shards (whole units) merge into the single run's table bit for bit.
[[nodiscard]] std::vector<std::size_t> warm_start_previous_rows(std::size_t n_dy, bool mirrored);

//! Table status of a solver status (every shared value checked at compile time).
[[nodiscard]] tables::CaseStatus case_status(SolveStatus status) noexcept;
//! Table status of a solved wheel before slot assignment: SolverException, or the solver's status.
[[nodiscard]] tables::CaseStatus case_status(const CaseWheel& solved) noexcept;

//! Stores one wheel of one case in the table: status, patches in slots, force components, s origin, strip
//! profiles. A lone case has no neighbour to follow, so its slots are the zone rule of slot_assignment.hpp (tread
//! 0, flange 1, further patches from 2 in order of y_rail); generate_table instead lets the slots follow the
//! contacts along dy. More patches than slots: the case gets SlotOverflow and keeps no patch (force is never
//! dropped silently).
void store_case_wheel(tables::Table& table, const SweepSetup& setup, std::size_t i_dy, std::size_t i_second,
                      std::size_t wheel, const CaseWheel& solved);

//! Progress observer, called from the calling thread only (about every 0.1 s) with cases done and total.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

//! A sweep run in parts (shards of `ctab generate --shard`, blocks handed to MPI ranks): set up once, then the
//! rows (lateral-shift indices, every load and both wheels) of any subset solved into a table of the full shape.
//! A case's values do not depend on which other rows are solved with it, so the rows are bit-identical to those
//! of generate_table, which is this class over all rows. For a mirrored sweep (header above) the rows must be
//! mirror-closed (i and n_dy - 1 - i together): the left wheel of row i is the right wheel of row n_dy - 1 - i.
class TableSweep {
 public:
  //! Set-up (serial); throws InputError as make_sweep_setup.
  TableSweep(const TableConfig& config, const GeneratorInfo& info);
  ~TableSweep();
  TableSweep(TableSweep&&) noexcept;
  TableSweep(const TableSweep&) = delete;
  TableSweep& operator=(const TableSweep&) = delete;
  TableSweep& operator=(TableSweep&&) = delete;

  [[nodiscard]] std::size_t n_dy() const noexcept;
  [[nodiscard]] bool mirrored() const noexcept;                             //!< only the right wheel is solved
  [[nodiscard]] std::size_t wheel_solves(std::size_t rows) const noexcept;  //!< wheel solves of `rows` rows
  //! A table of the config's shape: axes set, every case zero with status Converged, no jumps, no provenance.
  [[nodiscard]] tables::Table empty_table() const;
  //! Solves `rows` (OpenMP, GeneratorInfo::threads) and stores their cases in `table` (from empty_table); other
  //! rows are untouched. Throws std::invalid_argument for a row out of range, repeated, or not mirror-closed.
  void solve_rows(const std::vector<std::size_t>& rows, tables::Table& table,
                  const ProgressCallback& progress = {}) const;
  //! Once every row is in: the contact jumps and the provenance attributes.
  void finish(tables::Table& table) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

//! Generates the table. Throws InputError at set-up (e.g. a profile file that cannot be read). The sweep runs on the
//! calling thread's OpenMP team (GeneratorInfo::threads), started beside the set-up; a caller that writes the table
//! with openmp_parallel_for afterwards reuses that team.
[[nodiscard]] tables::Table generate_table(const TableConfig& config, const GeneratorInfo& info,
                                           const ProgressCallback& progress = {});

//! Equivalent ellipse of a patch (Kik-Piotrowski recipe: area and length/width ratio kept):
//! a = sqrt(area/pi) sqrt(L/W), b = sqrt(area/pi) sqrt(W/L) [m].
void equivalent_ellipse(double area_m2, double length_m, double width_m, double& a_m, double& b_m) noexcept;

}  // namespace ctab::gen
