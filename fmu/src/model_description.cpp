// SPDX-License-Identifier: Apache-2.0
// modelDescription.xml writer (model_description.hpp).
#include "model_description.hpp"

#include <cstdio>
#include <cstring>
#include <set>
#include <stdexcept>

#include "ctab/fmu/variables.hpp"

namespace ctab::fmu {

namespace {

// Units the variables may use, with their SI base-unit exponents (UnitDefinitions/Unit/BaseUnit).
struct UnitRow {
  const char* name;
  const char* base;  // BaseUnit attributes
};
constexpr UnitRow kUnits[] = {
    {"s", R"(s="1")"},           {"m", R"(m="1")"},   {"m2", R"(m="2")"}, {"N", R"(kg="1" m="1" s="-2")"},
    {"Pa", R"(kg="1" m="-1" s="-2")"}, {"rad", R"(rad="1")"}, {"1/m", R"(m="-1")"},
    {"N.m", R"(kg="1" m="2" s="-2")"},
};

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// A double that reads back to the same bits.
std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

const char* type_element(VarType type) {
  return type == VarType::Float64 ? "Float64" : type == VarType::Int32 ? "Int32" : "Boolean";
}

// One <Float64|Int32|Boolean .../> element.
std::string variable_element(const ctab_table* table, const VariableRef& ref) {
  const Variable& v = *ref.variable;
  std::string xml = std::string("    <") + type_element(v.type) + " name=\"" + escaped(full_name(ref)) +
                    "\" valueReference=\"" + std::to_string(ref.value_reference) + "\" description=\"" +
                    escaped(v.description) + "\"";
  if (ref.causality == Causality::Independent) {
    xml += R"( causality="independent" variability="continuous")";
  } else if (ref.causality == Causality::Input) {
    xml += R"( causality="input" variability="continuous")";
  } else if (ref.causality == Causality::Parameter) {
    xml += R"( causality="parameter" variability="fixed")";
  } else {
    xml += v.type == VarType::Float64 ? R"( causality="output" variability="continuous" initial="calculated")"
                                      : R"( causality="output" variability="discrete" initial="calculated")";
  }
  if (v.unit[0] != '\0') xml += std::string(" unit=\"") + v.unit + "\"";
  if (ref.causality == Causality::Input || ref.causality == Causality::Parameter)
    xml += " start=\"" + number(start_value(table, ref)) + "\"";
  return xml + "/>\n";
}

std::string unit_definitions(const Layout& layout) {
  std::set<std::string> used;
  for_each_variable(layout, [&](const VariableRef& ref) {
    if (ref.variable->unit[0] != '\0') used.insert(ref.variable->unit);
  });
  std::string xml = "  <UnitDefinitions>\n";
  for (const UnitRow& u : kUnits)
    if (used.erase(u.name)) xml += std::string("    <Unit name=\"") + u.name + "\"><BaseUnit " + u.base + "/></Unit>\n";
  if (!used.empty()) throw std::logic_error("FMU variable unit without a definition: " + *used.begin());
  return xml + "  </UnitDefinitions>\n";
}

std::string model_structure(const Layout& layout) {
  std::string outputs, initial;
  for_each_variable(layout, [&](const VariableRef& ref) {
    if (ref.causality != Causality::Output) return;
    outputs += "    <Output valueReference=\"" + std::to_string(ref.value_reference) + "\"/>\n";
    initial += "    <InitialUnknown valueReference=\"" + std::to_string(ref.value_reference) + "\"/>\n";
  });
  return "  <ModelStructure>\n" + outputs + initial + "  </ModelStructure>\n";
}

// What the table covers, for the model's description.
std::string table_summary(const ctab_table* table, const DescriptionInfo& info) {
  char text[768];
  const std::uint32_t n_second = ctab_table_second_count(table);
  std::snprintf(text, sizeof text,
                "Wheel-rail contact table %s: dy from %g to %g m (%u values), %u %s value(s) from %g to %g, %u "
                "patch slots per wheel. Outputs per wheel (right, left) and slot, creep forces from the creepage "
                "and friction inputs per wheel; inputs outside the table are clamped to its edge (status 1).",
                info.source.c_str(), ctab_table_dy_min(table), ctab_table_dy_max(table), ctab_table_dy_count(table),
                n_second, ctab_table_second_axis_name(table), ctab_table_second_value(table, 0),
                ctab_table_second_value(table, n_second - 1), ctab_table_slot_count(table));
  return text;
}

}  // namespace

std::string model_description(const ctab_table* table, const DescriptionInfo& info) {
  const Layout layout = layout_of(table);
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += std::string("<fmiModelDescription fmiVersion=\"3.0\" modelName=\"") + kModelIdentifier +
         "\" instantiationToken=\"" + escaped(info.token) + "\" description=\"" +
         escaped(table_summary(table, info)) + "\" generationTool=\"" + escaped(info.generation_tool) +
         "\" variableNamingConvention=\"flat\">\n";
  xml += std::string("  <CoSimulation modelIdentifier=\"") + kModelIdentifier +
         R"(" canHandleVariableCommunicationStepSize="true" canBeInstantiatedOnlyOncePerProcess="false")"
         R"( canGetAndSetFMUState="false" canSerializeFMUState="false" hasEventMode="false"/>)" + "\n";
  xml += unit_definitions(layout);
  xml += "  <LogCategories>\n"
         "    <Category name=\"logStatusError\" description=\"errors: refused calls, missing or corrupt table\"/>\n"
         "    <Category name=\"logStatusWarning\" description=\"warnings\"/>\n"
         "  </LogCategories>\n";
  xml += "  <DefaultExperiment startTime=\"0\" stepSize=\"0.001\"/>\n";
  xml += "  <ModelVariables>\n";
  for_each_variable(layout, [&](const VariableRef& ref) { xml += variable_element(table, ref); });
  xml += "  </ModelVariables>\n";
  xml += model_structure(layout);
  return xml + "</fmiModelDescription>\n";
}

}  // namespace ctab::fmu
