// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/contact_method.hpp"

#include <array>

namespace ctab::gen {

namespace {

// Cheapest first (the order of --help and of error messages).
constexpr std::array kMethods{ContactMethod::Hertz, ContactMethod::Kp, ContactMethod::Analyn, ContactMethod::Mim1d,
                              ContactMethod::Bem2d};

}  // namespace

const char* method_name(ContactMethod method) noexcept {
  switch (method) {
    case ContactMethod::Mim1d: return "mim1d";
    case ContactMethod::Hertz: return "hertz";
    case ContactMethod::Kp: return "kp";
    case ContactMethod::Analyn: return "analyn";
    case ContactMethod::Bem2d: return "bem2d";
  }
  return "unknown";
}

std::optional<ContactMethod> parse_contact_method(std::string_view name) noexcept {
  for (const ContactMethod method : kMethods)
    if (name == method_name(method)) return method;
  return std::nullopt;
}

std::string contact_method_choices() {
  std::string text;
  for (const ContactMethod method : kMethods) {
    if (!text.empty()) text += ", ";
    text += method_name(method);
  }
  return text;
}

}  // namespace ctab::gen
