// SPDX-License-Identifier: Apache-2.0
// The FMU's variable descriptors (variables.hpp): names, units and descriptions of every input and output.
#include "ctab/fmu/variables.hpp"

#include <cstring>
#include <iterator>

#include "ctab/lookup/ctab_lookup.h"

namespace ctab::fmu {

namespace {

static_assert(kMaxSlots == CTAB_MAX_SLOTS);

constexpr Variable kTime{"time", VarType::Float64, "s", "simulation time (the lookup does not depend on it)",
                         Source::Time, 0};

constexpr Variable kDy{"dy", VarType::Float64, "m",
                       "wheelset lateral displacement; + moves the right flange towards its rail (clamped to the "
                       "table's range)",
                       Source::Input, 0};

// The second axis as an input, by ctab_table_second_axis_name().
struct SecondAxisRow {
  const char* axis;
  Variable variable;
};
constexpr SecondAxisRow kSecondAxes[] = {
    {"vertical_load_N",
     {"vertical_load", VarType::Float64, "N", "vertical wheel load (clamped to the table's range)", Source::Input, 1}},
    {"normal_load_N",
     {"normal_load", VarType::Float64, "N", "normal load of the wheel (clamped to the table's range)", Source::Input,
      1}},
    {"approach_m",
     {"approach", VarType::Float64, "m", "prescribed approach (clamped to the table's range)", Source::Input, 1}},
};

constexpr Variable kWheelset[] = {
    {"roll", VarType::Float64, "rad", "wheelset roll angle", Source::Roll, 0},
    {"delta_r", VarType::Float64, "m", "rolling radius difference r_right - r_left", Source::RollingRadiusDifference,
     0},
    // Both bodies' material for the creep forces (the blob does not carry the table's; the generator's default).
    {"youngs_modulus", VarType::Float64, "Pa", "Young's modulus of wheel and rail for the creep forces",
     Source::Material, kYoungsModulus, 208e9},
    {"poisson_ratio", VarType::Float64, "", "Poisson's ratio of wheel and rail for the creep forces, in [0, 0.5)",
     Source::Material, kPoissonRatio, 0.3},
};

constexpr Variable kWheel[] = {
    {"status", VarType::Int32, "",
     "ctab_status of the query: 0 ok, 1 clamped to the table's edge, < 0 failed (outputs zero)", Source::Status, 0},
    {"worst_case_status", VarType::Int32, "",
     "most severe status of the table cases around the query point (< 0: a failed case is adjacent)",
     Source::WorstCaseStatus, 0},
    // Creep forces (docs/creep.md): CONTACT's creepages at each patch's s origin, in the wheel's side frame.
    {"xi", VarType::Float64, "", "longitudinal creepage (rail - wheel velocity) / V; > 0 driving", Source::CreepInput,
     kXi, 0.0},
    {"eta", VarType::Float64, "", "lateral creepage along s, + to the field side", Source::CreepInput, kEta, 0.0},
    {"phi", VarType::Float64, "1/m", "spin creepage about the contact normal", Source::CreepInput, kPhi, 0.0},
    {"friction", VarType::Float64, "", "Coulomb friction coefficient (> 0; else creep_status < 0 and creep outputs 0)",
     Source::CreepInput, kFriction, 0.3},
    {"creep_status", VarType::Int32, "",
     "ctab_status of the creep call: 0 ok, 1 clamped, < 0 failed (NaN creepage, friction <= 0: creep outputs 0)",
     Source::CreepStatus, 0},
    {"creep_fx", VarType::Float64, "N", "longitudinal creep force on the rail, sum over the patches",
     Source::CreepTotal, kTotalFx},
    {"creep_force_lateral", VarType::Float64, "N", "lateral part of the creep forces on the rail, + to the field side",
     Source::CreepTotal, kTotalLateral},
    {"creep_force_vertical", VarType::Float64, "N", "vertical part of the creep forces on the rail, + downwards",
     Source::CreepTotal, kTotalVertical},
    {"creep_mz", VarType::Float64, "N.m", "sum of the patches' spin moments (each about its s origin)",
     Source::CreepTotal, kTotalMz},
};

// Per slot: presence, then every quantity of ctab_patch in ctab_quantity order. Frames: each wheel in its own
// side frame, y lateral + to the field side, z vertical + down; forces of the wheel on the rail.
constexpr Variable kSlot[] = {
    {"present", VarType::Boolean, "", "true where the slot holds a contact patch (its quantities are 0 otherwise)",
     Source::Present, 0},
    {"normal_force", VarType::Float64, "N", "resultant normal force", Source::Quantity, CTAB_NORMAL_FORCE_N},
    {"force_lateral", VarType::Float64, "N", "lateral force on the rail, + to the field side", Source::Quantity,
     CTAB_FORCE_LATERAL_N},
    {"force_vertical", VarType::Float64, "N", "vertical force on the rail, + downwards", Source::Quantity,
     CTAB_FORCE_VERTICAL_N},
    {"area", VarType::Float64, "m2", "contact area", Source::Quantity, CTAB_AREA_M2},
    {"max_pressure", VarType::Float64, "Pa", "maximum contact pressure", Source::Quantity, CTAB_MAX_PRESSURE_PA},
    {"approach", VarType::Float64, "m", "normal approach of the patch", Source::Quantity, CTAB_APPROACH_M},
    {"contact_angle", VarType::Float64, "rad", "direction of the resultant normal force", Source::Quantity,
     CTAB_CONTACT_ANGLE_RAD},
    {"plane_angle", VarType::Float64, "rad", "inclination of the contact plane in which s is measured",
     Source::Quantity, CTAB_PLANE_ANGLE_RAD},
    {"s_origin_y_rail", VarType::Float64, "m", "rail profile point where s = 0, lateral", Source::Quantity,
     CTAB_S_ORIGIN_Y_RAIL_M},
    {"s_origin_z_rail", VarType::Float64, "m", "rail profile point where s = 0, vertical (+ down)", Source::Quantity,
     CTAB_S_ORIGIN_Z_RAIL_M},
    {"y_wheel", VarType::Float64, "m", "contact point on the wheel profile", Source::Quantity, CTAB_Y_WHEEL_M},
    {"y_rail", VarType::Float64, "m", "contact point on the rail profile", Source::Quantity, CTAB_Y_RAIL_M},
    {"y_cop_rail", VarType::Float64, "m", "centre of pressure on the rail profile", Source::Quantity,
     CTAB_Y_COP_RAIL_M},
    {"rolling_radius", VarType::Float64, "m", "wheel rolling radius at the contact point", Source::Quantity,
     CTAB_ROLLING_RADIUS_M},
    {"semi_axis_a", VarType::Float64, "m", "equivalent ellipse semi-axis, rolling direction", Source::Quantity,
     CTAB_SEMI_AXIS_A_M},
    {"semi_axis_b", VarType::Float64, "m", "equivalent ellipse semi-axis, lateral", Source::Quantity,
     CTAB_SEMI_AXIS_B_M},
    {"s_min", VarType::Float64, "m", "lower end of the patch in its contact plane", Source::Quantity, CTAB_S_MIN_M},
    {"s_max", VarType::Float64, "m", "upper end of the patch in its contact plane", Source::Quantity, CTAB_S_MAX_M},
    {"creep_fx", VarType::Float64, "N", "longitudinal creep force on the rail", Source::CreepPatch, kPatchFx},
    {"creep_fs", VarType::Float64, "N", "lateral creep force on the rail in the contact plane (along s)",
     Source::CreepPatch, kPatchFs},
    {"creep_mz", VarType::Float64, "N.m", "spin moment about the s origin", Source::CreepPatch, kPatchMz},
    {"slip_fraction", VarType::Float64, "", "share of the contact area in slip [0, 1]", Source::CreepPatch,
     kPatchSlipFraction},
};
static_assert(std::size(kSlot) == 1 + CTAB_QUANTITIES + 4, "one output per tabulated quantity, four creep outputs");
static_assert(std::size(kSlot) <= kSlotStride && std::size(kWheel) <= kWheelStride);

}  // namespace

namespace detail {
const Variable& time_variable() noexcept { return kTime; }
const Variable* input_variable(int i, const Layout& layout) noexcept {
  if (i == 0) return &kDy;
  if (i != 1 || !layout.second_input) return nullptr;
  for (const SecondAxisRow& row : kSecondAxes)
    if (layout.second_axis != nullptr && std::strcmp(row.axis, layout.second_axis) == 0) return &row.variable;
  return nullptr;
}
std::size_t wheelset_count() noexcept { return std::size(kWheelset); }
const Variable& wheelset_variable(std::size_t i) noexcept { return kWheelset[i]; }
std::size_t wheel_count() noexcept { return std::size(kWheel); }
const Variable& wheel_variable(std::size_t i) noexcept { return kWheel[i]; }
std::size_t slot_field_count() noexcept { return std::size(kSlot); }
const Variable& slot_variable(std::size_t i) noexcept { return kSlot[i]; }
}  // namespace detail

int input_count(const Layout& layout) noexcept { return detail::input_variable(1, layout) != nullptr ? 2 : 1; }

VariableRef find_variable(std::uint32_t vr, const Layout& layout) noexcept {
  if (vr == kTimeVr) return {&kTime, vr, Causality::Independent};
  if (vr >= kInputVr && vr < kInputVr + static_cast<std::uint32_t>(input_count(layout)))
    return {detail::input_variable(static_cast<int>(vr - kInputVr), layout), vr, Causality::Input};
  if (vr >= kWheelsetVr && vr < kWheelsetVr + std::size(kWheelset)) {
    const Variable& v = kWheelset[vr - kWheelsetVr];
    return {&v, vr, causality_of(v.source)};
  }
  if (vr >= kWheelVr && vr < kWheelVr + kWheels * kWheelStride) {
    const std::uint32_t i = (vr - kWheelVr) % kWheelStride;
    if (i < std::size(kWheel))
      return {&kWheel[i], vr, causality_of(kWheel[i].source), static_cast<int>((vr - kWheelVr) / kWheelStride)};
  }
  if (vr >= kSlotVr && vr < kSlotVr + kWheels * kMaxSlots * kSlotStride) {
    const std::uint32_t f = (vr - kSlotVr) % kSlotStride, ws = (vr - kSlotVr) / kSlotStride;
    if (f < std::size(kSlot) && ws % kMaxSlots < layout.n_slots)
      return {&kSlot[f], vr, Causality::Output, static_cast<int>(ws / kMaxSlots), static_cast<int>(ws % kMaxSlots)};
  }
  return {};
}

const char* wheel_name(int wheel) noexcept { return wheel == CTAB_WHEEL_LEFT ? "left" : "right"; }

std::string full_name(const VariableRef& ref) {
  std::string name;
  if (ref.wheel >= 0) name = std::string(wheel_name(ref.wheel)) + ".";
  if (ref.slot >= 0) name += "slot" + std::to_string(ref.slot) + ".";
  return name + ref.variable->name;
}

}  // namespace ctab::fmu

namespace ctab::fmu {

Layout layout_of(const ctab_table* table) noexcept {
  Layout layout;
  layout.n_slots = ctab_table_slot_count(table);
  layout.second_input = ctab_table_second_count(table) > 1;
  layout.second_axis = ctab_table_second_axis_name(table);
  return layout;
}

double input_start(const ctab_table* table, int i) noexcept {
  if (i == 1) return ctab_table_second_value(table, 0);
  const double lo = ctab_table_dy_min(table), hi = ctab_table_dy_max(table);
  return 0.0 < lo ? lo : (0.0 > hi ? hi : 0.0);
}

double start_value(const ctab_table* table, const VariableRef& ref) noexcept {
  return ref.variable->source == Source::Input ? input_start(table, ref.variable->index) : ref.variable->start;
}

}  // namespace ctab::fmu
