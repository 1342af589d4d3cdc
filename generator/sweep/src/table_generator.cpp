#include "ctab/sweep/table_generator.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <ctime>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "ctab/contact/error.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/strip_kernel.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/io/sha256.hpp"
#include "ctab/sweep/case_partition.hpp"
#include "ctab/sweep/slot_assignment.hpp"
#include "parallel_loop.hpp"

namespace ctab::gen {

// ---- status mapping: every value the two enums share is the same number ----
using tables::CaseStatus;
static_assert(static_cast<int>(SolveStatus::Converged) == static_cast<int>(CaseStatus::Converged));
static_assert(static_cast<int>(SolveStatus::NoContact) == static_cast<int>(CaseStatus::NoContact));
static_assert(static_cast<int>(SolveStatus::UnderResolved) == static_cast<int>(CaseStatus::UnderResolved));
static_assert(static_cast<int>(SolveStatus::MaxIterations) == static_cast<int>(CaseStatus::MaxIterations));
static_assert(static_cast<int>(SolveStatus::InvalidInput) == static_cast<int>(CaseStatus::InvalidInput));
static_assert(static_cast<int>(SolveStatus::ZoneTruncated) == static_cast<int>(CaseStatus::ZoneTruncated));
static_assert(static_cast<int>(SolveStatus::NumericalFailure) == static_cast<int>(CaseStatus::NumericalFailure));

tables::CaseStatus case_status(SolveStatus status) noexcept {
  switch (status) {
    case SolveStatus::Converged: return CaseStatus::Converged;
    case SolveStatus::NoContact: return CaseStatus::NoContact;
    case SolveStatus::UnderResolved: return CaseStatus::UnderResolved;
    case SolveStatus::MaxIterations: return CaseStatus::MaxIterations;
    case SolveStatus::InvalidInput: return CaseStatus::InvalidInput;
    case SolveStatus::ZoneTruncated: return CaseStatus::ZoneTruncated;
    case SolveStatus::NumericalFailure: return CaseStatus::NumericalFailure;
  }
  return CaseStatus::NumericalFailure;
}

tables::CaseStatus case_status(const CaseWheel& solved) noexcept {
  return solved.exception ? CaseStatus::SolverException : case_status(solved.contact.status);
}

void equivalent_ellipse(double area_m2, double length_m, double width_m, double& a_m, double& b_m) noexcept {
  if (!(area_m2 > 0.0 && length_m > 0.0 && width_m > 0.0)) {
    a_m = b_m = 0.0;
    return;
  }
  const double radius = std::sqrt(area_m2 / std::numbers::pi), ratio = std::sqrt(length_m / width_m);
  a_m = radius * ratio;
  b_m = radius / ratio;
}

SweepSetupError::SweepSetupError(const TableConfig& config, std::string key, std::string reason)
    : InputError(config.source, config.key_line(key), "'" + key + "': " + reason), key_(std::move(key)),
      reason_(std::move(reason)) {}

namespace {

ProfileTable load_checked(const TableConfig& config, const std::string& spec, ProfileRole role, const char* key,
                          ProfileSmoothing& smoothing) {
  ProfileReadOptions read;
  read.smoothing = role == ProfileRole::Wheel ? config.wheel_smoothing : config.rail_smoothing;
  read.inclination = config.inclination;
  try {
    return load_profile(spec, role, read, smoothing);
  } catch (const InputError& e) {
    throw SweepSetupError(config, key, e.what());
  }
}

// One wheel and one rail profile for both sides and a symmetric dy axis: the left wheel at dy is the right at -dy.
// Every node has its mirror image -dy (to 1e-9 of the span): a refined zone on one side only breaks the symmetry.
bool symmetric_axis(const std::vector<double>& dy_m) {
  const double span = std::max(std::abs(dy_m.front()), std::abs(dy_m.back()));
  for (std::size_t i = 0, n = dy_m.size(); i < n; ++i)
    if (std::abs(dy_m[i] + dy_m[n - 1 - i]) > 1e-9 * span + 1e-15) return false;
  return true;
}

void check_strip_width(const TableConfig& config) {
  if (config.strip_width_m >= kMinStripWidth_m && config.strip_width_m <= kMaxStripWidth_m) return;
  std::ostringstream range;
  range << "expected a strip width in [" << kMinStripWidth_m << ", " << kMaxStripWidth_m << "] m, got "
        << config.strip_width_m;
  throw SweepSetupError(config, "solver.strip_width_m", range.str());
}

}  // namespace

// ---- set-up ----

SweepSetup make_sweep_setup(const TableConfig& config) {
  check_strip_width(config);
  SweepSetup setup;
  setup.wheel = std::make_unique<const ProfileTable>(
      load_checked(config, config.wheel, ProfileRole::Wheel, "profiles.wheel", setup.wheel_smoothing));
  setup.rail = std::make_unique<const ProfileTable>(
      load_checked(config, config.rail, ProfileRole::Rail, "profiles.rail", setup.rail_smoothing));
  setup.side = std::make_unique<const SideGeometry>(place_profiles(config, *setup.wheel, *setup.rail));
  setup.E_star_Pa = effective_modulus(config.material, config.material);
  setup.options.method = config.method;
  setup.auto_tolerance = config.least_model ? config.tolerance : 0.0;
  setup.options.mim1d.strip_width_m = config.strip_width_m;  // range checked by the config
  setup.options.reference_at_interpenetration_centre = config.reference_at_interpenetration_centre;
  setup.options.reference_angle = config.reference_angle;
  setup.options.surface = config.surface;
  setup.mode = config.mode;
  setup.load_kind = config.load_kind;
  setup.dy_axis_m = config.lateral_displacement_m;
  setup.mirrored = !setup.dy_axis_m.empty() && symmetric_axis(setup.dy_axis_m);
  setup.warm_start = config.warm_start && config.method == NormalMethod::Mim1d && !config.least_model;
  (void)StripKernel::instance();  // process-wide tables are built here, not inside a parallel region
  HertzCoefficients warm_up;
  (void)hertz_coefficients_tabulated(1.0, 2.0, warm_up);
  return setup;
}

// ---- one case ----

CaseRoll solve_case_roll(const SweepSetup& setup, double dy_m, const RollGuess* guess) noexcept {
  if (setup.mode != ContactMode::Wheelset) return {};
  try {
    const WheelsetPose pose = rigid_wheelset_pose(*setup.side, *setup.side, dy_m, guess);
    return {pose.roll_rad, pose.converged, pose.detail};
  } catch (...) {
    return {0.0, false, "the wheelset roll search threw"};
  }
}

CaseWheel solve_case_wheel(const SweepSetup& setup, std::size_t wheel, double dy_m, const CaseRoll& roll,
                           double load_value, WheelContactWorkspace& workspace, Mim1dWarmStart* warm_start) noexcept {
  const double shift = wheel == 1 ? -dy_m : dy_m, angle = wheel == 1 ? -roll.roll_rad : roll.roll_rad;
  CaseWheel out;
  try {
    out.choice.method = setup.options.method;
    out.choice.strip_width_m = setup.options.mim1d.strip_width_m;
    out.choice.solves = 1;
    if (setup.auto_tolerance > 0.0)
      out.contact = solve_wheel_contact_auto(*setup.side, shift, angle, setup.E_star_Pa, setup.load_kind, load_value,
                                             setup.options, setup.auto_tolerance, workspace, &out.choice);
    else
      out.contact = warm_start == nullptr
                        ? solve_wheel_contact(*setup.side, shift, angle, setup.E_star_Pa, setup.load_kind, load_value,
                                              setup.options, workspace)
                        : solve_wheel_contact(*setup.side, shift, angle, setup.E_star_Pa, setup.load_kind, load_value,
                                              setup.options, workspace, *warm_start);
    if (!roll.converged) {
      if (warm_start != nullptr) warm_start->clear();
      out.contact.status = SolveStatus::MaxIterations;
      out.contact.detail = "wheelset roll did not converge: " + roll.detail;
      out.contact.patches.clear();
    }
  } catch (...) {
    out = CaseWheel{};
    out.exception = true;
    if (warm_start != nullptr) warm_start->clear();
  }
  return out;
}

std::vector<std::size_t> warm_start_previous_rows(std::size_t n_dy, bool mirrored) {
  std::vector<std::size_t> previous(n_dy, kColdStart);
  for (const std::vector<std::size_t>& unit : sweep_units(n_dy, mirrored))
    for (std::size_t j = 1; j < unit.size(); ++j)
      if (unit[j] == unit[j - 1] + 1) previous[unit[j]] = unit[j - 1];
  return previous;
}

namespace {

// The row a wheel's solve is computed at: a mirrored sweep solves the left wheel as the right wheel at -dy.
struct SolvedRow {
  std::size_t side = 0, row = 0;
};
SolvedRow solved_row(const SweepSetup& setup, std::size_t wheel, std::size_t row) {
  if (setup.mirrored && wheel == 1) return {0, setup.dy_axis_m.size() - 1 - row};
  return {wheel, row};
}

// A wheel of the case at axis row `row` as the sweep solves it: its warm-start chain replayed from its cold row.
CaseWheel replay_chain(const SweepSetup& setup, std::size_t wheel, std::size_t row, const CaseRoll& roll,
                       double load_value, WheelContactWorkspace& workspace) {
  const SolvedRow target = solved_row(setup, wheel, row);
  const std::vector<std::size_t> previous = warm_start_previous_rows(setup.dy_axis_m.size(), setup.mirrored);
  std::vector<std::size_t> chain{target.row};
  while (previous[chain.back()] != kColdStart) chain.push_back(previous[chain.back()]);
  Mim1dWarmStart warm;
  for (std::size_t k = chain.size() - 1; k > 0; --k) {
    const double dy = setup.dy_axis_m[chain[k]];
    (void)solve_case_wheel(setup, target.side, dy, solve_case_roll(setup, dy), load_value, workspace, &warm);
  }
  // The target itself in the wheel's own frame (bit-identical to the solved row's frame, roll_mirror_test).
  return solve_case_wheel(setup, wheel, setup.dy_axis_m[row], roll, load_value, workspace, &warm);
}

}  // namespace

CaseSolution solve_table_case(const SweepSetup& setup, double dy_m, double load_value, WheelSelection wheels) {
  CaseSolution solution;
  solution.dy_m = dy_m;
  solution.load_value = load_value;
  solution.roll = solve_case_roll(setup, dy_m);
  solution.solved = wheels;
  WheelContactWorkspace workspace;
  // A shift on the axis is solved as the sweep solves it (warm-started along its chain), any other cold.
  const auto on_axis = std::find(setup.dy_axis_m.begin(), setup.dy_axis_m.end(), dy_m);
  const bool replay = setup.warm_start && on_axis != setup.dy_axis_m.end();
  for (std::size_t wheel = 0; wheel < tables::kWheels; ++wheel)
    if (wheels[wheel])
      solution.wheels[wheel] =
          replay ? replay_chain(setup, wheel, static_cast<std::size_t>(on_axis - setup.dy_axis_m.begin()),
                                solution.roll, load_value, workspace)
                 : solve_case_wheel(setup, wheel, dy_m, solution.roll, load_value, workspace);
  if (wheels == kBothWheels)
    solution.rolling_radius_difference_m = solution.wheels[0].contact.rigid_contact.rolling_radius_m -
                                           solution.wheels[1].contact.rigid_contact.rolling_radius_m;
  return solution;
}

// ---- assembly of one wheel of one case ----

namespace {

// Linear interpolation of a strip profile at s (0 outside the strips).
double sample_strips(const std::vector<PatchStrip>& strips, double s, bool pressure) {
  if (strips.empty() || s < strips.front().s_m || s > strips.back().s_m) return 0.0;
  const auto upper =
      std::lower_bound(strips.begin(), strips.end(), s, [](const PatchStrip& a, double v) { return a.s_m < v; });
  if (upper == strips.begin()) return pressure ? upper->p0_Pa : upper->half_length_m;
  const PatchStrip& hi = *upper;
  const PatchStrip& lo = *(upper - 1);
  const double t = (s - lo.s_m) / (hi.s_m - lo.s_m);
  return pressure ? (1 - t) * lo.p0_Pa + t * hi.p0_Pa : (1 - t) * lo.half_length_m + t * hi.half_length_m;
}

// Lateral rail coordinate of s = 0: the point where the contact plane touches the rail (its slope there is
// tan(plane_angle); wheelrail_contact.cpp builds the plane at the reference minimum). A patch that holds s = 0
// has it as its contact point; otherwise (a run split off the reference window) the tangent point is found by
// secant steps on the rail slope from the strips' linear extrapolation to s = 0.
double s_origin_y_rail(const ContactPatch& patch, const ProfileTable& rail) {
  if (std::isfinite(patch.s_origin_y_rail_m)) return patch.s_origin_y_rail_m;  // conformal: the surface's origin
  if (patch.s_min_m <= 0.0 && patch.s_max_m >= 0.0) return patch.y_rail_m;
  const auto& strips = patch.strips;
  double y = patch.y_rail_m;
  if (strips.size() >= 2 && strips.back().s_m > strips.front().s_m)
    y = strips.front().y_rail_m - strips.front().s_m * (strips.back().y_rail_m - strips.front().y_rail_m) /
                                      (strips.back().s_m - strips.front().s_m);
  const double target = std::tan(patch.plane_angle_rad);
  auto f = [&](double at) { return rail.at(at).dz - target; };
  double y0 = y, y1 = y + 1e-4, f0 = f(y0), f1 = f(y1);
  for (int i = 0; i < 40 && std::abs(f1) > 1e-13 && f1 != f0; ++i) {
    const double next = y1 - f1 * (y1 - y0) / (f1 - f0);
    y0 = y1;
    f0 = f1;
    y1 = std::clamp(next, rail.y_min(), rail.y_max());
    f1 = f(y1);
  }
  return std::abs(f1) <= 1e-9 ? y1 : y;
}

void store_patch(tables::Table& table, const ProfileTable& rail, std::size_t k, const ContactPatch& patch) {
  auto& p = table.patch;
  p.present[k] = 1;
  p.normal_force_N[k] = patch.normal_force_N;
  // Force of the wheel on the rail, the solver's own components (those of its load balance): vertical + down,
  // lateral + to the field side (a flange force is > 0).
  p.force_vertical_N[k] = patch.force_vertical_N;
  p.force_lateral_N[k] = patch.force_lateral_N;
  p.area_m2[k] = patch.area_m2;
  p.max_pressure_Pa[k] = patch.max_pressure_Pa;
  p.approach_m[k] = patch.approach_m;
  p.contact_angle_rad[k] = patch.contact_angle_rad;
  p.plane_angle_rad[k] = patch.plane_angle_rad;
  p.s_origin_y_rail_m[k] = s_origin_y_rail(patch, rail);
  p.s_origin_z_rail_m[k] = rail.at(p.s_origin_y_rail_m[k]).z;
  p.y_wheel_m[k] = patch.y_wheel_m;
  p.y_rail_m[k] = patch.y_rail_m;
  p.y_cop_rail_m[k] = patch.y_cop_rail_m;
  p.rolling_radius_m[k] = patch.rolling_radius_m;
  p.s_min_m[k] = patch.s_min_m;
  p.s_max_m[k] = patch.s_max_m;
  double longest = 0.0;
  for (const PatchStrip& s : patch.strips) longest = std::max(longest, 2.0 * s.half_length_m);
  equivalent_ellipse(patch.area_m2, longest, patch.s_max_m - patch.s_min_m, p.semi_axis_a_m[k], p.semi_axis_b_m[k]);
  const std::size_t n = table.strip_samples;
  for (std::size_t j = 0; j < n; ++j) {
    const double s =
        patch.s_min_m + (patch.s_max_m - patch.s_min_m) * static_cast<double>(j) / static_cast<double>(n - 1);
    p.strip_half_length_m[k * n + j] = sample_strips(patch.strips, s, false);
    p.strip_peak_pressure_Pa[k * n + j] = sample_strips(patch.strips, s, true);
  }
}

}  // namespace

namespace {

SlotCase slot_case(const CaseWheel& solved) {
  SlotCase out;
  out.success = !solved.exception && tables::is_success(case_status(solved.contact.status));
  if (out.success)
    for (const ContactPatch& patch : solved.contact.patches)
      out.patches.push_back({patch.y_rail_m, patch.zone == "flange"});
  return out;
}

// Status and patches of one wheel of one case in the slots `assignment` gives them.
void store_wheel(tables::Table& table, const SweepSetup& setup, std::size_t i_dy, std::size_t i_second,
                 std::size_t wheel, const CaseWheel& solved, const SlotAssignment& assignment) {
  const std::size_t w = table.wheel_index(i_dy, i_second, wheel);
  table.method[w] = static_cast<std::int8_t>(solved.choice.method);
  table.strip_width_m[w] = solved.choice.strip_width_m;
  CaseStatus& status = table.status[w];
  status = case_status(solved);
  if (!tables::is_success(status)) return;  // a failed case holds no patches
  if (assignment.overflow) {
    status = CaseStatus::SlotOverflow;
    return;
  }
  for (std::size_t i = 0; i < assignment.slot_of.size(); ++i)
    store_patch(table, *setup.rail, table.patch_index(i_dy, i_second, wheel, assignment.slot_of[i]),
                solved.contact.patches[i]);
}

}  // namespace

void store_case_wheel(tables::Table& table, const SweepSetup& setup, std::size_t i_dy, std::size_t i_second,
                      std::size_t wheel, const CaseWheel& solved) {
  const std::vector<SlotAssignment> assignment = assign_slots_along_dy({slot_case(solved)}, table.n_slots);
  store_wheel(table, setup, i_dy, i_second, wheel, solved, assignment.front());
}

// ---- the whole table, in named steps ----

namespace {

struct SweepPlan {
  std::vector<double> dy_m;
  std::vector<double> load_values;
  bool mirrored = false;  // one wheel and one rail profile for both sides and a symmetric dy axis
  std::size_t sides = 2;  // wheels solved: 1 when mirrored
  int threads = 1;
  [[nodiscard]] std::size_t cases() const { return dy_m.size() * load_values.size(); }
};

SweepPlan make_plan(const TableConfig& config, const GeneratorInfo& info) {
  SweepPlan plan;
  plan.dy_m = config.lateral_displacement_m;
  plan.load_values = config.load_values;
  plan.mirrored = symmetric_axis(plan.dy_m);
  plan.sides = plan.mirrored ? 1 : 2;
  plan.threads = std::max(1, info.threads);
  return plan;
}

// Runs `work` on this thread, whose OpenMP threads (started once, generate_table) also serve the table's write,
// while a reporter thread calls `progress` every 0.1 s (no I/O in the parallel region); no reporter without
// `progress`.
void run_with_progress(const std::function<void()>& work, const std::atomic<std::size_t>& done, std::size_t total,
                       const ProgressCallback& progress) {
  if (!progress) return work();
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;
  std::thread reporter([&] {
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished) {
      lock.unlock();
      progress(done.load(std::memory_order_relaxed), total);
      lock.lock();
      finished_signal.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; });
    }
  });
  const auto stop_reporter = [&] {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      finished = true;
    }
    finished_signal.notify_one();
    reporter.join();
  };
  try {
    work();
  } catch (...) {
    stop_reporter();
    throw;
  }
  stop_reporter();
  progress(total, total);
}

// For each of `rows` (lateral-shift indices), the position in `rows` of the row whose roll it mirrors, or
// kSolveRoll where its roll is solved. Mirrored wheelset sweeps solve only dy >= 0: on mirror-image sides
// roll(-dy) = -roll(dy) to the bit (the mismatch z_right - z_left is exactly antisymmetric in (dy, roll), and the
// bracketed root finder's steps, from the symmetric bracket on, are exactly mirrored). The rows of a mirrored
// sweep are mirror-closed (TableSweep::solve_rows, sweep_units), so the source row is always among them.
constexpr std::size_t kSolveRoll = static_cast<std::size_t>(-1);

std::vector<std::size_t> roll_sources(const SweepSetup& setup, const SweepPlan& plan,
                                      const std::vector<std::size_t>& rows) {
  std::vector<std::size_t> source(rows.size(), kSolveRoll);
  if (!plan.mirrored || setup.mode != ContactMode::Wheelset) return source;
  const std::size_t n_dy = plan.dy_m.size();
  std::vector<std::size_t> position(n_dy, kSolveRoll);
  for (std::size_t k = 0; k < rows.size(); ++k) position[rows[k]] = k;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (plan.dy_m[rows[k]] < 0.0) source[k] = position[n_dy - 1 - rows[k]];
  return source;
}

// Consecutive rows (lateral-shift indices) whose rolls are solved, in runs of at most kRollRunRows: each run is
// one task, every roll after its first searched from its predecessors' (linear extrapolation). The guess changes
// only the search's cost, never its result (rigid_wheelset_pose), so any split gives the same table.
constexpr std::size_t kRollRunRows = 8;

std::vector<std::vector<std::size_t>> roll_runs(const std::vector<std::size_t>& rows,
                                                const std::vector<std::size_t>& solved) {
  std::vector<std::vector<std::size_t>> runs;
  for (std::size_t j = 0; j < solved.size(); ++j) {
    if (runs.empty() || runs.back().size() == kRollRunRows || rows[solved[j]] != rows[runs.back().back()] + 1)
      runs.emplace_back();
    runs.back().push_back(solved[j]);
  }
  return runs;
}

// The guess for the next roll of a run from the rolls before it (none for the run's first).
const RollGuess* next_roll_guess(const std::vector<CaseRoll>& rolls, const std::vector<std::size_t>& run,
                                 std::size_t position, RollGuess& guess) {
  if (position == 0 || !rolls[run[position - 1]].converged) return nullptr;
  const double previous = rolls[run[position - 1]].roll_rad;
  const bool two = position >= 2 && rolls[run[position - 2]].converged;
  const double change = two ? previous - rolls[run[position - 2]].roll_rad : 0.0;
  guess = {previous + change, std::abs(change)};
  return &guess;
}

// The rolls of one run (positions in `rows`, consecutive rows), each after the first searched from its
// predecessors'; then the rolls that mirror them (`mirrors`: for each position, the positions whose source it is),
// a failed source's mirror solved directly, so that its detail names its own dy.
void solve_roll_run(const SweepSetup& setup, const SweepPlan& plan, const std::vector<std::size_t>& rows,
                    const std::vector<std::size_t>& run, const std::vector<std::vector<std::size_t>>& mirrors,
                    std::vector<CaseRoll>& rolls) {
  RollGuess guess;
  for (std::size_t j = 0; j < run.size(); ++j) {
    const std::size_t k = run[j];
    rolls[k] = solve_case_roll(setup, plan.dy_m[rows[k]], next_roll_guess(rolls, run, j, guess));
    for (const std::size_t m : mirrors[k])
      rolls[m] =
          rolls[k].converged ? CaseRoll{-rolls[k].roll_rad, true, ""} : solve_case_roll(setup, plan.dy_m[rows[m]]);
  }
}

// The warm-start chains among `rows` (lateral-shift indices): positions k in `rows`, each chain in solve order. A row
// continues the chain of its warm_start_previous_rows row when that row is selected too (shards hold whole units,
// so their chains are those of the full sweep); without warm start every row is a chain of its own.
std::vector<std::vector<std::size_t>> warm_start_chains(const SweepSetup& setup, const SweepPlan& plan,
                                                        const std::vector<std::size_t>& rows) {
  const std::size_t n_dy = plan.dy_m.size();
  std::vector<std::size_t> position(n_dy, kColdStart);
  for (std::size_t k = 0; k < rows.size(); ++k) position[rows[k]] = k;
  const std::vector<std::size_t> previous =
      setup.warm_start ? warm_start_previous_rows(n_dy, plan.mirrored) : std::vector<std::size_t>(n_dy, kColdStart);
  std::vector<std::size_t> next(n_dy, kColdStart);
  for (const std::size_t row : rows)
    if (previous[row] != kColdStart && position[previous[row]] != kColdStart) next[previous[row]] = row;
  std::vector<std::vector<std::size_t>> chains;
  for (const std::size_t row : rows) {
    if (previous[row] != kColdStart && position[previous[row]] != kColdStart) continue;  // not a chain's start
    chains.emplace_back();
    for (std::size_t r = row; r != kColdStart; r = next[r]) chains.back().push_back(position[r]);
  }
  return chains;
}

// The order the chains are solved in: by the smallest |dy| of their rows, so that the first chains need the rolls
// of the first roll runs (those of the smallest |dy| >= 0, and their mirrors), and the dearer flange chains come
// before the last, cheap ones far out.
std::vector<std::size_t> chain_order(const SweepPlan& plan, const std::vector<std::size_t>& rows,
                                     const std::vector<std::vector<std::size_t>>& chains) {
  std::vector<double> nearest(chains.size(), std::numeric_limits<double>::infinity());
  for (std::size_t c = 0; c < chains.size(); ++c)
    for (const std::size_t k : chains[c]) nearest[c] = std::min(nearest[c], std::abs(plan.dy_m[rows[k]]));
  std::vector<std::size_t> order(chains.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nearest[a] < nearest[b]; });
  return order;
}

// Rolls (one per selected lateral shift) and every solved wheel of every selected case, in one parallel region:
// items are handed out in order from one counter, first the roll runs, then the wheel tasks (one warm-start chain
// of one side and one load each, writing only its own slots). A wheel task waits for its rows' rolls, which are
// then either done or being solved by a thread that waits for nothing (every roll run was handed out before any
// wheel task), so the region cannot stall; no barrier between the rolls and the solves. `rows` are lateral-shift
// indices; results are indexed (side, k, i_second) with k the position in `rows`, rolls by k. A case's solve
// depends on nothing but its own inputs and its chain, so any subset of whole chains gives the same values at any
// thread count, in any order.
std::vector<CaseWheel> sweep(const SweepSetup& setup, const SweepPlan& plan, const std::vector<std::size_t>& rows,
                             std::vector<CaseRoll>& rolls, const ProgressCallback& progress) {
  const std::size_t n_rows = rows.size(), n_second = plan.load_values.size(), row_cases = n_rows * n_second;
  const std::size_t total = row_cases * plan.sides;
  const std::vector<std::vector<std::size_t>> chains = warm_start_chains(setup, plan, rows);
  const std::vector<std::size_t> order = chain_order(plan, rows, chains);
  const std::size_t side_tasks = chains.size() * n_second, tasks = side_tasks * plan.sides;
  // The roll runs and, for each solved roll, the rows that mirror it.
  const std::vector<std::size_t> source = roll_sources(setup, plan, rows);
  std::vector<std::size_t> solved;
  std::vector<std::vector<std::size_t>> mirrors(n_rows);
  for (std::size_t k = 0; k < n_rows; ++k) {
    if (source[k] == kSolveRoll) solved.push_back(k);
    else mirrors[source[k]].push_back(k);
  }
  std::sort(solved.begin(), solved.end(), [&](std::size_t a, std::size_t b) { return rows[a] < rows[b]; });
  const std::vector<std::vector<std::size_t>> runs = roll_runs(rows, solved);
  std::vector<std::atomic<bool>> roll_ready(n_rows);  // value-initialised: false
  rolls = std::vector<CaseRoll>(n_rows);
  std::vector<CaseWheel> results(total);
  std::vector<WheelContactWorkspace> workspaces(static_cast<std::size_t>(plan.threads));  // one per thread
  std::atomic<std::size_t> done{0}, next_item{0};
  const std::size_t items = runs.size() + tasks;
  auto work = [&] {
#pragma omp parallel num_threads(plan.threads)
    {
      WheelContactWorkspace& workspace = workspaces[static_cast<std::size_t>(omp_get_thread_num())];
      for (std::size_t item = next_item.fetch_add(1); item < items; item = next_item.fetch_add(1)) {
        if (item < runs.size()) {
          const std::vector<std::size_t>& run = runs[item];
          solve_roll_run(setup, plan, rows, run, mirrors, rolls);
          for (const std::size_t k : run) {
            roll_ready[k].store(true, std::memory_order_release);
            for (const std::size_t m : mirrors[k]) roll_ready[m].store(true, std::memory_order_release);
          }
          continue;
        }
        const std::size_t task = item - runs.size(), side = task / side_tasks, rest = task % side_tasks;
        const std::vector<std::size_t>& chain = chains[order[rest / n_second]];
        const std::size_t i_second = rest % n_second;
        Mim1dWarmStart warm;  // the chain's first row starts cold
        for (const std::size_t k : chain) {
          while (!roll_ready[k].load(std::memory_order_acquire)) std::this_thread::yield();
          results[side * row_cases + k * n_second + i_second] =
              solve_case_wheel(setup, side, plan.dy_m[rows[k]], rolls[k], plan.load_values[i_second], workspace, &warm);
          done.fetch_add(1, std::memory_order_relaxed);
        }
      }
    }
  };
  run_with_progress(work, done, total, progress);
  return results;
}

tables::Table empty_table(const TableConfig& config, const SweepPlan& plan) {
  tables::Table table;
  table.lateral_displacement_m = plan.dy_m;
  table.second_axis = plan.load_values;
  table.second_axis_name = load_axis_name(config.load_kind);
  table.second_axis_units =
      std::string(1, config.load_kind == LoadKind::Approach ? 'm'
                                                            : 'N');  // not a literal: GCC 12 -Wrestrict false positive
  table.strip_samples = config.strip_samples;
  table.n_slots = config.patch_slots;
  table.allocate();
  return table;
}

// Stores the rows `rows` of the sweep's results (see sweep) in `table`.
void assemble(tables::Table& table, const SweepSetup& setup, const SweepPlan& plan,
              const std::vector<std::size_t>& rows, const std::vector<CaseRoll>& rolls,
              const std::vector<CaseWheel>& results) {
  const std::size_t n_dy = plan.dy_m.size(), n_second = plan.load_values.size(), row_cases = rows.size() * n_second;
  std::vector<std::size_t> position(n_dy, n_dy);  // k of each selected row, n_dy elsewhere
  for (std::size_t k = 0; k < rows.size(); ++k) position[rows[k]] = k;
  // Each row's cases write only that row's entries (and read the results): the rows in parallel.
  detail::parallel_loop(rows.size(), plan.threads, false, [&](std::size_t k) {
    for (std::size_t i_second = 0; i_second < n_second; ++i_second) {
      const std::size_t i_dy = rows[k];
      const CaseWheel& right = results[k * n_second + i_second];
      // Mirrored: the left wheel at dy is the right wheel at -dy (index n_dy - 1 - i_dy of a symmetric axis).
      const CaseWheel& left = plan.mirrored ? results[position[n_dy - 1 - i_dy] * n_second + i_second]
                                            : results[row_cases + k * n_second + i_second];
      store_case_wheel(table, setup, i_dy, i_second, 0, right);
      store_case_wheel(table, setup, i_dy, i_second, 1, left);
      const std::size_t c = i_dy * n_second + i_second;
      table.roll_rad[c] = rolls[k].roll_rad;
      table.rolling_radius_difference_m[c] =
          right.contact.rigid_contact.rolling_radius_m - left.contact.rigid_contact.rolling_radius_m;
    }
  });
}

std::string utc_now() {
  std::time_t now = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) now = static_cast<std::time_t>(std::atoll(epoch));
  char text[32];
  std::tm utc{};
  gmtime_r(&now, &utc);
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

// "<body>_smoothing_m", "<body>_smoothing_near_jumps_m", "<body>_noise_sigma_m" and with the arcs prior
// "<body>_arc_junctions" of a point profile (nothing for a built-in one).
void add_smoothing_provenance(tables::Table& table, const std::string& body, const ProfileSmoothing& smoothing) {
  if (!smoothing.point_data) return;
  table.number_attributes[body + "_smoothing_m"] = smoothing.length_m;
  table.number_attributes[body + "_smoothing_near_jumps_m"] = smoothing.jump_length_m;
  table.number_attributes[body + "_noise_sigma_m"] = smoothing.noise_sigma_m;
  if (smoothing.arc_junctions >= 0) table.number_attributes[body + "_arc_junctions"] = smoothing.arc_junctions;
}

void add_provenance(tables::Table& table, const TableConfig& config, const SweepSetup& setup, const SweepPlan& plan,
                    const GeneratorInfo& info) {
  auto& text = table.text_attributes;
  text["generator"] = "ctab";
  text["generator_version"] = info.version;
  text["git_commit"] = info.git_commit;
  text["compiler"] = info.compiler;
  text["build_flags"] = info.build_flags;
  text["config"] = config.text;
  text["config_source"] = config.source;
  text["created_utc"] = utc_now();
  text["wheel_profile"] = config.wheel;
  text["rail_profile"] = config.rail;
  text["wheel_profile_sha256"] =
      sha256_hex(setup.wheel->z_samples().data(), setup.wheel->z_samples().size() * sizeof(double));
  text["rail_profile_sha256"] =
      sha256_hex(setup.rail->z_samples().data(), setup.rail->z_samples().size() * sizeof(double));
  text["rail_inclination"] = config.inclination_text;
  text["smoothing"] =
      config.wheel_smoothing == config.rail_smoothing
          ? smoothing_text(config.wheel_smoothing)
          : "wheel " + smoothing_text(config.wheel_smoothing) + ", rail " + smoothing_text(config.rail_smoothing);
  text["mode"] = config.mode == ContactMode::Wheelset ? "wheelset" : "wheel";
  text["method"] = config.least_model ? "auto" : method_name(config.method);  // per case: /wheels/method
  text["surface"] = std::string(surface_name(config.surface));
  text["reference_point"] = std::string(reference_point_name(config.reference_at_interpenetration_centre));
  text["reference_angle"] = std::string(reference_angle_name(setup.options));
  text["mirrored"] = plan.mirrored ? "true: left wheel at dy = right wheel at -dy (mirror-image sides)" : "false";
  text["units"] = "SI: m, N, Pa, rad";
  auto& number = table.number_attributes;
  number["youngs_modulus_Pa"] = config.material.youngs_modulus_Pa;
  number["poisson_ratio"] = config.material.poisson_ratio;
  number["strip_width_m"] = config.strip_width_m;  // per case: /wheels/strip_width_m
  if (config.least_model) number["tolerance"] = config.tolerance;
  number["gauge_m"] = config.track.gauge_m;
  number["nominal_radius_m"] = config.track.nominal_radius_m;
  add_smoothing_provenance(table, "wheel", setup.wheel_smoothing);
  add_smoothing_provenance(table, "rail", setup.rail_smoothing);
  table.integer_attributes["threads"] = plan.threads;
  table.integer_attributes[tables::kCompressionLevelAttribute] = static_cast<std::int64_t>(config.compression_level);
}

}  // namespace

// ---- a sweep in parts ----

struct TableSweep::Impl {
  TableConfig config;
  SweepSetup setup;
  SweepPlan plan;
  GeneratorInfo info;
};

TableSweep::TableSweep(const TableConfig& config, const GeneratorInfo& info)
    : impl_(std::make_unique<Impl>(Impl{config, make_sweep_setup(config), make_plan(config, info), info})) {}
TableSweep::~TableSweep() = default;
TableSweep::TableSweep(TableSweep&&) noexcept = default;

std::size_t TableSweep::n_dy() const noexcept { return impl_->plan.dy_m.size(); }
bool TableSweep::mirrored() const noexcept { return impl_->plan.mirrored; }
std::size_t TableSweep::wheel_solves(std::size_t rows) const noexcept {
  return rows * impl_->plan.load_values.size() * impl_->plan.sides;
}
tables::Table TableSweep::empty_table() const { return gen::empty_table(impl_->config, impl_->plan); }

void TableSweep::solve_rows(const std::vector<std::size_t>& rows, tables::Table& table,
                            const ProgressCallback& progress) const {
  const std::size_t n = n_dy();
  std::vector<bool> selected(n, false);
  for (const std::size_t i : rows) {
    if (i >= n || selected[i]) throw std::invalid_argument("TableSweep::solve_rows: a row out of range or repeated");
    selected[i] = true;
  }
  if (mirrored())
    for (const std::size_t i : rows)
      if (!selected[n - 1 - i])
        throw std::invalid_argument("TableSweep::solve_rows: rows of a mirrored sweep must be mirror-closed");
  std::vector<CaseRoll> rolls;
  const std::vector<CaseWheel> results = sweep(impl_->setup, impl_->plan, rows, rolls, progress);
  assemble(table, impl_->setup, impl_->plan, rows, rolls, results);
}

void TableSweep::finish(tables::Table& table) const {
  assign_table_slots_along_dy(table, impl_->plan.threads);  // on all rows: slots follow the contacts along dy
  table.jumps = tables::detect_jumps(table);
  add_provenance(table, impl_->config, impl_->setup, impl_->plan, impl_->info);
}

namespace {

// Starts the calling thread's OpenMP team of `threads` (nothing for 1): a team's first region waits until every
// thread runs, which later regions of the same thread do not.
void start_openmp_threads(int threads) noexcept {
  if (threads <= 1) return;
  std::atomic<int> started{0};  // a region with a body: GCC drops an empty one
#pragma omp parallel num_threads(threads)
  started.fetch_add(1, std::memory_order_relaxed);
}

// The first parallel region of a thread creates its OpenMP threads and waits until every one of them runs: on a
// loaded or virtual machine that took 1 to 4 ms (the scheduler's tick), with every thread of the team idle. So the
// calling thread starts its team (and the HDF5 library) while a helper thread loads the profiles and builds the
// set-up; the sweep and the table's write then run on the started team. Without threads to start, the set-up runs
// here.
TableSweep make_sweep_starting_threads(const TableConfig& config, const GeneratorInfo& info) {
  if (info.threads <= 1) return TableSweep(config, info);
  std::optional<TableSweep> sweep;
  std::exception_ptr error;
  std::thread setup([&] {
    try {
      sweep.emplace(config, info);
    } catch (...) {
      error = std::current_exception();
    }
  });
  start_openmp_threads(info.threads);
  tables::start_hdf5();  // for the write, here rather than after the sweep (the set-up never calls HDF5)
  setup.join();
  if (error) std::rethrow_exception(error);
  return std::move(*sweep);
}

}  // namespace

tables::Table generate_table(const TableConfig& config, const GeneratorInfo& info, const ProgressCallback& progress) {
  const TableSweep sweep = make_sweep_starting_threads(config, info);
  std::vector<std::size_t> rows(sweep.n_dy());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  tables::Table table = sweep.empty_table();
  sweep.solve_rows(rows, table, progress);
  sweep.finish(table);
  return table;
}

}  // namespace ctab::gen
