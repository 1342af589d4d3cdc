#pragma once
//! Loading kinds, normal-contact methods and options of the wheel-rail contact (wheelrail_contact.hpp), free of
//! Eigen so that configurations can hold them.
#include <cstdint>
#include <optional>
#include <string_view>

#include "ctab/contact/bem2d_options.hpp"
#include "ctab/contact/contact_method.hpp"
#include "ctab/contact/mim1d_options.hpp"

namespace ctab::gen {

//! Wheel profile coordinate S [m] where the flange zone begins: S1002 sections C-H (EN 13715). A patch whose
//! contact point lies at S <= this is a flange patch, else a tread patch.
inline constexpr double kFlangeRootS_m = -0.026;

enum class LoadKind : std::int8_t {
  NormalForce = 0,    //!< total normal force [N]
  VerticalForce = 1,  //!< vertical wheel load [N]
  Approach = 2,       //!< vertical approach of the wheel beyond first contact [m]
};

//! The contact surface of a patch's strip problem (wheelrail_contact.hpp).
enum class ContactSurface : std::int8_t {
  Planar = 0,     //!< one plane tangent to the rail at the reference point; every strip has its normal
  Conformal = 1,  //!< a curved surface midway between rail and wheel, s its arc length, one normal per strip
};

//! The inclination of a patch's contact plane, its reference angle (WheelRailOptions::reference_angle).
enum class ReferenceAngle : std::int8_t {
  Tangent = 0,               //!< the rail's inclination at the reference point
  InterpenetrationMean = 1,  //!< CONTACT's: the mean of the rail's inclination over the interpenetration region
};

//! A contact reference point given from outside (WheelRailOptions::prescribed_reference).
struct PrescribedReference {
  double rail_y_m = 0.0;           //!< y on the rail profile [m]
  double contact_angle_rad = 0.0;  //!< inclination of the contact plane (negative on the gauge side) [rad]
};

//! The rung of the method ladder (contact_method.hpp); the earlier name, same values.
using NormalMethod = ContactMethod;

struct WheelRailOptions {
  NormalMethod method = NormalMethod::Mim1d;
  Mim1dOptions mim1d;             //!< strip width, curvature treatment, tolerances
  double sample_step_m = 0.1e-3;  //!< sampling of h(s) in the contact plane [m]
  //! Contact reference point (plane of the main patch): false = the deepest rigid point (the default, as the tables
  //! were validated); true = CONTACT's rule, the centre of the interpenetration region at the solved approach
  //! (weights pen^(5/2)), the plane inclined at the weighted mean of the rail's inclination over the region (a
  //! region spanning tread and flange root is one plane, as CONTACT combines them); it meets CONTACT's reference
  //! angle within 0.012 deg (flange_reference_test). On the flange flank (rail arc against the straight 70 deg wheel
  //! flank) the deepest point stays where the rail slope is -70 deg (-69.99 deg for every dy 6.7-7.6 mm, CONTACT
  //! -68.6 to -69.4 deg); on a flat tread it sits up to 3 mm from the centre (0.6 deg at dy 0). Not the default
  //! (README "Flange and flank": what switching it moves); the conformal surface at the deepest point (the default)
  //! centres its strips on this centre and keeps the deepest point as the contact point.
  bool reference_at_interpenetration_centre = false;
  //! Reference angle (config [solver] reference_angle, CLI --reference-angle); unset: InterpenetrationMean, CONTACT's
  //! reference angle (the default since the seventh session; Tangent with CONTACT's centre is invalid input).
  //! InterpenetrationMean at the deepest point: the plane through the deepest point inclined at CONTACT's reference
  //! angle, taken at each gap pass's sampling approach (no re-centring: a plane's gap does not depend on the point it
  //! passes through, only the strip grid's origin does). On CONTACT's flange cases it meets its force direction
  //! within 0.013 deg where the tangent (the rail's inclination at the deepest point, the earlier default) misses by
  //! up to 2.8 deg (README "Flange and flank").
  std::optional<ReferenceAngle> reference_angle;
  //! Whether the main patch's plane takes CONTACT's reference angle (the mean over the interpenetration region).
  [[nodiscard]] bool interpenetration_mean_angle() const noexcept {
    return reference_at_interpenetration_centre || reference_angle != ReferenceAngle::Tangent;
  }
  //! Contact surface (config [solver] surface, CLI --surface): conformal (the default since the eleventh session:
  //! CONTACT's conformal approach, D = 4, its strips centred on CONTACT's reference point; every CONTACT flange case
  //! within issue 8's targets) or planar (one plane per patch, 1.3-1.4x cheaper per table; README "Flange and
  //! flank").
  ContactSurface surface = ContactSurface::Conformal;
  //! bem2d's element placement in the patch frame (bem2d_options.hpp). CentresAtOrigin is CONTACT's wheel-rail grid
  //! (rows at s = k ds from the reference point, an element at x = 0); with CONTACT's reference point it is the
  //! like-for-like comparison with CONTACT (bem2d_wheelrail_test). Tables and `ctab bench accuracy` (at ctab's
  //! default deepest point) keep the edges at the origin.
  GridAlignment bem2d_alignment = GridAlignment::EdgesAtOrigin;
  //! bem2d's element length along x [m]; 0 = square elements of the strip width (MethodOptions).
  double bem2d_element_length_m = 0.0;
  //! The main patch's plane through the rail point at rail_y_m, inclined at contact_angle_rad, instead of ctab's
  //! own reference point (and no re-centring). For solving the same problem as another program: with CONTACT's
  //! reference point and angle from its output, bem2d is compared with CONTACT on identical geometry
  //! (bem2d_wheelrail_test). Planar surface only; a gap minimum outside the main patch's window still opens a patch
  //! of its own at its own reference point.
  std::optional<PrescribedReference> prescribed_reference;
};

//! Names of the contact surfaces (config [solver] surface, CLI --surface).
inline constexpr std::string_view kSurfacePlanar = "planar";
inline constexpr std::string_view kSurfaceConformal = "conformal";

//! "planar" / "conformal" -> the surface; else nullopt.
[[nodiscard]] inline std::optional<ContactSurface> parse_contact_surface(std::string_view name) noexcept {
  if (name == kSurfacePlanar) return ContactSurface::Planar;
  if (name == kSurfaceConformal) return ContactSurface::Conformal;
  return std::nullopt;
}

[[nodiscard]] inline std::string_view surface_name(ContactSurface surface) noexcept {
  return surface == ContactSurface::Conformal ? kSurfaceConformal : kSurfacePlanar;
}

//! Names of the contact reference point (config [solver] reference_point, CLI --reference-point).
inline constexpr std::string_view kReferencePointDeepest = "deepest";
inline constexpr std::string_view kReferencePointCentre = "interpenetration-centre";

//! "deepest" -> false, "interpenetration-centre" -> true (reference_at_interpenetration_centre); else nullopt.
[[nodiscard]] inline std::optional<bool> parse_reference_point(std::string_view name) noexcept {
  if (name == kReferencePointDeepest) return false;
  if (name == kReferencePointCentre) return true;
  return std::nullopt;
}

//! Names of the reference angle (config [solver] reference_angle, CLI --reference-angle).
inline constexpr std::string_view kReferenceAngleTangent = "tangent";
inline constexpr std::string_view kReferenceAngleMean = "interpenetration-mean";

//! "tangent" / "interpenetration-mean" -> the reference angle; else nullopt.
[[nodiscard]] inline std::optional<ReferenceAngle> parse_reference_angle(std::string_view name) noexcept {
  if (name == kReferenceAngleTangent) return ReferenceAngle::Tangent;
  if (name == kReferenceAngleMean) return ReferenceAngle::InterpenetrationMean;
  return std::nullopt;
}

//! The names of a reference point and angle as a table's provenance gives them (the angle resolved: unset is the
//! point's own).
[[nodiscard]] inline std::string_view reference_point_name(bool interpenetration_centre) noexcept {
  return interpenetration_centre ? kReferencePointCentre : kReferencePointDeepest;
}
[[nodiscard]] inline std::string_view reference_angle_name(const WheelRailOptions& options) noexcept {
  return options.interpenetration_mean_angle() ? kReferenceAngleMean : kReferenceAngleTangent;
}

}  // namespace ctab::gen
