// SPDX-License-Identifier: Apache-2.0
#include "ctab/sweep/table_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <toml++/toml.h>

#include "ctab/core/error.hpp"
#include "ctab/core/number_text.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/profiles/builtin_profiles.hpp"
#include "ctab/wheelrail/axis_range.hpp"
#include "axis_tolerance_config.hpp"
#include "toml_input.hpp"

namespace ctab::gen {

const char* const kDefaultTableConfig = R"(# ctab default table: S1002 on UIC60 1:40, Manchester benchmark set-up.
[profiles]
wheel = "S1002"          # built-in S1002, or a profile file (.prw, .whl, 2-column y z in mm)
rail = "UIC60"           # built-in 60E1 (UIC60), or a profile file (.prr, .ban, ...)
inclination = "1/40"     # rail inclination; "0" for a rail file that is already inclined
smoothing_m = "auto"     # point profiles: "auto" (from the points' noise; 1 mm when clean), "auto-arcs" (the same for
                         # profiles drawn as arcs and lines, e.g. new rails) or a length [m]; wheel_/rail_smoothing_m: one body

[track]
gauge_m = 1.435
gauge_height_m = 0.014
flange_back_distance_m = 1.360
flange_back_position_m = -0.070
nominal_radius_m = 0.460

[material]
youngs_modulus_Pa = 208e9
poisson_ratio = 0.3

[solver]
mode = "wheelset"        # "wheelset" (rigid roll, both wheels touching) or "wheel" (single wheel, roll 0)
method = "mim1d"         # "hertz", "kp", "analyn", "mim1d" or "bem2d" (docs/method.md "The method ladder")
strip_width_m = 0.2e-3
reference_point = "deepest"  # contact plane at the deepest point, or "interpenetration-centre" (CONTACT's rule)
reference_angle = "interpenetration-mean"  # plane inclination: CONTACT's mean over the interpenetration region,
                                          # or "tangent" (the rail's at the deepest point; docs/validation.md)
surface = "conformal"    # contact surface: "conformal" (curved, CONTACT D=4) or "planar" (one plane per patch)
warm_start = false       # true: start each solve from its neighbour in dy (faster fine sweeps; docs/performance.md)

[axes]
lateral_displacement_m = { start = -12e-3, stop = 12e-3, step = 0.1e-3 }
# finer steps where the contact climbs from flange root to flank (the lookup interpolates there to 0.3 % in force)
lateral_refinement_m = [ { start = -6.5e-3, stop = -6.1e-3, step = 0.025e-3 },
                         { start = 6.1e-3, stop = 6.5e-3, step = 0.025e-3 } ]
vertical_load_N = 78.5e3 # one value: fixed; a list or {start, stop, step}: a second axis
                         # (or normal_load_N, or approach_m)

[output]
strip_samples = 32
compression = 1         # HDF5 deflate level: 0 (none, fastest, ~3x larger) .. 9 (smallest, slowest)
)";

namespace {

using detail::line_of;

class Reader {
 public:
  Reader(const toml::table& root, std::string source) : root_(root), source_(std::move(source)) {}

  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& message) const {
    detail::fail_at(source_, node, key, message);
  }
  [[noreturn]] void fail_at(std::size_t line, const std::string& key, const std::string& message) const {
    throw InputError(source_, line, "'" + key + "': " + message);
  }
  //! Line of a key, else of its table's header, else 0.
  std::size_t line(const std::string& table, const std::string& key) const {
    if (const toml::node* node = find(table, key)) return line_of(*node);
    const toml::node* t = root_.get(table);
    return t ? line_of(*t) : 0;
  }

  // Rejects keys and tables outside the schema.
  void check_keys(const std::map<std::string, std::set<std::string>>& schema) const {
    for (const auto& [name, node] : root_) {
      const std::string table_name(name.str());
      const auto found = schema.find(table_name);
      if (found == schema.end() || !node.is_table())
        fail(node, table_name,
             "unknown table (expected [profiles], [track], [material], [solver], [axes] or [output])");
      for (const auto& [key, value] : *node.as_table())
        if (!found->second.count(std::string(key.str())))
          fail(value, table_name + "." + std::string(key.str()), "unknown key");
    }
  }

  [[nodiscard]] const toml::table& root() const noexcept { return root_; }

  const toml::node* find(const std::string& table, const std::string& key) const {
    const toml::node* t = root_.get(table);
    return t && t->is_table() ? t->as_table()->get(key) : nullptr;
  }

  double number(const std::string& table, const std::string& key, double fallback) const {
    const toml::node* node = find(table, key);
    if (!node) return fallback;
    if (const auto v = node->value<double>()) {
      if (!std::isfinite(*v)) fail(*node, table + "." + key, "must be finite");
      return *v;
    }
    fail(*node, table + "." + key, "expected a number");
  }

  //! A number in [low, high] (the range and its unit named in the message).
  double number_in(const std::string& table, const std::string& key, double fallback, double low, double high,
                   const std::string& range_text) const {
    const double value = number(table, key, fallback);
    if (!(value >= low && value <= high)) fail_at(line(table, key), table + "." + key, "expected " + range_text);
    return value;
  }

  //! An integer in [low, high].
  std::size_t integer_in(const std::string& table, const std::string& key, std::size_t fallback, std::size_t low,
                         std::size_t high) const {
    const double value = number(table, key, static_cast<double>(fallback));
    if (!(value >= static_cast<double>(low) && value <= static_cast<double>(high) && value == std::floor(value)))
      fail_at(line(table, key), table + "." + key,
              "expected an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
    return static_cast<std::size_t>(value);
  }

  bool flag(const std::string& table, const std::string& key, bool fallback) const {
    const toml::node* node = find(table, key);
    if (!node) return fallback;
    if (const auto v = node->value<bool>()) return *v;
    fail(*node, table + "." + key, "expected true or false");
  }

  std::string text(const std::string& table, const std::string& key, const std::string& fallback) const {
    const toml::node* node = find(table, key);
    if (!node) return fallback;
    if (const auto v = node->value<std::string>()) return *v;
    if (const auto v = node->value<double>()) return number_text(*v);
    fail(*node, table + "." + key, "expected a string");
  }

  // A number, a non-empty list of numbers, or {start, stop, step} (validated by make_uniform_axis).
  std::vector<double> axis(const toml::node& node, const std::string& key) const {
    if (const auto v = node.value<double>()) {
      if (!std::isfinite(*v)) fail(node, key, "must be finite");
      return {*v};
    }
    if (const toml::array* list = node.as_array()) return axis_list(*list, key);
    const toml::table* range = node.as_table();
    if (!range) fail(node, key, "expected a number, a list of numbers or {start, stop, step}");
    return axis_range(*range, key);
  }

 private:
  std::vector<double> axis_list(const toml::array& list, const std::string& key) const {
    if (list.size() > kMaxAxisPoints) fail(list, key, "more than " + std::to_string(kMaxAxisPoints) + " values");
    std::vector<double> values;
    for (const toml::node& item : list) {
      const auto v = item.value<double>();
      if (!v || !std::isfinite(*v)) fail(item, key, "expected a list of numbers");
      values.push_back(*v);
    }
    if (values.empty()) fail(list, key, "empty axis");
    for (std::size_t i = 1; i < values.size(); ++i)
      if (!(values[i] > values[i - 1])) fail(list, key, "values must be strictly increasing");
    return values;
  }

  std::vector<double> axis_range(const toml::table& range, const std::string& key) const {
    double bounds[3] = {0, 0, 0};  // start, stop, step
    static constexpr const char* kParts[3] = {"start", "stop", "step"};
    for (const auto& [name, value] : range) {
      const std::string part(name.str());
      const auto v = value.value<double>();
      if (!v || !std::isfinite(*v)) fail(value, key + "." + part, "expected a finite number");
      const auto at = std::find(std::begin(kParts), std::end(kParts), part);
      if (at == std::end(kParts)) fail(value, key + "." + part, "unknown key (expected start, stop, step)");
      bounds[at - std::begin(kParts)] = *v;
    }
    for (const char* part : kParts)
      if (!range.get(part)) fail(range, key, std::string("missing '") + part + "'");
    UniformAxis axis = make_uniform_axis(bounds[0], bounds[1], bounds[2]);
    if (!axis.ok()) {
      if (axis.part.empty()) fail(range, key, axis.message);
      fail(*range.get(axis.part), key + "." + axis.part, axis.message);
    }
    return std::move(axis.values);
  }

  const toml::table& root_;
  std::string source_;
};

// [profiles] `key`: "auto", "auto-arcs" or a length, into every setting of `into`.
void read_smoothing(const Reader& r, const char* key, std::initializer_list<SmoothingSetting*> into) {
  const toml::node* node = r.find("profiles", key);
  if (!node) return;
  const std::string name = std::string("profiles.") + key;
  const char* expected = "\"auto\", \"auto-arcs\" or a smoothing length in [0, 0.1] m";
  SmoothingSetting setting;
  if (node->is_string()) {
    const std::optional<SmoothingSetting> automatic = automatic_smoothing(node->value<std::string>().value_or(""));
    if (!automatic) r.fail(*node, name, std::string("expected ") + expected);
    setting = *automatic;
  } else {
    setting.automatic = false;
    setting.length_m = r.number_in("profiles", key, setting.length_m, 0.0, kMaxSmoothingLength_m, expected);
  }
  for (SmoothingSetting* s : into) *s = setting;
}

void read_profiles(const Reader& r, TableConfig& c) {
  c.wheel = r.text("profiles", "wheel", c.wheel);
  c.rail = r.text("profiles", "rail", c.rail);
  c.inclination_text = r.text("profiles", "inclination", c.inclination_text);
  c.inclination =
      parse_inclination(c.inclination_text, c.source, c.key_line("profiles.inclination"), "'profiles.inclination'");
  read_smoothing(r, "smoothing_m", {&c.wheel_smoothing, &c.rail_smoothing});
  read_smoothing(r, "wheel_smoothing_m", {&c.wheel_smoothing});
  read_smoothing(r, "rail_smoothing_m", {&c.rail_smoothing});
}

// Plausibility ranges: wide enough for every gauge and wheel in service, narrow enough to catch mm for m.
void read_track(const Reader& r, TableConfig& c) {
  TrackSetup& t = c.track;
  t.gauge_m = r.number_in("track", "gauge_m", t.gauge_m, 0.3, 3.0, "a track gauge in [0.3, 3] m");
  t.gauge_height_m = r.number_in("track", "gauge_height_m", t.gauge_height_m, 1e-4, 0.05,
                                 "a gauge measuring height in [1e-4, 0.05] m below the top of the rail");
  t.flange_back_distance_m = r.number("track", "flange_back_distance_m", t.flange_back_distance_m);
  if (!(t.flange_back_distance_m > 0.0 && t.flange_back_distance_m < t.gauge_m))
    r.fail_at(r.line("track", "flange_back_distance_m"), "track.flange_back_distance_m",
              "expected a positive distance below the gauge (" + std::to_string(t.gauge_m) + " m)");
  t.flange_back_position_m = r.number_in("track", "flange_back_position_m", t.flange_back_position_m, -0.2, 0.0,
                                         "a flange-back position S in [-0.2, 0] m (wheel profile coordinate)");
  t.nominal_radius_m = r.number_in("track", "nominal_radius_m", t.nominal_radius_m, 0.05, 2.0,
                                   "a nominal rolling radius in [0.05, 2] m");
}

void read_material(const Reader& r, TableConfig& c) {
  c.material.youngs_modulus_Pa = r.number("material", "youngs_modulus_Pa", c.material.youngs_modulus_Pa);
  if (!kYoungsModulusRange_Pa.contains(c.material.youngs_modulus_Pa))
    r.fail_at(r.line("material", "youngs_modulus_Pa"), "material.youngs_modulus_Pa",
              std::string("expected ") + kYoungsModulusRange_Pa.expectation);
  c.material.poisson_ratio = r.number("material", "poisson_ratio", c.material.poisson_ratio);
  if (!is_valid(c.material))
    r.fail_at(r.line("material", "poisson_ratio"), "material.poisson_ratio", "must lie in (-1, 0.5)");
}

void read_solver(const Reader& r, TableConfig& c) {
  const std::string mode = r.text("solver", "mode", "wheelset"), method = r.text("solver", "method", "mim1d");
  if (mode != "wheelset" && mode != "wheel")
    r.fail(*r.find("solver", "mode"), "solver.mode", "expected \"wheelset\" or \"wheel\", got \"" + mode + "\"");
  c.least_model = method == "auto";
  const std::optional<ContactMethod> parsed = c.least_model ? ContactMethod::Mim1d : parse_contact_method(method);
  if (!parsed)
    r.fail(*r.find("solver", "method"), "solver.method",
           "expected one of " + contact_method_choices() + ", auto, got \"" + method + "\"");
  c.mode = mode == "wheel" ? ContactMode::SingleWheel : ContactMode::Wheelset;
  c.method = *parsed;
  c.tolerance = r.number_in("solver", "tolerance", c.tolerance, 1e-6, 0.5, "a relative tolerance in [1e-06, 0.5]");
  c.strip_width_m = r.number_in("solver", "strip_width_m", c.strip_width_m, kMinStripWidth_m, kMaxStripWidth_m,
                                "a strip width in [1e-05, 0.005] m");
  const std::optional<bool> centre = parse_reference_point(r.text("solver", "reference_point", "deepest"));
  if (!centre)
    r.fail(*r.find("solver", "reference_point"), "solver.reference_point",
           "expected \"deepest\" or \"interpenetration-centre\", got \"" + r.text("solver", "reference_point", "") +
               "\"");
  std::optional<ReferenceAngle> angle;
  if (const toml::node* node = r.find("solver", "reference_angle")) {
    const std::string name = r.text("solver", "reference_angle", "");
    angle = parse_reference_angle(name);
    if (!angle)
      r.fail(*node, "solver.reference_angle",
             "expected \"tangent\" or \"interpenetration-mean\", got \"" + name + "\"");
    if (!reference_rule(*centre, angle))
      r.fail(*node, "solver.reference_angle",
             "\"tangent\" needs reference_point = \"deepest\": CONTACT's reference point (\"interpenetration-centre\") "
             "takes CONTACT's reference angle");
  }
  c.reference = *reference_rule(*centre, angle);
  const std::optional<ContactSurface> surface = parse_contact_surface(r.text("solver", "surface", "conformal"));
  if (!surface)
    r.fail(*r.find("solver", "surface"), "solver.surface",
           "expected \"planar\" or \"conformal\", got \"" + r.text("solver", "surface", "") + "\"");
  c.surface = *surface;
  c.warm_start = r.flag("solver", "warm_start", c.warm_start);
}

std::string metres_text(double value) { return number_text(value) + " m"; }

// [axes] lateral_refinement_m: zones {start, stop, step} of finer steps whose nodes join the dy axis (where the
// contact changes fast: the flange climb, two-point contact). A node within 1e-9 of a step of one already there is
// that node (the coarse axis keeps its values); no step may be finer than tables::kMinDyStep.
std::vector<double> refined_axis(const Reader& r, const toml::node& node, const std::vector<double>& axis) {
  const std::string key = "axes.lateral_refinement_m";
  const toml::array* zones = node.as_array();
  if (!zones || zones->empty()) r.fail(node, key, "expected a list of zones {start, stop, step}");
  if (axis.size() < 2) r.fail(node, key, "needs a lateral_displacement_m axis of at least two values");
  const double coarse = axis[1] - axis[0], same = 1e-9 * coarse;
  std::vector<std::pair<double, bool>> nodes;  // value, on the coarse axis
  for (const double v : axis) nodes.emplace_back(v, true);
  for (const toml::node& zone : *zones) {
    if (!zone.is_table()) r.fail(zone, key, "expected a list of zones {start, stop, step}");
    const std::vector<double> zone_nodes = r.axis(zone, key);
    if (zone_nodes.size() > 1 && !(zone_nodes[1] - zone_nodes[0] < coarse - same))
      r.fail(zone, key, "a zone's step must be finer than the axis's (" + metres_text(coarse) + ")");
    if (zone_nodes.front() < axis.front() - same || zone_nodes.back() > axis.back() + same)
      r.fail(zone, key,
             "a zone must lie within the axis (" + metres_text(axis.front()) + " .. " + metres_text(axis.back()) + ")");
    for (const double v : zone_nodes) nodes.emplace_back(v, false);
  }
  std::stable_sort(nodes.begin(), nodes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<double> merged;
  bool last_coarse = false;
  for (const auto& [value, on_axis] : nodes) {
    if (!merged.empty() && value - merged.back() <= same) {
      if (on_axis && !last_coarse) merged.back() = value, last_coarse = true;
      continue;
    }
    merged.push_back(value);
    last_coarse = on_axis;
  }
  if (merged.size() > kMaxAxisPoints) r.fail(node, key, "more than " + std::to_string(kMaxAxisPoints) + " dy values");
  // Zones that mirror each other give nodes that mirror each other exactly (the mirrored sweep solves the left wheel
  // at -dy as the right one): an axis symmetric to 1e-9 of a step is made symmetric bit for bit.
  bool symmetric = true;
  for (std::size_t i = 0, n = merged.size(); i < n; ++i)
    symmetric = symmetric && std::abs(merged[i] + merged[n - 1 - i]) <= same;
  for (std::size_t i = 0, n = merged.size(); symmetric && i < n / 2; ++i) {
    const double half = 0.5 * (merged[n - 1 - i] - merged[i]);
    merged[i] = -half;
    merged[n - 1 - i] = half;
  }
  if (symmetric && merged.size() % 2 == 1) merged[merged.size() / 2] = 0.0;
  for (std::size_t i = 1; i < merged.size(); ++i)
    if (!tables::dy_step_allowed(merged[i] - merged[i - 1]))
      r.fail(node, key,
             "a step of " + metres_text(merged[i] - merged[i - 1]) + " at dy " + metres_text(merged[i - 1]) +
                 " is finer than " + metres_text(tables::kMinDyStep) + " (tables::kMinDyStep)");
  return merged;
}

void read_axes(const Reader& r, TableConfig& c) {
  const toml::node* dy = r.find("axes", "lateral_displacement_m");
  if (!dy) r.fail_at(r.line("axes", ""), "axes.lateral_displacement_m", "required ({start, stop, step})");
  if (!dy->is_table()) r.fail(*dy, "axes.lateral_displacement_m", "expected {start, stop, step} (a uniform axis)");
  c.lateral_displacement_m = r.axis(*dy, "axes.lateral_displacement_m");
  if (const toml::node* zones = r.find("axes", "lateral_refinement_m"))
    c.lateral_displacement_m = refined_axis(r, *zones, c.lateral_displacement_m);
  c.axis_tolerance = detail::read_axis_tolerance(r.root(), c.source);
  if (c.axis_tolerance) {
    const toml::node& tolerance = *r.find("axes", "tolerance");
    if (r.find("axes", "lateral_refinement_m"))
      r.fail(tolerance, "axes.tolerance",
             "the generator places the dy nodes itself: drop lateral_refinement_m (or the tolerance)");
    if (c.warm_start)
      r.fail(tolerance, "axes.tolerance",
             "an adaptive axis solves every case cold: set solver.warm_start = false (or drop the tolerance)");
  }
  const toml::node* load_node = nullptr;
  for (const auto& [kind, key] :
       {std::pair{LoadKind::VerticalForce, "vertical_load_N"}, std::pair{LoadKind::NormalForce, "normal_load_N"},
        std::pair{LoadKind::Approach, "approach_m"}}) {
    const toml::node* node = r.find("axes", key);
    if (!node) continue;
    if (load_node)
      r.fail(*node, std::string("axes.") + key, "give only one of vertical_load_N, normal_load_N, approach_m");
    load_node = node;
    c.load_kind = kind;
    c.load_values = r.axis(*node, std::string("axes.") + key);
    c.second_axis = !node->value<double>().has_value();
    const QuantityRange& range = kind == LoadKind::Approach ? kApproachRange_m : kLoadRange_N;
    for (const double v : c.load_values)
      if (!range.contains(v))
        r.fail(*node, std::string("axes.") + key, "expected " + std::string(range.expectation) + ", got " +
                                                      number_text(v));
  }
  if (!load_node)
    r.fail_at(r.line("axes", ""), "axes.vertical_load_N",
              "missing: give the load as one of vertical_load_N [N], normal_load_N [N] or approach_m [m] "
              "(a number, a list or {start, stop, step})");
}

void read_output(const Reader& r, TableConfig& c) {
  c.strip_samples = r.integer_in("output", "strip_samples", c.strip_samples, 2, 1024);
  c.patch_slots = r.integer_in("output", "patch_slots", c.patch_slots, 1, kMaxPatchSlots);
  c.compression_level =
      r.integer_in("output", "compression", c.compression_level, static_cast<std::size_t>(tables::kMinCompressionLevel),
                   static_cast<std::size_t>(tables::kMaxCompressionLevel));
}

// Case count and table size, both before anything is allocated for the table.
void check_table_size(const Reader& r, const TableConfig& c) {
  const double cases = static_cast<double>(c.lateral_displacement_m.size()) * static_cast<double>(c.load_values.size());
  const std::size_t line = r.line("axes", "lateral_displacement_m");
  if (cases > static_cast<double>(kMaxTableCases))
    r.fail_at(line, "axes",
              std::to_string(static_cast<long long>(cases)) + " cases (max " + std::to_string(kMaxTableCases) +
                  "): reduce the dy range or increase the step, or use fewer load values");
  const double bytes = table_memory_bytes(c);
  if (bytes > kMaxTableBytes)
    r.fail_at(line, "axes",
              "the table would take " + std::to_string(bytes / (1024.0 * 1024.0 * 1024.0)) + " GiB (max " +
                  std::to_string(kMaxTableBytes / (1024.0 * 1024.0 * 1024.0)) +
                  " GiB): reduce the dy range or increase the step, or reduce strip_samples or patch_slots");
}

}  // namespace

std::size_t TableConfig::key_line(const std::string& key) const {
  for (const auto& [name, line] : key_lines)
    if (name == key) return line;
  return 0;
}

double table_memory_bytes(const TableConfig& c) noexcept {
  return tables::table_bytes(static_cast<double>(c.lateral_displacement_m.size()),
                             static_cast<double>(c.load_values.size()), static_cast<double>(c.patch_slots),
                             static_cast<double>(c.strip_samples));
}

const char* load_axis_name(LoadKind kind) noexcept {
  switch (kind) {
    case LoadKind::NormalForce: return "normal_load_N";
    case LoadKind::VerticalForce: return "vertical_load_N";
    case LoadKind::Approach: return "approach_m";
  }
  return "unknown";
}

TableConfig parse_table_config(const std::string& text, const std::string& source) {
  const toml::table root = detail::parse_toml(text, source);
  const Reader r(root, source);
  r.check_keys(
      {{"profiles", {"wheel", "rail", "inclination", "smoothing_m", "wheel_smoothing_m", "rail_smoothing_m"}},
       {"track", {"gauge_m", "gauge_height_m", "flange_back_distance_m", "flange_back_position_m", "nominal_radius_m"}},
       {"material", {"youngs_modulus_Pa", "poisson_ratio"}},
       {"solver",
        {"mode", "method", "tolerance", "strip_width_m", "reference_point", "reference_angle", "surface",
         "warm_start"}},
       {"axes",
        {"lateral_displacement_m", "lateral_refinement_m", "tolerance", "vertical_load_N", "normal_load_N",
         "approach_m"}},
       {"output", {"strip_samples", "patch_slots", "compression"}}});
  TableConfig c;
  c.source = source;
  c.text = text;
  for (const auto& [table, node] : root)
    for (const auto& [key, value] : *node.as_table())
      c.key_lines.emplace_back(std::string(table.str()) + "." + std::string(key.str()), line_of(value));
  read_profiles(r, c);
  read_track(r, c);
  read_material(r, c);
  read_solver(r, c);
  read_axes(r, c);
  read_output(r, c);
  check_table_size(r, c);
  return c;
}

SideGeometry place_profiles(const TableConfig& config, const ProfileTable& wheel, const ProfileTable& rail) {
  try {
    return SideGeometry(wheel, rail, config.track);
  } catch (const InputError& e) {
    const std::size_t line = config.key_line("track.gauge_height_m");
    const std::string key = line > 0 ? "track.gauge_height_m" : "profiles.rail";
    throw InputError(config.source, line > 0 ? line : config.key_line("profiles.rail"), "'" + key + "': " + e.what());
  }
}

void require_table_axes(const TableConfig& config) {
  if (config.lateral_displacement_m.size() >= 2) return;
  const std::string key = "axes.lateral_displacement_m";
  throw InputError(config.source, config.key_line(key),
                   "'" + key + "': gives one lateral shift; a table needs at least 2 (stop >= start + step)");
}

TableConfig read_table_config(const std::string& path) {
  TableConfig config = parse_table_config(detail::read_toml_file(path, "config"), path);
  // Profile files given relative to the config file.
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  for (std::string* spec : {&config.wheel, &config.rail}) {
    if (!is_builtin_profile(*spec) && std::filesystem::path(*spec).is_relative())
      *spec = (directory / *spec).lexically_normal().string();
  }
  return config;
}

}  // namespace ctab::gen
