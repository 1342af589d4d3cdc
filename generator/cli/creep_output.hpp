// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The creep options of `ctab solve` and `ctab query` (--creepage XI,ETA,PHI --friction MU [--creep-method M]) and
//! their output: the creep forces of each patch (docs/creep.md), with the strip method's traction per strip.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ctab/contact/material.hpp"
#include "ctab/lookup/creep.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::cli {

struct CreepOptions {
  std::vector<double> creepage;  //!< xi, eta [-], phi [1/m]; empty: no creep forces
  double friction = 0.0;
  std::string method = "carter";
  [[nodiscard]] bool wanted() const { return !creepage.empty(); }
  //! The C input for both bodies of `material`.
  [[nodiscard]] ctab_creep_input input(const gen::ElasticMaterial& material) const;
};

//! Registers --creepage, --friction and --creep-method; each requires the other (checked after parsing).
void add_creep_options(CLI::App& app, CreepOptions& options);
//! After parsing: --creepage and --friction come together. Throws InputError.
void check_creep_options(const CreepOptions& options);

//! One patch's creep forces as JSON (forces on the rail, contact plane and side frame).
[[nodiscard]] nlohmann::json creep_json(const ctab_creep_patch& patch);
//! A solved patch's creep forces from its own strips (resampled evenly when they are not, at most
//! lookup::kMaxCreepStrips), as JSON with the traction per strip (s, fx and fs per unit width, slip fraction).
[[nodiscard]] nlohmann::json solved_patch_creep(const gen::ContactPatch& patch, const ctab_creep_input& input);
//! One line of text for a patch's creep forces.
void print_creep(const char* indent, const nlohmann::json& creep);

}  // namespace ctab::cli
