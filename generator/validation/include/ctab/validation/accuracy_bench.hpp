// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The accuracy bench (`ctab bench accuracy`): every rung of the method ladder at several discretisations against a
//! reference, on three scenes:
//! - the Hertz sphere (reference: analytic Hertz);
//! - the non-Hertzian body (reference: bem2d at a fine mesh; CONTACT's row of the paper);
//! - a single wheel on its rail at 78.5 kN normal force from dy -6 to +8 mm (reference: bem2d at a fine mesh on
//!   every patch, through the sweep API; CONTACT's summary where the options hold it and the profiles are
//!   CONTACT's: its wheel-rail cases are the Manchester files, inclination 0).
//! Progress goes to stderr.
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ctab/sweep/table_config.hpp"
#include "ctab/validation/accuracy_metrics.hpp"

namespace ctab::gen {

//! CONTACT's figures of one case: area [m^2], max pressure [Pa], centre of pressure [m] (NaN: not given).
struct ContactFigures {
  double area_m2 = 0.0, max_pressure_Pa = 0.0;
  double centre_of_pressure_m = std::numeric_limits<double>::quiet_NaN();
};

//! CONTACT's wheel-rail cases by lateral shift [um].
using ContactCases = std::map<long, ContactFigures>;

//! CONTACT's wheel-rail rows under `dir` (wheelrail/summary.csv, wheelrail/flange/planar_normal_force.csv: one row
//! per patch), summed per lateral shift. Throws InputError naming the file (and line).
[[nodiscard]] ContactCases read_contact_wheelrail(const std::string& dir);

struct AccuracyBenchOptions {
  bool quick = false;  //!< fewer shifts, a coarser reference, fewer repeats (what the tests run)
  //! CONTACT's wheel-rail cases (read_contact_wheelrail); compared where the profiles are CONTACT's.
  std::optional<ContactCases> contact;
  TableConfig profiles;  //!< the wheel-rail scene's wheel, rail and inclination
};

//! Worst errors of one scene x region x rung over its cases.
struct AccuracyRow {
  std::string scene, region, method, reference;
  double width_m = 0.0;    //!< strip width / element size [m]; NaN for the least model (it chooses per case)
  double tolerance = 0.0;  //!< the least model's tolerance [-]; 0 for a fixed rung
  int cases = 0, failed = 0, contact_cases = 0;
  double time_sum_s = 0.0;          //!< the cases' times (each the minimum over its repeats) [s]
  std::vector<double> solve_times_s;  //!< every repeat of every case, for the timing spread [s]
  AccuracyErrors worst;
  //! Worst relative area and max-pressure errors and worst centre-of-pressure error [m] against CONTACT.
  double contact_area = 0.0, contact_pressure = 0.0, contact_point = std::numeric_limits<double>::quiet_NaN();

  //! Adds one case: its summary against the reference's, whether it succeeded, the times of its repeats [s] (at
  //! least one), CONTACT's figures.
  void add(const ContactSummary& candidate, const ContactSummary& reference_summary, bool ok,
           const std::vector<double>& times_s,
           const std::optional<ContactFigures>& contact);
};

//! Runs the three scenes; rows ordered by scene, region, method and discretisation.
[[nodiscard]] std::vector<AccuracyRow> run_accuracy_bench(const AccuracyBenchOptions& options);

//! CSV of the rows (header line first; SI units; empty field for NaN).
[[nodiscard]] std::string accuracy_csv(const std::vector<AccuracyRow>& rows);

//! Whether the profiles are CONTACT's wheel-rail ones (MBench_S1002_v3.prw on MBench_UIC60_v3.prr, inclination 0):
//! compared with other profiles CONTACT's figures would measure the profiles, not the methods.
[[nodiscard]] bool contact_profiles(const TableConfig& profiles);

}  // namespace ctab::gen
