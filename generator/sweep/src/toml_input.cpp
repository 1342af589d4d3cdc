// SPDX-License-Identifier: Apache-2.0
#include "toml_input.hpp"

#include <fstream>
#include <sstream>

#include "ctab/core/error.hpp"

namespace ctab::gen::detail {

std::string read_toml_file(const std::string& path, const std::string& kind) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open " + kind + " file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

toml::table parse_toml(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(source, static_cast<std::size_t>(e.source().begin.line),
                     "TOML syntax: " + std::string(e.description()));
  }
}

std::size_t line_of(const toml::node& node) { return static_cast<std::size_t>(node.source().begin.line); }

void fail_at(const std::string& source, const toml::node& node, const std::string& key, const std::string& message) {
  throw InputError(source, line_of(node), "'" + key + "': " + message);
}

}  // namespace ctab::gen::detail
