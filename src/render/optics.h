// The formulas of POV-Ray 3.7's surface optics, kept apart from the tracer
// so they can be tested on their own: how much a surface mirrors, how a
// ray bends at a change of ior, how metallic surfaces tint, and how light
// fades inside an interior. Each was measured against the reference
// renderer (see tests/unit/optics_test.cpp).
#pragma once

#include <optional>

#include "scene/interior.h"
#include "scene/object.h"
#include "scene/texture.h"
#include "util/color.h"
#include "util/vec3.h"

namespace frameray::render {

// Unpolarised Fresnel reflectance for a ray meeting a surface at an angle
// whose cosine is `cosIncidence`, going from a medium of ior n1 into one of
// ior n2 (`relativeIor` = n2 / n1). 1 under total internal reflection.
double fresnelReflectance(double cosIncidence, double relativeIor);

// povray's empirical Fresnel curve for metals, as a function of the angle
// between the normal and a direction (its cosine): 0 head-on, rising to 1
// at grazing angles. Used to tint highlights and reflections.
double metallicFresnel(double cosAngle);

// The tint a metallic amount gives light of any colour leaving a surface
// of colour `pigment`: toward the pigment head-on, toward white at
// grazing angles.
RGB metallicTint(double metallic, double cosAngle, const RGB& pigment);

// How much of the mirrored ray a finish adds at this angle (per channel);
// `variationScale` scales the part above the minimum (interior fading).
RGB reflectance(const scene::Reflection& r, double cosIncidence, double relativeIor,
                const RGB& pigment, const RGB& variationScale = RGB(1.0));

// The direction of a unit ray `d` refracted at a surface with unit normal
// `n` facing against d, going from ior n1 to n2 (`eta` = n1 / n2); empty
// under total internal reflection.
std::optional<Vec3> refractedDirection(const Vec3& d, const Vec3& n, double eta);

// The factor by which light crossing `distance` inside `interior` is
// multiplied (1 when the interior does not fade).
RGB interiorFade(const scene::Interior& interior, double distance);

// irid's film thickness at world point p: thickness * (1 + turbulence *
// (2 T(p) - 1)), T being povray's 5-octave noise turbulence (omega 0.5,
// lambda 2) in world space (measured: exact to 1e-5 on a flat plane,
// unmoved by the object's transformations).
double iridFilmThickness(const scene::Iridescence& irid, const Vec3& p);

// The tint irid gives light arriving at cosine cosLight and leaving toward
// the viewer at cosine cosView, per channel of wavelength w:
// 1 + amount * cos(2 pi thickness (cosView + cosLight) / w) (measured;
// it scales diffuse light and highlights, not ambient).
RGB iridTint(double amount, double thickness, const RGB& wavelength, double cosView,
             double cosLight);

// povray's fake caustics: the factor by which light passing through the
// surface of `obj` at p along `dir` (a shadow ray) is brightened,
// 1 + |cos|^(45 * caustics), cos between dir and the surface's normal
// turned against dir and then perturbed by the texture's normal (measured:
// doubles the light head-on at any caustics value; a bumpy box matches
// only with the normal turned before the perturbation). 1 when the
// object's interior has no caustics.
double fakeCaustics(const scene::Object& obj, const Vec3& p, const Vec3& dir);

// Per channel max(c, 0)^(1 / exponent): reflection { exponent E }.
RGB reflectionExponent(const RGB& c, double exponent);

}  // namespace frameray::render
