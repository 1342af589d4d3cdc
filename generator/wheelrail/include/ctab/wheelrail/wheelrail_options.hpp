// SPDX-License-Identifier: Apache-2.0
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

//! The inclination of a patch's contact plane as the config and CLI name it ([solver] reference_angle,
//! --reference-angle); with the reference point it makes the ReferenceRule.
enum class ReferenceAngle : std::int8_t {
  Tangent = 0,               //!< the rail's inclination at the reference point
  InterpenetrationMean = 1,  //!< CONTACT's: the mean of the rail's inclination over the interpenetration region
};

//! Where the main patch's contact plane lies and how it is inclined (WheelRailOptions::reference). CONTACT's
//! reference point is the centre of the interpenetration region at the solved approach (weights pen^(5/2)); its
//! reference angle is the weighted mean of the rail's inclination over that region (docs/method.md "Contact search
//! and patches"; docs/validation.md "Flange and flank" for what each rule moves against CONTACT).
enum class ReferenceRule : std::int8_t {
  //! The deepest rigid point, the plane tangent to the rail there.
  DeepestTangent = 0,
  //! The deepest rigid point, the plane inclined at CONTACT's reference angle, taken at each gap pass's sampling
  //! approach (the default: CONTACT's force direction within 0.013 deg on its flange cases, where the tangent misses
  //! by up to 2.8 deg). The conformal surface centres its strip grid on CONTACT's reference point.
  DeepestContactsAngle = 1,
  //! CONTACT's rule: the plane through CONTACT's reference point at CONTACT's reference angle (a region spanning
  //! tread and flange root is one plane, as CONTACT combines them).
  InterpenetrationCentre = 2,
  //! The point and angle of WheelRailOptions::prescribed_reference (planar surface only): for solving the same
  //! problem as another program, e.g. bem2d in CONTACT's own plane (bem2d_wheelrail_test).
  Prescribed = 3,
};

//! A contact reference point given from outside (WheelRailOptions::prescribed_reference).
struct PrescribedReference {
  double rail_y_m = 0.0;           //!< y on the rail profile [m]
  double contact_angle_rad = 0.0;  //!< inclination of the contact plane (negative on the gauge side) [rad]
};

//! The rung of the method ladder (contact_method.hpp).
using NormalMethod = ContactMethod;

struct WheelRailOptions {
  NormalMethod method = NormalMethod::Mim1d;
  Mim1dOptions mim1d;             //!< strip width, curvature treatment, tolerances
  double sample_step_m = 0.1e-3;  //!< sampling of h(s) in the contact plane [m]
  //! Contact reference point and angle of the main patch (config [solver] reference_point and reference_angle, CLI
  //! --reference-point and --reference-angle).
  ReferenceRule reference = ReferenceRule::DeepestContactsAngle;
  [[nodiscard]] bool at_interpenetration_centre() const noexcept {
    return reference == ReferenceRule::InterpenetrationCentre;
  }
  //! Whether the main patch's plane takes CONTACT's reference angle (the mean over the interpenetration region).
  [[nodiscard]] bool takes_contacts_angle() const noexcept {
    return reference == ReferenceRule::DeepestContactsAngle || reference == ReferenceRule::InterpenetrationCentre;
  }
  //! Contact surface (config [solver] surface, CLI --surface): conformal (the default: CONTACT's conformal approach,
  //! D = 4, its strips centred on CONTACT's reference point; every CONTACT flange case within the validation targets)
  //! or planar (one plane per patch, about 1.3x cheaper per table; docs/validation.md "Flange and flank").
  ContactSurface surface = ContactSurface::Conformal;
  //! bem2d's element placement in the patch frame (bem2d_options.hpp). CentresAtOrigin is CONTACT's wheel-rail grid
  //! (rows at s = k ds from the reference point, an element at x = 0); with CONTACT's reference point it is the
  //! like-for-like comparison with CONTACT (bem2d_wheelrail_test). Tables and `ctab bench accuracy` (at ctab's
  //! default deepest point) keep the edges at the origin.
  GridAlignment bem2d_alignment = GridAlignment::EdgesAtOrigin;
  //! bem2d's element length along x [m]; 0 = square elements of the strip width (MethodOptions).
  double bem2d_element_length_m = 0.0;
  //! The main patch's plane through this rail point at this angle where reference is ReferenceRule::Prescribed (no
  //! re-centring); a gap minimum outside the main patch's window still opens a patch at its own reference point.
  PrescribedReference prescribed_reference;
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

//! "deepest" -> false, "interpenetration-centre" -> true (CONTACT's reference point); else nullopt.
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

//! The rule of a reference point and an optional angle (unset: CONTACT's); nullopt for CONTACT's reference point
//! with the tangent, which is not a rule (CONTACT's point takes CONTACT's angle).
[[nodiscard]] inline std::optional<ReferenceRule> reference_rule(bool interpenetration_centre,
                                                                 std::optional<ReferenceAngle> angle) noexcept {
  const bool tangent = angle == ReferenceAngle::Tangent;
  if (interpenetration_centre) return tangent ? std::nullopt : std::optional(ReferenceRule::InterpenetrationCentre);
  return tangent ? ReferenceRule::DeepestTangent : ReferenceRule::DeepestContactsAngle;
}

//! The names of a rule's reference point and angle as the config and a table's provenance give them.
[[nodiscard]] inline std::string_view reference_point_name(ReferenceRule rule) noexcept {
  return rule == ReferenceRule::InterpenetrationCentre ? kReferencePointCentre : kReferencePointDeepest;
}
[[nodiscard]] inline std::string_view reference_angle_name(ReferenceRule rule) noexcept {
  return rule == ReferenceRule::DeepestTangent ? kReferenceAngleTangent : kReferenceAngleMean;
}

}  // namespace ctab::gen
