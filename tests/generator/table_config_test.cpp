// Table configs: the embedded default equals examples/configs/default.toml; every error names key and line.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "ctab/contact/error.hpp"
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

const std::string kAxis = "[axes]\nlateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\n";

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
  ASSERT_EQ(c.lateral_displacement_m.size(), 241u);
  EXPECT_NEAR(c.lateral_displacement_m.front(), -12e-3, 1e-15);
  EXPECT_NEAR(c.lateral_displacement_m.back(), 12e-3, 1e-15);
  for (std::size_t i = 0; i < 241; ++i) EXPECT_EQ(c.lateral_displacement_m[240 - i], -c.lateral_displacement_m[i]);
  EXPECT_EQ(c.load_kind, LoadKind::VerticalForce);
  EXPECT_FALSE(c.second_axis);
  EXPECT_EQ(c.load_values, std::vector<double>{78.5e3});
  EXPECT_DOUBLE_EQ(c.strip_width_m, 0.2e-3);
}

TEST(TableConfig, ErrorsNameKeyAndLine) {
  EXPECT_EQ(error_of("[solver]\nspeed = 3\n" + kAxis), "c.toml:2: 'solver.speed': unknown key");
  EXPECT_EQ(error_of("[solver]\nstrip_width_m = \"thin\"\n" + kAxis), "c.toml:2: 'solver.strip_width_m': expected a number");
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = 0 }\n"),
            "c.toml:2: 'axes.lateral_displacement_m.step': must be positive");
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, step = -1e-4 }\n"),
            "c.toml:2: 'axes.lateral_displacement_m.step': must be positive");
  EXPECT_EQ(error_of("[axes]\nlateral_displacement_m = { start = 1e-3, stop = 0, step = 1e-4 }\n"),
            "c.toml:2: 'axes.lateral_displacement_m.stop': must not be below start (empty axis)");
  EXPECT_EQ(error_of(kAxis + "vertical_load_N = []\n"), "c.toml:3: 'axes.vertical_load_N': empty axis");
  EXPECT_EQ(error_of("[solver]\nmode = \"bogie\"\n" + kAxis), "c.toml:2: 'solver.mode': expected \"wheelset\" or \"wheel\", got \"bogie\"");
  EXPECT_EQ(error_of("[wheels]\nx = 1\n" + kAxis).substr(0, 20), "c.toml:1: 'wheels': ");
  EXPECT_EQ(error_of("[profiles]\ninclination = \"1/0\"\n" + kAxis).rfind("c.toml:2: 'profiles.inclination': expected", 0), 0u);
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
