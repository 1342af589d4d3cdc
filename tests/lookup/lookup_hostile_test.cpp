// SPDX-License-Identifier: Apache-2.0
// Hostile tables and callers: indices that wrap in 32 bits, tampered locations, reserved header bytes, axes without
// a finite inverse step, values beyond what interpolation or single precision holds, one-value axes, the size limit
// and an allocation failure while loading. Every case ends in a status, never a crash or a non-finite answer.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/open.hpp"
#include "synthetic_table.hpp"

namespace ctab::lookup {
namespace {

// Rewrites the header's checksum after the payload was edited (a crafted blob, not a corrupted one).
void reseal(std::vector<unsigned char>& blob) {
  const std::uint64_t sum = fnv1a64(blob.data() + kBlobHeaderBytes, blob.size() - kBlobHeaderBytes);
  for (int i = 0; i < 8; ++i) blob[32 + static_cast<std::size_t>(i)] = static_cast<unsigned char>(sum >> (8 * i));
}

ctab_status blob_status(const std::vector<unsigned char>& blob, const LoadOptions& options = {}) {
  Table table;
  const LoadResult r = open_memory(blob.data(), blob.size(), options, table);
  EXPECT_EQ(table.loaded(), r.ok()) << r.message;
  return r.status;
}

void expect_finite(const ctab_result& r) {
  for (const ctab_patch& patch : r.patch)
    for (const double v : patch.q) ASSERT_TRUE(std::isfinite(v));
  EXPECT_TRUE(std::isfinite(r.roll_rad) && std::isfinite(r.rolling_radius_difference_m));
}

TEST(LookupHostile, JumpWhoseCellIndexWrapsIn32BitsIsRefused) {
  TableData data = test::make_synthetic();
  data.jumps.push_back({0, 0xFFFFFFFFu, 0, 0, JumpKind::Moves});  // i_dy + 1 wraps to 0 in 32 bits
  Table table;
  EXPECT_EQ(table.load(data, {}).status, CTAB_ERR_CONTENT);
  EXPECT_EQ(blob_status(write_blob(data, false)), CTAB_ERR_CONTENT) << "a crafted, correctly checksummed blob";
  std::vector<unsigned char> refused;
  EXPECT_EQ(write_blob(data, false, refused).status, CTAB_ERR_CONTENT);
  EXPECT_TRUE(refused.empty());
}

TEST(LookupHostile, EveryFieldOfACallersLocationIsChecked) {
  ctab_table* table = nullptr;
  const std::vector<unsigned char> blob = write_blob(test::make_synthetic({.n_second = 2}), false);
  ASSERT_EQ(ctab_table_open_memory(blob.data(), blob.size(), nullptr, &table), CTAB_OK);
  ctab_location good;
  ASSERT_EQ(ctab_prelookup(table, 1e-3, 70e3, &good), CTAB_OK);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto tamper = [&](auto edit) {
    ctab_location where = good;
    edit(where);
    return where;
  };
  const ctab_location bad[] = {
      tamper([](ctab_location& w) { w.i_dy = UINT32_MAX; }),
      tamper([](ctab_location& w) { w.i_dy = 24; }),  // the last node starts no cell
      tamper([](ctab_location& w) { w.i_second = UINT32_MAX; }),
      tamper([](ctab_location& w) { w.i_second = 1; }),
      tamper([](ctab_location& w) { w.f_dy = -0.1; }),
      tamper([&](ctab_location& w) { w.f_second = nan; }),
      tamper([](ctab_location& w) { w.f_second = 1.5; }),
      tamper([&](ctab_location& w) { w.dy_m = nan; }),
      tamper([](ctab_location& w) { w.second = INFINITY; }),
      tamper([](ctab_location& w) { w.status = 7; }),
      tamper([](ctab_location& w) { w.status = CTAB_INVALID_INPUT; }),
      tamper([](ctab_location& w) { w.reserved = 1; }),
  };
  for (const ctab_location& where : bad) {
    ctab_result r;
    std::memset(&r, 0x7f, sizeof r);
    EXPECT_EQ(ctab_query_prelooked(table, &where, CTAB_WHEEL_RIGHT, &r), CTAB_INVALID_INPUT);
    expect_finite(r);
    double s[8], a[8], p0[8];
    std::uint32_t count = 99;
    EXPECT_EQ(ctab_strip_profile(table, &where, CTAB_WHEEL_RIGHT, 0, s, a, p0, 8, &count), CTAB_INVALID_INPUT);
    EXPECT_EQ(count, 0u);
  }
  ctab_result r;
  EXPECT_EQ(ctab_query_prelooked(table, &good, CTAB_WHEEL_LEFT, &r), CTAB_OK) << "the untouched location";
  ctab_table_close(table);
}

TEST(LookupHostile, ReservedHeaderBytesMustBeZero) {
  std::vector<unsigned char> blob = write_blob(test::make_synthetic(), false);
  ASSERT_EQ(blob_status(blob), CTAB_OK);
  for (const std::size_t at : {std::size_t{40}, std::size_t{63}}) {
    std::vector<unsigned char> bad = blob;
    bad[at] = 1;
    EXPECT_EQ(blob_status(bad), CTAB_ERR_NOT_A_TABLE) << "header byte " << at;
  }
}

TEST(LookupHostile, AxisStepsWithoutAFiniteInverseAreRefused) {
  TableData data = test::make_synthetic({.n_second = 2});
  const double subnormal = 4.9e-324;
  for (double& dy : data.dy_m) dy = dy / 1e-3 * subnormal * 2.0;  // whole axis in subnormal steps
  Table table;
  EXPECT_EQ(table.load(data, {}).status, CTAB_ERR_AXES);
  EXPECT_EQ(blob_status(write_blob(data, false)), CTAB_ERR_AXES);
  data = test::make_synthetic({.n_second = 2});
  data.second[1] = data.second[0] + subnormal;  // a second-axis step of one subnormal
  EXPECT_EQ(table.load(data, {}).status, CTAB_ERR_AXES);
  data = test::make_synthetic({.n_second = 2});
  data.second = {-1.5e308, 1.5e308};  // the step overflows
  EXPECT_EQ(table.load(data, {}).status, CTAB_ERR_AXES);
}

TEST(LookupHostile, ValuesBeyondWhatInterpolationHoldsAreRefusedAtLoad) {
  for (const double huge : {1e308, -1e308}) {
    TableData data = test::make_synthetic();
    data.quantities[data.patch_index(3, 0, 0, 0) * kQuantities + CTAB_NORMAL_FORCE_N] = huge;
    for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
      Table table;
      EXPECT_EQ(table.load(data, {mode, false}).status, CTAB_ERR_CONTENT);
    }
    EXPECT_EQ(blob_status(write_blob(data, false)), CTAB_ERR_CONTENT);
  }
  // Within kMaxTableValue but changing over the narrowest cells (tables::kMinDyStep) of an axis whose last cell is
  // wide: a PCHIP slope times that width would overflow a cubic.
  TableData steep = test::make_synthetic();
  for (std::size_t i = 0; i < steep.n_dy(); ++i) {
    steep.dy_m[i] = i + 1 < steep.n_dy() ? 1e-7 * static_cast<double>(i) : 1e3;
    for (std::size_t w = 0; w < kWheels; ++w)
      steep.quantities[steep.patch_index(i, 0, w, 0) * kQuantities + CTAB_APPROACH_M] = i % 2 ? 1e300 : -1e300;
  }
  Table pchip, linear;
  EXPECT_EQ(pchip.load(steep, {CTAB_PCHIP, false}).status, CTAB_ERR_CONTENT);
  ASSERT_TRUE(linear.load(steep, {}).ok()) << "linear blends stay within the values";
  ctab_location where;
  linear.prelookup(3.3e-7, 0.0, where);
  ctab_result r;
  std::memset(&r, 0, sizeof r);  // slots beyond the table's are not written
  linear.query(where, 0, r);
  EXPECT_GE(r.status, 0);
  expect_finite(r);
}

TEST(LookupHostile, SinglePrecisionRefusesValuesBeyondTheFloatRange) {
  TableData data = test::make_synthetic();
  data.strip_peak_pressure_Pa[data.patch_index(2, 0, 1, 0) * data.strip_samples + 1] = 1e39;
  std::vector<unsigned char> blob;
  const LoadResult written = write_blob(data, true, blob);
  EXPECT_EQ(written.status, CTAB_ERR_CONTENT);
  EXPECT_NE(written.message.find("strip peak pressure"), std::string::npos) << written.message;
  EXPECT_TRUE(blob.empty());
  ASSERT_TRUE(write_blob(data, false, blob).ok()) << "double precision holds it";
  EXPECT_EQ(blob_status(blob), CTAB_OK);
  EXPECT_EQ(blob_status(blob, {CTAB_LINEAR, true}), CTAB_ERR_CONTENT) << "loaded as single precision";
}

TEST(LookupHostile, OneValueDyAxisIsRefusedWithAMessage) {
  TableData data = test::make_synthetic({.dy_min_m = 0.0, .dy_max_m = 0.0});
  ASSERT_EQ(data.n_dy(), 1u);
  Table table;
  const LoadResult r = table.load(data, {});
  EXPECT_EQ(r.status, CTAB_ERR_AXES);
  EXPECT_NE(r.message.find("at least 2"), std::string::npos) << r.message;
  std::vector<unsigned char> blob;
  EXPECT_EQ(write_blob(data, false, blob).status, CTAB_ERR_AXES);
}

TEST(LookupHostile, TablesBeyondTheSizeLimitAreRefusedBeforeAllocating) {
  std::vector<unsigned char> blob = write_blob(test::make_synthetic(), false);
  // Counts of 2^20 dy values x 16 slots x 4096 samples: exabytes declared by a 64-byte payload.
  const std::uint32_t counts[] = {1u << 20, 1u << 10, 16, 4096};
  for (std::size_t k = 0; k < 4; ++k)
    for (int b = 0; b < 4; ++b)
      blob[kBlobHeaderBytes + 4 * k + static_cast<std::size_t>(b)] = static_cast<unsigned char>(counts[k] >> (8 * b));
  reseal(blob);
  Table table;
  const LoadResult r = open_memory(blob.data(), blob.size(), {}, table);
  EXPECT_EQ(r.status, CTAB_ERR_SHAPE);
  EXPECT_NE(r.message.find("limit"), std::string::npos) << r.message;
}

// A blob file is read in chunks straight into the table's description: the same checks as in memory.
TEST(LookupHostile, BlobFilesAreCheckedAsTheyAreReadInChunks) {
  const std::vector<unsigned char> blob = write_blob(test::make_synthetic({.n_second = 3}), false);
  const auto status_of = [](const std::vector<unsigned char>& bytes) {
    const std::string path = ::testing::TempDir() + "lookup_hostile.blob";
    std::FILE* file = std::fopen(path.c_str(), "wb");
    EXPECT_NE(file, nullptr);
    std::fwrite(bytes.data(), 1, bytes.size(), file);
    std::fclose(file);
    Table table;
    const LoadResult r = open_blob_file(path, {}, table);
    EXPECT_EQ(table.loaded(), r.ok()) << r.message;
    return r.status;
  };
  EXPECT_EQ(status_of(blob), CTAB_OK);
  std::vector<unsigned char> bad = blob;
  bad[bad.size() - 9] ^= 1;
  EXPECT_EQ(status_of(bad), CTAB_ERR_CHECKSUM);
  bad = blob;
  bad.resize(blob.size() - 8);
  EXPECT_EQ(status_of(bad), CTAB_ERR_NOT_A_TABLE);
  bad = blob;
  bad[50] = 3;
  EXPECT_EQ(status_of(bad), CTAB_ERR_NOT_A_TABLE) << "reserved header byte";
  TableData data = test::make_synthetic();
  data.jumps.push_back({0, 0xFFFFFFFFu, 0, 0, JumpKind::Appears});
  EXPECT_EQ(status_of(write_blob(data, false)), CTAB_ERR_CONTENT);
  Table table;
  EXPECT_EQ(open_blob_file(::testing::TempDir() + "lookup_hostile_missing.blob", {}, table).status,
            CTAB_ERR_CANNOT_OPEN);
}

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CTAB_NO_ADDRESS_SPACE_LIMIT 1  // the sanitizers reserve terabytes of address space
#endif

// Bytes of address space this process has mapped (the RLIMIT_AS measure).
std::size_t mapped_bytes() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  unsigned long pages = 0;
  if (statm == nullptr || std::fscanf(statm, "%lu", &pages) != 1) pages = 0;
  if (statm) std::fclose(statm);
  return pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

TEST(LookupHostile, AllocationFailureWhileLoadingIsOutOfMemory) {
#ifdef CTAB_NO_ADDRESS_SPACE_LIMIT
  GTEST_SKIP() << "address-space limit under a sanitizer";
#else
  // About 50 MB of strip profiles, loaded in a child whose address space ends a few MB above what it has mapped.
  const TableData data = test::make_synthetic({.n_second = 4, .strip_samples = 4096});
  const std::vector<unsigned char> blob = write_blob(data, false);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const rlim_t limit = mapped_bytes() + (8u << 20);
    const rlimit as{limit, limit};
    if (setrlimit(RLIMIT_AS, &as) != 0) _exit(10);
    ctab_table* handle = nullptr;
    if (ctab_table_open_memory(blob.data(), blob.size(), nullptr, &handle) != CTAB_ERR_OUT_OF_MEMORY) _exit(11);
    if (handle != nullptr) _exit(12);
    Table table;
    if (table.load(data, {}).status != CTAB_ERR_OUT_OF_MEMORY || table.loaded()) _exit(13);
    if (open_memory(blob.data(), blob.size(), {CTAB_PCHIP, false}, table).status != CTAB_ERR_OUT_OF_MEMORY) _exit(14);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child died of signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "10 setrlimit, 11 status, 12 handle, 13 C++ load, 14 open_memory";
#endif
}

}  // namespace
}  // namespace ctab::lookup
