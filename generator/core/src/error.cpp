// SPDX-License-Identifier: Apache-2.0
#include "ctab/core/error.hpp"

#include <sstream>

namespace ctab::gen {

namespace {
std::string format_input_error(const std::string& source, std::size_t line, const std::string& message) {
  std::ostringstream text;
  text << source;
  if (line > 0) text << ':' << line;
  text << ": " << message;
  return text.str();
}
}  // namespace

InputError::InputError(std::string source, std::size_t line, const std::string& message)
    : Error(format_input_error(source, line, message)), source_(std::move(source)), line_(line) {}

}  // namespace ctab::gen
