// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading of the sweep's TOML inputs (the table config and the batch manifest): the file's text, the parse, and
// errors naming the file, the line and the key. Throws InputError (setup only).
#include <cstddef>
#include <string>
#include <toml++/toml.h>

namespace ctab::gen::detail {

//! The whole text of `path`; InputError(path, 0, "cannot open KIND file") when it cannot be read.
[[nodiscard]] std::string read_toml_file(const std::string& path, const std::string& kind);

//! The TOML document of `text` read from `source`; InputError(source, line, "TOML syntax: ...") on a syntax error.
[[nodiscard]] toml::table parse_toml(const std::string& text, const std::string& source);

//! The line of `node` in its file (1-based).
[[nodiscard]] std::size_t line_of(const toml::node& node);

//! Throws InputError(source, line of `node`, "'KEY': MESSAGE").
[[noreturn]] void fail_at(const std::string& source, const toml::node& node, const std::string& key,
                          const std::string& message);

}  // namespace ctab::gen::detail
