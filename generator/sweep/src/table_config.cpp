#include "ctab/sweep/table_config.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "ctab/contact/error.hpp"
#include "ctab/io/profile_io.hpp"

namespace ctab::gen {

const char* const kDefaultTableConfig = R"(# ctab default table: S1002 on UIC60 1:40, Manchester benchmark set-up.
[profiles]
wheel = "S1002"          # built-in S1002, or a profile file (.prw, .whl, 2-column y z in mm)
rail = "UIC60"           # built-in 60E1 (UIC60), or a profile file (.prr, .ban, ...)
inclination = "1/40"     # rail inclination; "0" for a rail file that is already inclined
smoothing_m = 1e-3       # smoothing length of point profiles [m]

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
method = "mim1d"         # "mim1d" or "hertz"
strip_width_m = 0.2e-3

[axes]
lateral_displacement_m = { start = -12e-3, stop = 12e-3, step = 0.1e-3 }
vertical_load_N = 78.5e3 # one value: fixed; a list or {start, stop, step}: a second axis
                         # (or normal_load_N, or approach_m)

[output]
strip_samples = 32
)";

namespace {

std::size_t line_of(const toml::node& node) { return node.source().begin.line; }

class Reader {
 public:
  Reader(const toml::table& root, std::string source) : root_(root), source_(std::move(source)) {}

  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& message) const {
    throw InputError(source_, line_of(node), "'" + key + "': " + message);
  }

  // Rejects keys and tables outside the schema.
  void check_keys(const std::map<std::string, std::set<std::string>>& schema) const {
    for (const auto& [name, node] : root_) {
      const std::string table_name(name.str());
      const auto found = schema.find(table_name);
      if (found == schema.end() || !node.is_table()) fail(node, table_name, "unknown table (expected [profiles], [track], [material], [solver], [axes] or [output])");
      for (const auto& [key, value] : *node.as_table())
        if (!found->second.count(std::string(key.str())))
          fail(value, table_name + "." + std::string(key.str()), "unknown key");
    }
  }

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

  std::string text(const std::string& table, const std::string& key, const std::string& fallback) const {
    const toml::node* node = find(table, key);
    if (!node) return fallback;
    if (const auto v = node->value<std::string>()) return *v;
    if (const auto v = node->value<double>()) {
      std::ostringstream out;
      out << *v;
      return out.str();
    }
    fail(*node, table + "." + key, "expected a string");
  }

  // A number, a non-empty list of numbers, or {start, stop, step} with step > 0 and stop >= start.
  std::vector<double> axis(const toml::node& node, const std::string& key) const {
    if (const auto v = node.value<double>()) return {*v};
    std::vector<double> values;
    if (const toml::array* list = node.as_array()) {
      for (const toml::node& item : *list) {
        const auto v = item.value<double>();
        if (!v || !std::isfinite(*v)) fail(item, key, "expected a list of numbers");
        values.push_back(*v);
      }
      if (values.empty()) fail(node, key, "empty axis");
      for (std::size_t i = 1; i < values.size(); ++i)
        if (!(values[i] > values[i - 1])) fail(node, key, "values must be strictly increasing");
      return values;
    }
    const toml::table* range = node.as_table();
    if (!range) fail(node, key, "expected a number, a list of numbers or {start, stop, step}");
    double start = 0, stop = 0, step = 0;
    for (const auto& [name, value] : *range) {
      const std::string part(name.str());
      const auto v = value.value<double>();
      if (!v || !std::isfinite(*v)) fail(value, key + "." + part, "expected a number");
      if (part == "start") start = *v;
      else if (part == "stop") stop = *v;
      else if (part == "step") step = *v;
      else fail(value, key + "." + part, "unknown key (expected start, stop, step)");
    }
    for (const char* part : {"start", "stop", "step"})
      if (!range->get(part)) fail(node, key, std::string("missing '") + part + "'");
    if (!(step > 0.0)) fail(*range->get("step"), key + ".step", "must be positive");
    if (stop < start) fail(*range->get("stop"), key + ".stop", "must not be below start (empty axis)");
    const auto count = static_cast<std::size_t>(std::floor((stop - start) / step + 1e-9)) + 1;
    if (count > 1000000) fail(node, key, "more than 10^6 values");
    for (std::size_t i = 0; i < count; ++i) values.push_back(start + step * static_cast<double>(i));
    // A range symmetric about zero is made exactly antisymmetric (values[n-1-i] = -values[i], 0 in the middle),
    // so that mirroring one wheel onto the other is exact.
    if (count > 1 && std::abs(start + values.back()) <= 1e-9 * step)
      for (std::size_t i = 0; i < count / 2; ++i) {
        values[count - 1 - i] = -values[i];
        if (count % 2 == 1) values[count / 2] = 0.0;
      }
    return values;
  }

 private:
  const toml::table& root_;
  std::string source_;
};

}  // namespace

std::size_t TableConfig::key_line(const std::string& key) const {
  for (const auto& [name, line] : key_lines)
    if (name == key) return line;
  return 0;
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
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source, e.source().begin.line, std::string("TOML syntax: ") + std::string(e.description()));
  }
  const Reader r(root, source);
  r.check_keys({{"profiles", {"wheel", "rail", "inclination", "smoothing_m"}},
                {"track", {"gauge_m", "gauge_height_m", "flange_back_distance_m", "flange_back_position_m", "nominal_radius_m"}},
                {"material", {"youngs_modulus_Pa", "poisson_ratio"}},
                {"solver", {"mode", "method", "strip_width_m"}},
                {"axes", {"lateral_displacement_m", "vertical_load_N", "normal_load_N", "approach_m"}},
                {"output", {"strip_samples", "patch_slots"}}});
  TableConfig c;
  c.source = source;
  c.text = text;
  for (const auto& [table, node] : root)
    for (const auto& [key, value] : *node.as_table())
      c.key_lines.emplace_back(std::string(table.str()) + "." + std::string(key.str()), line_of(value));
  c.wheel = r.text("profiles", "wheel", c.wheel);
  c.rail = r.text("profiles", "rail", c.rail);
  c.inclination_text = r.text("profiles", "inclination", c.inclination_text);
  c.inclination = parse_inclination(c.inclination_text, source, c.key_line("profiles.inclination"), "'profiles.inclination'");
  c.smoothing_length_m = r.number("profiles", "smoothing_m", c.smoothing_length_m);
  c.track.gauge_m = r.number("track", "gauge_m", c.track.gauge_m);
  c.track.gauge_height_m = r.number("track", "gauge_height_m", c.track.gauge_height_m);
  c.track.flange_back_distance_m = r.number("track", "flange_back_distance_m", c.track.flange_back_distance_m);
  c.track.flange_back_position_m = r.number("track", "flange_back_position_m", c.track.flange_back_position_m);
  c.track.nominal_radius_m = r.number("track", "nominal_radius_m", c.track.nominal_radius_m);
  c.material.youngs_modulus_Pa = r.number("material", "youngs_modulus_Pa", c.material.youngs_modulus_Pa);
  c.material.poisson_ratio = r.number("material", "poisson_ratio", c.material.poisson_ratio);
  c.strip_width_m = r.number("solver", "strip_width_m", c.strip_width_m);
  const std::string mode = r.text("solver", "mode", "wheelset"), method = r.text("solver", "method", "mim1d");
  if (mode != "wheelset" && mode != "wheel")
    r.fail(*r.find("solver", "mode"), "solver.mode", "expected \"wheelset\" or \"wheel\", got \"" + mode + "\"");
  if (method != "mim1d" && method != "hertz")
    r.fail(*r.find("solver", "method"), "solver.method", "expected \"mim1d\" or \"hertz\", got \"" + method + "\"");
  c.mode = mode == "wheel" ? ContactMode::SingleWheel : ContactMode::Wheelset;
  c.method = method == "hertz" ? NormalMethod::Hertz : NormalMethod::Mim1d;
  // Positivity of physical parameters, each named with its line.
  auto positive = [&](const char* table, const char* key, double value) {
    if (!(value > 0.0)) {
      const toml::node* node = r.find(table, key);
      throw InputError(source, node ? line_of(*node) : 0, std::string("'") + table + "." + key + "': must be positive");
    }
  };
  positive("track", "gauge_m", c.track.gauge_m);
  positive("track", "gauge_height_m", c.track.gauge_height_m);
  positive("track", "flange_back_distance_m", c.track.flange_back_distance_m);
  positive("track", "nominal_radius_m", c.track.nominal_radius_m);
  positive("material", "youngs_modulus_Pa", c.material.youngs_modulus_Pa);
  positive("solver", "strip_width_m", c.strip_width_m);
  if (!(c.smoothing_length_m >= 0.0)) throw InputError(source, c.key_line("profiles.smoothing_m"), "'profiles.smoothing_m': must be >= 0");
  if (!is_valid(c.material))
    throw InputError(source, c.key_line("material.poisson_ratio"), "'material.poisson_ratio': must lie in (-1, 0.5)");
  // Axes.
  const toml::node* dy = r.find("axes", "lateral_displacement_m");
  if (!dy) throw InputError(source, 0, "'axes.lateral_displacement_m': required ({start, stop, step})");
  if (!dy->is_table()) r.fail(*dy, "axes.lateral_displacement_m", "expected {start, stop, step} (a uniform axis)");
  c.lateral_displacement_m = r.axis(*dy, "axes.lateral_displacement_m");
  int loads = 0;
  for (const auto& [kind, key] : {std::pair{LoadKind::VerticalForce, "vertical_load_N"}, std::pair{LoadKind::NormalForce, "normal_load_N"},
                                  std::pair{LoadKind::Approach, "approach_m"}}) {
    const toml::node* node = r.find("axes", key);
    if (!node) continue;
    ++loads;
    c.load_kind = kind;
    c.load_values = r.axis(*node, std::string("axes.") + key);
    c.second_axis = !node->value<double>().has_value();
    for (const double v : c.load_values)
      if (!(v > 0.0)) r.fail(*node, std::string("axes.") + key, "values must be positive");
  }
  if (loads > 1) throw InputError(source, c.key_line("axes.approach_m"), "'axes': give one of vertical_load_N, normal_load_N, approach_m");
  if (loads == 0) c.load_values = {78.5e3};
  const double samples = r.number("output", "strip_samples", 32.0);
  if (!(samples >= 2 && samples <= 1024 && samples == std::floor(samples)))
    throw InputError(source, c.key_line("output.strip_samples"), "'output.strip_samples': expected an integer in [2, 1024]");
  c.strip_samples = static_cast<std::size_t>(samples);
  const double slots = r.number("output", "patch_slots", 3.0);
  if (!(slots >= 1 && slots <= 16 && slots == std::floor(slots)))
    throw InputError(source, c.key_line("output.patch_slots"), "'output.patch_slots': expected an integer in [1, 16]");
  c.patch_slots = static_cast<std::size_t>(slots);
  return c;
}

TableConfig read_table_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open config file");
  std::ostringstream text;
  text << in.rdbuf();
  TableConfig config = parse_table_config(text.str(), path);
  // Profile files given relative to the config file.
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  for (std::string* spec : {&config.wheel, &config.rail}) {
    const std::string name = *spec;
    const bool builtin = name == "S1002" || name == "s1002" || name == "UIC60" || name == "uic60" || name == "60E1" || name == "60e1";
    if (!builtin && std::filesystem::path(name).is_relative()) *spec = (directory / name).lexically_normal().string();
  }
  return config;
}

}  // namespace ctab::gen
