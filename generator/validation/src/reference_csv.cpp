// SPDX-License-Identifier: Apache-2.0
// The CSV reader of reference_csv.hpp.
#include "ctab/validation/reference_csv.hpp"

#include <fstream>
#include <sstream>

#include "ctab/core/error.hpp"

namespace ctab::gen {

namespace {

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  for (std::string field; std::getline(ss, field, ',');) fields.push_back(field);
  return fields;
}

}  // namespace

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c] == name) return c;
  throw InputError(source, 1, "expected a column '" + name + "'");
}

std::vector<double> CsvTable::numbers(const std::string& name) const {
  const std::size_t c = column(name);
  std::vector<double> out;
  out.reserve(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (c >= rows[r].size())
      throw InputError(source, row_lines[r], "expected " + std::to_string(header.size()) + " columns");
    try {
      out.push_back(std::stod(rows[r][c]));
    } catch (const std::exception&) {
      throw InputError(source, row_lines[r], "expected a number in column '" + name + "'");
    }
  }
  return out;
}

CsvTable read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot be read");
  CsvTable table;
  table.source = path;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    if (table.header.empty()) {
      table.header = split_fields(line);
      continue;
    }
    table.rows.push_back(split_fields(line));
    table.row_lines.push_back(number);
  }
  return table;
}

}  // namespace ctab::gen
