// SPDX-License-Identifier: Apache-2.0
#include "ctab/sweep/batch_manifest.hpp"

#include <glob.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "ctab/core/error.hpp"
#include "ctab/profiles/builtin_profiles.hpp"
#include "toml_input.hpp"

namespace ctab::gen {

namespace {

namespace fs = std::filesystem;

struct ManifestReader {
  std::string source;
  std::string directory;

  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& what) const {
    detail::fail_at(source, node, key, what);
  }

  std::string resolve(const std::string& spec) const {
    if (is_builtin_profile(spec) || fs::path(spec).is_absolute()) return spec;
    return (fs::path(directory) / spec).lexically_normal().string();
  }

  // A file, a glob (sorted matches; none is an error) or a built-in name.
  std::vector<std::string> expand(const toml::node& node, const std::string& key) const {
    const auto spec = node.value<std::string>();
    if (!spec || spec->empty()) fail(node, key, "expected a profile file, glob or built-in name (a non-empty string)");
    if (spec->find_first_of("*?[") == std::string::npos) return {resolve(*spec)};
    const std::string pattern = resolve(*spec);
    glob_t matches{};
    const int result = ::glob(pattern.c_str(), 0, nullptr, &matches);
    std::vector<std::string> files(matches.gl_pathv, matches.gl_pathv + (result == 0 ? matches.gl_pathc : 0));
    ::globfree(&matches);
    if (files.empty()) fail(node, key, "the glob '" + *spec + "' matches no file");
    return files;
  }

  std::vector<std::string> profile_list(const toml::node* node, const std::string& key) const {
    const toml::array* list = node ? node->as_array() : nullptr;
    if (!list || list->empty()) {
      if (!node)
        throw InputError(source, 0, "'" + key + "': missing (a list of profile files, globs or built-in names)");
      fail(*node, key, "expected a non-empty list of profile files, globs or built-in names");
    }
    std::vector<std::string> specs;
    for (const toml::node& item : *list) {
      const std::vector<std::string> expanded = expand(item, key);
      specs.insert(specs.end(), expanded.begin(), expanded.end());
    }
    return specs;
  }
};

std::string stem_of(const std::string& spec) {
  std::string stem = is_builtin_profile(spec) ? spec : fs::path(spec).stem().string();
  for (char& c : stem)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '_';
  return stem;
}

}  // namespace

BatchManifest parse_batch_manifest(const std::string& text, const std::string& source, const std::string& directory) {
  const toml::table root = detail::parse_toml(text, source);
  const ManifestReader r{source, directory};
  for (const auto& [key, node] : root) {
    const std::string name(key.str());
    if (name != "config" && name != "wheels" && name != "rails" && name != "pairing" && name != "pairs")
      r.fail(node, name, "unknown key (expected config, wheels, rails, pairing, pairs)");
  }
  BatchManifest manifest;
  manifest.source = source;
  if (const toml::node* config = root.get("config")) {
    const auto path = config->value<std::string>();
    if (!path || path->empty()) r.fail(*config, "config", "expected the path of a table config (a string)");
    manifest.base = read_table_config(r.resolve(*path));
  } else {
    manifest.base = parse_table_config(kDefaultTableConfig, "default config");
  }
  std::string pairing = "all";
  if (const toml::node* node = root.get("pairing")) {
    const auto value = node->value<std::string>();
    if (!value || (*value != "all" && *value != "listed")) r.fail(*node, "pairing", "expected \"all\" or \"listed\"");
    pairing = *value;
  }
  if (pairing == "all") {
    if (const toml::node* pairs = root.get("pairs")) r.fail(*pairs, "pairs", "only with pairing = \"listed\"");
    const std::vector<std::string> wheels = r.profile_list(root.get("wheels"), "wheels");
    const std::vector<std::string> rails = r.profile_list(root.get("rails"), "rails");
    if (wheels.size() * rails.size() > kMaxBatchPairs)
      r.fail(*root.get("wheels"), "wheels", "more than " + std::to_string(kMaxBatchPairs) + " pairs");
    for (const std::string& wheel : wheels)
      for (const std::string& rail : rails) manifest.pairs.push_back({wheel, rail, ""});
  } else {
    for (const char* key : {"wheels", "rails"})
      if (const toml::node* node = root.get(key)) r.fail(*node, key, "not with pairing = \"listed\" (list the pairs)");
    const toml::node* node = root.get("pairs");
    const toml::array* list = node ? node->as_array() : nullptr;
    if (!list || list->empty() || list->size() > kMaxBatchPairs) {
      if (!node) throw InputError(source, 0, "'pairs': missing (pairing = \"listed\" needs [[wheel, rail], ...])");
      r.fail(*node, "pairs",
             "expected a non-empty list (at most " + std::to_string(kMaxBatchPairs) + ") of [wheel, rail]");
    }
    for (const toml::node& item : *list) {
      const toml::array* pair = item.as_array();
      if (!pair || pair->size() != 2 || !(*pair)[0].is_string() || !(*pair)[1].is_string())
        r.fail(item, "pairs", "expected [wheel, rail] (two strings)");
      const std::string wheel = *(*pair)[0].value<std::string>(), rail = *(*pair)[1].value<std::string>();
      if (wheel.find_first_of("*?[") != std::string::npos || rail.find_first_of("*?[") != std::string::npos)
        r.fail(item, "pairs", "listed pairs take files or built-in names, not globs");
      manifest.pairs.push_back({r.resolve(wheel), r.resolve(rail), ""});
    }
  }
  std::map<std::string, const ProfilePair*> names;
  for (ProfilePair& pair : manifest.pairs) {
    pair.table_name = stem_of(pair.wheel) + "__" + stem_of(pair.rail) + ".h5";
    if (const auto [at, inserted] = names.emplace(pair.table_name, &pair); !inserted)
      throw InputError(source, 0,
                       "two pairs make the table name " + pair.table_name + ": (" + at->second->wheel + ", " +
                           at->second->rail + ") and (" + pair.wheel + ", " + pair.rail + "); rename a profile file");
  }
  return manifest;
}

BatchManifest read_batch_manifest(const std::string& path) {
  return parse_batch_manifest(detail::read_toml_file(path, "manifest"), path, fs::path(path).parent_path().string());
}

TableConfig pair_config(const BatchManifest& manifest, const ProfilePair& pair) {
  TableConfig config = manifest.base;
  config.wheel = pair.wheel;
  config.rail = pair.rail;
  return config;
}

}  // namespace ctab::gen
