// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The manifest of `ctab batch` (TOML): one base table config and the wheel and rail profiles to pair.
//!
//!   config = "base.toml"                 # optional (default: the embedded default config); relative to the manifest
//!   wheels = ["wheels/*.prw", "S1002"]   # files, globs (sorted matches) or built-in names
//!   rails  = ["UIC60", "rails/r1.prr"]
//!   pairing = "all"                      # every wheel with every rail (the default), or "listed":
//!   pairs = [["wheels/w1.prw", "UIC60"], ["wheels/w2.prw", "rails/r1.prr"]]   # (wheel, rail), no globs
//!
//! Paths are relative to the manifest. Each pair's table is named `<wheel stem>__<rail stem>.h5` (characters
//! other than letters, digits, '-', '_' and '.' become '_'). Unknown keys, wrong types, an empty list, a glob that
//! matches no file, `pairs` without pairing = "listed" (or the reverse) and two pairs with the same table name
//! give an InputError `manifest:line: 'key': what was expected`. Profile files are not read here: a bad profile
//! is that pair's failure, not the batch's.
#include <string>
#include <vector>

#include "ctab/sweep/table_config.hpp"

namespace ctab::gen {

//! Most pairs in one manifest. Chosen: a 1 000-wheel fleet on 10 rail profiles, with room to spare.
inline constexpr std::size_t kMaxBatchPairs = 100'000;

struct ProfilePair {
  std::string wheel, rail;  //!< built-in name or resolved path
  std::string table_name;   //!< file name of its table in the output directory
};

struct BatchManifest {
  std::string source;  //!< the manifest path (messages)
  TableConfig base;    //!< the base config (profiles replaced per pair)
  std::vector<ProfilePair> pairs;
};

//! Reads a manifest file; throws InputError.
[[nodiscard]] BatchManifest read_batch_manifest(const std::string& path);
//! Parses a manifest text; `directory` resolves relative paths; `source` names it in errors. Throws InputError.
[[nodiscard]] BatchManifest parse_batch_manifest(const std::string& text, const std::string& source,
                                                 const std::string& directory);
//! The base config with the pair's profiles.
[[nodiscard]] TableConfig pair_config(const BatchManifest& manifest, const ProfilePair& pair);

}  // namespace ctab::gen
