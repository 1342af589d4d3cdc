// SPDX-License-Identifier: Apache-2.0
// Creating, loading and querying an FMU instance (instance.hpp).
#include "instance.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>

#include "ctab/fmu/token.hpp"

namespace ctab::fmu {

namespace {

struct FreeDeleter {
  void operator()(void* p) const noexcept { std::free(p); }
};
using Bytes = std::unique_ptr<unsigned char, FreeDeleter>;

// The whole file `path` in memory; empty (with `error` set) when it cannot be read.
Bytes read_file(const char* path, std::size_t& size, const char*& error) noexcept {
  Bytes bytes;
  std::FILE* file = std::fopen(path, "rb");
  if (file == nullptr) {
    error = "cannot open";
    return bytes;
  }
  long length = -1;
  if (std::fseek(file, 0, SEEK_END) == 0) length = std::ftell(file);
  size = length > 0 ? static_cast<std::size_t>(length) : 0;
  if (size == 0 || std::fseek(file, 0, SEEK_SET) != 0) {
    error = "empty or unreadable";
  } else {
    bytes.reset(static_cast<unsigned char*>(std::malloc(size)));
    if (!bytes) error = "out of memory";
    else if (std::fread(bytes.get(), 1, size, file) != size) error = "read failed";
    if (error != nullptr) bytes.reset();
  }
  std::fclose(file);
  return bytes;
}

// Loads the table of `resource_path` into `instance`, checking the instantiation token; fmi3OK or a logged error.
fmi3Status load_table(Instance& instance, fmi3String token, fmi3String resource_path) noexcept {
  if (resource_path == nullptr || resource_path[0] == '\0')
    return log_status(instance, fmi3Error, "no resource path: the table is in the FMU's resources/%s", kTableResource);
  char path[4096];
  const std::size_t n = std::strlen(resource_path);
  const char* separator = resource_path[n - 1] == '/' ? "" : "/";
  if (std::snprintf(path, sizeof path, "%s%s%s", resource_path, separator, kTableResource) >= int(sizeof path))
    return log_status(instance, fmi3Error, "resource path too long");
  std::size_t size = 0;
  const char* error = nullptr;
  const Bytes bytes = read_file(path, size, error);
  if (!bytes) return log_status(instance, fmi3Error, "%s: %s", path, error);
  char expected[kTokenSize];
  instantiation_token(bytes.get(), size, expected);
  if (token == nullptr || std::strcmp(token, expected) != 0)
    return log_status(instance, fmi3Error, "instantiationToken %s does not match the table in %s (%s)",
                      token ? token : "(null)", path, expected);
  const ctab_status status = ctab_table_open_memory(bytes.get(), size, nullptr, &instance.table);
  if (status != CTAB_OK)
    return log_status(instance, fmi3Error, "%s: %s", path, ctab_status_message(status));
  instance.layout = layout_of(instance.table);
  return fmi3OK;
}

}  // namespace

fmi3Status log_status(Instance& instance, fmi3Status status, const char* format, ...) noexcept {
  const unsigned category = status >= fmi3Error ? 0u : 1u;
  if (!instance.logging_on || instance.log_message == nullptr || (instance.categories & (1u << category)) == 0)
    return status;
  va_list arguments;
  va_start(arguments, format);
  std::vsnprintf(instance.message, sizeof instance.message, format, arguments);
  va_end(arguments);
  instance.log_message(instance.environment, status, kLogCategories[category], instance.message);
  return status;
}

Instance* create_instance(fmi3String name, fmi3String token, fmi3String resource_path, bool logging_on,
                          fmi3InstanceEnvironment environment, fmi3LogMessageCallback log_message) noexcept {
  Instance* instance = new (std::nothrow) Instance;
  if (instance == nullptr) return nullptr;
  instance->logging_on = logging_on;
  instance->categories = ~0u;
  instance->environment = environment;
  instance->log_message = log_message;
  std::snprintf(instance->name, sizeof instance->name, "%s", name ? name : "");
  if (name == nullptr || name[0] == '\0') {
    log_status(*instance, fmi3Error, "instanceName must not be empty");
  } else if (load_table(*instance, token, resource_path) == fmi3OK) {
    reset_instance(*instance);
    return instance;
  }
  destroy_instance(instance);
  return nullptr;
}

void destroy_instance(Instance* instance) noexcept {
  if (instance == nullptr) return;
  ctab_table_close(instance->table);
  delete instance;
}

namespace {

// Field `field` (CreepField) of a creep input.
template <class In>
auto* creep_input_field(In& in, int field) noexcept {
  decltype(&in.xi) const fields[] = {&in.xi, &in.eta, &in.phi_per_m, &in.friction, &in.youngs_modulus_Pa,
                                     &in.poisson_ratio};
  return fields[field];
}
double creep_total(const ctab_creep_result& r, int field) noexcept {
  const double values[] = {r.fx_N, r.force_lateral_N, r.force_vertical_N, r.mz_Nm};
  return values[field];
}
double creep_patch(const ctab_creep_patch& p, int field) noexcept {
  const double values[] = {p.fx_N, p.fs_N, p.mz_Nm, p.slip_fraction};
  return values[field];
}

}  // namespace

void reset_instance(Instance& instance) noexcept {
  instance.state = State::Instantiated;
  instance.time = 0.0;
  for (ctab_creep_input& in : instance.creep_input) in = ctab_creep_input{};  // CTAB_CREEP_STRIPS_CARTER, 16 cells
  for_each_variable(instance.layout, [&](const VariableRef& ref) {
    if (ref.causality == Causality::Input || ref.causality == Causality::Parameter)
      set_float64(instance, ref, start_value(instance.table, ref));
  });
}

void set_float64(Instance& instance, const VariableRef& ref, double value) noexcept {
  const Variable& v = *ref.variable;
  if (v.source == Source::Input) instance.inputs[v.index] = value;
  if (v.source == Source::CreepInput) *creep_input_field(instance.creep_input[ref.wheel], v.index) = value;
  if (v.source == Source::Material)
    for (ctab_creep_input& in : instance.creep_input) *creep_input_field(in, v.index) = value;
  instance.dirty = true;
}

void update_outputs(Instance& instance) noexcept {
  if (!instance.dirty) return;
  ctab_location where;
  ctab_prelookup(instance.table, instance.inputs[0], instance.layout.second_input ? instance.inputs[1] : 0.0, &where);
  for (int w = 0; w < kWheels; ++w) {
    ctab_query_prelooked(instance.table, &where, w, &instance.result[w]);
    ctab_creep_prelooked(instance.table, &where, w, &instance.creep_input[w], &instance.creep[w]);
  }
  instance.dirty = false;
}

double float64_value(const Instance& instance, const VariableRef& ref) noexcept {
  const Variable& v = *ref.variable;
  switch (v.source) {
    case Source::Time: return instance.time;
    case Source::Input: return instance.inputs[v.index];
    case Source::Quantity: return instance.result[ref.wheel].patch[ref.slot].q[v.index];
    case Source::Roll: return instance.result[CTAB_WHEEL_RIGHT].roll_rad;
    case Source::RollingRadiusDifference: return instance.result[CTAB_WHEEL_RIGHT].rolling_radius_difference_m;
    case Source::CreepInput: return *creep_input_field(instance.creep_input[ref.wheel], v.index);
    case Source::Material: return *creep_input_field(instance.creep_input[0], v.index);
    case Source::CreepTotal: return creep_total(instance.creep[ref.wheel], v.index);
    case Source::CreepPatch: return creep_patch(instance.creep[ref.wheel].patch[ref.slot], v.index);
    default: return 0.0;
  }
}

int int32_value(const Instance& instance, const VariableRef& ref) noexcept {
  if (ref.variable->source == Source::Status) return instance.result[ref.wheel].status;
  if (ref.variable->source == Source::WorstCaseStatus) return instance.result[ref.wheel].worst_case_status;
  if (ref.variable->source == Source::CreepStatus) return instance.creep[ref.wheel].status;
  return 0;
}

bool boolean_value(const Instance& instance, const VariableRef& ref) noexcept {
  return ref.variable->source == Source::Present && instance.result[ref.wheel].patch[ref.slot].present != 0;
}

}  // namespace ctab::fmu
