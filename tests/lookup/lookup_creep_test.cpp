// SPDX-License-Identifier: Apache-2.0
// Creep forces: Kalker's coefficients, the Hertzian limits (small creepage, saturation), input checks; the
// tangential ladder against CONTACT (../shared/reference/contact/wheelrail/tangential) in CreepContact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <tuple>
#include <vector>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/creep.hpp"
#include "synthetic_table.hpp"

namespace ctab::lookup {
namespace {

constexpr double kE = 208e9, kNu = 0.3, kG = kE / (2.0 * (1.0 + kNu));

// A Hertzian patch (semi-axes a along x, b along s, force N) as n strip samples over [-b, b].
struct HertzStrips {
  std::vector<double> s, a, p0;
  HertzStrips(double semi_a, double semi_b, double force, std::uint32_t n) {
    const double peak = 3.0 * force / (2.0 * std::numbers::pi * semi_a * semi_b);
    for (std::uint32_t i = 0; i < n; ++i) {
      const double v = -1.0 + 2.0 * i / (n - 1.0), w = std::sqrt(std::max(0.0, 1.0 - v * v));
      s.push_back(semi_b * v);
      a.push_back(semi_a * w);
      p0.push_back(peak * w);
    }
  }
  [[nodiscard]] StripPatch patch(double force) const {
    return {s.data(), a.data(), p0.data(), static_cast<std::uint32_t>(s.size()), force, 0.0};
  }
};

ctab_creep_input input(double xi, double eta, double phi, int method) {
  return {xi, eta, phi, 0.3, kE, kNu, method, 0};
}

TEST(CreepKalker, TableValuesAtTheNodes) {
  double c[4];
  ASSERT_EQ(ctab_kalker_coefficients(1.0, 1.0, 0.25, c), CTAB_OK);
  EXPECT_NEAR(c[0], 4.12, 1e-9);
  EXPECT_NEAR(c[1], 3.67, 1e-9);
  EXPECT_NEAR(c[2], 1.47, 1e-9);
  EXPECT_NEAR(c[3], 1.19, 1e-9);
  ASSERT_EQ(ctab_kalker_coefficients(0.5, 1.0, 0.0, c), CTAB_OK);  // a/b = 0.5, nu = 0
  EXPECT_NEAR(c[0], 2.88, 1e-9);
  EXPECT_NEAR(c[2], 0.827, 1e-9);
  ASSERT_EQ(ctab_kalker_coefficients(2.0, 1.0, 0.5, c), CTAB_OK);  // b/a = 0.5, nu = 0.5
  EXPECT_NEAR(c[0], 6.11, 1e-9);
  EXPECT_NEAR(c[1], 5.56, 1e-9);
  EXPECT_EQ(ctab_kalker_coefficients(0.0, 1.0, 0.3, c), CTAB_INVALID_INPUT);
  EXPECT_EQ(c[0], 0.0);
}

// Fx / (G a b xi) at xi = 1e-5 on a Hertzian patch within 2 % of Kalker's C11 (strips and ellipse FASTSIM), for
// a/b from 0.3 to 3.
TEST(CreepHertz, SmallCreepageGivesKalkersC11) {
  for (const double ratio : {0.3, 0.6, 1.0, 1.6, 3.0}) {
    const double b = 5e-3 / std::sqrt(ratio), a = 5e-3 * std::sqrt(ratio), force = 80e3;
    const HertzStrips hertz(a, b, force, 32);
    const double c11 = kalker_coefficients(a, b, kNu).c11;
    for (const int method :
         {CTAB_CREEP_STRIPS, CTAB_CREEP_FASTSIM_ELLIPSE, CTAB_CREEP_LINEAR, CTAB_CREEP_STRIPS_CARTER}) {
      ctab_creep_patch out;
      ASSERT_EQ(creep_patch(hertz.patch(force), input(1e-5, 0.0, 0.0, method), out), CTAB_OK);
      const double measured = -out.fx_N / (kG * a * b * 1e-5);
      EXPECT_NEAR(measured / c11, 1.0, 0.02) << "a/b " << ratio << " method " << method << ": Fx/(G a b xi) "
                                             << measured << " against C11 " << c11;
      EXPECT_LT(out.slip_fraction, 0.05) << "a/b " << ratio << " method " << method;
    }
  }
}

// |F| -> mu N within 0.5 % at xi = 0.05 (and with lateral and spin creepage added).
TEST(CreepHertz, LargeCreepageSaturatesAtMuN) {
  const double a = 6e-3, b = 4e-3, force = 80e3;
  const HertzStrips hertz(a, b, force, 32);
  for (const int method : {CTAB_CREEP_STRIPS, CTAB_CREEP_FASTSIM_ELLIPSE, CTAB_CREEP_STRIPS_CARTER})
    for (const auto& [xi, eta, phi] : {std::tuple{0.05, 0.0, 0.0}, {0.0, 0.05, 0.0}, {0.05, 0.03, 1.0}}) {
      ctab_creep_patch out;
      ASSERT_EQ(creep_patch(hertz.patch(force), input(xi, eta, phi, method), out), CTAB_OK);
      EXPECT_NEAR(std::hypot(out.fx_N, out.fs_N) / (0.3 * force), 1.0, 0.005)
          << "method " << method << " xi " << xi << " eta " << eta << " phi " << phi;
      EXPECT_GT(out.slip_fraction, 0.95) << "method " << method;
      if (xi > 0.0) {
        EXPECT_LT(out.fx_N, 0.0) << "a driving wheel (xi > 0) pushes the rail back (CONTACT's sign)";
      }
    }
}

TEST(CreepInput, InvalidInputZeroesEveryOutput) {
  const HertzStrips hertz(6e-3, 4e-3, 80e3, 32);
  const double nan = std::nan(""), inf = INFINITY;
  const ctab_creep_input bad[] = {input(nan, 0, 0, 0),         input(0, inf, 0, 0), input(0, 0, -inf, 0),
                                  {0.001, 0, 0, 0.0, 0, 0, 0, 0}, {0.001, 0, 0, -0.3, 0, 0, 0, 0},
                                  {0.001, 0, 0, nan, 0, 0, 0, 0}, {0.001, 0, 0, 0.3, 0, 0, 7, 0},
                                  {0.001, 0, 0, 0.3, 0, 0, 0, 2}, {0.001, 0, 0, 0.3, kE, 0.5, 0, 0}};
  ctab_creep_patch zero;
  std::memset(&zero, 0, sizeof zero);
  zero.status = CTAB_INVALID_INPUT;
  for (std::size_t k = 0; k < std::size(bad); ++k) {
    ctab_creep_patch out;
    std::memset(&out, 0x5a, sizeof out);
    EXPECT_EQ(ctab_creep_strips(hertz.s.data(), hertz.a.data(), hertz.p0.data(), 32, 0.0, 0.0, &bad[k], &out),
              CTAB_INVALID_INPUT)
        << "bad input " << k;
    EXPECT_EQ(std::memcmp(&out, &zero, sizeof out), 0) << "bad input " << k << ": outputs not zeroed";
  }
  // Through a table: the whole result zeroed.
  const std::vector<unsigned char> blob = write_blob(test::make_synthetic({}), false);
  ctab_table* table = nullptr;
  ASSERT_EQ(ctab_table_open_memory(blob.data(), blob.size(), nullptr, &table), CTAB_OK);
  ctab_location where;
  ASSERT_EQ(ctab_prelookup(table, 1e-3, 80e3, &where), CTAB_OK);
  ctab_creep_result result;
  std::memset(&result, 0x5a, sizeof result);
  EXPECT_EQ(ctab_creep_prelooked(table, &where, 0, &bad[0], &result), CTAB_INVALID_INPUT);
  EXPECT_EQ(result.fx_N, 0.0);
  for (const ctab_creep_patch& p : result.patch) EXPECT_EQ(p.present, 0);
  EXPECT_EQ(ctab_creep_prelooked(table, &where, 5, &bad[0], &result), CTAB_INVALID_INPUT);
  const ctab_creep_input good = input(0.001, 0.0, 0.0, CTAB_CREEP_STRIPS);
  EXPECT_EQ(ctab_creep_prelooked(table, nullptr, 0, &good, &result), CTAB_INVALID_INPUT);
  EXPECT_EQ(ctab_creep_prelooked(nullptr, &where, 0, &good, &result), CTAB_NOT_LOADED);
  ctab_table_close(table);
}

// Through a table: every present slot gets forces, the totals are the sums, the side-frame parts rotate fs.
TEST(CreepTable, SlotsAndTotals) {
  const std::vector<unsigned char> blob = write_blob(test::make_synthetic({}), false);
  ctab_table* table = nullptr;
  ASSERT_EQ(ctab_table_open_memory(blob.data(), blob.size(), nullptr, &table), CTAB_OK);
  ctab_location where;
  ASSERT_EQ(ctab_prelookup(table, 2e-3, 80e3, &where), CTAB_OK);
  ctab_result normal;
  ASSERT_EQ(ctab_query_prelooked(table, &where, 0, &normal), CTAB_OK);
  const ctab_creep_input in = input(0.001, 0.0005, 0.2, CTAB_CREEP_STRIPS);
  ctab_creep_result result;
  ASSERT_EQ(ctab_creep_prelooked(table, &where, 0, &in, &result), CTAB_OK);
  double fx = 0.0, lateral = 0.0;
  int present = 0;
  for (int s = 0; s < result.n_slots; ++s) {
    const ctab_creep_patch& p = result.patch[s];
    EXPECT_EQ(p.present, normal.patch[s].present) << "slot " << s;
    if (!p.present) continue;
    ++present;
    const double plane = normal.patch[s].q[CTAB_PLANE_ANGLE_RAD];
    EXPECT_NEAR(p.force_lateral_N, p.fs_N * std::cos(plane), 1e-9 * std::abs(p.fs_N) + 1e-12) << "slot " << s;
    EXPECT_NEAR(p.force_vertical_N, p.fs_N * std::sin(plane), 1e-9 * std::abs(p.fs_N) + 1e-12) << "slot " << s;
    EXPECT_NEAR(p.normal_force_N, normal.patch[s].q[CTAB_NORMAL_FORCE_N], 1e-6 * p.normal_force_N) << "slot " << s;
    EXPECT_LT(std::hypot(p.fx_N, p.fs_N), 0.3 * p.normal_force_N * 1.003) << "slot " << s;
    fx += p.fx_N;
    lateral += p.force_lateral_N;
  }
  for (int s = 0; s < result.n_slots; ++s) {  // the slot call gives the wheel call's patch
    ctab_creep_patch one;
    EXPECT_EQ(ctab_creep_slot_prelooked(table, &where, 0, s, &in, &one), CTAB_OK) << "slot " << s;
    EXPECT_EQ(std::memcmp(&one, &result.patch[s], sizeof one), 0) << "slot " << s;
  }
  ctab_creep_patch bad;
  EXPECT_EQ(ctab_creep_slot_prelooked(table, &where, 0, result.n_slots, &in, &bad), CTAB_INVALID_INPUT);
  EXPECT_EQ(bad.fx_N, 0.0);
  // The batch equals the single calls.
  const double dys[2] = {2e-3, -1e-3}, seconds[2] = {80e3, 80e3};
  const int32_t wheels[2] = {0, 1};
  const ctab_creep_input inputs[2] = {in, input(-0.002, 0.001, -0.5, CTAB_CREEP_FASTSIM_ELLIPSE)};
  ctab_creep_result batch[2], single;
  EXPECT_EQ(ctab_creep_batch(table, 2, dys, seconds, wheels, inputs, batch), CTAB_OK);
  for (int i = 0; i < 2; ++i) {
    ctab_location at;
    ctab_prelookup(table, dys[i], seconds[i], &at);
    ctab_creep_prelooked(table, &at, wheels[i], &inputs[i], &single);
    EXPECT_EQ(std::memcmp(&single, &batch[i], sizeof single), 0) << "batch entry " << i;
  }
  EXPECT_GT(present, 0);
  EXPECT_NEAR(result.fx_N, fx, 1e-9 * std::abs(fx));
  EXPECT_NEAR(result.force_lateral_N, lateral, 1e-9 * std::abs(lateral) + 1e-12);
  ctab_table_close(table);
}

}  // namespace
}  // namespace ctab::lookup
