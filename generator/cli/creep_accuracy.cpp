// SPDX-License-Identifier: Apache-2.0
#include "creep_accuracy.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "ctab/core/error.hpp"
#include "ctab/validation/creep_validation.hpp"
#include "exit_codes.hpp"

namespace ctab::cli {

int run_creep_accuracy(const std::string& out_dir, const std::string& reference_dir) {
  const std::filesystem::path dir(reference_dir);
  const std::vector<gen::CreepReference> cases = gen::read_creep_reference((dir / "creep_zfix.csv").string());
  const std::string profiles = (dir / "../../../../profiles").lexically_normal().string();
  const std::vector<gen::CreepRow> rows = gen::run_creep_validation(cases, profiles);
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) throw IoError(out_dir + ": cannot create the output directory (" + error.message() + ")");
  const std::filesystem::path csv = std::filesystem::path(out_dir) / "creep.csv";
  {
    std::ofstream out(csv);
    out << gen::creep_csv(rows);
    out.flush();
    if (!out) throw IoError(csv.string() + ": cannot be written");
  }
  std::printf("%swrote %s (%zu rows)\n", gen::creep_summary(rows).c_str(), csv.c_str(), rows.size());
  std::printf("chart: /usr/bin/python3 scripts/creep_chart.py %s %s/creep\n", csv.c_str(), out_dir.c_str());
  return kExitSuccess;
}

}  // namespace ctab::cli
