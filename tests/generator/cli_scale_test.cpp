// SPDX-License-Identifier: Apache-2.0
// ctab at scale through the executable: `generate --shard` + `merge` against one run (byte for byte), and
// `batch` (index, a bad profile, resume, a changed profile).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using ctab::test::CtabRun;
using ctab::test::read_text;
using ctab::test::run_ctab;

std::string fresh_directory(const std::string& name) {
  const std::string directory = ::testing::TempDir() + "ctab_scale_" + name;
  fs::remove_all(directory);
  fs::create_directories(directory);
  return directory + "/";
}

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Wheelset, mirrored, 9 rows: a second apart the runs would differ only in created_utc, which the epoch fixes.
const char* const kSmallConfig =
    "[axes]\nlateral_displacement_m = { start = -2e-3, stop = 2e-3, step = 0.5e-3 }\nvertical_load_N = 78.5e3\n";
const ctab::test::CtabSpawnOptions kFixedEpoch{-1, {"SOURCE_DATE_EPOCH=1700000000"}};

std::vector<std::string> index_lines(const std::string& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

TEST(CliShard, TwoShardsMergeIntoTheSingleRunFileByteForByte) {
  const std::string dir = fresh_directory("shards");
  write_file(dir + "small.toml", kSmallConfig);
  for (const std::string threads : {"1", "2"}) {
    const std::vector<std::string> common = {"generate", dir + "small.toml", "--quiet", "--threads", threads};
    auto with = [&](std::vector<std::string> extra) {
      std::vector<std::string> args = common;
      args.insert(args.end(), extra.begin(), extra.end());
      return args;
    };
    ASSERT_EQ(run_ctab(with({"-o", dir + "single.h5"}), kFixedEpoch).exit_code, 0);
    ASSERT_EQ(run_ctab(with({"-o", dir + "s2.h5", "--shard", "2/2"}), kFixedEpoch).exit_code, 0);
    ASSERT_EQ(run_ctab(with({"-o", dir + "s1.h5", "--shard", "1/2"}), kFixedEpoch).exit_code, 0);
    const CtabRun merged = run_ctab({"merge", dir + "s2.h5", dir + "s1.h5", "-o", dir + "merged.h5"});
    ASSERT_EQ(merged.exit_code, 0) << merged.output();
    EXPECT_NE(read_text(dir + "s1.h5"), read_text(dir + "single.h5"));
    EXPECT_EQ(read_text(dir + "merged.h5"), read_text(dir + "single.h5")) << "threads " << threads;
  }
  const CtabRun missing = run_ctab({"merge", dir + "s1.h5", "-o", dir + "m.h5"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("missing shard(s) 2 of 2"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(dir + "m.h5"));
  const CtabRun not_shard = run_ctab({"merge", dir + "single.h5", "-o", dir + "m.h5"});
  EXPECT_EQ(not_shard.exit_code, 2);
  EXPECT_NE(not_shard.err.find("not a shard file"), std::string::npos) << not_shard.err;
  const CtabRun bad_spec = run_ctab({"generate", dir + "small.toml", "--shard", "3/2", "-o", dir + "x.h5"});
  EXPECT_EQ(bad_spec.exit_code, 2);
  EXPECT_NE(bad_spec.err.find("--shard: expected K/N with 1 <= K <= N"), std::string::npos) << bad_spec.err;
}

TEST(CliBatch, TablePerPairIndexBadProfileAndResume) {
  const std::string dir = fresh_directory("batch");
  const std::string wheel_file = std::string(CTAB_SHARED_DIR) + "/profiles/MBench_S1002_v3.prw";
  ASSERT_TRUE(fs::exists(wheel_file));
  fs::create_directories(dir + "wheels");
  fs::copy_file(wheel_file, dir + "wheels/w1.prw");
  write_file(dir + "wheels/bad.prw", "not a profile\n");
  write_file(dir + "small.toml", "[solver]\nmode = \"wheel\"\n" + std::string(kSmallConfig));
  write_file(dir + "m.toml", "config = \"small.toml\"\nwheels = [\"wheels/*.prw\", \"S1002\"]\nrails = [\"UIC60\"]\n");
  const CtabRun first = run_ctab({"batch", dir + "m.toml", "-o", dir + "out", "--quiet"});
  EXPECT_EQ(first.exit_code, 4) << first.output();
  EXPECT_NE(first.err.find("bad__UIC60.h5"), std::string::npos);
  std::vector<std::string> index = index_lines(dir + "out/index.csv");
  ASSERT_EQ(index.size(), 4u);
  EXPECT_EQ(index[1].rfind("\"bad__UIC60.h5\",", 0), 0u) << index[1];  // glob matches sorted
  EXPECT_NE(index[1].find(",input-error,-,0,0,"), std::string::npos) << index[1];
  EXPECT_NE(index[2].find(",ok,generated,18,0,"), std::string::npos) << index[2];
  EXPECT_NE(index[3].find("\"S1002__UIC60.h5\",\"S1002\",\"UIC60\",ok,generated,18,0,builtin,builtin,"),
            std::string::npos)
      << index[3];
  EXPECT_FALSE(fs::exists(dir + "out/bad__UIC60.h5"));
  const CtabRun inspect = run_ctab({"inspect", dir + "out/w1__UIC60.h5"});
  EXPECT_EQ(inspect.exit_code, 0) << inspect.output();

  // Resume: nothing solved again; then a changed profile is solved again, the other pairs are not.
  const CtabRun second = run_ctab({"batch", dir + "m.toml", "-o", dir + "out", "--quiet"});
  EXPECT_EQ(second.exit_code, 4);
  index = index_lines(dir + "out/index.csv");
  EXPECT_NE(index[2].find(",ok,resumed,18,0,"), std::string::npos) << index[2];
  EXPECT_NE(index[3].find(",ok,resumed,18,0,"), std::string::npos) << index[3];
  fs::copy_file(std::string(CTAB_SHARED_DIR) + "/profiles/MBench_S1002_v3.prw", dir + "wheels/w1.prw",
                fs::copy_options::overwrite_existing);
  std::ofstream(dir + "wheels/w1.prw", std::ios::app) << "\n";  // same points: resumed by its samples
  write_file(dir + "wheels/bad.prw", read_text(wheel_file));    // the bad profile repaired
  const CtabRun third = run_ctab({"batch", dir + "m.toml", "-o", dir + "out", "--quiet"});
  EXPECT_EQ(third.exit_code, 0) << third.output();
  index = index_lines(dir + "out/index.csv");
  EXPECT_NE(index[1].find(",ok,generated,18,0,"), std::string::npos) << index[1];
  EXPECT_NE(index[2].find(",ok,resumed,18,0,"), std::string::npos) << index[2];
  // A changed base config: every table is solved again.
  write_file(dir + "small.toml", "[solver]\nmode = \"wheel\"\nstrip_width_m = 0.25e-3\n" + std::string(kSmallConfig));
  EXPECT_EQ(run_ctab({"batch", dir + "m.toml", "-o", dir + "out", "--quiet"}).exit_code, 0);
  index = index_lines(dir + "out/index.csv");
  for (std::size_t i = 1; i < 4; ++i) EXPECT_NE(index[i].find(",ok,generated,18,0,"), std::string::npos) << index[i];
}

TEST(CliBatch, ManifestErrorsNameTheLine) {
  const std::string dir = fresh_directory("manifest");
  write_file(dir + "m.toml", "wheels = [\"S1002\"]\nrails = [\"nothing/*.prr\"]\n");
  const CtabRun glob = run_ctab({"batch", dir + "m.toml", "-o", dir + "out"});
  EXPECT_EQ(glob.exit_code, 2);
  EXPECT_NE(glob.err.find("m.toml:2: 'rails': the glob 'nothing/*.prr' matches no file"), std::string::npos)
      << glob.err;
  write_file(dir + "m.toml", "pairing = \"listed\"\npairs = [[\"S1002\", \"UIC60\"], [\"S1002\"]]\n");
  const CtabRun pair = run_ctab({"batch", dir + "m.toml", "-o", dir + "out"});
  EXPECT_EQ(pair.exit_code, 2);
  EXPECT_NE(pair.err.find("m.toml:2: 'pairs': expected [wheel, rail]"), std::string::npos) << pair.err;
  write_file(dir + "m.toml", "wheels = [\"S1002\"]\nrails = [\"UIC60\"]\nspeed = 3\n");
  const CtabRun unknown = run_ctab({"batch", dir + "m.toml", "-o", dir + "out"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("m.toml:3: 'speed': unknown key"), std::string::npos) << unknown.err;
}
