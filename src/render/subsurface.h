// Subsurface light transport (finish { subsurface { translucency C } }
// with global_settings { subsurface { } }), the model POV-Ray 3.7 uses
// (Jensen et al. 2001, "A Practical Model for Subsurface Light Transport":
// a dipole diffusion term plus single scattering; facts read in povray's
// render/trace.cpp and lighting/subsurface.cpp, the code here is our own):
//
// - Lengths are in millimetres: scene units times global mm_per_unit.
// - translucency is, per channel, the reciprocal of the reduced scattering
//   coefficient s' (1/mm). The reduced albedo a' is the one whose diffuse
//   reflectance Rd(a') equals pigment * diffuse, found on a table of 101
//   values (Rd = 0, 0.01 .. 1) by inversion and read by linear
//   interpolation; then the extinction t' = s' / a' and absorption
//   a = t' - s'.
// - The lights' diffuse term is left out of such a finish: the light that
//   enters the surface near the point and comes out there takes its place.
//   Highlights, ambient, reflection stay.
// - Diffuse term: from a base point below the surface (one mean free path
//   1 / mean t' deep, or halfway to the far side when the object is
//   thinner than two of them) rays in D uniformly spread directions find
//   points of the object's surface; each point counts with the area it
//   stands for (4 pi r^2 / |cos|, cos at least 0.01) and adds each light
//   arriving there (cos_in times its shadowed colour) times the dipole's
//   diffuse reflectance times both surfaces' Fresnel transmittances; the
//   sum is divided by the number of points found.
// - Single scattering: S random depths along the refracted eye ray
//   (exponentially distributed with t'), each lit by the lights through the
//   point where the straight line to the light leaves the object.
// - Unscattered light: the refracted eye ray, dimmed by exp(-t' d), traced
//   on past the object's far side, refracted again.
// - Light seen under the surface of a second subsurface object takes one
//   sample of each kind; a third level none.
#pragma once

#include "util/color.h"

namespace frameray::render::subsurface {

// Fresnel transmittance of unpolarised light reaching a surface at
// `cosAngle` (to its normal), relative ior `eta`.
double fresnelTransmittance(double cosAngle, double eta);

// povray 3.7's approximation of the diffuse Fresnel reflectance F_dr.
double diffuseFresnelReflectance(double eta);

// The total diffuse reflectance Rd of a half-space of reduced albedo
// `alphaPrime` under uniform light, A = (1 + F_dr) / (1 - F_dr).
double diffuseReflectance(double A, double alphaPrime);

// The reduced albedo whose diffuse reflectance is `rd` (clamped to [0, 1])
// for a material of ior `ior`, as povray's 101-value table gives it.
double reducedAlbedo(double rd, double ior);

// The dipole's diffuse reflectance at `distSqr` mm^2 from the point of
// entry, for reduced scattering sPrime and absorption a (1/mm), with
// A = (1 + F_dr) / (1 - F_dr). Without the 1/pi factor (povray's lights
// already carry it).
double dipole(double distSqr, double sPrime, double a, double A);

}  // namespace frameray::render::subsurface
