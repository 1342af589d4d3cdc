// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the profile readers (generator/io profile_io.hpp), every format. The first byte picks the
// format (by the file name's extension, as the reader does), the role and the options; the rest is the file. Point
// files with few points are also smoothed and tabulated (load_profile), as `ctab generate` does. InputError is the
// readers' answer to a bad file; anything else is a finding.
#include <array>
#include <cstdint>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/io/profile_io.hpp"
#include "fuzz_file.hpp"

namespace {

constexpr std::array<const char*, 6> kExtensions = {".prw", ".prr", ".whl", ".ban", ".txt", ".csv"};
// Smoothing costs O(points) with a large constant: a bound that keeps an execution in milliseconds.
constexpr std::size_t kMostPointsToSmooth = 400;

ctab::gen::ProfileReadOptions options_of(std::uint8_t code) {
  ctab::gen::ProfileReadOptions options;
  if (code & 0x01) options.mirror_y = (code & 0x02) != 0;
  if (code & 0x04) options.mirror_z = (code & 0x08) != 0;
  if (code & 0x10) options.length_unit_m = 1.0;  // metres instead of millimetres
  if (code & 0x20) options.inclination = 0.0;
  options.smoothing.automatic = (code & 0x40) == 0;
  if (code & 0x80) options.smoothing.prior = ctab::gen::CurvaturePrior::Arcs;
  return options;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::uint8_t format = data[0], option_bits = data[1];
  const auto role = (format & 0x80) ? ctab::gen::ProfileRole::Rail : ctab::gen::ProfileRole::Wheel;
  const std::string path = ctab::fuzz::scratch_path(kExtensions[(format & 0x7F) % kExtensions.size()]);
  ctab::fuzz::write_scratch(path, data + 2, size - 2);
  const ctab::gen::ProfileReadOptions options = options_of(option_bits);
  try {
    const ctab::gen::ProfilePoints points = ctab::gen::read_profile_points(path, role, options);
    if (points.y_m.size() <= kMostPointsToSmooth) {
      ctab::gen::ProfileSmoothing smoothing;
      static_cast<void>(ctab::gen::load_profile(path, role, options, smoothing));
    }
  } catch (const ctab::gen::InputError&) {
  }
  return 0;
}
