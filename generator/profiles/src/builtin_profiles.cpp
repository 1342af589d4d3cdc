// SPDX-License-Identifier: Apache-2.0
#include "ctab/profiles/builtin_profiles.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <vector>

namespace ctab::gen {

namespace {

// S1002 section bounds [mm] and coefficients (facts/profiles.md 1.2, sources [N1][N2]).
constexpr double kBoundHG = -62.764705882, kBoundGF = -49.662510381, kBoundFE = -39.764473993, kBoundED = -38.426669071,
                 kBoundDC = -35.0, kBoundCB = -26.0, kBoundBA = 32.15796;
constexpr std::array<double, 9> kSectionB = {0.0,
                                             -3.358537058e-02,
                                             1.565681624e-03,
                                             -2.810427944e-05,
                                             5.844240864e-08,
                                             -1.562379023e-08,
                                             5.309217349e-15,
                                             -5.957839843e-12,
                                             2.646656573e-13};
constexpr std::array<double, 8> kSectionC = {-4.320221063e+03, -1.038384026e+03, -1.065501873e+02, -6.051367875,
                                             -2.054332446e-01, -4.169739389e-03, -4.687195829e-05, -2.252755540e-07};

template <std::size_t N>
S1002Value polynomial(const std::array<double, N>& c, double s, char section) {
  double f = 0, df = 0, d2f = 0;
  for (std::size_t k = N; k-- > 0;) {
    d2f = d2f * s + 2.0 * df;
    df = df * s + f;
    f = f * s + c[k];
  }
  return {f, df, d2f, section};
}

// F = a + sign * sqrt(r^2 - (S + c)^2)
S1002Value arc(double a, double r, double c, double sign, double s, char section) {
  const double u = s + c, root = std::sqrt(r * r - u * u);
  return {a + sign * root, -sign * u / root, -sign * r * r / (root * root * root), section};
}

class S1002Curve final : public ProfileCurve {
 public:
  [[nodiscard]] double t_begin() const override { return -69.6e-3; }
  [[nodiscard]] double t_end() const override { return 60.0e-3; }
  [[nodiscard]] CurvePoint at(double t) const override {
    const S1002Value v = s1002_mm(t * 1e3);
    return {t, v.f * 1e-3, 1.0, v.df, 0.0, v.d2f * 1e3};
  }
};

// A chain of arcs and lines in arc length (mm inside, SI outside).
class ArcLineChain final : public ProfileCurve {
 public:
  struct Segment {
    bool is_arc;
    double y0, z0;  // line: start point; arc: centre
    double a, b;    // line: unit direction (a, b); arc: radius a, start angle b (from -z, towards +y)
    double length;
  };
  void add_arc(double yc, double zc, double radius, double angle_begin, double angle_end) {
    segments_.push_back({true, yc, zc, radius, angle_begin, radius * (angle_end - angle_begin)});
  }
  void add_line(double y0, double z0, double dy, double dz, double length) {
    segments_.push_back({false, y0, z0, dy, dz, length});
  }
  [[nodiscard]] double t_begin() const override { return 0.0; }
  [[nodiscard]] double t_end() const override {
    double total = 0;
    for (const auto& s : segments_) total += s.length;
    return total * 1e-3;
  }
  [[nodiscard]] CurvePoint at(double t) const override {
    double u = t * 1e3;
    std::size_t i = 0;
    while (i + 1 < segments_.size() && u > segments_[i].length) u -= segments_[i++].length;
    const Segment& s = segments_[i];
    CurvePoint p;
    if (s.is_arc) {
      const double angle = s.b + u / s.a, c = std::cos(angle), sn = std::sin(angle);
      p = {s.y0 + s.a * sn, s.z0 - s.a * c, c, sn, -sn / s.a, c / s.a};
    } else {
      p = {s.y0 + s.a * u, s.z0 + s.b * u, s.a, s.b, 0.0, 0.0};
    }
    p.y *= 1e-3;
    p.z *= 1e-3;
    p.d2y *= 1e3;
    p.d2z *= 1e3;
    return p;
  }

 private:
  std::vector<Segment> segments_;
};

}  // namespace

S1002Value s1002_mm(double s) noexcept {
  if (s < kBoundHG) return arc(9.519259302, 20.5, 49.5, +1.0, s, 'H');
  if (s < kBoundGF) return arc(16.0, 12.0, 55.0, +1.0, s, 'G');
  if (s < kBoundFE) return arc(8.834924130, 20.0, 58.558326413, +1.0, s, 'F');
  if (s < kBoundED) return {-93.576667419 - 2.747477419 * s, -2.747477419, 0.0, 'E'};
  if (s < kBoundDC) return arc(16.446, 13.0, 26.210665, -1.0, s, 'D');
  if (s < kBoundCB) return polynomial(kSectionC, s, 'C');
  if (s < kBoundBA) return polynomial(kSectionB, s, 'B');
  return {1.364323640 - 0.066666667 * s, -0.066666667, 0.0, 'A'};
}

std::shared_ptr<const ProfileCurve> s1002_curve() { return std::make_shared<S1002Curve>(); }

std::shared_ptr<const ProfileCurve> uic60_curve() {
  // EN 13674-1 60E1 head [G1][R1]: tangent points at half-widths X1, X2; R13 ends on the 1:20 flank.
  constexpr double kR1 = 300.0, kR2 = 80.0, kR3 = 13.0, kX1 = 20.456 / 2, kX2 = 52.053 / 2, kFlankDepth = 37.5;
  const double phi1 = std::asin(kX1 / kR1);
  const double c2y = (kR1 - kR2) * std::sin(phi1), c2z = kR1 - (kR1 - kR2) * std::cos(phi1);
  const double phi2 = std::asin((kX2 - c2y) / kR2);
  const double c3y = c2y + (kR2 - kR3) * std::sin(phi2), c3z = c2z - (kR2 - kR3) * std::cos(phi2);
  const double phi3 = std::numbers::pi / 2 - std::atan(1.0 / 20.0);
  const double end_y = c3y + kR3 * std::sin(phi3), end_z = c3z - kR3 * std::cos(phi3);
  const double flank = (kFlankDepth - end_z) / std::sin(phi3);
  auto chain = std::make_shared<ArcLineChain>();
  chain->add_line(-(end_y + flank * std::cos(phi3)), kFlankDepth, std::cos(phi3), -std::sin(phi3), flank);
  chain->add_arc(-c3y, c3z, kR3, -phi3, -phi2);
  chain->add_arc(-c2y, c2z, kR2, -phi2, -phi1);
  chain->add_arc(0.0, kR1, kR1, -phi1, phi1);
  chain->add_arc(c2y, c2z, kR2, phi1, phi2);
  chain->add_arc(c3y, c3z, kR3, phi2, phi3);
  chain->add_line(end_y, end_z, std::cos(phi3), std::sin(phi3), flank);
  return chain;
}

std::shared_ptr<const ProfileCurve> uic60_inclined_curve(double inclination) {
  auto upright = uic60_curve();
  if (inclination == 0.0) return upright;
  // Gauge side (y < 0) down: rotation by -theta in TransformedCurve's sense, which moves the crown centre
  // (0, R) to (R sin theta, R cos theta); the highest point lies straight above it, at (R sin theta, R cos theta - R),
  // and becomes the origin.
  const double theta = std::atan(inclination), crown_radius = 0.300;
  return std::make_shared<TransformedCurve>(upright, -theta, -crown_radius * std::sin(theta),
                                            crown_radius * (1.0 - std::cos(theta)));
}

BuiltinProfile builtin_profile(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "s1002") return BuiltinProfile::S1002;
  if (lower == "uic60" || lower == "60e1") return BuiltinProfile::Uic60;
  return BuiltinProfile::None;
}

bool is_builtin_profile(const std::string& name) { return builtin_profile(name) != BuiltinProfile::None; }

}  // namespace ctab::gen
