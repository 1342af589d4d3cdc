// SPDX-License-Identifier: Apache-2.0
// The array datasets of schema 2 (tables/README.md lists the same, with the reasons).
#include "schema_fields.hpp"

#include <algorithm>

namespace ctab::tables::detail {

void* Field::data() const noexcept {
  if (doubles != nullptr) return doubles->data();
  if (bytes != nullptr) return bytes->data();
  if (int8s != nullptr) return int8s->data();
  return statuses->data();
}

std::size_t Field::size() const noexcept {
  if (doubles != nullptr) return doubles->size();
  if (bytes != nullptr) return bytes->size();
  if (int8s != nullptr) return int8s->size();
  return statuses->size();
}

void Field::resize(std::size_t n) const {
  if (doubles != nullptr) doubles->assign(n, 0.0);
  if (bytes != nullptr) bytes->assign(n, 0);
  if (statuses != nullptr) statuses->assign(n, CaseStatus::Converged);
  if (int8s != nullptr) int8s->assign(n, 0);
}

void Field::fill_missing() const {
  if (doubles != nullptr) std::fill(doubles->begin(), doubles->end(), missing_value);
  if (int8s != nullptr) std::fill(int8s->begin(), int8s->end(), static_cast<std::int8_t>(missing_value));
}

namespace {

Field f64(const char* path, const char* units, const char* description, Extent extent, std::vector<double>& v,
          int sign = 0) {
  Field f{path, units, description, extent, Element::Float64};
  f.doubles = &v;
  f.sign = sign;
  f.patch = extent == Extent::PerSlot || extent == Extent::PerSample;
  return f;
}

constexpr int kAny = 0, kNonNegative = 1, kPositive = 2;

}  // namespace

std::vector<Field> schema_fields(Table& t) {
  auto& p = t.patch;
  Field status{"/wheels/status", "1", "case status per wheel, an enum (names in tables/README.md)", Extent::PerWheel,
               Element::Status};
  status.statuses = &t.status;
  Field present{"/patches/present", "1", "1 where the slot holds a patch, else 0 (every patch value is then 0)",
                Extent::PerSlot, Element::Presence};
  present.bytes = &p.present;
  present.patch = true;
  Field method{"/wheels/method", "1",
               "normal-contact method that solved the case, an enum of the ContactMethod values (0 mim1d, 1 hertz, "
               "2 kp, 3 analyn, 4 bem2d; -1 not_recorded); the least model's choice with method auto",
               Extent::PerWheel, Element::Int8};
  method.int8s = &t.method;
  method.optional = true;
  method.missing_value = kMethodNotRecorded;
  Field width =
      f64("/wheels/strip_width_m", "m", "strip width of that solve (the least model's choice with method auto)",
          Extent::PerWheel, t.strip_width_m);
  width.optional = true;
  Field cell_error =
      f64("/axes/cell_error", "1, 1, m, 1",
          "interpolation error measured per dy cell and second-axis value: relative patch normal force, relative "
          "patch area, contact point [m], total lateral force / wheel load; -1 where not measured (jump cells)",
          Extent::PerCell, t.cell_error);
  cell_error.optional = true;
  cell_error.empty_when_missing = true;
  return {
      f64("/axes/lateral_displacement_m", "m", "wheelset lateral shift dy, + moves the right flange towards its rail",
          Extent::DyAxis, t.lateral_displacement_m),
      f64("/axes/second", "", "second axis (attribute name: its quantity; units: N or m)", Extent::SecondAxis,
          t.second_axis),
      f64("/cases/roll_rad", "rad", "wheelset roll angle (0 in single-wheel mode)", Extent::PerCase, t.roll_rad),
      f64("/cases/rolling_radius_difference_m", "m", "r_right - r_left at the rigid contact points", Extent::PerCase,
          t.rolling_radius_difference_m),
      status,
      method,
      width,
      present,
      f64("/patches/normal_force_N", "N", "resultant normal force", Extent::PerSlot, p.normal_force_N, kPositive),
      f64("/patches/force_lateral_N", "N", "lateral force on the rail in the side frame, + towards the field side",
          Extent::PerSlot, p.force_lateral_N, kAny),
      f64("/patches/force_vertical_N", "N", "vertical force on the rail, + downwards", Extent::PerSlot,
          p.force_vertical_N, kPositive),
      f64("/patches/area_m2", "m^2", "contact area", Extent::PerSlot, p.area_m2, kPositive),
      f64("/patches/max_pressure_Pa", "Pa", "maximum pressure", Extent::PerSlot, p.max_pressure_Pa, kPositive),
      f64("/patches/approach_m", "m", "normal approach of the patch", Extent::PerSlot, p.approach_m, kAny),
      f64("/patches/contact_angle_rad", "rad",
          "direction of the resultant normal force, atan2(-force_lateral_N, force_vertical_N) (< 0 gauge side)",
          Extent::PerSlot, p.contact_angle_rad, kAny),
      f64("/patches/plane_angle_rad", "rad", "inclination delta of the contact plane in which s is measured",
          Extent::PerSlot, p.plane_angle_rad, kAny),
      f64("/patches/s_origin_y_rail_m", "m", "rail profile point where s = 0, lateral", Extent::PerSlot,
          p.s_origin_y_rail_m, kAny),
      f64("/patches/s_origin_z_rail_m", "m", "rail profile point where s = 0, vertical (+ down)", Extent::PerSlot,
          p.s_origin_z_rail_m, kAny),
      f64("/patches/y_wheel_m", "m", "contact point on the wheel profile, origin at the tape circle", Extent::PerSlot,
          p.y_wheel_m, kAny),
      f64("/patches/y_rail_m", "m", "contact point on the rail profile, origin at the top of the inclined head",
          Extent::PerSlot, p.y_rail_m, kAny),
      f64("/patches/y_cop_rail_m", "m", "centre of pressure on the rail profile", Extent::PerSlot, p.y_cop_rail_m,
          kAny),
      f64("/patches/rolling_radius_m", "m", "wheel rolling radius at the contact point", Extent::PerSlot,
          p.rolling_radius_m, kPositive),
      f64("/patches/semi_axis_a_m", "m", "equivalent ellipse semi-axis, rolling direction (area and L/W kept)",
          Extent::PerSlot, p.semi_axis_a_m, kPositive),
      f64("/patches/semi_axis_b_m", "m", "equivalent ellipse semi-axis, lateral", Extent::PerSlot, p.semi_axis_b_m,
          kPositive),
      f64("/patches/s_min_m", "m", "lower end of the patch in its contact plane", Extent::PerSlot, p.s_min_m, kAny),
      f64("/patches/s_max_m", "m", "upper end of the patch in its contact plane", Extent::PerSlot, p.s_max_m, kAny),
      f64("/patches/strip_half_length_m", "m", "strip half-length a(s) on strip_samples points over [s_min, s_max]",
          Extent::PerSample, p.strip_half_length_m, kNonNegative),
      f64("/patches/strip_peak_pressure_Pa", "Pa",
          "strip peak pressure p0(s) on strip_samples points over [s_min, s_max]", Extent::PerSample,
          p.strip_peak_pressure_Pa, kNonNegative),
      cell_error,
  };
}

std::vector<hsize_t> shape_of(Extent extent, hsize_t n_dy, hsize_t n_second, hsize_t n_slots, hsize_t strip_samples) {
  switch (extent) {
    case Extent::DyAxis: return {n_dy};
    case Extent::SecondAxis: return {n_second};
    case Extent::PerCase: return {n_dy, n_second};
    case Extent::PerWheel: return {n_dy, n_second, kWheels};
    case Extent::PerSlot: return {n_dy, n_second, kWheels, n_slots};
    case Extent::PerSample: return {n_dy, n_second, kWheels, n_slots, strip_samples};
    case Extent::PerCell: return {n_dy > 0 ? n_dy - 1 : 0, n_second, kCellErrorQuantities};
  }
  return {};
}

std::string index_text(Extent extent, const std::vector<hsize_t>& shape, std::size_t flat) {
  static const char* const names[] = {"i_dy", "i_2", "wheel", "slot", "sample"};
  static const char* const cell_names[] = {"i_cell", "i_2", "quantity"};
  std::vector<std::size_t> index(shape.size());
  for (std::size_t d = shape.size(); d-- > 0;) {
    index[d] = flat % shape[d];
    flat /= shape[d];
  }
  std::string text;
  const std::size_t first = extent == Extent::SecondAxis ? 1 : 0;
  for (std::size_t d = 0; d < index.size(); ++d)
    text += (d ? ", " : "") + std::string(extent == Extent::PerCell ? cell_names[d] : names[d + first]) + "=" +
            std::to_string(index[d]);
  return text;
}

}  // namespace ctab::tables::detail
