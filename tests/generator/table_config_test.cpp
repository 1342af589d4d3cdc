// SPDX-License-Identifier: Apache-2.0
// Table configs: the embedded default equals examples/configs/default.toml; every error names key and line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

std::string error_of(const std::string& text) {
  try {
    (void)parse_table_config(text, "c.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kAxis =
    "[axes]\nlateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\nvertical_load_N = 78.5e3\n";

std::string dy_axis(const std::string& range) {
  return "[axes]\nlateral_displacement_m = " + range + "\nvertical_load_N = 78.5e3\n";
}

}  // namespace

TEST(TableConfig, DefaultIsTheExampleFileAndTheIssuesDefault) {
  std::ifstream in(ctab::test::source_path("examples/configs/default.toml"));
  std::ostringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), kDefaultTableConfig);
  const TableConfig c = parse_table_config(kDefaultTableConfig, "default");
  EXPECT_EQ(c.wheel, "S1002");
  EXPECT_EQ(c.rail, "UIC60");
  EXPECT_DOUBLE_EQ(c.inclination, 1.0 / 40.0);
  EXPECT_EQ(c.mode, ContactMode::Wheelset);
  // 241 nodes every 0.1 mm, and 12 more in each of the two zones of 0.025 mm steps at |dy| 6.1 ... 6.5 mm
  ASSERT_EQ(c.lateral_displacement_m.size(), 241u + 2 * 12);
  EXPECT_NEAR(c.lateral_displacement_m.front(), -12e-3, 1e-15);
  EXPECT_NEAR(c.lateral_displacement_m.back(), 12e-3, 1e-15);
  for (std::size_t i = 0; i < 265; ++i) EXPECT_EQ(c.lateral_displacement_m[264 - i], -c.lateral_displacement_m[i]) << i;
  EXPECT_EQ(c.load_kind, LoadKind::VerticalForce);
  EXPECT_FALSE(c.second_axis);
  EXPECT_EQ(c.load_values, std::vector<double>{78.5e3});
  EXPECT_DOUBLE_EQ(c.strip_width_m, 0.2e-3);
}

TEST(TableConfig, ErrorsNameKeyAndLine) {
  EXPECT_EQ(error_of("[solver]\nspeed = 3\n" + kAxis), "c.toml:2: 'solver.speed': unknown key");
  EXPECT_EQ(error_of("[solver]\nstrip_width_m = \"thin\"\n" + kAxis),
            "c.toml:2: 'solver.strip_width_m': expected a number");
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = 0 }\n"),
            "c.toml:2: 'axes.lateral_displacement_m.step': must be positive");
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = -1e-4 }\n"),
            "c.toml:2: 'axes.lateral_displacement_m.step': must be positive");
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 1e-3, stop = 0, step = 1e-4 }\n"),
            "c.toml:2: 'axes.lateral_displacement_m.stop': must not be below start (empty axis)");
  EXPECT_EQ(error_of(
                "[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = 1e-4 }\nvertical_load_N = []\n"),
            "c.toml:3: 'axes.vertical_load_N': empty axis");
  EXPECT_EQ(error_of("[solver]\nmode = \"bogie\"\n" + kAxis),
            "c.toml:2: 'solver.mode': expected \"wheelset\" or \"wheel\", got \"bogie\"");
  EXPECT_EQ(error_of("[wheels]\nx = 1\n" + kAxis).substr(0, 20), "c.toml:1: 'wheels': ");
  EXPECT_EQ(
      error_of("[profiles]\ninclination = \"1/0\"\n" + kAxis).rfind("c.toml:2: 'profiles.inclination': expected", 0),
      0u);
  EXPECT_EQ(error_of("[axes\n").substr(0, 22), "c.toml:1: TOML syntax:");
  // An unknown profile names the config key and line at generation set-up.
  const TableConfig bad = parse_table_config("[profiles]\nwheel = \"no_such_wheel.whl\"\n" + kAxis, "c.toml");
  try {
    (void)generate_table(bad, GeneratorInfo{});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 49), "c.toml:2: 'profiles.wheel': no_such_wheel.whl: ca");
  }
}

TEST(TableConfig, ExampleConfigsGenerate) {
  for (const char* name : {"examples/configs/manchester_files.toml", "examples/configs/load_axis.toml"}) {
    TableConfig c = read_table_config(ctab::test::source_path(name));
    if (c.lateral_displacement_m.size() > 21) {  // keep the test short: the first 21 shifts
      c.lateral_displacement_m.resize(21);
    }
    const ctab::tables::Table t = generate_table(c, GeneratorInfo{});
    for (const auto status : t.status) EXPECT_GE(static_cast<int>(status), 0) << name;
  }
}

TEST(TableConfig, MissingLoadNamesTheKeyAndTheSection) {
  EXPECT_EQ(
      error_of(
          "[solver]\nmethod = \"mim1d\"\n[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = 1e-3 }\n")
          .rfind("c.toml:3: 'axes.vertical_load_N': missing: give the load as one of vertical_load_N [N], "
                 "normal_load_N [N] or approach_m",
                 0),
      0u);
  EXPECT_EQ(error_of("[solver]\nmethod = \"mim1d\"\n"),
            "c.toml: 'axes.lateral_displacement_m': required ({start, stop, step})");
  EXPECT_EQ(error_of(kAxis + "normal_load_N = 1e3\n"),
            "c.toml:4: 'axes.normal_load_N': give only one of vertical_load_N, normal_load_N, approach_m");
}

TEST(TableConfig, AxisRangesAreValidatedBeforeAllocation) {
  // A step of 1e-21 overflowed the point count (a crash); now it is counted in double and refused.
  EXPECT_EQ(error_of(dy_axis("{ start = -12e-3, stop = 12e-3, step = 1e-21 }"))
                .rfind("c.toml:2: 'axes.lateral_displacement_m': more than 1000000 values", 0),
            0u);
  // The same on the load axis (it gave zero cases).
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = 1e-3 }\n"
                     "vertical_load_N = { start = 70e3, stop = 80e3, step = 1e-20 }\n")
                .rfind("c.toml:3: 'axes.vertical_load_N': more than 1000000 values", 0),
            0u);
  // Consecutive points that coincide in floating point.
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = 1e-3 }\n"
                     "vertical_load_N = { start = 70e3, stop = 70000.00000000001, step = 1e-12 }\n"),
            "c.toml:3: 'axes.vertical_load_N.step': too small for the values (consecutive points coincide)");
  EXPECT_EQ(error_of(dy_axis("{ start = 0, stop = 1e-3, step = inf }")),
            "c.toml:2: 'axes.lateral_displacement_m.step': expected a finite number");
  EXPECT_EQ(error_of(dy_axis("{ start = 0, stop = 1e-3 }")), "c.toml:2: 'axes.lateral_displacement_m': missing 'step'");
  EXPECT_EQ(error_of(dy_axis("{ start = 0, stop = 1e-3, step = 1e-4 }") + "approach_m = nan\n").substr(0, 8),
            "c.toml:4");
  // 10^6 points is allowed on one axis, but 10^6 shifts x 3 loads exceeds the case limit.
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 0, stop = 0.999999, step = 1e-6 }\n"
                     "vertical_load_N = [1e3, 2e3, 3e3]\n"),
            "c.toml:2: 'axes': 3000000 cases (max 2000000): reduce the dy range or increase the step, or use fewer "
            "load values");
}

TEST(TableConfig, TableMemoryIsLimited) {
  // 2 10^5 shifts x 5 loads x 2 wheels x 16 slots x (20 + 2 x 1024) x 8 B = 2.6 TB.
  const std::string big =
      "[axes]\nlateral_displacement_m = { start = 0, stop = 0.199999, step = 1e-6 }\n"
      "vertical_load_N = [1e3, 2e3, 3e3, 4e3, 5e3]\n[output]\nstrip_samples = 1024\npatch_slots = 16\n";
  EXPECT_EQ(error_of(big).rfind("c.toml:2: 'axes': the table would take ", 0), 0u);
  EXPECT_NE(error_of(big).find("reduce the dy range or increase the step, or reduce strip_samples or patch_slots"),
            std::string::npos);
  const TableConfig c = parse_table_config(kDefaultTableConfig, "default");
  EXPECT_DOUBLE_EQ(table_memory_bytes(c), 265.0 * 2 * 3 * (20 + 2 * 32) * 8);
  EXPECT_LT(table_memory_bytes(c), kMaxTableBytes);
}

TEST(TableConfig, PatchSlotsAndStripWidthRanges) {
  EXPECT_EQ(parse_table_config(kDefaultTableConfig, "default").patch_slots, 3u);
  EXPECT_EQ(parse_table_config(kAxis + "[output]\npatch_slots = 16\n", "c.toml").patch_slots, 16u);
  EXPECT_EQ(error_of(kAxis + "[output]\npatch_slots = 0\n"),
            "c.toml:5: 'output.patch_slots': expected an integer in [1, 16]");
  EXPECT_EQ(error_of(kAxis + "[output]\npatch_slots = 2.5\n"),
            "c.toml:5: 'output.patch_slots': expected an integer in [1, 16]");
  EXPECT_EQ(error_of(kAxis + "[output]\nstrip_samples = 1\n"),
            "c.toml:5: 'output.strip_samples': expected an integer in [2, 1024]");
  EXPECT_EQ(error_of("[solver]\nstrip_width_m = 1e-6\n" + kAxis),
            "c.toml:2: 'solver.strip_width_m': expected a strip width in [1e-05, 0.005] m");
  EXPECT_EQ(error_of("[solver]\nstrip_width_m = 6e-3\n" + kAxis),
            "c.toml:2: 'solver.strip_width_m': expected a strip width in [1e-05, 0.005] m");
  EXPECT_DOUBLE_EQ(parse_table_config("[solver]\nstrip_width_m = 1e-5\n" + kAxis, "c.toml").strip_width_m, 1e-5);
}

TEST(TableConfig, TrackErrorsNameTheConfigLine) {
  EXPECT_EQ(error_of("[track]\ngauge_m = 1435\n" + kAxis),
            "c.toml:2: 'track.gauge_m': expected a track gauge in [0.3, 3] m");
  EXPECT_EQ(error_of("[track]\ngauge_m = 1.0\nflange_back_distance_m = 1.36\n" + kAxis)
                .rfind("c.toml:3: 'track.flange_back_distance_m': expected a positive distance below the gauge", 0),
            0u);
  EXPECT_EQ(error_of("[track]\nnominal_radius_m = 0\n" + kAxis),
            "c.toml:2: 'track.nominal_radius_m': expected a nominal rolling radius in [0.05, 2] m");
  // A rail that does not reach the gauge height: the placement error carries the config's line.
  const TableConfig c = parse_table_config("[track]\ngauge_height_m = 0.049\n" + kAxis, "c.toml");
  ProfileReadOptions o;
  o.inclination = 1.0 / 40.0;
  const ProfileTable wheel = load_profile("S1002", ProfileRole::Wheel, o),
                     rail = load_profile("UIC60", ProfileRole::Rail, o);
  try {
    (void)place_profiles(c, wheel, rail);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("c.toml:2: 'track.gauge_height_m': ", 0), 0u) << e.what();
  }
  EXPECT_NO_THROW((void)place_profiles(parse_table_config(kDefaultTableConfig, "default"), wheel, rail));
}

// [axes] lateral_refinement_m: zones of finer steps whose nodes join the dy axis (the coarse nodes keep their
// values); every zone error names the key and its line.
TEST(TableConfig, RefinementZonesJoinTheDyAxis) {
  const std::string coarse = "[axes]\nlateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 0.5e-3 }\n";
  const TableConfig plain = parse_table_config(coarse + "vertical_load_N = 78.5e3\n", "c.toml");
  const TableConfig refined = parse_table_config(
      coarse +
          "lateral_refinement_m = [ { start = 0.2e-3, stop = 0.6e-3, step = 0.1e-3 } ]\nvertical_load_N = 78.5e3\n",
      "c.toml");
  ASSERT_EQ(refined.lateral_displacement_m.size(), 9u);  // -1, -0.5, 0, 0.2, 0.3, 0.4, 0.5, 0.6, 1 mm
  const std::vector<double> expected = {-1e-3, -0.5e-3, 0.0, 0.2e-3, 0.3e-3, 0.4e-3, 0.5e-3, 0.6e-3, 1e-3};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(refined.lateral_displacement_m[i], expected[i], 1e-15) << i;
  for (const std::size_t i : {0u, 1u, 2u, 6u, 8u})  // the coarse nodes: the very values of the plain axis
    EXPECT_EQ(std::count(plain.lateral_displacement_m.begin(), plain.lateral_displacement_m.end(),
                         refined.lateral_displacement_m[i]),
              1)
        << i;

  const auto zone_error = [&](const std::string& zones) {
    return error_of(coarse + "lateral_refinement_m = " + zones + "\nvertical_load_N = 78.5e3\n");
  };
  EXPECT_EQ(zone_error("[ { start = 0.5e-3, stop = 1.5e-3, step = 0.1e-3 } ]"),
            "c.toml:3: 'axes.lateral_refinement_m': a zone must lie within the axis (-0.001 m .. 0.001 m)");
  EXPECT_EQ(zone_error("[ { start = 0, stop = 1e-3, step = 0.5e-3 } ]"),
            "c.toml:3: 'axes.lateral_refinement_m': a zone's step must be finer than the axis's (0.0005 m)");
  EXPECT_EQ(zone_error("0.1e-3"),
            "c.toml:3: 'axes.lateral_refinement_m': expected a list of zones {start, stop, step}");
  EXPECT_EQ(zone_error("[ 0.1e-3 ]"),
            "c.toml:3: 'axes.lateral_refinement_m': expected a list of zones {start, stop, step}");
  EXPECT_EQ(zone_error("[ { start = 0, stop = 1e-4, stride = 1e-5 } ]"),
            "c.toml:3: 'axes.lateral_refinement_m.stride': unknown key (expected start, stop, step)");
  EXPECT_EQ(zone_error("[ { start = 0.2e-3, stop = 0.20005e-3, step = 0.00005e-3 } ]")
                .rfind("c.toml:3: 'axes.lateral_refinement_m': a step of 5e-08 m at dy 0.0002 m is finer than 1e-07 m",
                       0),
            0u);
}

// A refined table: its rows at the coarse nodes are the plain table's, bit for bit (each case is solved on its
// own), at 1 and 2 threads alike; a zone on one side only turns the mirror off (the left wheel solved itself).
TEST(TableConfig, RefinedTableKeepsTheCoarseRowsAndTheMirrorOnlyWhenSymmetric) {
  const std::string head =
      "[solver]\nmode = \"wheelset\"\n[axes]\nlateral_displacement_m = { start = -7e-3, stop = 7e-3, "
      "step = 1e-3 }\nvertical_load_N = 78.5e3\n";
  const std::string both = "lateral_refinement_m = [ { start = -6.5e-3, stop = -6e-3, step = 0.25e-3 }, "
                           "{ start = 6e-3, stop = 6.5e-3, step = 0.25e-3 } ]\n";
  const std::string one = "lateral_refinement_m = [ { start = 6e-3, stop = 6.5e-3, step = 0.25e-3 } ]\n";
  const auto generate = [&](const std::string& zones, int threads) {
    GeneratorInfo info;
    info.threads = threads;
    return generate_table(parse_table_config(head + zones, "r.toml"), info);
  };
  const ctab::tables::Table plain = generate("", 2), symmetric = generate(both, 2), symmetric_1 = generate(both, 1),
                            one_sided = generate(one, 2);
  EXPECT_EQ(symmetric.n_dy(), 15u + 4u);
  EXPECT_EQ(one_sided.n_dy(), 15u + 2u);
  EXPECT_EQ(symmetric.text_attributes.at("mirrored").substr(0, 4), "true");
  EXPECT_EQ(one_sided.text_attributes.at("mirrored"), "false");
  EXPECT_EQ(symmetric.patch.normal_force_N, symmetric_1.patch.normal_force_N);
  EXPECT_EQ(symmetric.patch.strip_peak_pressure_Pa, symmetric_1.patch.strip_peak_pressure_Pa);
  for (const ctab::tables::Table* refined : {&symmetric, &one_sided})
    for (std::size_t i = 0; i < plain.n_dy(); ++i) {
      const auto at = std::find(refined->lateral_displacement_m.begin(), refined->lateral_displacement_m.end(),
                                plain.lateral_displacement_m[i]);
      ASSERT_NE(at, refined->lateral_displacement_m.end()) << i;
      const auto j = static_cast<std::size_t>(at - refined->lateral_displacement_m.begin());
      EXPECT_EQ(refined->roll_rad[j], plain.roll_rad[i]) << i;
      for (std::size_t wheel = 0; wheel < 2; ++wheel)
        for (std::size_t slot = 0; slot < plain.n_slots; ++slot) {
          const std::size_t a = plain.patch_index(i, 0, wheel, slot), b = refined->patch_index(j, 0, wheel, slot);
          EXPECT_EQ(refined->patch.present[b], plain.patch.present[a]) << i;
          EXPECT_EQ(refined->patch.normal_force_N[b], plain.patch.normal_force_N[a]) << i << " wheel " << wheel;
        }
    }
}

// [solver] reference_point and reference_angle make one ReferenceRule; the angle defaults to CONTACT's for both points.
TEST(TableConfig, ReferencePointAndAngleMakeOneRule) {
  const auto rule = [](const std::string& solver) {
    return parse_table_config("[solver]\nmode = \"wheel\"\n" + solver +
                                  "[axes]\nlateral_displacement_m = { start = 0.0, stop = 1e-3, step = 1e-3 }\n"
                                  "vertical_load_N = 78.5e3\n",
                              "reference.toml")
        .reference;
  };
  EXPECT_EQ(rule(""), ReferenceRule::DeepestContactsAngle);
  EXPECT_EQ(rule("reference_angle = \"tangent\"\n"), ReferenceRule::DeepestTangent);
  EXPECT_EQ(rule("reference_point = \"deepest\"\nreference_angle = \"interpenetration-mean\"\n"),
            ReferenceRule::DeepestContactsAngle);
  EXPECT_EQ(rule("reference_point = \"interpenetration-centre\"\n"), ReferenceRule::InterpenetrationCentre);
  EXPECT_EQ(rule("reference_point = \"interpenetration-centre\"\nreference_angle = \"interpenetration-mean\"\n"),
            ReferenceRule::InterpenetrationCentre);
  try {
    (void)rule("reference_point = \"interpenetration-centre\"\nreference_angle = \"tangent\"\n");
    ADD_FAILURE() << "CONTACT's point with the tangent accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"tangent\" needs reference_point"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(reference_rule(true, ReferenceAngle::Tangent).has_value());
  EXPECT_EQ(reference_angle_name(ReferenceRule::InterpenetrationCentre), "interpenetration-mean");
  EXPECT_EQ(reference_point_name(ReferenceRule::DeepestTangent), "deepest");
}

TEST(TableConfig, LoadsAndModulusAreInTheirPhysicalRanges) {
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\n"
                     "vertical_load_N = 1e12\n"),
            "c.toml:3: 'axes.vertical_load_N': expected a load in (0, 1e8] N, got 1e+12");
  EXPECT_EQ(error_of(kAxis + "[material]\nyoungs_modulus_Pa = 1e-21\n"),
            "c.toml:5: 'material.youngs_modulus_Pa': expected a Young's modulus in (1e6, 1e13] Pa");
  EXPECT_EQ(error_of(kAxis + "[material]\nyoungs_modulus_Pa = 210e9\n"), "no error");
}

TEST(TableConfig, ATableNeedsTwoLateralShifts) {
  for (const char* range : {"{ start = 1e-3, stop = 1e-3, step = 1e-4 }", "{ start = 0, stop = 1e-3, step = 2e-3 }"}) {
    const TableConfig config = parse_table_config(dy_axis(range), "c.toml");  // a config for one solve
    try {
      require_table_axes(config);
      ADD_FAILURE() << range << " makes a one-row table";
    } catch (const InputError& e) {
      EXPECT_STREQ(e.what(), "c.toml:2: 'axes.lateral_displacement_m': gives one lateral shift; a table needs at least 2 "
                             "(stop >= start + step)");
    }
  }
  EXPECT_NO_THROW(require_table_axes(parse_table_config(kAxis, "c.toml")));
}
