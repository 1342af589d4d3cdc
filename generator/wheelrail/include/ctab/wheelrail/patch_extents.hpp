// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The loaded patches of a solved wheel as the resolution rule (ctab/contact/resolution.hpp) measures them: the
//! sweep refines the strip width of a case whose patches span too few strips.
#include <vector>

#include "ctab/contact/resolution.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen {

//! The loaded patches' extents in their contact planes (resolution.hpp).
[[nodiscard]] std::vector<PatchExtent> patch_extents(const WheelContact& result);

}  // namespace ctab::gen
