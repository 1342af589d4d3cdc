// SPDX-License-Identifier: Apache-2.0
// Accuracy of the interpolated default table (0.1 mm, 0.025 mm at |dy| 6.1-6.5 mm) against a direct solve of the same
// case (the generator's per-case API) at 1000 random off-grid lateral shifts, linear and PCHIP, where no jump lies
// between the neighbours (cell rule Interpolate); prints the error distributions (median, p95, max) split into cases
// with one patch and with two (tread and flange sharing the load), and what happens in cells with a jump. Targets
// (issue 9): force and area 0.5 %, contact points 0.01 mm. Met with one patch (the flange patch's force since the
// refined steps of its climb from root to flank); with two patches the load moves from tread to flange within a few
// table steps and the max error is larger (lookup/README.md "Accuracy").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "ctab/lookup/hdf5_table.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"

namespace ctab::lookup {
namespace {

struct Distribution {
  std::vector<double> values;
  double worst = 0.0, worst_dy_m = 0.0;  // the largest value and where it was
  void add(double value, double dy_m) {
    values.push_back(value);
    if (value > worst) worst = value, worst_dy_m = dy_m;
  }
  [[nodiscard]] double at(double q) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
  }
  void print(const char* name, const char* unit, double scale) {
    std::printf("    %-24s n %5zu  median %9.3g  p95 %9.3g  max %9.3g %s (at dy %.3f mm)\n", name, values.size(),
                at(0.5) * scale, at(0.95) * scale, at(1.0) * scale, unit, worst_dy_m * 1e3);
  }
};

struct Errors {
  Distribution force, area, point;  // relative, relative, metres (worst of wheel, rail, centre of pressure)
};

struct Outcome {
  Errors tread_only, flange_only, two_patches;  // by the patches of the direct solve
  std::size_t jump_queries = 0, jump_presence_mismatch = 0, smooth_presence_mismatch = 0;
  std::size_t nearest_rule_violations = 0;  // jump-cell queries whose presence is not the nearer node's
  Distribution jump_force_of_wheel;         // |lookup - direct| / total normal force of the wheel, in jump cells
};

class LookupAccuracy : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = new gen::TableConfig(gen::parse_table_config(gen::kDefaultTableConfig, "default config"));
    generated_ = new tables::Table(gen::generate_table(*config_, gen::GeneratorInfo{}));
    setup_ = new gen::SweepSetup(gen::make_sweep_setup(*config_));
  }
  static void TearDownTestSuite() {
    delete config_;
    delete generated_;
    delete setup_;
  }

  static Outcome measure(ctab_interpolation mode) {
    TableData data;
    EXPECT_TRUE(from_tables(*generated_, data).ok());
    Table table;
    EXPECT_TRUE(table.load(data, {mode, false}).ok());
    const double load = config_->load_values.front();
    tables::Table direct;  // one case, filled by the generator's own store
    direct.lateral_displacement_m = {0.0};
    direct.second_axis = {load};
    direct.second_axis_name = generated_->second_axis_name;
    direct.n_slots = generated_->n_slots;
    direct.strip_samples = generated_->strip_samples;
    Outcome out;
    std::mt19937_64 random(2024);
    std::uniform_real_distribution<double> uniform(table.dy_min(), table.dy_max());
    for (int k = 0; k < 1000; ++k) {
      const double dy = uniform(random);
      const gen::CaseSolution solved = gen::solve_table_case(*setup_, dy, load);
      direct.allocate();                                                  // store_case_wheel expects empty slots
      gen::store_case_wheel(direct, *setup_, 0, 0, 0, solved.wheels[0]);  // right wheel (left: its mirror image)
      ctab_location where;
      table.prelookup(dy, load, where);
      ctab_result r;
      table.query(where, CTAB_WHEEL_RIGHT, r);
      std::size_t patches = 0;
      double total = 0.0;
      for (std::size_t s = 0; s < direct.n_slots; ++s) {
        patches += direct.patch.present[s];
        total += direct.patch.normal_force_N[s];
      }
      Errors& errors = patches >= 2 ? out.two_patches : direct.patch.present[0] ? out.tread_only : out.flange_only;
      for (std::size_t s = 0; s < direct.n_slots; ++s) {
        const bool present = direct.patch.present[s] != 0, found = r.patch[s].present != 0;
        const CellRule rule = table.rule(where.i_dy, 0, 0, s);
        const bool lookup_has_patch_nearby = data.present[data.patch_index(where.i_dy, 0, 0, s)] ||
                                             data.present[data.patch_index(where.i_dy + 1, 0, 0, s)];
        if (rule != CellRule::Interpolate) {
          if (!lookup_has_patch_nearby && !present) continue;  // no patch anywhere near: nothing to compare
          ++out.jump_queries;
          out.jump_presence_mismatch += present != found;
          if (rule == CellRule::Nearest) {
            const double f = (dy - data.dy_m[where.i_dy]) / (data.dy_m[where.i_dy + 1] - data.dy_m[where.i_dy]);
            const std::size_t nearer = f < 0.5 ? where.i_dy : where.i_dy + 1;
            out.nearest_rule_violations += found != (data.present[data.patch_index(nearer, 0, 0, s)] != 0);
          }
          out.jump_force_of_wheel.add(std::fabs(r.patch[s].q[CTAB_NORMAL_FORCE_N] - direct.patch.normal_force_N[s]) /
                                          total,
                                      dy);
          continue;
        }
        out.smooth_presence_mismatch += present != found;
        if (!present) continue;
        errors.force.add(std::fabs(r.patch[s].q[CTAB_NORMAL_FORCE_N] / direct.patch.normal_force_N[s] - 1.0), dy);
        errors.area.add(std::fabs(r.patch[s].q[CTAB_AREA_M2] / direct.patch.area_m2[s] - 1.0), dy);
        errors.point.add(std::max({std::fabs(r.patch[s].q[CTAB_Y_WHEEL_M] - direct.patch.y_wheel_m[s]),
                                   std::fabs(r.patch[s].q[CTAB_Y_RAIL_M] - direct.patch.y_rail_m[s]),
                                   std::fabs(r.patch[s].q[CTAB_Y_COP_RAIL_M] - direct.patch.y_cop_rail_m[s])}),
                         dy);
      }
    }
    std::printf("%s, default table (dy step 0.1 mm, 0.025 mm at |dy| 6.1-6.5 mm), 1000 random dy, right wheel, cells "
                "without a jump:\n",
                mode == CTAB_PCHIP ? "PCHIP" : "linear");
    const std::pair<Errors*, const char*> groups[] = {{&out.tread_only, "tread patch only"},
                                                      {&out.two_patches, "tread and flange"},
                                                      {&out.flange_only, "flange patch only"}};
    for (const auto& [errors, label] : groups) {
      std::printf("  %s:\n", label);
      errors->force.print("normal force", "%", 100.0);
      errors->area.print("area", "%", 100.0);
      errors->point.print("contact points (worst)", "mm", 1e3);
    }
    std::printf(
        "  cells with a jump (slot-queries with a patch nearby): %zu; presence differs from the direct solve in "
        "%zu (elsewhere %zu)\n",
        out.jump_queries, out.jump_presence_mismatch, out.smooth_presence_mismatch);
    out.jump_force_of_wheel.print("|force error| / wheel load", "%", 100.0);
    return out;
  }

  static gen::TableConfig* config_;
  static tables::Table* generated_;
  static gen::SweepSetup* setup_;
};

gen::TableConfig* LookupAccuracy::config_ = nullptr;
tables::Table* LookupAccuracy::generated_ = nullptr;
gen::SweepSetup* LookupAccuracy::setup_ = nullptr;

// Tread contact (the single patch of |dy| up to about 4.6 mm): force and area within the targets as maxima,
// contact points at the 95th percentile, linear and PCHIP. The flange patch alone: its force within the target as a
// maximum (measured 0.30 / 0.06 %; 3.5 / 3.3 % without the refined steps at |dy| 6.1-6.5 mm, where the contact
// climbs from root to flank within 0.07 mm).
// Where tread and flange share the load, the load and the contact move fast with dy: the figures are reported
// (README), and the bars below guard the measured maxima against regression; they are above the targets.
TEST_F(LookupAccuracy, TreadContactMeetsTheTargets) {
  for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
    Outcome out = measure(mode);
    EXPECT_EQ(out.smooth_presence_mismatch, 0u);
    EXPECT_LE(out.tread_only.force.at(1.0), 5e-3);
    EXPECT_LE(out.tread_only.area.at(1.0), 5e-3);
    EXPECT_LE(out.tread_only.point.at(0.95), 0.01e-3);
    EXPECT_LE(out.tread_only.point.at(1.0), 0.05e-3) << "regression guard: the tread point moves fast where the other "
                                                        "wheel's flange jump changes the roll (target 0.01 mm)";
    // Guard at the measured maximum: one query at dy 4.616 mm on a flange patch of about 400 N, born at 4.595 mm
    // (since the gap is sampled at the solved approach; 4.585 mm before, max 36 %).
    EXPECT_LE(out.two_patches.force.at(1.0), 0.65) << "regression guard (target 0.5 %)";
    EXPECT_LE(out.flange_only.force.at(1.0), 5e-3);
    EXPECT_LE(out.flange_only.area.at(1.0), 0.02) << "regression guard (target 0.5 %)";
    EXPECT_LE(out.flange_only.point.at(1.0), 0.05e-3) << "regression guard (target 0.01 mm)";
    // In a jump cell the query takes the nearer node's patch (it may differ from the direct solve between the
    // jump and the cell's middle: a jump is misplaced by at most half a step).
    EXPECT_GT(out.jump_queries, 0u);
    EXPECT_EQ(out.nearest_rule_violations, 0u) << "the nearer-neighbour rule misplaces a jump by at most half a step";
  }
}

}  // namespace
}  // namespace ctab::lookup
