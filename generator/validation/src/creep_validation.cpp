// SPDX-License-Identifier: Apache-2.0
#include "ctab/validation/creep_validation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "ctab/core/error.hpp"
#include "ctab/lookup/creep.hpp"
#include "ctab/lookup/hdf5_table.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/validation/reference_csv.hpp"

namespace ctab::gen {

namespace {

constexpr double kVerticalLoad_N = 78.5e3;  // CONTACT's zfix loading

// The Manchester set-up in wheel mode, dy 0..7 mm, CONTACT's reference point, planar or conformal surface.
lookup::Table manchester_table(const std::string& profiles_dir, bool conformal) {
  std::ostringstream text;
  text << "[profiles]\nwheel = \"" << profiles_dir << "/MBench_S1002_v3.prw\"\nrail = \"" << profiles_dir
       << "/MBench_UIC60_v3.prr\"\ninclination = \"0\"\n"
       << "[track]\ngauge_m = 1.435\ngauge_height_m = 0.014\nflange_back_distance_m = 1.360\n"
       << "flange_back_position_m = -0.070\nnominal_radius_m = 0.460\n"
       << "[material]\nyoungs_modulus_Pa = 208e9\npoisson_ratio = 0.3\n"
       << "[solver]\nmode = \"wheel\"\nmethod = \"mim1d\"\nstrip_width_m = 0.2e-3\n"
       << "reference_point = \"interpenetration-centre\"\nsurface = \"" << (conformal ? "conformal" : "planar")
       << "\"\n[axes]\nlateral_displacement_m = { start = 0, stop = 7e-3, step = 0.5e-3 }\n"
       << "vertical_load_N = " << kVerticalLoad_N << "\n[output]\nstrip_samples = 32\n";
  const TableConfig config = parse_table_config(text.str(), "creep validation set-up");
  lookup::TableData data;
  const lookup::LoadResult converted = lookup::from_tables(generate_table(config, GeneratorInfo{}), data);
  lookup::Table table;
  if (!converted.ok() || !table.load(data, {}).ok())
    throw InputError("creep validation", 0, "the Manchester table did not load: " + converted.message);
  return table;
}

double error_of(const CreepReference& ref, double fx, double fs) {
  const double muN = ref.friction * ref.normal_force_N;
  if (ref.name.rfind("xi", 0) == 0 || ref.name.rfind("natxi", 0) == 0) return std::abs(fx - ref.fx_N) / muN;
  if (ref.name == "comb") return std::abs(std::hypot(fx, fs) - std::hypot(ref.fx_N, ref.fs_N)) / muN;
  return std::abs(fs - ref.fs_N) / muN;
}

CreepRow solve_case(const lookup::Table& table, const CreepReference& ref, int method) {
  ctab_location where;
  table.prelookup(ref.dy_m, kVerticalLoad_N, where);
  const ctab_creep_input input{ref.xi, ref.eta, ref.phi_per_m, ref.friction, 208e9, 0.3, method, 0};
  ctab_creep_result result;
  double times[15];
  for (double& t : times) {
    const auto start = std::chrono::steady_clock::now();
    (void)lookup::creep_query(table, where, 0, input, result);
    t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::nth_element(times, times + 7, times + 15);
  CreepRow row;
  row.reference = ref;
  row.method = method;
  row.time_s = times[7];
  double slip_area = 0.0, force = 0.0;
  for (int s = 0; s < result.n_slots; ++s) {
    const ctab_creep_patch& p = result.patch[s];
    row.fx_N += p.fx_N;
    row.fs_N += p.fs_N;
    row.mz_Nm += p.mz_Nm;
    slip_area += p.slip_fraction * p.normal_force_N;
    force += p.normal_force_N;
  }
  row.slip_fraction = force > 0.0 ? slip_area / force : 0.0;
  row.error_muN = error_of(ref, row.fx_N, row.fs_N);
  row.mz_error = std::abs(row.mz_Nm - ref.mz_Nm) / std::max(std::abs(ref.mz_Nm), 1e-9);
  return row;
}

const char* method_label(int method) {
  if (method == CTAB_CREEP_STRIPS_CARTER) return "carter-strips";
  return method == CTAB_CREEP_LINEAR ? "linear-ellipse" : method == CTAB_CREEP_FASTSIM_ELLIPSE ? "fastsim-ellipse"
                                                                                               : "fastsim-strips";
}

std::string kind_of(const std::string& name) { return name.substr(0, name.find('_')); }

}  // namespace

std::string CreepRow::region() const { return reference.dy_m < 5e-3 ? "tread" : "flange"; }

std::vector<CreepReference> read_creep_reference(const std::string& csv_path) {
  const CsvTable csv = read_csv(csv_path);
  const std::size_t name = csv.column("case");
  const std::vector<double> discns = csv.numbers("discns_D"), dy = csv.numbers("dy_mm"), xi = csv.numbers("cksi"),
                            eta = csv.numbers("ceta"), phi = csv.numbers("cphi_per_m"), fn = csv.numbers("FN_N"),
                            fx = csv.numbers("Fx_N"), fs = csv.numbers("Fs_N"), mz = csv.numbers("Mz_Nmm");
  std::vector<CreepReference> out;
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    out.push_back({csv.rows[r][name], discns[r] == 4, dy[r] * 1e-3, xi[r], eta[r], phi[r], fn[r], fx[r], fs[r],
                   mz[r] * 1e-3, 0.3});
  return out;
}

std::vector<CreepRow> run_creep_validation(const std::vector<CreepReference>& cases, const std::string& profiles_dir) {
  std::vector<CreepRow> rows;
  for (const bool conformal : {false, true}) {
    if (std::none_of(cases.begin(), cases.end(), [&](const CreepReference& c) { return c.conformal == conformal; }))
      continue;
    const lookup::Table table = manchester_table(profiles_dir, conformal);
    for (const CreepReference& ref : cases)
      if (ref.conformal == conformal)
        for (const int method :
             {CTAB_CREEP_LINEAR, CTAB_CREEP_FASTSIM_ELLIPSE, CTAB_CREEP_STRIPS, CTAB_CREEP_STRIPS_CARTER})
          rows.push_back(solve_case(table, ref, method));
  }
  return rows;
}

std::string creep_csv(const std::vector<CreepRow>& rows) {
  std::ostringstream out;
  out.precision(9);
  out << "surface,dy_m,case,xi,eta,phi_per_m,method,fx_N,fs_N,mz_Nm,slip_fraction,ref_fn_N,ref_fx_N,ref_fs_N,"
         "ref_mz_Nm,error_muN,mz_error,time_s\n";
  for (const CreepRow& r : rows) {
    const CreepReference& c = r.reference;
    out << (c.conformal ? "conformal" : "planar") << ',' << c.dy_m << ',' << c.name << ',' << c.xi << ',' << c.eta
        << ',' << c.phi_per_m << ',' << method_label(r.method) << ',' << r.fx_N << ',' << r.fs_N << ',' << r.mz_Nm
        << ',' << r.slip_fraction << ',' << c.normal_force_N << ',' << c.fx_N << ',' << c.fs_N << ',' << c.mz_Nm
        << ',' << r.error_muN << ',' << r.mz_error << ',' << r.time_s << '\n';
  }
  return out.str();
}

std::string creep_summary(const std::vector<CreepRow>& rows) {
  std::map<std::string, std::vector<const CreepRow*>> groups;
  for (const CreepRow& r : rows)
    groups[std::string(r.reference.conformal ? "conformal" : "planar") + " " + r.region() + " " +
           kind_of(r.reference.name) + " " + method_label(r.method)]
        .push_back(&r);
  std::ostringstream out;
  char line[200];
  std::snprintf(line, sizeof line, "%-44s %5s %10s %10s %10s %10s\n", "surface region kind method", "cases",
                "median/muN", "worst/muN", "worst Mz", "time [us]");
  out << line;
  for (auto& [key, group] : groups) {
    std::vector<double> e, t;
    double mz = 0.0;
    for (const CreepRow* r : group) e.push_back(r->error_muN), t.push_back(r->time_s), mz = std::max(mz, r->mz_error);
    std::sort(e.begin(), e.end());
    std::sort(t.begin(), t.end());
    std::snprintf(line, sizeof line, "%-44s %5zu %10.4f %10.4f %9.1f%% %10.2f\n", key.c_str(), group.size(),
                  e[e.size() / 2], e.back(), 100.0 * mz, 1e6 * t[t.size() / 2]);
    out << line;
  }
  return out.str();
}

}  // namespace ctab::gen
