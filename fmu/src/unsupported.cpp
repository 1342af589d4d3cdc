// SPDX-License-Identifier: Apache-2.0
// The FMI 3.0 functions this FMU does not support (Model Exchange, Scheduled Execution, event mode, FMU state,
// derivatives, clocks) and the access functions of types it has no variables of: each logs why and returns
// fmi3Error (instantiation returns NULL), as the standard requires of every exported function.
#include "fmi3/fmi3Functions.h"
#include "instance.hpp"

namespace {

fmi3Status unsupported(fmi3Instance handle, const char* function) noexcept {
  auto* instance = static_cast<ctab::fmu::Instance*>(handle);
  if (instance == nullptr) return fmi3Error;
  return log_status(*instance, fmi3Error,
                    "%s: not supported (a Co-Simulation FMU without event mode, FMU state, derivatives or clocks)",
                    function);
}

// Access to a type without variables: nothing to do for no value reference, an error for any.
fmi3Status no_variables(fmi3Instance handle, const char* function, size_t n) noexcept {
  auto* instance = static_cast<ctab::fmu::Instance*>(handle);
  if (instance == nullptr) return fmi3Error;
  if (n == 0) return fmi3OK;
  return log_status(*instance, fmi3Error, "%s: the FMU has no variable of this type", function);
}

}  // namespace

#define CTAB_FMU_NO_VARIABLES(T)                                                                                    \
  fmi3Status fmi3Get##T(fmi3Instance instance, const fmi3ValueReference[], size_t nValueReferences, fmi3##T[],    \
                        size_t) {                                                                                   \
    return no_variables(instance, "fmi3Get" #T, nValueReferences);                                                 \
  }                                                                                                                 \
  fmi3Status fmi3Set##T(fmi3Instance instance, const fmi3ValueReference[], size_t nValueReferences,                \
                        const fmi3##T[], size_t) {                                                                  \
    return no_variables(instance, "fmi3Set" #T, nValueReferences);                                                 \
  }

extern "C" {

fmi3Instance fmi3InstantiateModelExchange(fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean,
                                          fmi3InstanceEnvironment environment, fmi3LogMessageCallback log) {
  if (log) log(environment, fmi3Error, "logStatusError", "fmi3InstantiateModelExchange: a Co-Simulation FMU only");
  return nullptr;
}
fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean, fmi3Boolean,
                                               fmi3InstanceEnvironment environment, fmi3LogMessageCallback log,
                                               fmi3ClockUpdateCallback, fmi3LockPreemptionCallback,
                                               fmi3UnlockPreemptionCallback) {
  if (log)
    log(environment, fmi3Error, "logStatusError", "fmi3InstantiateScheduledExecution: a Co-Simulation FMU only");
  return nullptr;
}

CTAB_FMU_NO_VARIABLES(Float32)
CTAB_FMU_NO_VARIABLES(Int8)
CTAB_FMU_NO_VARIABLES(UInt8)
CTAB_FMU_NO_VARIABLES(Int16)
CTAB_FMU_NO_VARIABLES(UInt16)
CTAB_FMU_NO_VARIABLES(UInt32)
CTAB_FMU_NO_VARIABLES(Int64)
CTAB_FMU_NO_VARIABLES(UInt64)
CTAB_FMU_NO_VARIABLES(String)

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference[], size_t n, const fmi3Int32[], size_t) {
  return no_variables(instance, "fmi3SetInt32 (the Int32 variables are outputs)", n);
}
fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference[], size_t n, const fmi3Boolean[], size_t) {
  return no_variables(instance, "fmi3SetBoolean (the Boolean variables are outputs)", n);
}
fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t n, size_t[], fmi3Binary[], size_t) {
  return no_variables(instance, "fmi3GetBinary", n);
}
fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference[], size_t n, const size_t[],
                         const fmi3Binary[], size_t) {
  return no_variables(instance, "fmi3SetBinary", n);
}
fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference[], size_t n, fmi3Clock[]) {
  return no_variables(instance, "fmi3GetClock", n);
}
fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference[], size_t n, const fmi3Clock[]) {
  return no_variables(instance, "fmi3SetClock", n);
}

fmi3Status fmi3EnterEventMode(fmi3Instance i) { return unsupported(i, "fmi3EnterEventMode"); }
fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance i, fmi3ValueReference, size_t*) {
  return unsupported(i, "fmi3GetNumberOfVariableDependencies");
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance i, fmi3ValueReference, size_t[], fmi3ValueReference[], size_t[],
                                       fmi3DependencyKind[], size_t) {
  return unsupported(i, "fmi3GetVariableDependencies");
}
fmi3Status fmi3GetFMUState(fmi3Instance i, fmi3FMUState*) { return unsupported(i, "fmi3GetFMUState"); }
fmi3Status fmi3SetFMUState(fmi3Instance i, fmi3FMUState) { return unsupported(i, "fmi3SetFMUState"); }
fmi3Status fmi3FreeFMUState(fmi3Instance i, fmi3FMUState*) { return unsupported(i, "fmi3FreeFMUState"); }
fmi3Status fmi3SerializedFMUStateSize(fmi3Instance i, fmi3FMUState, size_t*) {
  return unsupported(i, "fmi3SerializedFMUStateSize");
}
fmi3Status fmi3SerializeFMUState(fmi3Instance i, fmi3FMUState, fmi3Byte[], size_t) {
  return unsupported(i, "fmi3SerializeFMUState");
}
fmi3Status fmi3DeserializeFMUState(fmi3Instance i, const fmi3Byte[], size_t, fmi3FMUState*) {
  return unsupported(i, "fmi3DeserializeFMUState");
}
fmi3Status fmi3GetDirectionalDerivative(fmi3Instance i, const fmi3ValueReference[], size_t, const fmi3ValueReference[],
                                        size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t) {
  return unsupported(i, "fmi3GetDirectionalDerivative");
}
fmi3Status fmi3GetAdjointDerivative(fmi3Instance i, const fmi3ValueReference[], size_t, const fmi3ValueReference[],
                                    size_t, const fmi3Float64[], size_t, fmi3Float64[], size_t) {
  return unsupported(i, "fmi3GetAdjointDerivative");
}
fmi3Status fmi3EnterConfigurationMode(fmi3Instance i) { return unsupported(i, "fmi3EnterConfigurationMode"); }
fmi3Status fmi3ExitConfigurationMode(fmi3Instance i) { return unsupported(i, "fmi3ExitConfigurationMode"); }
fmi3Status fmi3GetIntervalDecimal(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3Float64[],
                                  fmi3IntervalQualifier[]) {
  return unsupported(i, "fmi3GetIntervalDecimal");
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3UInt64[], fmi3UInt64[],
                                   fmi3IntervalQualifier[]) {
  return unsupported(i, "fmi3GetIntervalFraction");
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3Float64[]) {
  return unsupported(i, "fmi3GetShiftDecimal");
}
fmi3Status fmi3GetShiftFraction(fmi3Instance i, const fmi3ValueReference[], size_t, fmi3UInt64[], fmi3UInt64[]) {
  return unsupported(i, "fmi3GetShiftFraction");
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance i, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
  return unsupported(i, "fmi3SetIntervalDecimal");
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance i, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                   const fmi3UInt64[]) {
  return unsupported(i, "fmi3SetIntervalFraction");
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance i, const fmi3ValueReference[], size_t, const fmi3Float64[]) {
  return unsupported(i, "fmi3SetShiftDecimal");
}
fmi3Status fmi3SetShiftFraction(fmi3Instance i, const fmi3ValueReference[], size_t, const fmi3UInt64[],
                                const fmi3UInt64[]) {
  return unsupported(i, "fmi3SetShiftFraction");
}
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance i) { return unsupported(i, "fmi3EvaluateDiscreteStates"); }
fmi3Status fmi3UpdateDiscreteStates(fmi3Instance i, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*, fmi3Boolean*,
                                    fmi3Boolean*, fmi3Float64*) {
  return unsupported(i, "fmi3UpdateDiscreteStates");
}
fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance i) { return unsupported(i, "fmi3EnterContinuousTimeMode"); }
fmi3Status fmi3CompletedIntegratorStep(fmi3Instance i, fmi3Boolean, fmi3Boolean*, fmi3Boolean*) {
  return unsupported(i, "fmi3CompletedIntegratorStep");
}
fmi3Status fmi3SetTime(fmi3Instance i, fmi3Float64) { return unsupported(i, "fmi3SetTime"); }
fmi3Status fmi3SetContinuousStates(fmi3Instance i, const fmi3Float64[], size_t) {
  return unsupported(i, "fmi3SetContinuousStates");
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance i, fmi3Float64[], size_t) {
  return unsupported(i, "fmi3GetContinuousStateDerivatives");
}
fmi3Status fmi3GetEventIndicators(fmi3Instance i, fmi3Float64[], size_t) {
  return unsupported(i, "fmi3GetEventIndicators");
}
fmi3Status fmi3GetContinuousStates(fmi3Instance i, fmi3Float64[], size_t) {
  return unsupported(i, "fmi3GetContinuousStates");
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance i, fmi3Float64[], size_t) {
  return unsupported(i, "fmi3GetNominalsOfContinuousStates");
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance i, size_t*) {
  return unsupported(i, "fmi3GetNumberOfEventIndicators");
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance i, size_t*) {
  return unsupported(i, "fmi3GetNumberOfContinuousStates");
}
fmi3Status fmi3EnterStepMode(fmi3Instance i) { return unsupported(i, "fmi3EnterStepMode (no event mode)"); }
fmi3Status fmi3GetOutputDerivatives(fmi3Instance i, const fmi3ValueReference[], size_t, const fmi3Int32[],
                                    fmi3Float64[], size_t) {
  return unsupported(i, "fmi3GetOutputDerivatives");
}
fmi3Status fmi3ActivateModelPartition(fmi3Instance i, fmi3ValueReference, fmi3Float64) {
  return unsupported(i, "fmi3ActivateModelPartition");
}

}  // extern "C"
