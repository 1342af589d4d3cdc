// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Exceptions of the generator. They are thrown only at setup and CLI boundaries (input files, options);
//! per-case solver outcomes are SolveStatus values, never exceptions.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace ctab::gen {

//! Base of every ctab generator exception.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Bad user input: names the source (file or option), the line (0 when not line based), and what was expected.
class InputError : public Error {
 public:
  InputError(std::string source, std::size_t line, const std::string& message);
  [[nodiscard]] const std::string& source() const noexcept { return source_; }
  [[nodiscard]] std::size_t line() const noexcept { return line_; }

 private:
  std::string source_;
  std::size_t line_;
};

}  // namespace ctab::gen
