#include "ctab/sweep/table_generator.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "ctab/contact/error.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/io/sha256.hpp"
#include "ctab/contact/strip_kernel.hpp"

namespace ctab::gen {

void equivalent_ellipse(double area_m2, double length_m, double width_m, double& a_m, double& b_m) noexcept {
  if (!(area_m2 > 0.0 && length_m > 0.0 && width_m > 0.0)) {
    a_m = b_m = 0.0;
    return;
  }
  const double radius = std::sqrt(area_m2 / std::numbers::pi), ratio = std::sqrt(length_m / width_m);
  a_m = radius * ratio;
  b_m = radius / ratio;
}

namespace {

ProfileTable load_checked(const TableConfig& config, const std::string& spec, ProfileRole role, const char* key) {
  ProfileReadOptions read;
  read.smoothing_length_m = config.smoothing_length_m;
  read.inclination = config.inclination;
  try {
    return load_profile(spec, role, read);
  } catch (const InputError& e) {
    throw InputError(config.source, config.key_line(key), std::string("'") + key + "': " + e.what());
  }
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

// Linear interpolation of a strip profile at s (0 outside the strips).
double sample_strips(const std::vector<PatchStrip>& strips, double s, bool pressure) {
  if (strips.empty() || s < strips.front().s_m || s > strips.back().s_m)
    return 0.0;
  const auto upper = std::lower_bound(strips.begin(), strips.end(), s, [](const PatchStrip& a, double v) { return a.s_m < v; });
  if (upper == strips.begin()) return pressure ? upper->p0_Pa : upper->half_length_m;
  const PatchStrip& hi = *upper;
  const PatchStrip& lo = *(upper - 1);
  const double t = (s - lo.s_m) / (hi.s_m - lo.s_m);
  return pressure ? (1 - t) * lo.p0_Pa + t * hi.p0_Pa : (1 - t) * lo.half_length_m + t * hi.half_length_m;
}

void store_wheel(tables::Table& table, std::size_t i_dy, std::size_t i_second, std::size_t wheel, const WheelContact& c) {
  table.status[(i_dy * table.n_second() + i_second) * tables::kWheels + wheel] = static_cast<std::int8_t>(c.status);
  std::array<bool, tables::kSlots> used{};
  auto& p = table.patch;
  for (const ContactPatch& patch : c.patches) {
    std::size_t slot = patch.zone == "flange" ? 1 : 0;
    if (used[slot]) slot = 2;  // a second patch in the same zone goes to the spare slot
    if (used[slot]) continue;  // more than three patches: the weakest are dropped (never seen on standard profiles)
    used[slot] = true;
    const std::size_t k = table.patch_index(i_dy, i_second, wheel, slot);
    p.present[k] = 1;
    p.normal_force_N[k] = patch.normal_force_N;
    p.area_m2[k] = patch.area_m2;
    p.max_pressure_Pa[k] = patch.max_pressure_Pa;
    p.approach_m[k] = patch.approach_m;
    p.contact_angle_rad[k] = patch.contact_angle_rad;
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
      const double s = patch.s_min_m + (patch.s_max_m - patch.s_min_m) * static_cast<double>(j) / static_cast<double>(n - 1);
      p.strip_half_length_m[k * n + j] = sample_strips(patch.strips, s, false);
      p.strip_peak_pressure_Pa[k * n + j] = sample_strips(patch.strips, s, true);
    }
  }
}

}  // namespace

tables::Table generate_table(const TableConfig& config, const GeneratorInfo& info, const ProgressCallback& progress) {
  // ---- set-up (serial; may throw) ----
  const ProfileTable wheel = load_checked(config, config.wheel, ProfileRole::Wheel, "profiles.wheel");
  const ProfileTable rail = load_checked(config, config.rail, ProfileRole::Rail, "profiles.rail");
  const SideGeometry side(wheel, rail, config.track);
  const double E_star = effective_modulus(config.material, config.material);
  WheelRailOptions options;
  options.method = config.method;
  options.mim1d.strip_width_m = config.strip_width_m;
  if (options.mim1d.strip_width_m <= 0.0) throw InputError(config.source, config.key_line("solver.strip_width_m"), "strip width must be positive");
  (void)StripKernel::instance();  // process-wide tables are built here, not inside the parallel region
  HertzCoefficients warm_up;
  (void)hertz_coefficients_tabulated(1.0, 2.0, warm_up);

  const auto& dy = config.lateral_displacement_m;
  const std::size_t n_dy = dy.size(), n_second = config.load_values.size();
  const double span = std::max(std::abs(dy.front()), std::abs(dy.back()));
  const bool mirrored = std::abs(dy.front() + dy.back()) <= 1e-9 * span + 1e-15;  // same profiles both sides, symmetric axis
  const int threads = std::max(1, info.threads);

  // ---- roll angles (parallel; one per lateral shift) ----
  std::vector<double> roll(n_dy, 0.0);
  std::vector<std::int8_t> roll_ok(n_dy, 1);
  // ---- contact solves (parallel): right wheel at every case, left wheel only when not mirrored ----
  const std::size_t sides = mirrored ? 1 : 2;
  const std::size_t total = n_dy * n_second * sides;
  std::vector<WheelContact> results(total);
  std::vector<WheelContactWorkspace> workspaces(static_cast<std::size_t>(threads));  // one per thread
  std::atomic<std::size_t> done{0};
  auto work = [&] {
    if (config.mode == ContactMode::Wheelset) {
      // schedule(dynamic): the roll iteration costs more where the contact jumps.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
      for (std::size_t i = 0; i < n_dy; ++i) {
        try {
          const WheelsetPose pose = rigid_wheelset_pose(side, side, dy[i]);
          roll[i] = pose.roll_rad;
          roll_ok[i] = pose.converged ? 1 : 0;
        } catch (...) {
          roll_ok[i] = 0;
        }
      }
    }
    // schedule(dynamic): flange cases cost several times tread cases.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::size_t task = 0; task < total; ++task) {
      const std::size_t left = task / (n_dy * n_second), rest = task % (n_dy * n_second);
      const std::size_t i_dy = rest / n_second, i_second = rest % n_second;
      const double shift = left ? -dy[i_dy] : dy[i_dy], angle = left ? -roll[i_dy] : roll[i_dy];
      try {
        WheelContactWorkspace& workspace = workspaces[static_cast<std::size_t>(omp_get_thread_num())];
        results[task] = solve_wheel_contact(side, shift, angle, E_star, config.load_kind, config.load_values[i_second], options, workspace);
        if (!roll_ok[i_dy]) results[task].status = SolveStatus::MaxIterations;
      } catch (...) {
        results[task] = WheelContact{};
        results[task].status = SolveStatus::NumericalFailure;
      }
      done.fetch_add(1, std::memory_order_relaxed);
    }
  };
  // The sweep runs on a worker thread so that this thread can report progress without any I/O in the region;
  // it wakes every 0.1 s, and at once when the sweep ends.
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;
  std::thread worker([&] {
    work();
    const std::lock_guard<std::mutex> lock(mutex);
    finished = true;
    finished_signal.notify_one();
  });
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished) {
      if (progress) {
        lock.unlock();
        progress(done.load(std::memory_order_relaxed), total);
        lock.lock();
      }
      finished_signal.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; });
    }
  }
  worker.join();
  if (progress) progress(total, total);

  // ---- assemble the table (serial) ----
  tables::Table table;
  table.lateral_displacement_m = dy;
  table.second_axis = config.load_values;
  table.second_axis_name = load_axis_name(config.load_kind);
  table.strip_samples = config.strip_samples;
  table.allocate();
  for (std::size_t i_dy = 0; i_dy < n_dy; ++i_dy)
    for (std::size_t i_second = 0; i_second < n_second; ++i_second) {
      const WheelContact& right = results[i_dy * n_second + i_second];
      const WheelContact& left = mirrored ? results[(n_dy - 1 - i_dy) * n_second + i_second]
                                          : results[n_dy * n_second + i_dy * n_second + i_second];
      store_wheel(table, i_dy, i_second, 0, right);
      store_wheel(table, i_dy, i_second, 1, left);
      const std::size_t c = i_dy * n_second + i_second;
      table.roll_rad[c] = roll[i_dy];
      table.rolling_radius_difference_m[c] = right.rigid_contact.rolling_radius_m - left.rigid_contact.rolling_radius_m;
    }
  // ---- provenance ----
  auto& text = table.text_attributes;
  text["generator"] = "ctab";
  text["generator_version"] = info.version;
  text["git_commit"] = info.git_commit;
  text["config"] = config.text;
  text["config_source"] = config.source;
  text["created_utc"] = utc_now();
  text["wheel_profile"] = config.wheel;
  text["rail_profile"] = config.rail;
  text["wheel_profile_sha256"] = sha256_hex(wheel.z_samples().data(), wheel.z_samples().size() * sizeof(double));
  text["rail_profile_sha256"] = sha256_hex(rail.z_samples().data(), rail.z_samples().size() * sizeof(double));
  text["rail_inclination"] = config.inclination_text;
  text["mode"] = config.mode == ContactMode::Wheelset ? "wheelset" : "wheel";
  text["method"] = config.method == NormalMethod::Hertz ? "hertz" : "mim1d";
  text["mirrored"] = mirrored ? "true: left wheel at dy = right wheel at -dy (mirror-image sides)" : "false";
  text["units"] = "SI: m, N, Pa, rad";
  auto& number = table.number_attributes;
  number["youngs_modulus_Pa"] = config.material.youngs_modulus_Pa;
  number["poisson_ratio"] = config.material.poisson_ratio;
  number["strip_width_m"] = config.strip_width_m;
  number["threads"] = threads;
  number["gauge_m"] = config.track.gauge_m;
  number["nominal_radius_m"] = config.track.nominal_radius_m;
  return table;
}

}  // namespace ctab::gen
