// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The reader of CONTACT's result files (../shared/reference/contact/..., read by the tests and by
//! `ctab bench accuracy --reference DIR`) and of the benches' own CSV output: a header row, then rows of fields
//! separated by commas (no quoting), values kept as text. Throws InputError naming the file (and line) at setup.
#include <cstddef>
#include <string>
#include <vector>

namespace ctab::gen {

struct CsvTable {
  std::string source;                          //!< the file read
  std::vector<std::string> header;             //!< column names
  std::vector<std::vector<std::string>> rows;  //!< fields of each row after the header (empty lines skipped)
  std::vector<std::size_t> row_lines;          //!< the file's line number of each row

  //! Index of column `name`; throws InputError when the header has none.
  [[nodiscard]] std::size_t column(const std::string& name) const;
  //! Column `name` of every row as numbers; throws InputError naming the line of a missing or non-numeric field.
  [[nodiscard]] std::vector<double> numbers(const std::string& name) const;
};

//! Reads `path` (throws InputError when it cannot be read).
[[nodiscard]] CsvTable read_csv(const std::string& path);

}  // namespace ctab::gen
