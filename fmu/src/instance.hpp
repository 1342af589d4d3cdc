// SPDX-License-Identifier: Apache-2.0
#pragma once
// One FMU instance of the wrapper: the loaded table, the inputs, both wheels' last results (normal and creep) and
// the FMI state. All memory is taken at instantiation; Set, Get and DoStep only read and write these members.
#include "ctab/fmu/variables.hpp"
#include "ctab/lookup/ctab_lookup.h"
#include "fmi3/fmi3FunctionTypes.h"

namespace ctab::fmu {

enum class State { Instantiated, Initialization, Step, Terminated, Failed };

struct Instance {
  ctab_table* table = nullptr;
  Layout layout;
  State state = State::Instantiated;
  double time = 0.0;
  double inputs[kMaxInputs] = {};
  bool dirty = true;  // inputs changed since the results were computed
  ctab_result result[kWheels];
  ctab_creep_input creep_input[kWheels] = {};  // creepages and friction per wheel; the material of both
  ctab_creep_result creep[kWheels];
  fmi3LogMessageCallback log_message = nullptr;
  fmi3InstanceEnvironment environment = nullptr;
  bool logging_on = false;
  unsigned categories = 0;  // bit i: kLogCategories[i] enabled
  char name[128] = {};
  char message[512] = {};
};

inline constexpr const char* kLogCategories[] = {"logStatusError", "logStatusWarning"};

//! A new instance with the table of resource_path/table.ctab checked against `token`; nullptr (after logging why
//! with status fmi3Error) when the resources are missing or corrupt, the token differs, or memory runs out.
Instance* create_instance(fmi3String name, fmi3String token, fmi3String resource_path, bool logging_on,
                          fmi3InstanceEnvironment environment, fmi3LogMessageCallback log_message) noexcept;
void destroy_instance(Instance* instance) noexcept;
//! Inputs and parameters back to their start values, time 0, state Instantiated.
void reset_instance(Instance& instance) noexcept;
//! Queries both wheels and their creep forces where the inputs changed since the last query (no allocation).
void update_outputs(Instance& instance) noexcept;
//! Sets an input or parameter (the caller checked its causality) and marks the outputs stale.
void set_float64(Instance& instance, const VariableRef& ref, double value) noexcept;

//! Logs through the importer's callback (when logging is on and the status' category enabled); returns `status`.
fmi3Status log_status(Instance& instance, fmi3Status status, const char* format, ...) noexcept
    __attribute__((format(printf, 3, 4)));

//! The value of a variable (its type as declared).
double float64_value(const Instance& instance, const VariableRef& ref) noexcept;
int int32_value(const Instance& instance, const VariableRef& ref) noexcept;
bool boolean_value(const Instance& instance, const VariableRef& ref) noexcept;

}  // namespace ctab::fmu
