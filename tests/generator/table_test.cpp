// SPDX-License-Identifier: Apache-2.0
// The table generator and the HDF5 format: round trip, grid values against direct solves, determinism at 1 and 2
// threads, malformed files rejected with clear errors, failed writes leave no table.
#include <gtest/gtest.h>
#include <unistd.h>
#include <hdf5.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "ctab/contact/material.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/tables/table.hpp"
#include "ctab/tables/case_status.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "test_support.hpp"

using namespace ctab::gen;
using ctab::tables::CaseStatus;
using ctab::tables::Table;
using ctab::tables::TableStatus;

namespace {

const char* const kSmallConfig = R"(
[solver]
mode = "wheelset"
[axes]
lateral_displacement_m = { start = -7e-3, stop = 7e-3, step = 1e-3 }
vertical_load_N = [50e3, 78.5e3]
[output]
strip_samples = 16
)";

const Table& small_table(int threads) {
  static std::map<int, Table> tables;
  auto found = tables.find(threads);
  if (found == tables.end()) {
    GeneratorInfo info;
    info.threads = threads;
    found = tables.emplace(threads, generate_table(parse_table_config(kSmallConfig, "small.toml"), info)).first;
  }
  return found->second;
}

std::string temp_path(const std::string& name) { return ::testing::TempDir() + name; }

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

template <class T>
void expect_bitwise_equal(const std::vector<T>& a, const std::vector<T>& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(T)), 0) << what;
}

void expect_same_data(const Table& a, const Table& b) {
  expect_bitwise_equal(a.lateral_displacement_m, b.lateral_displacement_m, "dy");
  expect_bitwise_equal(a.second_axis, b.second_axis, "second axis");
  expect_bitwise_equal(a.roll_rad, b.roll_rad, "roll");
  expect_bitwise_equal(a.rolling_radius_difference_m, b.rolling_radius_difference_m, "dr");
  expect_bitwise_equal(a.status, b.status, "status");
  const auto& p = a.patch;
  const auto& q = b.patch;
  expect_bitwise_equal(p.present, q.present, "present");
  expect_bitwise_equal(p.normal_force_N, q.normal_force_N, "normal force");
  expect_bitwise_equal(p.area_m2, q.area_m2, "area");
  expect_bitwise_equal(p.max_pressure_Pa, q.max_pressure_Pa, "pmax");
  expect_bitwise_equal(p.contact_angle_rad, q.contact_angle_rad, "angle");
  expect_bitwise_equal(p.y_cop_rail_m, q.y_cop_rail_m, "cop");
  expect_bitwise_equal(p.semi_axis_a_m, q.semi_axis_a_m, "a");
  expect_bitwise_equal(p.strip_half_length_m, q.strip_half_length_m, "strip a");
  expect_bitwise_equal(p.strip_peak_pressure_Pa, q.strip_peak_pressure_Pa, "strip p0");
  expect_bitwise_equal(p.force_lateral_N, q.force_lateral_N, "lateral force");
  expect_bitwise_equal(p.force_vertical_N, q.force_vertical_N, "vertical force");
  expect_bitwise_equal(p.plane_angle_rad, q.plane_angle_rad, "plane angle");
  expect_bitwise_equal(p.s_origin_y_rail_m, q.s_origin_y_rail_m, "s origin y");
  expect_bitwise_equal(p.s_origin_z_rail_m, q.s_origin_z_rail_m, "s origin z");
  ASSERT_EQ(a.jumps.size(), b.jumps.size());
  for (std::size_t i = 0; i < a.jumps.size(); ++i) EXPECT_EQ(a.jumps[i].i_dy, b.jumps[i].i_dy) << "jump " << i;
}

}  // namespace

TEST(Table, RoundTrip) {
  const Table& table = small_table(2);
  ASSERT_EQ(table.n_dy(), 15u);
  ASSERT_EQ(table.n_second(), 2u);
  const std::string path = temp_path("round_trip.h5");
  ASSERT_TRUE(ctab::tables::write_table(table, path).ok());
  Table back;
  const auto result = ctab::tables::read_table(path, back);
  ASSERT_TRUE(result.ok()) << result.message;
  expect_same_data(table, back);
  EXPECT_EQ(back.text_attributes, table.text_attributes);
  EXPECT_EQ(back.number_attributes, table.number_attributes);
  EXPECT_EQ(back.integer_attributes, table.integer_attributes);
  EXPECT_EQ(back.jumps.size(), table.jumps.size());
  EXPECT_EQ(back.second_axis_name, "vertical_load_N");
  EXPECT_NE(back.text_attributes.at("config").find("vertical_load_N"), std::string::npos);
  EXPECT_EQ(back.text_attributes.at("wheel_profile_sha256").size(), 64u);
}

TEST(Table, GridPointEqualsDirectSolve) {
  const Table& table = small_table(2);
  const ProfileTable wheel = load_profile("S1002", ProfileRole::Wheel, {});
  const ProfileTable rail = load_profile("UIC60", ProfileRole::Rail, {});
  const SideGeometry side(wheel, rail, TrackSetup{});
  for (const std::size_t i_dy : {std::size_t{3}, std::size_t{9}, std::size_t{13}}) {
    const double dy = table.lateral_displacement_m[i_dy];
    const WheelsetPose pose = rigid_wheelset_pose(side, side, dy);
    EXPECT_EQ(pose.roll_rad, table.roll_rad[i_dy * 2 + 1]);
    // Right wheel, second load value; left wheel = right wheel at -dy.
    const WheelContact right = solve_wheel_contact(side, dy, pose.roll_rad, effective_modulus(kSteel, kSteel),
                                                   LoadKind::VerticalForce, 78.5e3, WheelRailOptions{});
    const WheelContact left = solve_wheel_contact(side, -dy, -pose.roll_rad, effective_modulus(kSteel, kSteel),
                                                  LoadKind::VerticalForce, 78.5e3, WheelRailOptions{});
    for (const auto& [wheel_index, contact] : {std::pair<std::size_t, const WheelContact*>{0, &right}, {1, &left}}) {
      double table_force = 0.0;
      for (std::size_t slot = 0; slot < table.n_slots; ++slot)
        table_force += table.patch.normal_force_N[table.patch_index(i_dy, 1, wheel_index, slot)];
      EXPECT_EQ(table_force == 0.0, contact->patches.empty());
      EXPECT_NEAR(table_force, contact->normal_force_N, 1e-9 * contact->normal_force_N) << "dy " << dy;
      EXPECT_EQ(table.status[table.wheel_index(i_dy, 1, wheel_index)], case_status(contact->status));
      const ContactPatch& first = contact->patches.front();
      const std::size_t slot = first.zone == "flange" ? 1 : 0;
      const std::size_t k = table.patch_index(i_dy, 1, wheel_index, slot);
      EXPECT_EQ(table.patch.present[k], 1);
      // The right wheel is the same computation: bitwise equal. The left wheel is the mirrored right wheel at
      // -dy; the direct solve at (-dy, -roll) starts from inputs that differ in the last bits (FMA contraction breaks
      // exact antisymmetry of the roll) and so agrees to the solver's convergence tolerance only (6e-9 seen).
      const double tolerance = wheel_index == 0 ? 0.0 : 1e-7;
      EXPECT_NEAR(table.patch.area_m2[k], first.area_m2, tolerance * first.area_m2)
          << "wheel " << wheel_index << " dy " << dy;
      EXPECT_NEAR(table.patch.y_cop_rail_m[k], first.y_cop_rail_m, tolerance * 0.05) << "wheel " << wheel_index;
      EXPECT_NEAR(table.patch.contact_angle_rad[k], first.contact_angle_rad, tolerance) << "wheel " << wheel_index;
      EXPECT_NEAR(table.patch.max_pressure_Pa[k], first.max_pressure_Pa, tolerance * first.max_pressure_Pa);
    }
  }
}

TEST(Table, BitIdenticalForOneAndTwoThreads) {
  const Table& one = small_table(1);
  const Table& two = small_table(2);
  expect_same_data(one, two);
  // Files: identical bytes once the two attributes that must differ (threads, creation time) agree.
  Table a = one, b = two;
  a.integer_attributes["threads"] = b.integer_attributes["threads"] = 0;
  a.text_attributes["created_utc"] = b.text_attributes["created_utc"] = "fixed";
  const std::string pa = temp_path("one.h5"), pb = temp_path("two.h5");
  ASSERT_TRUE(ctab::tables::write_table(a, pa).ok());
  ASSERT_TRUE(ctab::tables::write_table(b, pb).ok());
  const std::string bytes_a = file_bytes(pa), bytes_b = file_bytes(pb);
  EXPECT_EQ(bytes_a.size(), bytes_b.size());
  EXPECT_TRUE(bytes_a == bytes_b);
}

// Five threads on this table's one roll run: four of them take wheel tasks at once and wait for its rolls
// (generate_table's single region); more threads than cores here, so the waits yield to the solving thread.
TEST(Table, SameDataWhenWheelTasksWaitForTheirRolls) { expect_same_data(small_table(1), small_table(5)); }

TEST(Table, MalformedFilesAreRejectedClearly) {
  const std::string good = temp_path("good.h5");
  ASSERT_TRUE(ctab::tables::write_table(small_table(2), good).ok());
  Table t;
  auto read = [&](const std::string& path) { return ctab::tables::read_table(path, t); };
  EXPECT_EQ(read(temp_path("missing.h5")).status, TableStatus::CannotOpen);
  {
    std::ofstream(temp_path("text.h5")) << "not a table";
    const auto r = read(temp_path("text.h5"));
    EXPECT_EQ(r.status, TableStatus::NotATable);
    EXPECT_NE(r.message.find("text.h5"), std::string::npos);
  }
  {  // truncated: the first half of a good file
    const std::string bytes = file_bytes(good);
    std::ofstream(temp_path("truncated.h5"), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    EXPECT_NE(read(temp_path("truncated.h5")).status, TableStatus::Ok);
  }
  auto edited = [&](const char* name, const std::function<void(hid_t)>& edit) {
    const std::string path = temp_path(name);
    std::filesystem::copy_file(good, path, std::filesystem::copy_options::overwrite_existing);
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    edit(file);
    H5Fclose(file);
    return read(path);
  };
  {
    const auto r = edited("version.h5", [](hid_t file) {
      const hid_t attribute = H5Aopen(file, "schema_version", H5P_DEFAULT);
      const double version = 99;
      H5Awrite(attribute, H5T_NATIVE_DOUBLE, &version);
      H5Aclose(attribute);
    });
    EXPECT_EQ(r.status, TableStatus::WrongSchemaVersion);
    EXPECT_NE(r.message.find("schema version 99"), std::string::npos) << r.message;
  }
  {
    const auto r = edited("missing_dataset.h5", [](hid_t file) { H5Ldelete(file, "/patches/area_m2", H5P_DEFAULT); });
    EXPECT_EQ(r.status, TableStatus::MissingDataset);
    EXPECT_NE(r.message.find("/patches/area_m2"), std::string::npos) << r.message;
  }
  {
    const auto r = edited("wrong_shape.h5", [](hid_t file) {
      H5Ldelete(file, "/cases/roll_rad", H5P_DEFAULT);
      const hsize_t dims[1] = {7};
      const hid_t space = H5Screate_simple(1, dims, nullptr);
      const hid_t dataset =
          H5Dcreate2(file, "/cases/roll_rad", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      H5Dclose(dataset);
      H5Sclose(space);
    });
    EXPECT_EQ(r.status, TableStatus::WrongShape);
    EXPECT_NE(r.message.find("/cases/roll_rad"), std::string::npos) << r.message;
  }
}

TEST(Table, FailedWriteLeavesNoTableAndKeepsTheOldOne) {
  Table broken = small_table(2);
  broken.patch.area_m2.pop_back();  // inconsistent: the writer fails half-way through
  const std::string fresh = temp_path("fresh.h5");
  std::filesystem::remove(fresh);
  const auto r = ctab::tables::write_table(broken, fresh);
  EXPECT_EQ(r.status, TableStatus::WriteFailed);
  EXPECT_FALSE(std::filesystem::exists(fresh));
  const std::string existing = temp_path("existing.h5");
  ASSERT_TRUE(ctab::tables::write_table(small_table(2), existing).ok());
  const auto size = std::filesystem::file_size(existing);
  EXPECT_FALSE(ctab::tables::write_table(broken, existing).ok());
  EXPECT_EQ(std::filesystem::file_size(existing), size);
  Table back;
  EXPECT_TRUE(ctab::tables::read_table(existing, back).ok());
  // Only this test's temporaries (<target>.tmp-<pid>): other tests running at the same time (ctest -j) write
  // tables into the same directory, and their temporaries may exist for a moment.
  for (const std::string& target : {fresh, existing})
    EXPECT_FALSE(std::filesystem::exists(target + ".tmp-" + std::to_string(::getpid())))
        << "temporary left: " << target;
}

namespace {

// The identity of tables/README.md on every case: over a wheel's present patches, sum force_vertical_N equals the
// vertical load (vertical-load axis) or sum normal_force_N the normal load (normal-load axis). Returns the
// largest relative residual.
double identity_residual(const Table& table, bool vertical) {
  const bool planar = table.text_attributes.at("surface") == "planar";
  double worst = 0.0;
  for (std::size_t i = 0; i < table.n_dy(); ++i)
    for (std::size_t j = 0; j < table.n_second(); ++j)
      for (std::size_t wheel = 0; wheel < ctab::tables::kWheels; ++wheel) {
        const CaseStatus status = table.status[table.wheel_index(i, j, wheel)];
        EXPECT_TRUE(status == CaseStatus::Converged || status == CaseStatus::UnderResolved)
            << "dy " << i << " wheel " << wheel;
        double sum = 0.0;
        for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
          const std::size_t k = table.patch_index(i, j, wheel, slot);
          sum += vertical ? table.patch.force_vertical_N[k] : table.patch.normal_force_N[k];
          const double lateral = table.patch.force_lateral_N[k], vertical_N = table.patch.force_vertical_N[k];
          const double normal = table.patch.normal_force_N[k];
          if (planar) {  // the components of the normal force along the contact-plane normal
            EXPECT_NEAR(std::hypot(lateral, vertical_N), normal, 1e-12 * normal);
          } else {  // the resultant of the strips' own normals: no larger than their sum
            EXPECT_LE(std::hypot(lateral, vertical_N), normal * (1.0 + 1e-12));
          }
          // on both surfaces the resultant lies along contact_angle_rad
          if (table.patch.present[k]) {
            EXPECT_NEAR(-std::atan2(lateral, vertical_N), table.patch.contact_angle_rad[k], 1e-12);
          }
        }
        worst = std::max(worst, std::abs(sum - table.second_axis[j]) / table.second_axis[j]);
      }
  return worst;
}

}  // namespace

TEST(Table, VerticalLoadIdentityOnEveryCaseOfTheDefaultTable) {
  GeneratorInfo info;
  info.threads = 2;
  const Table table = generate_table(parse_table_config(kDefaultTableConfig, "default"), info);
  ASSERT_EQ(table.cases(), 265u);
  const double residual = identity_residual(table, true);
  std::printf("default table: max relative residual of the vertical-load identity %.3g\n", residual);
  // No case stays under-resolved: where a patch with >= 5 % of the load spans fewer than 8 strips of 0.2 mm (the
  // flank contact at |dy| = 9.0-12 mm, 1.4 mm wide, 7 strips on CONTACT's grid) the sweep solves the case again at
  // a strip width halved until it does, and stores that width.
  EXPECT_EQ(table.text_attributes.at("surface"), "conformal");
  std::size_t refined = 0;
  for (std::size_t i = 0; i < table.n_dy(); ++i)
    for (std::size_t wheel = 0; wheel < ctab::tables::kWheels; ++wheel) {
      const std::size_t w = table.wheel_index(i, 0, wheel);
      EXPECT_NE(table.status[w], CaseStatus::UnderResolved) << "dy " << table.lateral_displacement_m[i];
      if (table.strip_width_m[w] == 0.2e-3) continue;
      ++refined;
      EXPECT_EQ(table.strip_width_m[w], 0.1e-3);
      EXPECT_GT(std::abs(table.lateral_displacement_m[i]) * 1e3, 8.95)
          << "refined at dy " << table.lateral_displacement_m[i];
    }
  EXPECT_EQ(refined, 62u);
  EXPECT_LE(residual, 1e-9);
  // The default table passes the reader's validation (what `ctab inspect` reports as valid).
  const std::string path = temp_path("default.h5");
  ASSERT_TRUE(ctab::tables::write_table(table, path).ok());
  Table back;
  const auto read = ctab::tables::read_table(path, back);
  EXPECT_TRUE(read.ok()) << read.message;
  EXPECT_FALSE(back.jumps.empty());
}

TEST(Table, NormalLoadIdentityOnEveryCaseOfALoadAxisTable) {
  const Table table = generate_table(parse_table_config(R"(
[solver]
mode = "wheelset"
[axes]
lateral_displacement_m = { start = -8e-3, stop = 8e-3, step = 0.5e-3 }
normal_load_N = [40e3, 80e3, 120e3]
[output]
strip_samples = 8
)",
                                                        "normal.toml"),
                                     GeneratorInfo{});
  EXPECT_EQ(table.second_axis_name, "normal_load_N");
  EXPECT_EQ(table.second_axis_units, "N");
  EXPECT_LE(identity_residual(table, false), 1e-9);
}

TEST(Table, FlangeForcePushesTheRailToTheFieldSide) {
  // Single-wheel mode, right wheel at dy = +7 mm: flange contact (slot 1) on the gauge side; on a plane the deepest
  // point with the rail's tangent there and with CONTACT's reference angle, and CONTACT's rule; the conformal surface
  // (the default) at the deepest point with CONTACT's angle.
  struct SetUp {
    const char* point;
    const char* angle;
    const char* surface;
  };
  double contacts_angle = 0.0, centres_angle = 0.0;  // the plane angles of the planar set-ups with CONTACT's angle
  for (const SetUp set_up : {SetUp{"deepest", "tangent", "planar"}, SetUp{"deepest", "interpenetration-mean", "planar"},
                             SetUp{"interpenetration-centre", "interpenetration-mean", "planar"},
                             SetUp{"deepest", "interpenetration-mean", "conformal"}}) {
    const std::string rule = std::string(set_up.point) + " / " + set_up.angle + " / " + set_up.surface;
    const Table table =
        generate_table(parse_table_config(std::string("[solver]\nmode = \"wheel\"\nreference_point = \"") +
                                              set_up.point + "\"\nreference_angle = \"" + set_up.angle +
                                              "\"\nsurface = \"" + set_up.surface +
                                              "\"\n[axes]\nlateral_displacement_m = { start = -7e-3, "
                                              "stop = 7e-3, step = 7e-3 }\nvertical_load_N = 78.5e3\n",
                                          "flange.toml"),
                       GeneratorInfo{});
    const std::size_t k = table.patch_index(2, 0, 0, 1);
    ASSERT_EQ(table.patch.present[k], 1) << rule;
    EXPECT_LT(table.patch.plane_angle_rad[k], -0.5) << rule;   // steep gauge-side contact plane
    EXPECT_GT(table.patch.force_lateral_N[k], 0.0) << rule;    // + towards the field side
    EXPECT_GT(table.patch.force_vertical_N[k], 0.0) << rule;   // + down
    EXPECT_LT(table.patch.contact_angle_rad[k], 0.0) << rule;  // negative on the gauge side
    // s = 0 lies on the rail at the reference point. The tangent: the plane is tangent there (rail slope =
    // tan(plane angle)); CONTACT's angle: the mean inclination over the interpenetration region, on the flank within
    // 0.4 deg of the tangent at its centre (measured 0.37 deg here), and the same at the deepest point as at the
    // centre. The conformal surface's s = 0 is above CONTACT's reference point too (its strips centred there).
    const bool tangent = std::string(set_up.angle) == "tangent";
    const bool conformal = std::string(set_up.surface) == "conformal";
    const bool centre = std::string(set_up.point) == "interpenetration-centre" || conformal;
    const ProfileTable rail = load_profile("UIC60", ProfileRole::Rail, {});
    for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
      const std::size_t q = table.patch_index(2, 0, 0, slot);
      if (!table.patch.present[q]) continue;
      const ProfilePoint at = rail.at(table.patch.s_origin_y_rail_m[q]);
      if (tangent || centre) {
        EXPECT_NEAR(std::atan(at.dz), table.patch.plane_angle_rad[q], tangent ? 1e-9 : 0.4 * std::numbers::pi / 180.0)
            << rule << " slot " << slot;
      }
      EXPECT_DOUBLE_EQ(at.z, table.patch.s_origin_z_rail_m[q]) << rule;
    }
    if (!conformal) (centre ? centres_angle : contacts_angle) = table.patch.plane_angle_rad[k];
  }
  // the same angle at the deepest point as at the centre (built-in profiles, dy 7 mm: measured 0.033 deg apart, the
  // approaches they settle at differ with their strip grids)
  EXPECT_NEAR(contacts_angle, centres_angle, 0.05 * std::numbers::pi / 180.0);
}

TEST(Table, MorePatchesThanSlotsIsASlotOverflowNotALostForce) {
  // One slot: the two-patch case (dy = 5 mm: tread and flange) overflows and keeps no patch. (A lone flange patch
  // fits the one slot: slot_assignment_test.)
  const Table table = generate_table(parse_table_config(R"(
[solver]
mode = "wheel"
[axes]
lateral_displacement_m = { start = -5e-3, stop = 5e-3, step = 5e-3 }
vertical_load_N = 78.5e3
[output]
patch_slots = 1
)",
                                                        "one_slot.toml"),
                                     GeneratorInfo{});
  EXPECT_EQ(table.n_slots, 1u);
  EXPECT_EQ(table.status[table.wheel_index(2, 0, 0)], CaseStatus::SlotOverflow);
  EXPECT_EQ(table.patch.present[table.patch_index(2, 0, 0, 0)], 0);
  EXPECT_EQ(table.status[table.wheel_index(1, 0, 0)], CaseStatus::Converged);  // dy = 0: tread only
}

TEST(Table, SolveTableCaseEqualsTheTable) {
  const TableConfig config = parse_table_config(kSmallConfig, "small.toml");
  const SweepSetup setup = make_sweep_setup(config);
  const Table& table = small_table(1);
  const std::size_t i_dy = 12;
  const CaseSolution solution = solve_table_case(setup, table.lateral_displacement_m[i_dy], 78.5e3);
  EXPECT_EQ(solution.roll.roll_rad, table.roll_rad[i_dy * 2 + 1]);
  Table one = table;
  store_case_wheel(one, setup, i_dy, 1, 0, solution.wheels[0]);
  for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
    const std::size_t k = table.patch_index(i_dy, 1, 0, slot);
    EXPECT_EQ(one.patch.normal_force_N[k], table.patch.normal_force_N[k]);
    EXPECT_EQ(one.patch.force_lateral_N[k], table.patch.force_lateral_N[k]);
  }
}
