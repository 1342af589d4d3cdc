// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The FMU's variables, one table of descriptors read by both the wrapper (value reference -> value) and the
//! exporter (modelDescription.xml). Adding a variable is one row in variables.cpp plus where its value comes from
//! in the wrapper (Source); the Source also gives its causality (causality_of).
//!
//! Value references: 0 time; 1 + i input i; 100 + i wheelset variable i (outputs, the material parameters);
//! 1000 + 100 w + i variable i of wheel w (outputs, the creepage and friction inputs); 10000 + 64 (16 w + s) + f
//! field f of slot s of wheel w (w: 0 right, 1 left).
#include <cstddef>
#include <cstdint>
#include <string>

namespace ctab::fmu {

inline constexpr const char* kModelIdentifier = "ctab_contact_table";  //!< the wrapper is <this>.so
inline constexpr const char* kTableResource = "table.ctab";            //!< the blob under resources/

enum class VarType : std::uint8_t { Float64, Int32, Boolean };
enum class Causality : std::uint8_t { Independent, Input, Output, Parameter };

//! Where the wrapper takes a variable's value from.
enum class Source : std::uint8_t {
  Time,
  Input,            //!< inputs[index]
  Quantity,         //!< patch[slot].q[index] of the wheel's ctab_result
  Present,          //!< patch[slot].present
  Status,           //!< the wheel's query status (ctab_status)
  WorstCaseStatus,  //!< the wheel's worst neighbouring case status
  Roll,             //!< roll_rad of the right wheel's result
  RollingRadiusDifference,
  CreepInput,       //!< input: field index of the wheel's ctab_creep_input (CreepField)
  Material,         //!< parameter (fixed): field index of both wheels' ctab_creep_input (CreepField)
  CreepTotal,       //!< wheel total index of the wheel's ctab_creep_result (CreepTotalField)
  CreepStatus,      //!< the wheel's creep call status (ctab_status)
  CreepPatch        //!< field index of patch[slot] of the wheel's ctab_creep_result (CreepPatchField)
};

//! Fields of ctab_creep_input, ctab_creep_result and ctab_creep_patch addressed by Variable::index.
enum CreepField : int { kXi, kEta, kPhi, kFriction, kYoungsModulus, kPoissonRatio };
enum CreepTotalField : int { kTotalFx, kTotalLateral, kTotalVertical, kTotalMz };
enum CreepPatchField : int { kPatchFx, kPatchFs, kPatchMz, kPatchSlipFraction };

struct Variable {
  const char* name;  //!< leaf name (under "right.", "right.slot0." ... for per-wheel and per-slot variables)
  VarType type;
  const char* unit;  //!< "" for none
  const char* description;
  Source source;
  int index;
  double start = 0.0;  //!< start value of a per-wheel input or a parameter
};

//! Inputs and parameters by their source; every other variable is an output (time independent).
[[nodiscard]] constexpr Causality causality_of(Source source) noexcept {
  return source == Source::Time         ? Causality::Independent
         : source == Source::Input ||
               source == Source::CreepInput ? Causality::Input
         : source == Source::Material       ? Causality::Parameter
                                            : Causality::Output;
}

//! What the variables of a table depend on: its slot count and whether the second axis is an input (more than one
//! value).
struct Layout {
  std::uint32_t n_slots = 0;
  bool second_input = false;
  const char* second_axis = "vertical_load_N";  //!< ctab_table_second_axis_name()
};

inline constexpr std::uint32_t kTimeVr = 0, kInputVr = 1, kWheelsetVr = 100, kWheelVr = 1000, kWheelStride = 100,
                               kSlotVr = 10000, kSlotStride = 64;
inline constexpr int kWheels = 2;
inline constexpr int kMaxInputs = 8;
inline constexpr std::uint32_t kMaxSlots = 16;  //!< = CTAB_MAX_SLOTS (checked in variables.cpp)

//! One variable of a table's FMU: its descriptor, value reference, full name, causality, wheel and slot (-1 where
//! not per wheel or per slot).
struct VariableRef {
  const Variable* variable = nullptr;
  std::uint32_t value_reference = 0;
  Causality causality = Causality::Output;
  int wheel = -1, slot = -1;
};

//! The variable with value reference `vr` in this layout; variable == nullptr when none.
[[nodiscard]] VariableRef find_variable(std::uint32_t vr, const Layout& layout) noexcept;
//! Number of inputs of the layout (dy, and the second axis where it is one).
[[nodiscard]] int input_count(const Layout& layout) noexcept;
//! Calls f(VariableRef) for every variable of the layout in value-reference order.
template <class F>
void for_each_variable(const Layout& layout, F&& f);
//! Full name of a variable: "dy", "roll", "right.status", "left.slot1.normal_force".
[[nodiscard]] std::string full_name(const VariableRef& ref);
//! Wheel names by index (CTAB_WHEEL_RIGHT, CTAB_WHEEL_LEFT).
[[nodiscard]] const char* wheel_name(int wheel) noexcept;

namespace detail {
//! The rows: time, inputs (the second axis' row for the layout), wheelset, per-wheel and per-slot outputs.
const Variable& time_variable() noexcept;
const Variable* input_variable(int i, const Layout& layout) noexcept;
std::size_t wheelset_count() noexcept;
const Variable& wheelset_variable(std::size_t i) noexcept;
std::size_t wheel_count() noexcept;
const Variable& wheel_variable(std::size_t i) noexcept;
std::size_t slot_field_count() noexcept;
const Variable& slot_variable(std::size_t i) noexcept;
}  // namespace detail

template <class F>
void for_each_variable(const Layout& layout, F&& f) {
  f(VariableRef{&detail::time_variable(), kTimeVr, Causality::Independent});
  for (int i = 0; i < input_count(layout); ++i)
    f(VariableRef{detail::input_variable(i, layout), kInputVr + static_cast<std::uint32_t>(i), Causality::Input});
  for (std::size_t i = 0; i < detail::wheelset_count(); ++i)
    f(VariableRef{&detail::wheelset_variable(i), kWheelsetVr + static_cast<std::uint32_t>(i),
                  causality_of(detail::wheelset_variable(i).source)});
  for (int w = 0; w < kWheels; ++w)
    for (std::size_t i = 0; i < detail::wheel_count(); ++i)
      f(VariableRef{&detail::wheel_variable(i), kWheelVr + kWheelStride * static_cast<std::uint32_t>(w) + static_cast<std::uint32_t>(i),
                    causality_of(detail::wheel_variable(i).source), w});
  for (int w = 0; w < kWheels; ++w)
    for (std::uint32_t s = 0; s < layout.n_slots; ++s)
      for (std::size_t f_i = 0; f_i < detail::slot_field_count(); ++f_i)
        f(VariableRef{&detail::slot_variable(f_i),
                      kSlotVr + kSlotStride * (kMaxSlots * static_cast<std::uint32_t>(w) + s) + static_cast<std::uint32_t>(f_i),
                      Causality::Output, w, static_cast<int>(s)});
}

}  // namespace ctab::fmu

struct ctab_table;

namespace ctab::fmu {

//! The layout of a loaded table's FMU.
[[nodiscard]] Layout layout_of(const ::ctab_table* table) noexcept;
//! Start value of input i (dy: 0 clamped to the table's range; the second axis: its first value).
[[nodiscard]] double input_start(const ::ctab_table* table, int i) noexcept;
//! Start value of any input or parameter (input_start for the axes, the descriptor's start otherwise).
[[nodiscard]] double start_value(const ::ctab_table* table, const VariableRef& ref) noexcept;

}  // namespace ctab::fmu
