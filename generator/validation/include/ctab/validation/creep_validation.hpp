// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The tangential ladder against CONTACT (`ctab bench accuracy --creep-reference DIR`, tests/lookup): CONTACT's
//! steady-rolling creep forces (wheelrail/tangential/creep_zfix.csv: Manchester profiles, right wheel, mu 0.3, the
//! normal problem held at the frictionless 78.5 kN vertical-load solution) against ctab's creep call fed ctab's own
//! normal solution of the same case: a table of the Manchester set-up in wheel mode (planar or conformal surface,
//! CONTACT's reference point), looked up at each shift and handed to ctab::lookup::creep_query.
#include <string>
#include <vector>

namespace ctab::gen {

//! One CONTACT case (SI units: moment in N m).
struct CreepReference {
  std::string name;          //!< xi_0p002, eta_0p001, phi_0p5, comb, ...
  bool conformal = false;    //!< discns_D 4 (else 2, planar)
  double dy_m = 0.0;
  double xi = 0.0, eta = 0.0, phi_per_m = 0.0;
  double normal_force_N = 0.0, fx_N = 0.0, fs_N = 0.0, mz_Nm = 0.0;
  double friction = 0.3;
};

//! Reads creep_zfix.csv (or creep_zfix_natural.csv). Throws InputError naming the file and line.
[[nodiscard]] std::vector<CreepReference> read_creep_reference(const std::string& csv_path);

//! One case solved by one method, with its errors.
struct CreepRow {
  CreepReference reference;
  int method = 0;           //!< ctab_creep_method
  double fx_N = 0.0, fs_N = 0.0, mz_Nm = 0.0, slip_fraction = 0.0;
  double error_muN = 0.0;   //!< pure xi: |dFx|, pure eta or phi: |dFs|, combined: ||F| - |F_ref||, over mu N_ref
  double mz_error = 0.0;    //!< |Mz - Mz_ref| / |Mz_ref|
  double time_s = 0.0;      //!< one creep call (median of repeats)
  [[nodiscard]] std::string region() const;  //!< "tread" (dy < 5 mm) or "flange"
};

//! Every reference case by every method (linear, ellipse FASTSIM, strips). `profiles_dir` holds
//! MBench_S1002_v3.prw and MBench_UIC60_v3.prr.
[[nodiscard]] std::vector<CreepRow> run_creep_validation(const std::vector<CreepReference>& cases,
                                                         const std::string& profiles_dir);

//! CSV of the rows (one per case and method; SI units).
[[nodiscard]] std::string creep_csv(const std::vector<CreepRow>& rows);
//! Per surface, region, case kind and method: median and worst error [mu N], worst Mz error, median time.
[[nodiscard]] std::string creep_summary(const std::vector<CreepRow>& rows);

}  // namespace ctab::gen
