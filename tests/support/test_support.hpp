#pragma once
// Shared helpers for the tests: reference data paths and a small CSV reader for CONTACT's result files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ctab::test {

//! True when ../shared (CTAB_SHARED_DIR: reference data, profiles) is there.
inline bool shared_dir_present() { return std::filesystem::is_directory(CTAB_SHARED_DIR); }

//! Skips the current test (or, in SetUpTestSuite, the whole suite) when ../shared is absent: a clone without
//! the reference data still runs everything else. Such test executables carry the CTest label `shared`.
#define CTAB_REQUIRE_SHARED()                                                                      \
  do {                                                                                             \
    if (!::ctab::test::shared_dir_present()) GTEST_SKIP() << "no shared data at " CTAB_SHARED_DIR; \
  } while (false)

//! Path of a file under ../shared (reference data; tests only).
inline std::string shared_path(const std::string& relative) { return std::string(CTAB_SHARED_DIR) + "/" + relative; }
inline std::string source_path(const std::string& relative) { return std::string(CTAB_SOURCE_DIR) + "/" + relative; }

//! A CSV table with a header row, values kept as text.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  [[nodiscard]] std::size_t column(const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return c;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  [[nodiscard]] std::vector<double> numbers(const std::string& name) const {
    std::vector<double> out;
    const std::size_t c = column(name);
    for (const auto& row : rows) out.push_back(std::stod(row.at(c)));
    return out;
  }
};

//! Reads a CSV file (no quoted commas except in a last free-text column, which is ignored here).
inline CsvTable read_csv(const std::string& path) {
  CsvTable table;
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot open reference file " << path << " (is ../shared beside the checkout?)";
  std::string line;
  bool first = true;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) fields.push_back(field);
    if (first) {
      table.header = fields;
      first = false;
    } else {
      table.rows.push_back(fields);
    }
  }
  return table;
}

}  // namespace ctab::test
