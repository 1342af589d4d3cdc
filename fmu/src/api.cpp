// SPDX-License-Identifier: Apache-2.0
// The FMI 3.0 functions the wrapper supports: Co-Simulation instantiation, the initialization and step sequence,
// and Float64, Int32 and Boolean access. Set, Get and DoStep neither allocate nor lock.
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <iterator>

#include "fmi3/fmi3Functions.h"
#include "instance.hpp"

using ctab::fmu::Causality;
using ctab::fmu::Instance;
using ctab::fmu::State;
using ctab::fmu::VariableRef;
using ctab::fmu::VarType;

namespace {

// The instance, or nullptr when the state is not one of `allowed` (logged as an error).
Instance* in_state(fmi3Instance handle, const char* function, std::initializer_list<State> allowed) noexcept {
  auto* instance = static_cast<Instance*>(handle);
  if (instance == nullptr) return nullptr;
  for (const State s : allowed)
    if (instance->state == s) return instance;
  ctab::fmu::log_status(*instance, fmi3Error, "%s: not allowed in the instance's current state", function);
  return nullptr;
}

// Reads `n` variables of type `type` into values[] through `read`.
template <class T, class Read>
fmi3Status get_values(fmi3Instance handle, const char* function, VarType type, const fmi3ValueReference vrs[],
                      size_t n, T values[], size_t n_values, Read read) noexcept {
  Instance* instance = in_state(handle, function, {State::Initialization, State::Step, State::Terminated});
  if (instance == nullptr) return fmi3Error;
  if (n != n_values) return log_status(*instance, fmi3Error, "%s: %zu values for %zu value references", function, n_values, n);
  ctab::fmu::update_outputs(*instance);
  for (size_t i = 0; i < n; ++i) {
    const VariableRef ref = ctab::fmu::find_variable(vrs[i], instance->layout);
    if (ref.variable == nullptr || ref.variable->type != type)
      return log_status(*instance, fmi3Error, "%s: no variable of this type has value reference %u", function, vrs[i]);
    values[i] = read(*instance, ref);
  }
  return fmi3OK;
}

}  // namespace

extern "C" {

const char* fmi3GetVersion(void) { return fmi3Version; }

fmi3Status fmi3SetDebugLogging(fmi3Instance handle, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[]) {
  auto* instance = static_cast<Instance*>(handle);
  if (instance == nullptr) return fmi3Error;
  unsigned mask = nCategories == 0 ? ~0u : 0u;
  for (size_t i = 0; i < nCategories; ++i) {
    unsigned bit = 0;
    for (unsigned c = 0; c < std::size(ctab::fmu::kLogCategories); ++c)
      if (categories[i] != nullptr && std::strcmp(categories[i], ctab::fmu::kLogCategories[c]) == 0) bit = 1u << c;
    if (bit == 0) return log_status(*instance, fmi3Error, "fmi3SetDebugLogging: unknown log category %s", categories[i]);
    mask |= bit;
  }
  instance->logging_on = loggingOn;
  instance->categories = mask;
  return fmi3OK;
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean, fmi3Boolean loggingOn,
                                         fmi3Boolean eventModeUsed, fmi3Boolean, const fmi3ValueReference[], size_t,
                                         fmi3InstanceEnvironment instanceEnvironment, fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback) {
  Instance* instance = ctab::fmu::create_instance(instanceName, instantiationToken, resourcePath, loggingOn,
                                                  instanceEnvironment, logMessage);
  if (instance != nullptr && eventModeUsed) {
    log_status(*instance, fmi3Error, "eventModeUsed: this FMU has no event mode (hasEventMode = false)");
    ctab::fmu::destroy_instance(instance);
    return nullptr;
  }
  return instance;
}

void fmi3FreeInstance(fmi3Instance instance) { ctab::fmu::destroy_instance(static_cast<Instance*>(instance)); }

fmi3Status fmi3EnterInitializationMode(fmi3Instance handle, fmi3Boolean, fmi3Float64, fmi3Float64 startTime,
                                       fmi3Boolean, fmi3Float64) {
  Instance* instance = in_state(handle, "fmi3EnterInitializationMode", {State::Instantiated});
  if (instance == nullptr) return fmi3Error;
  instance->time = startTime;
  instance->state = State::Initialization;
  return fmi3OK;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance handle) {
  Instance* instance = in_state(handle, "fmi3ExitInitializationMode", {State::Initialization});
  if (instance == nullptr) return fmi3Error;
  ctab::fmu::update_outputs(*instance);
  instance->state = State::Step;
  return fmi3OK;
}

fmi3Status fmi3Terminate(fmi3Instance handle) {
  Instance* instance = in_state(handle, "fmi3Terminate", {State::Initialization, State::Step});
  if (instance == nullptr) return fmi3Error;
  instance->state = State::Terminated;
  return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance handle) {
  auto* instance = static_cast<Instance*>(handle);
  if (instance == nullptr) return fmi3Error;
  ctab::fmu::reset_instance(*instance);
  return fmi3OK;
}

fmi3Status fmi3DoStep(fmi3Instance handle, fmi3Float64 currentCommunicationPoint, fmi3Float64 communicationStepSize,
                      fmi3Boolean, fmi3Boolean* eventHandlingNeeded, fmi3Boolean* terminateSimulation,
                      fmi3Boolean* earlyReturn, fmi3Float64* lastSuccessfulTime) {
  Instance* instance = in_state(handle, "fmi3DoStep", {State::Step});
  if (instance == nullptr) return fmi3Error;
  if (!(communicationStepSize > 0.0) || !std::isfinite(currentCommunicationPoint + communicationStepSize))
    return log_status(*instance, fmi3Error, "fmi3DoStep: step size %g from %g: not a positive finite step",
                      communicationStepSize, currentCommunicationPoint);
  ctab::fmu::update_outputs(*instance);
  instance->time = currentCommunicationPoint + communicationStepSize;
  if (eventHandlingNeeded) *eventHandlingNeeded = fmi3False;
  if (terminateSimulation) *terminateSimulation = fmi3False;
  if (earlyReturn) *earlyReturn = fmi3False;
  if (lastSuccessfulTime) *lastSuccessfulTime = instance->time;
  return fmi3OK;
}

fmi3Status fmi3SetFloat64(fmi3Instance handle, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          const fmi3Float64 values[], size_t nValues) {
  Instance* instance =
      in_state(handle, "fmi3SetFloat64", {State::Instantiated, State::Initialization, State::Step});
  if (instance == nullptr) return fmi3Error;
  if (nValueReferences != nValues)
    return log_status(*instance, fmi3Error, "fmi3SetFloat64: %zu values for %zu value references", nValues,
                      nValueReferences);
  for (size_t i = 0; i < nValueReferences; ++i) {
    const VariableRef ref = ctab::fmu::find_variable(valueReferences[i], instance->layout);
    if (ref.variable == nullptr || (ref.causality != Causality::Input && ref.causality != Causality::Parameter))
      return log_status(*instance, fmi3Error, "fmi3SetFloat64: value reference %u is not an input", valueReferences[i]);
    if (ref.causality == Causality::Parameter && instance->state == State::Step)
      return log_status(*instance, fmi3Error, "fmi3SetFloat64: %s is a fixed parameter, set before initialisation ends",
                        ref.variable->name);
    ctab::fmu::set_float64(*instance, ref, values[i]);
  }
  return fmi3OK;
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Float64 values[], size_t nValues) {
  return get_values(instance, "fmi3GetFloat64", VarType::Float64, valueReferences, nValueReferences, values, nValues,
                    ctab::fmu::float64_value);
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                        fmi3Int32 values[], size_t nValues) {
  return get_values(instance, "fmi3GetInt32", VarType::Int32, valueReferences, nValueReferences, values, nValues,
                    ctab::fmu::int32_value);
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference valueReferences[], size_t nValueReferences,
                          fmi3Boolean values[], size_t nValues) {
  return get_values(instance, "fmi3GetBoolean", VarType::Boolean, valueReferences, nValueReferences, values, nValues,
                    ctab::fmu::boolean_value);
}

}  // extern "C"
