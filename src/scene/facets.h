// The facets normal pattern: flat facets from crackle's cells, matched to
// the normals povray 3.7 renders (recovered from lit renders to 1e-3).
// A point q — the surface point in coords mode, the unit normal otherwise,
// so that facets follow the curvature whatever the object's size — is
// scaled by 1 / size and the nearest of crackle's feature points f found.
//  - coords C: the normal gets C times the vector noise at f, less its
//    part along the normal (flat facets on flat surfaces);
//  - otherwise the normal snaps to the direction of f (a perturbed grid of
//    normal directions).
// povray ignores the normal's bump size for facets (measured).
#pragma once

#include "util/vec3.h"

namespace frameray::scene {

struct FacetsSettings {
    double coords = 0;  // `coords C`: facets of the point, tilted by C (0: size mode)
    double size = 0.1;  // `size S`: the cell size
};

// The facetted normal (not normalised) for the unit pattern-space normal n
// at pattern-space point p, with distance metric `metric` (crackle's
// keyword).
Vec3 facetsNormal(const Vec3& p, const Vec3& n, const FacetsSettings& s, double metric);

}  // namespace frameray::scene
