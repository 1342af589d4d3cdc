#include "ctab/gen/error.hpp"

namespace ctab::gen {

namespace {
std::string format_input_error(const std::string& source, std::size_t line, const std::string& message) {
  std::string text = source;
  if (line > 0) text += ":" + std::to_string(line);
  return text + ": " + message;
}
}  // namespace

InputError::InputError(std::string source, std::size_t line, const std::string& message)
    : Error(format_input_error(source, line, message)), source_(std::move(source)), line_(line) {}

}  // namespace ctab::gen
