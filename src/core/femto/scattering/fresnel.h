#pragma once
// Fresnel reflectance of smooth interfaces, refraction in the local shading
// frame (normal = +z), and a table of conductor optical constants. Shared by
// every BSDF that has a dielectric or conductor boundary (smooth and rough).
//
// Conventions (as Mitsuba 3): `eta` is the relative index of refraction of
// the interface, interior over exterior (int_ior / ext_ior); the interior is
// on the -z side. A cosine < 0 means the direction is on the interior side.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto {

/// Unpolarised Fresnel reflectance of a smooth dielectric interface (the
/// average of the s- and p-polarised Fresnel equations; Born & Wolf,
/// "Principles of Optics", sec. 1.5.2; pbrt-v4 sec. 9.3; Walter et al. 2007,
/// "Microfacet Models for Refraction through Rough Surfaces", eq. 22 is the
/// same quantity). `cosThetaI` is the cosine of the incident direction with
/// the normal and may be negative (arriving from the interior). Returns R and
/// sets `cosThetaT` to the cosine of the transmitted direction, which points
/// to the other side: its sign is opposite to cosThetaI's. Total internal
/// reflection gives R = 1 and cosThetaT = 0.
float fresnelDielectric(float cosThetaI, float eta, float& cosThetaT);
/// As above, without the transmitted cosine.
float fresnelDielectric(float cosThetaI, float eta);

/// Exact unpolarised Fresnel reflectance of a conductor with complex index of
/// refraction eta + i k (relative to the exterior), per colour channel.
/// Standard closed form of the s and p amplitudes for absorbing media
/// (Born & Wolf sec. 14.2; the arrangement of terms follows pbrt-v3
/// `FrConductor`). cosThetaI is clamped to [0, 1] (conductors are opaque).
Color3f fresnelConductor(float cosThetaI, const Color3f& eta, const Color3f& k);

/// Direction refracted about the +z normal: wi points away from the surface,
/// cosThetaT is the value fresnelDielectric returned for wi.z and the same
/// `eta` (interior over exterior). The result points away from the surface on
/// the other side. (Snell's law in vector form, as Mitsuba 3's `refract`.)
Vec3f refract(const Vec3f& wi, float cosThetaT, float eta);
/// Refraction about an arbitrary unit normal `m` (a microfacet normal on the
/// exterior side, m.z > 0): cosThetaT is fresnelDielectric(dot(wi, m), eta, .).
Vec3f refract(const Vec3f& wi, const Vec3f& m, float cosThetaT, float eta);

/// Hemispherical, cosine-weighted average of the dielectric Fresnel
/// reflectance, 2 * integral_0^1 R(mu) mu dmu, for light arriving from the
/// side where the relative index (other side over this side) is `eta`. So
/// fresnelDiffuseReflectance(1.5) ~ 0.092 (outside of glass) and
/// fresnelDiffuseReflectance(1/1.5) ~ 0.596 (inside, with total internal
/// reflection). Polynomial fits: eta < 1 Egan & Hilgeman 1979 ("Optical
/// Properties of Inhomogeneous Materials", as quoted by Jensen et al. 2001),
/// eta >= 1 d'Eon & Irving 2011 ("A Quantized-Diffusion Model for Rendering
/// Translucent Materials", eq. for the first moment of R); both < 1% off for
/// common indices (tested against numerical integration).
float fresnelDiffuseReflectance(float eta);

/// RGB complex index of refraction (eta, k) of a named conductor (Mitsuba's
/// material names: "Ag", "Al", "Au", "Cu", "Cr", "Hg", "Ni", ...; "none" is a
/// perfect mirror, eta = 0, k = 1 giving R = 1). nullopt for unknown names.
std::optional<std::pair<Color3f, Color3f>> lookupConductor(std::string_view name);
/// The names lookupConductor knows.
std::vector<std::string> knownConductorNames();

}  // namespace femto
