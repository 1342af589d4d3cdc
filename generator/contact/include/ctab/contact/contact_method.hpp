// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The rungs of the method ladder (docs/method.md "The method ladder"), their names on the command line, in configs and in
//! table attributes. Eigen-free, so that configurations and the CLI can hold a method.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ctab::gen {

//! Normal-contact methods, cheapest first in accuracy terms. Explicit values: they are stored (configs, tables)
//! and must not change; tables that record only Mim1d = 0 or Hertz = 1 read the same.
enum class ContactMethod : std::int8_t {
  Mim1d = 0,   //!< MIM-1D strip solver (Qazi et al. 2022), mim1d.hpp
  Hertz = 1,   //!< one Hertz ellipse at the deepest point of the gap, hertz_strip.hpp
  Kp = 2,      //!< Kik-Piotrowski virtual penetration (Piotrowski & Kik 2008), kik_piotrowski.hpp
  Analyn = 3,  //!< ANALYN analytical surface-deformation correction (Sichani, Enblom & Berg 2014), analyn.hpp
  Bem2d = 4,   //!< 2-D boundary-element reference (Love elements, Polonsky-Keer CG, FFT), bem2d.hpp
};

//! "mim1d", "hertz", "kp", "analyn", "bem2d"; never null.
[[nodiscard]] const char* method_name(ContactMethod method) noexcept;

//! The method named `name` (exactly as method_name writes it), or nothing.
[[nodiscard]] std::optional<ContactMethod> parse_contact_method(std::string_view name) noexcept;

//! The accepted names for messages and --help: "hertz, kp, analyn, mim1d, bem2d".
[[nodiscard]] std::string contact_method_choices();

}  // namespace ctab::gen
