// SPDX-License-Identifier: Apache-2.0
// `ctab bench accuracy --quick` (issue 10, "The chart"): the CSV's columns, every rung on every scene, finite
// errors, MIM-1D ahead of Hertz on the non-Hertzian body, the chart when matplotlib is there, CONTACT columns
// filled from --reference (when ../shared is there) and a bad --reference refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "ctab/validation/reference_csv.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using ctab::gen::CsvTable;

const std::vector<std::string> kColumns = {"scene",
                                           "region",
                                           "method",
                                           "discretisation_m",
                                           "reference",
                                           "cases",
                                           "failed_cases",
                                           "time_per_case_s",
                                           "area_error_rel",
                                           "max_pressure_error_rel",
                                           "p0_profile_rms_error_rel",
                                           "contact_point_error_m",
                                           "error_rel",
                                           "contact_cases",
                                           "vs_contact_area_error_rel",
                                           "vs_contact_max_pressure_error_rel",
                                           "vs_contact_point_error_m",
                                           "tolerance",
                                           "time_min_s",
                                           "time_median_s",
                                           "time_max_s"};

std::string field(const CsvTable& t, const std::vector<std::string>& row, const std::string& name) {
  const std::size_t c = t.column(name);
  return c < row.size() ? row[c] : "";
}

bool with_reference() { return ctab::test::shared_dir_present(); }

bool matplotlib_importable() { return std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0; }

void expect_columns(const ctab::test::CtabRun* run_, const CsvTable* table_) {
  EXPECT_EQ(run_->exit_code, matplotlib_importable() ? 0 : 3) << run_->output();
  EXPECT_EQ(table_->header, kColumns);
  EXPECT_FALSE(table_->rows.empty());
}

void expect_every_method(const CsvTable* table_) {
  for (const std::string scene : {"hertz_sphere", "nonhertz", "wheelrail"}) {
    std::set<std::string> methods;
    for (const auto& row : table_->rows)
      if (field(*table_, row, "scene") == scene) methods.insert(field(*table_, row, "method"));
    std::set<std::string> expected = {"hertz", "kp", "analyn", "mim1d", "bem2d"};
    if (std::string(scene) == "wheelrail") expected.insert("auto");  // the least model: wheel-rail cases only
    EXPECT_EQ(methods, expected) << scene;
  }
  std::set<std::string> regions;
  for (const auto& row : table_->rows)
    if (field(*table_, row, "scene") == "wheelrail") regions.insert(field(*table_, row, "region"));
  EXPECT_EQ(regions, (std::set<std::string>{"tread", "two_point", "flange_root", "knee", "flange_flank"}));
}

void expect_finite(const CsvTable* table_) {
  for (const auto& row : table_->rows)
    for (const std::string name : {"time_per_case_s", "area_error_rel", "max_pressure_error_rel",
                                   "p0_profile_rms_error_rel", "contact_point_error_m", "error_rel", "time_min_s",
                                   "time_median_s", "time_max_s"}) {
      const std::string text = field(*table_, row, name);
      EXPECT_FALSE(text.empty()) << name << " of " << field(*table_, row, "scene") << " "
                                 << field(*table_, row, "method");
      if (text.empty()) continue;
      EXPECT_TRUE(std::isfinite(std::stod(text))) << name << " = " << text;
      EXPECT_GE(std::stod(text), 0.0) << name;
    }
}

// The timing spread over single solves brackets the mean of the cases' best times.
void expect_spread(const CsvTable* table_) {
  for (const auto& row : table_->rows) {
    const double low = std::stod(field(*table_, row, "time_min_s")), mid = std::stod(field(*table_, row, "time_median_s")),
                 high = std::stod(field(*table_, row, "time_max_s")),
                 per_case = std::stod(field(*table_, row, "time_per_case_s"));
    EXPECT_LE(low, mid);
    EXPECT_LE(mid, high);
    EXPECT_LE(low, per_case * (1 + 1e-9));
    EXPECT_LE(per_case, high * (1 + 1e-9));
  }
}

double error_of(const CsvTable& t, const std::string& scene, const std::string& method, double width_m) {
  for (const auto& row : t.rows)
    if (field(t, row, "scene") == scene && field(t, row, "method") == method &&
        std::fabs(std::stod(field(t, row, "discretisation_m")) - width_m) < 1e-9)
      return std::stod(field(t, row, "error_rel"));
  ADD_FAILURE() << "no row " << scene << " " << method << " " << width_m;
  return NAN;
}

void expect_mim1d_beats_hertz(const CsvTable* table_) {
  const double hertz = error_of(*table_, "nonhertz", "hertz", 0.1e-3);
  for (const double width : {0.4e-3, 0.2e-3, 0.1e-3}) EXPECT_LT(error_of(*table_, "nonhertz", "mim1d", width), hertz);
  // and Hertz is exact (to its p0 sampling) on the Hertz sphere
  EXPECT_LT(error_of(*table_, "hertz_sphere", "hertz", 0.1e-3), 0.02);
}

void expect_chart(const fs::path* dir_) {
  if (!matplotlib_importable()) return;
  EXPECT_GT(fs::file_size(*dir_ / "accuracy.png"), 1000u);
  EXPECT_GT(fs::file_size(*dir_ / "accuracy.svg"), 1000u);
}

// The least model's rows: every wheel-rail region, no failed case, its tolerance and no fixed discretisation.
void expect_least_model(const CsvTable* table_) {
  int rows = 0;
  for (const auto& row : table_->rows) {
    if (field(*table_, row, "method") != "auto") {
      EXPECT_EQ(field(*table_, row, "tolerance"), "");
      continue;
    }
    ++rows;
    EXPECT_EQ(field(*table_, row, "scene"), "wheelrail");
    EXPECT_EQ(field(*table_, row, "failed_cases"), "0");
    EXPECT_EQ(field(*table_, row, "tolerance"), "0.02");
    EXPECT_EQ(field(*table_, row, "discretisation_m"), "");
  }
  EXPECT_EQ(rows, 5);  // tread, two-point, flange root, knee, flange flank
}

void expect_contact_columns(const CsvTable* table_) {
  for (const auto& row : table_->rows) {
    const std::string scene = field(*table_, row, "scene");
    // The knee (6.55-7.1 mm) has no CONTACT case.
    const bool expected = scene == "nonhertz" ||
                          (scene == "wheelrail" && with_reference() && field(*table_, row, "region") != "knee");
    EXPECT_EQ(!field(*table_, row, "vs_contact_area_error_rel").empty(), expected) << scene;
    if (scene == "hertz_sphere") {
      EXPECT_EQ(field(*table_, row, "contact_cases"), "0");
    }
  }
}

// One --quick run (about a minute) checked in one test: CTest runs every test in its own process.
TEST(AccuracyBench, QuickRun) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("ctab_accuracy_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  std::vector<std::string> args = {"bench", "accuracy", "--quick", "--out", dir.string()};
  if (with_reference()) {  // CONTACT's wheel-rail cases are on the Manchester files, already inclined
    for (const std::string& arg :
         {std::string("--reference"), ctab::test::shared_path("reference/contact"), std::string("--wheel"),
          ctab::test::shared_path("profiles/MBench_S1002_v3.prw"), std::string("--rail"),
          ctab::test::shared_path("profiles/MBench_UIC60_v3.prr"), std::string("--inclination"), std::string("0")})
      args.push_back(arg);
  }
  const ctab::test::CtabRun run = ctab::test::run_ctab(args);
  const CsvTable table = ctab::gen::read_csv((dir / "accuracy.csv").string());
  expect_columns(&run, &table);
  expect_every_method(&table);
  expect_finite(&table);
  expect_spread(&table);
  expect_mim1d_beats_hertz(&table);
  expect_chart(&dir);
  expect_contact_columns(&table);
  expect_least_model(&table);
  fs::remove_all(dir);
}

TEST(AccuracyBench, MissingReferenceDirectoryIsAUsageError) {
  const auto run =
      ctab::test::run_ctab({"bench", "accuracy", "--quick", "--out", ::testing::TempDir() + "ctab_accuracy_bad",
                            "--reference", "/nonexistent/contact"});
  EXPECT_EQ(run.exit_code, 2) << run.output();
  EXPECT_NE(run.err.find("/nonexistent/contact/wheelrail/summary.csv"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(fs::path(::testing::TempDir()) / "ctab_accuracy_bad" / "accuracy.csv"));
}

}  // namespace
