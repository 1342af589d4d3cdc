// SPDX-License-Identifier: Apache-2.0
// The FMU importer harness (no FMU importer is installable here): `ctab export --format fmu` on a synthetic table,
// the archive read back with our own ZIP reader, modelDescription.xml checked against the FMI 3.0 rules
// (check_model_description.py), the wrapper dlopen'ed and driven through the standard Co-Simulation calling
// sequence for 10 000 steps, its outputs compared bit for bit with ctab_query and ctab_creep_prelooked on the same
// blob (creepages and friction varying, invalid ones included); then the error
// paths: missing or corrupt resources, a wrong token, unsupported functions, a missing wrapper.
// CTAB_FMU_TEST_CTAB names the ctab executable to export with (the installed one in package.fmu_installed).
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ctab/fmu/token.hpp"
#include "ctab/fmu/variables.hpp"
#include "ctab/lookup/blob.hpp"
#include "fmi3/fmi3FunctionTypes.h"
#include "synthetic_table.hpp"
#include "zip_reader.hpp"

namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

fs::path process_dir() { return fs::path(::testing::TempDir()) / ("ctab_fmu_" + std::to_string(::getpid())); }

std::string ctab_executable() {
  const char* given = std::getenv("CTAB_FMU_TEST_CTAB");
  return given != nullptr && given[0] != '\0' ? given : CTAB_EXECUTABLE;
}

int run(const std::string& command, std::string& output) {
  const fs::path out = process_dir() / "command_output.txt";
  const int status = std::system((command + " > " + out.string() + " 2>&1").c_str());
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  output = text.str();
  return WEXITSTATUS(status);
}

Bytes read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}
void write_bytes(const fs::path& path, const Bytes& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
}

// What the importer learns from the checked modelDescription.xml.
struct Description {
  std::string token, identifier;
  struct Var {
    std::string type, causality, name;
    fmi3ValueReference vr;
  };
  std::vector<Var> variables;
  std::vector<fmi3ValueReference> outputs(const std::string& type) const {
    std::vector<fmi3ValueReference> vrs;
    for (const Var& v : variables)
      if (v.causality == "output" && v.type == type) vrs.push_back(v.vr);
    return vrs;
  }
  fmi3ValueReference vr_of(const std::string& name) const {
    for (const Var& v : variables)
      if (v.name == name) return v.vr;
    ADD_FAILURE() << "no variable " << name;
    return 0;
  }
};

// The FMI functions of the wrapper, looked up by name as an importer does.
struct Fmu {
  void* library = nullptr;
  template <class T>
  T* get(const char* name) {
    void* symbol = dlsym(library, name);
    EXPECT_NE(symbol, nullptr) << name;
    return reinterpret_cast<T*>(symbol);
  }
};

std::vector<std::string> g_log;
void log_message(fmi3InstanceEnvironment, fmi3Status status, fmi3String category, fmi3String message) {
  g_log.push_back(std::to_string(status) + " " + category + ": " + message);
}
bool logged(const std::string& text) {
  for (const std::string& line : g_log)
    if (line.find(text) != std::string::npos) return true;
  return false;
}

class FmuHarness : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = process_dir();
    fs::create_directories(dir_);
    using namespace ctab::lookup;
    blob_ = write_blob(test::make_synthetic({.n_second = 3, .failed_case = true}), false);
    write_bytes(dir_ / "synthetic.blob", blob_);
    std::string output;
    const fs::path fmu = dir_ / "synthetic.fmu";
    ASSERT_EQ(run(ctab_executable() + " export " + (dir_ / "synthetic.blob").string() + " --format fmu -o " +
                      fmu.string(), output), 0) << output;
    archive_ = read_bytes(fmu);
    files_ = ctab::fmu::test::read_zip(archive_);
    for (const auto& [name, bytes] : files_) write_bytes(dir_ / "extracted" / name, bytes);
    ASSERT_EQ(run(std::string(CTAB_PYTHON) + " " + CTAB_FMU_CHECKER + " " + (dir_ / "extracted").string(), output), 0)
        << output;
    std::istringstream lines(output);
    std::string word;
    while (lines >> word) {
      if (word == "token") lines >> description_.token;
      else if (word == "identifier") lines >> description_.identifier;
      else {
        Description::Var v{word, "", "", 0};
        lines >> v.vr >> v.causality >> v.name;
        description_.variables.push_back(v);
      }
    }
    const fs::path so = dir_ / "extracted/binaries/x86_64-linux" / (description_.identifier + ".so");
    fmu_.library = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(fmu_.library, nullptr) << dlerror();
  }
  static void TearDownTestSuite() {
    if (fmu_.library) dlclose(fmu_.library);
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  void SetUp() override { g_log.clear(); }

  static fmi3Instance instantiate(const std::string& resources, const std::string& token, bool logging = true) {
    return fmu_.get<fmi3InstantiateCoSimulationTYPE>("fmi3InstantiateCoSimulation")(
        "harness", token.c_str(), resources.empty() ? nullptr : resources.c_str(), fmi3False, logging, fmi3False,
        fmi3False, nullptr, 0, nullptr, log_message, nullptr);
  }
  static std::string resources() { return (dir_ / "extracted/resources/").string(); }

  static fs::path dir_;
  static Bytes blob_, archive_;
  static std::map<std::string, Bytes> files_;
  static Description description_;
  static Fmu fmu_;
};
fs::path FmuHarness::dir_;
Bytes FmuHarness::blob_, FmuHarness::archive_;
std::map<std::string, Bytes> FmuHarness::files_;
Description FmuHarness::description_;
Fmu FmuHarness::fmu_;

TEST_F(FmuHarness, ArchiveHoldsTheDescriptionTheWrapperAndTheBlob) {
  ASSERT_EQ(files_.size(), 3u);
  EXPECT_TRUE(files_.count("modelDescription.xml"));
  EXPECT_TRUE(files_.count("binaries/x86_64-linux/ctab_contact_table.so"));
  ASSERT_TRUE(files_.count("resources/table.ctab"));
  EXPECT_EQ(files_.at("resources/table.ctab"), blob_) << "the blob travels unchanged";
  char token[ctab::fmu::kTokenSize];
  ctab::fmu::instantiation_token(blob_.data(), blob_.size(), token);
  EXPECT_EQ(description_.token, token);
  EXPECT_EQ(description_.identifier, "ctab_contact_table");
  EXPECT_EQ(fmu_.get<fmi3GetVersionTYPE>("fmi3GetVersion")(), std::string("3.0"));
  std::printf("FMU: %zu bytes (wrapper %zu, table %zu, description %zu)\n", archive_.size(),
              files_.at("binaries/x86_64-linux/ctab_contact_table.so").size(), blob_.size(),
              files_.at("modelDescription.xml").size());
}

TEST_F(FmuHarness, DescriptionNamesEveryQuantityOfEverySlotOfBothWheels) {
  ctab_table* table = nullptr;
  ASSERT_EQ(ctab_table_open_memory(blob_.data(), blob_.size(), nullptr, &table), CTAB_OK);
  const ctab::fmu::Layout layout = ctab::fmu::layout_of(table);
  ctab_table_close(table);
  // time; inputs dy and the load; roll, delta r and the 2 material parameters; per wheel 2 statuses, 4 creep
  // inputs, the creep status and 4 creep totals; per slot present, 18 quantities and 4 creep outputs
  const std::size_t expected = 1 + 2 + 4 + 2 * (2 + 4 + 5) + 2 * layout.n_slots * (1 + CTAB_QUANTITIES + 4);
  EXPECT_EQ(description_.variables.size(), expected);
  for (const Description::Var& v : description_.variables) {
    const ctab::fmu::VariableRef ref = ctab::fmu::find_variable(v.vr, layout);
    ASSERT_NE(ref.variable, nullptr) << v.name;
    EXPECT_EQ(ctab::fmu::full_name(ref), v.name);
  }
  EXPECT_EQ(description_.vr_of("dy"), 1u);
  EXPECT_EQ(description_.vr_of("vertical_load"), 2u);
  for (const char* name : {"right.xi", "right.eta", "right.phi", "right.friction", "left.xi", "left.friction"})
    EXPECT_EQ(find_variable(description_.vr_of(name), layout).causality, ctab::fmu::Causality::Input) << name;
  for (const char* name : {"youngs_modulus", "poisson_ratio"})
    EXPECT_EQ(find_variable(description_.vr_of(name), layout).causality, ctab::fmu::Causality::Parameter) << name;
  const std::string xml(files_.at("modelDescription.xml").begin(), files_.at("modelDescription.xml").end());
  for (const char* text : {R"(<Unit name="1/m"><BaseUnit m="-1"/>)", R"(<Unit name="N.m"><BaseUnit kg="1" m="2" s="-2"/>)",
                           R"(name="right.phi" valueReference="1004")", R"(unit="1/m" start="0")",
                           R"(name="left.friction")", R"(start="0.29999999999999999")", R"(start="208000000000")",
                           R"(causality="parameter" variability="fixed")", R"(name="left.slot2.creep_mz")"})
    EXPECT_NE(xml.find(text), std::string::npos) << text;
}

// Every output of the description, read with one Get call per type, compared with the C API's answers.
struct Outputs {
  std::vector<fmi3ValueReference> f64, i32, b;
  std::vector<fmi3Float64> f64_values;
  std::vector<fmi3Int32> i32_values;
  std::unique_ptr<fmi3Boolean[]> b_values;

  explicit Outputs(const Description& d)
      : f64(d.outputs("Float64")), i32(d.outputs("Int32")), b(d.outputs("Boolean")), f64_values(f64.size()),
        i32_values(i32.size()), b_values(new fmi3Boolean[b.size()]) {}
  std::size_t count() const { return f64.size() + i32.size() + b.size(); }

  bool get(Fmu& fmu, fmi3Instance instance) {
    return fmu.get<fmi3GetFloat64TYPE>("fmi3GetFloat64")(instance, f64.data(), f64.size(), f64_values.data(),
                                                         f64.size()) == fmi3OK &&
           fmu.get<fmi3GetInt32TYPE>("fmi3GetInt32")(instance, i32.data(), i32.size(), i32_values.data(),
                                                     i32.size()) == fmi3OK &&
           fmu.get<fmi3GetBooleanTYPE>("fmi3GetBoolean")(instance, b.data(), b.size(), b_values.get(), b.size()) ==
               fmi3OK;
  }

  // The C API's answer for a Float64 output: the query r, the creep forces c.
  static double expected(const ctab::fmu::VariableRef& ref, const ctab_result (&r)[2],
                         const ctab_creep_result (&c)[2]) {
    using ctab::fmu::Source;
    const int w = ref.wheel < 0 ? 0 : ref.wheel, s = ref.slot < 0 ? 0 : ref.slot, i = ref.variable->index;
    const ctab_creep_patch& p = c[w].patch[s];
    const double totals[] = {c[w].fx_N, c[w].force_lateral_N, c[w].force_vertical_N, c[w].mz_Nm};
    const double patch[] = {p.fx_N, p.fs_N, p.mz_Nm, p.slip_fraction};
    switch (ref.variable->source) {
      case Source::Quantity: return r[w].patch[s].q[i];
      case Source::Roll: return r[0].roll_rad;
      case Source::RollingRadiusDifference: return r[0].rolling_radius_difference_m;
      case Source::CreepTotal: return totals[i];
      case Source::CreepPatch: return patch[i];
      default: ADD_FAILURE() << ref.variable->name; return 0.0;
    }
  }

  // Outputs that differ from the answers r[wheel], c[wheel] (doubles compared bit for bit).
  std::size_t mismatches(const ctab::fmu::Layout& layout, const ctab_result (&r)[2],
                         const ctab_creep_result (&c)[2]) const {
    using ctab::fmu::find_variable;
    using ctab::fmu::Source;
    std::size_t n = 0;
    for (std::size_t i = 0; i < f64.size(); ++i) {
      const double value = expected(find_variable(f64[i], layout), r, c);
      n += std::memcmp(&value, &f64_values[i], sizeof(double)) != 0;
    }
    for (std::size_t i = 0; i < i32.size(); ++i) {
      const ctab::fmu::VariableRef ref = find_variable(i32[i], layout);
      const Source source = ref.variable->source;
      n += i32_values[i] != (source == Source::Status        ? r[ref.wheel].status
                             : source == Source::CreepStatus ? c[ref.wheel].status
                                                             : r[ref.wheel].worst_case_status);
    }
    for (std::size_t i = 0; i < b.size(); ++i) {
      const ctab::fmu::VariableRef ref = find_variable(b[i], layout);
      n += b_values[i] != (r[ref.wheel].patch[ref.slot].present != 0);
    }
    return n;
  }
};

// The inputs of step `step`: dy beyond both table edges, the load beyond both ends of its axis (clamped answers
// included), per wheel creepages and friction; a NaN creepage on the right wheel and friction 0 on the left now
// and then (creep status CTAB_INVALID_INPUT, creep outputs 0).
void step_inputs(int step, fmi3Float64 (&in)[10]) {
  const auto sweep = [step](double from, double to, double rate) { return from + (to - from) * std::fmod(step * rate, 1.0); };
  in[0] = sweep(-15e-3, 15e-3, 0.6180339887);
  in[1] = sweep(45e3, 115e3, 0.4142135623);
  for (int w = 0; w < 2; ++w) {
    in[2 + 4 * w] = sweep(-0.01, 0.01, 0.7548776662 + 0.1 * w);  // xi
    in[3 + 4 * w] = sweep(-0.01, 0.01, 0.5698402910 + 0.1 * w);  // eta
    in[4 + 4 * w] = sweep(-3.0, 3.0, 0.3247179572 + 0.1 * w);    // phi [1/m]
    in[5 + 4 * w] = sweep(0.1, 0.5, 0.2207440846 + 0.1 * w);     // friction
  }
  if (step % 97 == 5) in[2] = std::nan("");
  if (step % 101 == 7) in[9] = 0.0;
}

// The standard sequence: instantiate, enter initialisation, set a parameter, exit initialisation, then per step set
// inputs, do step, get every output; terminate, free. Every output equals ctab_query's and ctab_creep_prelooked's
// answers on the same blob, bit for bit.
TEST_F(FmuHarness, TenThousandStepsEqualTheCApiBitForBit) {
  ctab_table* table = nullptr;
  ASSERT_EQ(ctab_table_open_memory(blob_.data(), blob_.size(), nullptr, &table), CTAB_OK);
  const ctab::fmu::Layout layout = ctab::fmu::layout_of(table);
  const fmi3Instance instance = instantiate(resources(), description_.token);
  ASSERT_NE(instance, nullptr) << (g_log.empty() ? "" : g_log.back());
  auto set_float64 = fmu_.get<fmi3SetFloat64TYPE>("fmi3SetFloat64");
  auto do_step = fmu_.get<fmi3DoStepTYPE>("fmi3DoStep");
  ASSERT_EQ(fmu_.get<fmi3EnterInitializationModeTYPE>("fmi3EnterInitializationMode")(instance, fmi3False, 0.0, 0.0,
                                                                                      fmi3False, 0.0), fmi3OK);
  fmi3ValueReference inputs[10] = {description_.vr_of("dy"), description_.vr_of("vertical_load")};
  for (int w = 0; w < 2; ++w)
    for (int i = 0; i < 4; ++i)
      inputs[2 + 4 * w + i] = description_.vr_of(std::string(w == 0 ? "right." : "left.") +
                                                 std::array{"xi", "eta", "phi", "friction"}[static_cast<std::size_t>(i)]);
  const fmi3ValueReference young = description_.vr_of("youngs_modulus");
  const fmi3Float64 modulus = 210e9;
  ASSERT_EQ(set_float64(instance, &young, 1, &modulus, 1), fmi3OK);
  ASSERT_EQ(fmu_.get<fmi3ExitInitializationModeTYPE>("fmi3ExitInitializationMode")(instance), fmi3OK);
  Outputs outputs(description_);
  const fmi3ValueReference named[4] = {description_.vr_of("left.slot1.max_pressure"),
                                       description_.vr_of("right.slot0.normal_force"),
                                       description_.vr_of("right.creep_fx"), description_.vr_of("left.slot0.creep_mz")};
  const double h = 1e-3;
  double busy_s = 0.0;
  std::size_t mismatches = 0, invalid = 0, valid = 0, forces = 0;
  for (int step = 0; step < 10000; ++step) {
    fmi3Float64 in[10];
    step_inputs(step, in);
    fmi3Boolean event = fmi3True, terminate = fmi3True, early = fmi3True;
    fmi3Float64 last = -1.0;
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_EQ(set_float64(instance, inputs, 10, in, 10), fmi3OK);
    ASSERT_EQ(do_step(instance, step * h, h, fmi3True, &event, &terminate, &early, &last), fmi3OK);
    ASSERT_TRUE(outputs.get(fmu_, instance));
    busy_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_FALSE(event || terminate || early);
    ASSERT_EQ(last, step * h + h);
    ctab_result r[2];
    ctab_creep_result c[2];
    ctab_location where;
    ctab_prelookup(table, in[0], in[1], &where);
    for (int w = 0; w < 2; ++w) {
      ctab_query(table, in[0], in[1], w, &r[w]);
      const ctab_creep_input creep{in[2 + 4 * w], in[3 + 4 * w], in[4 + 4 * w], in[5 + 4 * w], 210e9, 0.3,
                                   CTAB_CREEP_STRIPS_CARTER, 0};
      ctab_creep_prelooked(table, &where, w, &creep, &c[w]);
      (c[w].status == CTAB_INVALID_INPUT ? invalid : valid) += 1;
      forces += c[w].fx_N != 0.0 && c[w].force_lateral_N != 0.0 && c[w].patch[0].mz_Nm != 0.0;
    }
    mismatches += outputs.mismatches(layout, r, c);
    // Four outputs by name, independently of the descriptor table.
    fmi3Float64 values[4];
    ASSERT_EQ(fmu_.get<fmi3GetFloat64TYPE>("fmi3GetFloat64")(instance, named, 4, values, 4), fmi3OK);
    mismatches += values[0] != r[1].patch[1].q[CTAB_MAX_PRESSURE_PA] || values[1] != r[0].patch[0].q[CTAB_NORMAL_FORCE_N] ||
                  values[2] != c[0].fx_N || values[3] != c[1].patch[0].mz_Nm;
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(invalid, 150u) << "NaN creepages and zero friction answered with status and zeros";
  EXPECT_GT(valid, 19000u);
  EXPECT_GT(forces, 15000u) << "creep forces and moments where a patch is present";
  std::printf("FMU step (set 10 inputs, fmi3DoStep, get %zu outputs): %.2f us mean over 10000 steps\n",
              outputs.count(), busy_s / 10000 * 1e6);
  EXPECT_EQ(fmu_.get<fmi3TerminateTYPE>("fmi3Terminate")(instance), fmi3OK);
  fmu_.get<fmi3FreeInstanceTYPE>("fmi3FreeInstance")(instance);
  ctab_table_close(table);
  EXPECT_TRUE(g_log.empty()) << g_log.front();
}

TEST_F(FmuHarness, MissingOrCorruptResourcesAreLoggedErrors) {
  EXPECT_EQ(instantiate((dir_ / "nowhere/").string(), description_.token), nullptr);
  EXPECT_TRUE(logged("cannot open")) << ::testing::PrintToString(g_log);
  EXPECT_EQ(instantiate("", description_.token), nullptr);
  EXPECT_TRUE(logged("no resource path"));
  EXPECT_EQ(instantiate(resources(), "{not-this-table}"), nullptr);
  EXPECT_TRUE(logged("instantiationToken"));
  // A corrupt table under its own token: the blob's checksum refuses it.
  Bytes corrupt = blob_;
  corrupt[corrupt.size() / 2] ^= 0x5a;
  write_bytes(dir_ / "corrupt/resources/table.ctab", corrupt);
  char token[ctab::fmu::kTokenSize];
  ctab::fmu::instantiation_token(corrupt.data(), corrupt.size(), token);
  EXPECT_EQ(instantiate((dir_ / "corrupt/resources").string(), token), nullptr);
  EXPECT_TRUE(logged("checksum")) << ::testing::PrintToString(g_log);
  write_bytes(dir_ / "empty/resources/table.ctab", {});
  EXPECT_EQ(instantiate((dir_ / "empty/resources/").string(), token), nullptr);
  EXPECT_TRUE(logged("empty"));
  for (const std::string& line : g_log) EXPECT_EQ(line.rfind("3 logStatusError: ", 0), 0u) << line;
  g_log.clear();
  EXPECT_EQ(instantiate((dir_ / "nowhere/").string(), description_.token, false), nullptr);
  EXPECT_TRUE(g_log.empty()) << "loggingOn = false logs nothing";
}

TEST_F(FmuHarness, CallsOutOfSequenceAndUnsupportedFunctionsAreErrors) {
  const fmi3Instance instance = instantiate(resources(), description_.token);
  ASSERT_NE(instance, nullptr);
  fmi3Float64 value = 0.0;
  const fmi3ValueReference roll = description_.vr_of("roll"), dy = description_.vr_of("dy");
  fmi3Boolean flags[3];
  fmi3Float64 last;
  EXPECT_EQ(fmu_.get<fmi3GetFloat64TYPE>("fmi3GetFloat64")(instance, &roll, 1, &value, 1), fmi3Error);
  EXPECT_EQ(fmu_.get<fmi3DoStepTYPE>("fmi3DoStep")(instance, 0, 1e-3, fmi3True, flags, flags + 1, flags + 2, &last),
            fmi3Error);
  EXPECT_EQ(fmu_.get<fmi3SetFloat64TYPE>("fmi3SetFloat64")(instance, &roll, 1, &value, 1), fmi3Error);
  EXPECT_TRUE(logged("not an input"));
  EXPECT_EQ(fmu_.get<fmi3SetFloat64TYPE>("fmi3SetFloat64")(instance, &dy, 1, &value, 1), fmi3OK);
  // The material is a fixed parameter: set before initialisation ends, refused afterwards.
  const fmi3ValueReference nu = description_.vr_of("poisson_ratio");
  const fmi3Float64 ratio = 0.25;
  EXPECT_EQ(fmu_.get<fmi3SetFloat64TYPE>("fmi3SetFloat64")(instance, &nu, 1, &ratio, 1), fmi3OK);
  fmi3FMUState state = nullptr;
  EXPECT_EQ(fmu_.get<fmi3GetFMUStateTYPE>("fmi3GetFMUState")(instance, &state), fmi3Error);
  EXPECT_TRUE(logged("fmi3GetFMUState: not supported"));
  EXPECT_EQ(fmu_.get<fmi3EnterEventModeTYPE>("fmi3EnterEventMode")(instance), fmi3Error);
  fmi3Int8 i8 = 0;
  EXPECT_EQ(fmu_.get<fmi3GetInt8TYPE>("fmi3GetInt8")(instance, &roll, 1, &i8, 1), fmi3Error);
  const fmi3String unknown[1] = {"logNoSuchCategory"};
  EXPECT_EQ(fmu_.get<fmi3SetDebugLoggingTYPE>("fmi3SetDebugLogging")(instance, fmi3True, 1, unknown), fmi3Error);
  EXPECT_EQ(fmu_.get<fmi3EnterInitializationModeTYPE>("fmi3EnterInitializationMode")(instance, fmi3False, 0.0, 0.0,
                                                                                      fmi3False, 0.0), fmi3OK);
  EXPECT_EQ(fmu_.get<fmi3ExitInitializationModeTYPE>("fmi3ExitInitializationMode")(instance), fmi3OK);
  EXPECT_EQ(fmu_.get<fmi3SetFloat64TYPE>("fmi3SetFloat64")(instance, &nu, 1, &ratio, 1), fmi3Error);
  EXPECT_TRUE(logged("poisson_ratio is a fixed parameter"));
  EXPECT_EQ(fmu_.get<fmi3ResetTYPE>("fmi3Reset")(instance), fmi3OK);
  fmu_.get<fmi3FreeInstanceTYPE>("fmi3FreeInstance")(instance);
  EXPECT_EQ(fmu_.get<fmi3InstantiateModelExchangeTYPE>("fmi3InstantiateModelExchange")(
                "me", description_.token.c_str(), resources().c_str(), fmi3False, fmi3True, nullptr, log_message),
            nullptr);
  EXPECT_TRUE(logged("Co-Simulation FMU only"));
}

TEST_F(FmuHarness, MissingWrapperIsAClearError) {
  std::string output;
  const int code = run("CTAB_FMU_WRAPPER=" + (dir_ / "no_wrapper.so").string() + " " + ctab_executable() +
                           " export " + (dir_ / "synthetic.blob").string() + " --format fmu -o " +
                           (dir_ / "none.fmu").string(), output);
  EXPECT_EQ(code, 3) << output;
  EXPECT_NE(output.find("FMU wrapper"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(dir_ / "none.fmu"));
}

}  // namespace
