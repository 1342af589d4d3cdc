// SPDX-License-Identifier: Apache-2.0
#include "ctab/io/profile_io.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "ctab/core/error.hpp"
#include "ctab/io/text_input.hpp"
#include "ctab/profiles/builtin_profiles.hpp"
#include "ctab/profiles/rail_cant.hpp"
#include "ctab/profiles/smoothing_spline.hpp"
#include "profile_plausibility.hpp"

namespace ctab::gen {

namespace {

struct RawPoint {
  double y, z;            // canonical, [m] once converted
  std::size_t line;       // source line
  double file_y, file_z;  // the numbers as written in the file (for messages)
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string extension_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lower(path.substr(dot + 1));
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split_numbers(const std::string& line) {
  std::vector<std::string> fields;
  std::string current;
  for (const char c : line) {
    if (c == ',' || c == ';' || c == ' ' || c == '\t' || c == '\r') {
      if (!current.empty()) fields.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) fields.push_back(current);
  return fields;
}

bool parse_double(const std::string& text, double& value) {
  const char* begin = text.data() + (text.size() > 1 && text[0] == '+' ? 1 : 0);  // from_chars rejects '+'
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  return ec == std::errc() && ptr == end;
}

RawPoint parse_point(const std::vector<std::string>& fields, std::size_t column_y, std::size_t column_z,
                     const std::string& path, std::size_t line) {
  if (fields.size() <= std::max(column_y, column_z))
    throw InputError(path, line,
                     "expected a point with at least " + std::to_string(std::max(column_y, column_z) + 1) +
                         " numbers, got " + std::to_string(fields.size()));
  RawPoint p{0, 0, line, 0, 0};
  if (!parse_double(fields[column_y], p.y) || !parse_double(fields[column_z], p.z))
    throw InputError(path, line,
                     "expected numeric coordinates, got " + quote_user_text(fields[column_y] + " " + fields[column_z]));
  if (!std::isfinite(p.y) || !std::isfinite(p.z)) throw InputError(path, line, "non-finite coordinate");
  p.file_y = p.y;
  p.file_z = p.z;
  return p;
}

struct Parsed {
  std::vector<RawPoint> points;  // in metres
  bool mirror_y = false, mirror_z = false, invert = false;
  std::optional<bool> default_mirror_y;
  double shift_y = 0.0;         // applied after mirroring [m]
  bool scaled_by_file = false;  // the file sets its own unit (Simpack units.len.f): check the profile's size
};

bool starts_comment(const std::string& t) { return t.front() == '#' || t.front() == '!' || t.front() == '%'; }

// The last two data rows of a file, for the cut-short check.
struct RowHistory {
  std::vector<std::string> last, previous;
  std::size_t last_line = 0, previous_line = 0;
  void add(const std::vector<std::string>& fields, std::size_t line) {
    previous = std::move(last);
    previous_line = last_line;
    last = fields;
    last_line = line;
  }
};

// How a number is written: with or without an exponent, and the digits after the decimal point.
std::pair<bool, std::size_t> number_shape(const std::string& field) {
  const auto exponent = field.find_first_of("eE");
  const std::string mantissa = field.substr(0, exponent);
  const auto point = mantissa.find('.');
  return {exponent != std::string::npos, point == std::string::npos ? 0 : mantissa.size() - point - 1};
}

// A file that ends inside its last data row (no final newline) may have been cut there, which leaves a number
// that still parses ("3.66" from "3.6653225E+01"): that row's numbers must be written like the row before.
void check_last_row_complete(const std::string& path, const LineReader& reader, const RowHistory& rows) {
  if (!reader.unterminated() || rows.last_line != reader.line() || rows.previous_line == 0) return;
  for (std::size_t f = 0; f < rows.last.size() && f < rows.previous.size(); ++f)
    if (number_shape(rows.last[f]) != number_shape(rows.previous[f]))
      throw InputError(path, rows.last_line,
                       "the last point looks cut short: " + quote_user_text(rows.last[f]) + " is not written like " +
                           quote_user_text(rows.previous[f]) + " on line " + std::to_string(rows.previous_line) +
                           " and the file ends without a newline (truncated file?)");
}

Parsed read_simpack(std::istream& in, const std::string& path) {
  Parsed parsed;
  parsed.scaled_by_file = true;
  std::map<std::string, double> keys;
  bool header = false, spline = false, points = false, ended = false;
  std::string text;
  LineReader reader(in);
  std::vector<RawPoint> raw;
  while (reader.next(text)) {
    const std::size_t line = reader.line();
    std::string t = trim(text.substr(0, text.find_first_of("!%")));
    if (t.empty()) continue;
    const std::string key = lower(t);
    if (key == "header.begin") header = true;
    else if (key == "spline.begin") spline = true;
    else if (key == "point.begin") points = true;
    else if (key == "point.end") {
      points = false;
      ended = true;
    } else if (points) raw.push_back(parse_point(split_numbers(t), 0, 1, path, line));
    else if (const auto eq = t.find('='); eq != std::string::npos) {
      double value = 0.0;
      if (parse_double(trim(t.substr(eq + 1)), value)) keys[lower(trim(t.substr(0, eq)))] = value;
    }
  }
  if (!header || !spline) throw InputError(path, 0, "missing Simpack header.begin/spline.begin block");
  if (!ended) throw InputError(path, reader.line(), "missing point.begin ... point.end block");
  auto get = [&](const char* name, double fallback) { return keys.count(name) ? keys[name] : fallback; };
  if (std::abs(get("rotate", 0.0)) > 1e-12) throw InputError(path, 0, "Simpack 'rotate' is not supported (must be 0)");
  const double per_metre = get("units.len.f", 1.0);
  if (!(per_metre > 0.0)) throw InputError(path, 0, "units.len.f must be positive");
  const double shift_y = get("shift.y", 0.0), shift_z = get("shift.z", 0.0), min_distance = get("point.dist.min", 0.0);
  const double y_lo = get("bound.y.min", 1.0), y_hi = get("bound.y.max", 0.0);
  const double z_lo = get("bound.z.min", 1.0), z_hi = get("bound.z.max", 0.0);
  for (RawPoint p : raw) {
    p.y += shift_y;
    p.z += shift_z;
    if (y_lo < y_hi && (p.y < y_lo || p.y > y_hi)) continue;
    if (z_lo < z_hi) p.z = std::clamp(p.z, z_lo, z_hi);
    if (!parsed.points.empty() && min_distance > 0.0 &&
        std::hypot(p.y / per_metre - parsed.points.back().y, p.z / per_metre - parsed.points.back().z) <
            min_distance / per_metre)
      continue;
    parsed.points.push_back({p.y / per_metre, p.z / per_metre, p.line, p.file_y, p.file_z});
  }
  parsed.mirror_y = get("mirror.y", 0.0) != 0.0;
  parsed.mirror_z = get("mirror.z", 0.0) != 0.0;
  parsed.invert = get("inversion", 0.0) != 0.0;
  return parsed;
}

// MiniProf header values checked against the data: XYPoints (rows) and ColumnDef (numbers per row).
struct MiniProfDeclared {
  std::optional<std::size_t> points;
  std::size_t points_line = 0;
  std::size_t columns = 0;  // 0: no ColumnDef
  std::size_t columns_line = 0;
};

Parsed read_miniprof(std::istream& in, const std::string& path, const std::string& extension, double unit) {
  Parsed parsed;
  std::size_t column_y = 0, column_z = 1, rows = 0;
  MiniProfDeclared declared;
  RowHistory history;
  bool in_header = true, saw_header = false;
  std::string text;
  LineReader reader(in);
  while (reader.next(text)) {
    const std::size_t line = reader.line();
    const std::string t = trim(text);
    if (in_header) {
      if (t.empty()) {
        if (saw_header) in_header = false;
        continue;
      }
      if (starts_comment(t) || t.front() == '"') continue;
      const auto eq = t.find('=');
      if (eq == std::string::npos) {
        if (!saw_header) throw InputError(path, line, "expected a MiniProf 'Key=Value' header before the points");
        in_header = false;  // data without the blank separator line
      } else {
        saw_header = true;
        const std::string key = lower(trim(t.substr(0, eq))), value = trim(t.substr(eq + 1));
        if (key == "columndef") {
          const auto columns = split_numbers(lower(value));
          const auto x = std::find(columns.begin(), columns.end(), "x"),
                     y = std::find(columns.begin(), columns.end(), "y");
          if (x == columns.end() || y == columns.end()) throw InputError(path, line, "ColumnDef must name X and Y");
          column_y = static_cast<std::size_t>(x - columns.begin());
          column_z = static_cast<std::size_t>(y - columns.begin());
          declared.columns = columns.size();
          declared.columns_line = line;
        } else if (key == "xypoints" && !value.empty()) {
          double count = -1.0;
          if (!parse_double(value, count) || !(count >= 0.0 && count < 1e9 && count == std::floor(count)))
            throw InputError(path, line, "XYPoints: expected a whole number of points, got " + quote_user_text(value));
          declared.points = static_cast<std::size_t>(count);
          declared.points_line = line;
        }
        continue;
      }
    }
    if (t.empty() || starts_comment(t)) continue;
    // A row starting with '"' is a point MiniProf marked: it counts towards XYPoints but is not used.
    const bool marked = t.front() == '"';
    const auto fields = split_numbers(marked ? t.substr(1) : t);
    double probe = 0.0;
    if (marked && (fields.empty() || !parse_double(fields[0], probe))) continue;  // a quoted remark
    if (declared.columns > 0 && fields.size() != declared.columns)
      throw InputError(path, line,
                       "expected " + std::to_string(declared.columns) + " numbers per point (ColumnDef on line " +
                           std::to_string(declared.columns_line) + "), found " + std::to_string(fields.size()));
    const RawPoint p = parse_point(fields, column_y, column_z, path, line);
    ++rows;
    history.add(fields, line);
    if (!marked) parsed.points.push_back({p.y * unit, p.z * unit, line, p.y, p.z});
  }
  if (!saw_header) throw InputError(path, 0, "missing MiniProf header (Key=Value lines and an empty line)");
  if (declared.points && rows != *declared.points)
    throw InputError(path, reader.line(),
                     "expected " + std::to_string(*declared.points) + " points (XYPoints on line " +
                         std::to_string(declared.points_line) + "), found " + std::to_string(rows));
  check_last_row_complete(path, reader, history);
  if (extension == "whl") parsed.shift_y = -70.0e-3;  // X from the flange back: S = X - 70 mm
  if (extension == "ban") parsed.default_mirror_y = true;
  return parsed;
}

Parsed read_columns(std::istream& in, const std::string& path, double unit) {
  Parsed parsed;
  RowHistory history;
  std::string text;
  LineReader reader(in);
  bool first = true;
  while (reader.next(text)) {
    const std::size_t line = reader.line();
    const std::string t = trim(text);
    if (t.empty() || starts_comment(t)) continue;
    const auto fields = split_numbers(t);
    double probe = 0.0;
    if (first && fields.size() >= 2 && !parse_double(fields[0], probe) && !parse_double(fields[1], probe)) {
      first = false;  // a header line
      continue;
    }
    first = false;
    if (fields.size() != 2)
      throw InputError(path, line, "expected 2 columns 'y z', got " + std::to_string(fields.size()));
    const RawPoint p = parse_point(fields, 0, 1, path, line);
    history.add(fields, line);
    parsed.points.push_back({p.y * unit, p.z * unit, line, p.y, p.z});
  }
  check_last_row_complete(path, reader, history);
  return parsed;
}

std::shared_ptr<const ProfileCurve> reorigin_at_highest_point(std::shared_ptr<const ProfileCurve> curve,
                                                              const std::string& name) {
  const ProfileTable provisional(*curve, kProfileTableStep_m, name);
  const auto [y, z] = provisional.highest_point();
  return std::make_shared<TransformedCurve>(std::move(curve), 0.0, -y, -z);
}

std::string duplicate_point_message(const RawPoint& a, const RawPoint& b) {
  char text[200];
  std::snprintf(text, sizeof text,
                "duplicate point at line %zu (y = %.9g, z = %.9g as in the file; the same as line %zu): remove it",
                std::max(a.line, b.line), b.file_y, b.file_z, std::min(a.line, b.line));
  return text;
}

// A rail file that is already inclined must not be inclined again (rail_cant.hpp). The limit is half the
// requested inclination, at most 1/80 (half of the smallest standard inclination 1:40), so that a 1:40 file
// is caught under 1:20 as well.
void check_not_inclined_twice(const ProfilePoints& points, double inclination, const std::string& path) {
  if (!(inclination > 0.0)) return;
  const auto measured = measure_head_cant(points.y_m, points.z_m);
  const double limit = 0.5 * std::min(inclination, 1.0 / 40.0);
  if (!measured || measured->cant <= limit) return;
  const double combined = std::tan(std::atan(measured->cant) + std::atan(inclination));
  char text[400];
  std::snprintf(text, sizeof text,
                "the rail head is already canted: measured cant %.4f (1:%.1f; the limit is %.4f), and inclining it by "
                "1:%.0f would give 1:%.1f. For a rail file that is already inclined pass --inclination 0 "
                "(inclination = \"0\" in a config)",
                measured->cant, 1.0 / measured->cant, limit, 1.0 / inclination, 1.0 / combined);
  throw InputError(path, 0, text);
}

}  // namespace

ProfilePoints read_profile_points(const std::string& path, ProfileRole role, const ProfileReadOptions& options) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open profile file");
  const std::string extension = extension_of(path);
  Parsed parsed = (extension == "prw" || extension == "prr") ? read_simpack(in, path)
                  : (extension == "whl" || extension == "ban")
                      ? read_miniprof(in, path, extension, options.length_unit_m)
                      : read_columns(in, path, options.length_unit_m);
  auto& points = parsed.points;
  if (points.size() < 10)
    throw InputError(path, 0, "expected at least 10 profile points, got " + std::to_string(points.size()));
  bool mirror_y = parsed.mirror_y != options.mirror_y.value_or(parsed.default_mirror_y.value_or(false));
  bool mirror_z = parsed.mirror_z;
  for (RawPoint& p : points) {
    if (mirror_y) p.y = -p.y;
    if (mirror_z) p.z = -p.z;
    p.y += parsed.shift_y;
  }
  if (parsed.invert) std::reverse(points.begin(), points.end());
  if (points.front().y > points.back().y) std::reverse(points.begin(), points.end());
  // Auto-detect z (and a wheel's y): a rail's ends lie below its top; a wheel's flange tip is its lowest point.
  if (!options.mirror_z) {
    const auto mid = points[points.size() / 2].z;
    const bool upside_down =
        role == ProfileRole::Rail
            ? std::max(points.front().z, points.back().z) < mid
            : -std::min_element(points.begin(), points.end(), [](auto& a, auto& b) { return a.z < b.z; })->z >
                  std::max_element(points.begin(), points.end(), [](auto& a, auto& b) { return a.z < b.z; })->z;
    if (upside_down)
      for (RawPoint& p : points) p.z = -p.z;
  } else if (*options.mirror_z) {
    for (RawPoint& p : points) p.z = -p.z;
  }
  if (role == ProfileRole::Wheel && !options.mirror_y && !parsed.default_mirror_y) {
    const auto tip = std::max_element(points.begin(), points.end(), [](auto& a, auto& b) { return a.z < b.z; });
    if (tip->y > 0.5 * (points.front().y + points.back().y)) {
      for (RawPoint& p : points) p.y = -p.y;
      std::reverse(points.begin(), points.end());
    }
  }
  // Drop near-vertical end roundings (never in contact; they would make z(y) multivalued).
  auto steep = [](const RawPoint& a, const RawPoint& b) { return std::abs(b.z - a.z) > 50.0 * std::abs(b.y - a.y); };
  while (points.size() > 10 && steep(points[0], points[1])) points.erase(points.begin());
  while (points.size() > 10 && steep(points[points.size() - 2], points.back())) points.pop_back();
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const RawPoint &a = points[i - 1], &b = points[i];
    if (a.y == b.y && a.z == b.z) throw InputError(path, std::max(a.line, b.line), duplicate_point_message(a, b));
    if (!(b.y > a.y))
      throw InputError(path, b.line,
                       "profile steps backwards in y (a loop or overhang); points must be ordered along the profile");
    length += std::hypot(b.y - a.y, b.z - a.z);
  }
  if (length < 5e-3 || length > 0.5)
    throw InputError(path, 0,
                     "profile length " + std::to_string(length * 1e3) +
                         " mm is implausible (expected 5 to 500 mm): check the length unit");
  ProfilePoints out;
  for (const RawPoint& p : points) {
    out.y_m.push_back(p.y);
    out.z_m.push_back(p.z);
    out.line.push_back(p.line);
  }
  if (parsed.scaled_by_file)
    if (const auto problem = detail::implausible_size(out.y_m, out.z_m, role)) throw InputError(path, 0, *problem);
  return out;
}

double parse_inclination(const std::string& text, const std::string& source, std::size_t line,
                         const std::string& what) {
  double value = -1.0;
  const auto slash = text.find('/');
  if (slash == std::string::npos) {
    if (!parse_double(trim(text), value)) value = -1.0;
  } else {
    double numerator = 0.0, denominator = 0.0;
    if (parse_double(trim(text.substr(0, slash)), numerator) &&
        parse_double(trim(text.substr(slash + 1)), denominator) && denominator != 0.0)
      value = numerator / denominator;
  }
  if (!(std::isfinite(value) && value >= 0.0 && value < 0.2))
    throw InputError(source, line,
                     (what.empty() ? "" : what + ": ") + "expected a ratio such as 1/40 or a number in [0, 0.2), got " +
                         quote_user_text(text));
  return value;
}

std::string smoothing_text(const SmoothingSetting& setting) {
  if (setting.automatic) return setting.prior == CurvaturePrior::Arcs ? kSmoothingAutoArcs : kSmoothingAuto;
  std::ostringstream text;
  text << setting.length_m << " m";
  return text.str();
}

std::optional<SmoothingSetting> automatic_smoothing(const std::string& text) {
  if (text == kSmoothingAuto) return SmoothingSetting{true, CurvaturePrior::Smooth, kDefaultSmoothingLength_m};
  if (text == kSmoothingAutoArcs) return SmoothingSetting{true, CurvaturePrior::Arcs, kDefaultSmoothingLength_m};
  return std::nullopt;
}

ProfileTable load_profile(const std::string& spec, ProfileRole role, const ProfileReadOptions& options) {
  ProfileSmoothing smoothing;
  return load_profile(spec, role, options, smoothing);
}

ProfileTable load_profile(const std::string& spec, ProfileRole role, const ProfileReadOptions& options,
                          ProfileSmoothing& smoothing) {
  smoothing = ProfileSmoothing{};
  const BuiltinProfile builtin = builtin_profile(spec);
  std::shared_ptr<const ProfileCurve> curve;
  if (role == ProfileRole::Wheel && builtin == BuiltinProfile::S1002) {
    return ProfileTable(*s1002_curve(), kProfileTableStep_m, "S1002");
  }
  if (role == ProfileRole::Rail && builtin == BuiltinProfile::Uic60) {
    return ProfileTable(*uic60_inclined_curve(options.inclination), kProfileTableStep_m, "UIC60");
  }
  const ProfilePoints points = read_profile_points(spec, role, options);
  if (role == ProfileRole::Rail) check_not_inclined_twice(points, options.inclination, spec);
  SmoothingChoice choice = choose_smoothing(points.y_m, points.z_m);
  if (!options.smoothing.automatic) {
    choice.length_m = options.smoothing.length_m;
    choice.adaptive = false;
  }
  choice.prior = options.smoothing.prior;
  const SmoothedPointCurve smoothed = smooth_point_profile(points.y_m, points.z_m, choice);
  smoothing = {true,
               options.smoothing.automatic,
               smoothed.length_m,
               smoothed.shortest_length_m,
               choice.noise_sigma_m,
               choice.adaptive && choice.prior == CurvaturePrior::Arcs ? smoothed.arc_junctions : -1};
  curve = smoothed.curve;
  if (role == ProfileRole::Rail) {
    if (options.inclination != 0.0)
      curve = std::make_shared<TransformedCurve>(curve, -std::atan(options.inclination), 0.0, 0.0);
    curve = reorigin_at_highest_point(curve, spec);
  }
  return ProfileTable(*curve, kProfileTableStep_m, spec);
}

}  // namespace ctab::gen
