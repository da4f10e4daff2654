#include "scene/camera.h"

#include <cmath>

namespace frameray::scene {

double defaultAngle(Projection projection) {
    // Measured from povray 3.7: every angular projection defaults to 90
    // degrees except spherical, which covers the whole sphere.
    return projection == Projection::Spherical ? 360.0 : 90.0;
}

namespace {

// povray's arithmetic, to the last bit: a vector is made unit length by
// multiplying with the reciprocal of its length, and half an angle in
// degrees becomes radians through the constant pi / 360. Primary rays then
// match povray's exactly, which decides on which side of a pattern's cell
// boundary a surface lying on it falls (a plane at y = 0 under quilted).
Vec3 unitByReciprocal(const Vec3& v) {
    const double l = length(v);
    return l > 0 ? v * (1.0 / l) : v;
}
constexpr double kPiOver360 = 0.00872664625997164788;

}  // namespace

void finalizeCamera(Camera& cam, const CameraEdits& edits) {
    if (edits.angle) {
        const double halfTan = std::tan(*edits.angle * kPiOver360);
        if (cam.projection == Projection::Perspective) {
            // The horizontal field of view sets the direction's length
            // relative to the right vector.
            cam.direction = unitByReciprocal(cam.direction) * (length(cam.right) / halfTan / 2.0);
        } else if (cam.projection == Projection::Orthographic) {
            // Same image area as a perspective camera of that angle has at
            // the look_at point (povray measures from the default look_at
            // <0,0,1> when none is given).
            const double width = 2.0 * halfTan * length(cam.lookAt - cam.location);
            const double aspect = length(cam.up) / length(cam.right);
            cam.right = normalize(cam.right) * width;
            cam.up = normalize(cam.up) * (width * aspect);
        }
    } else if (cam.projection == Projection::Orthographic && !edits.sized) {
        // Neither angle nor right/up: the view is as wide as the perspective
        // view (right/direction) at the look_at distance (measured: location
        // -4*z look_at 0 sees 1.33*4 units across, direction 2*z halves
        // that, no look_at measures to <0,0,1>, right or up given keeps them).
        const double scale = length(cam.lookAt - cam.location) / length(cam.direction);
        if (scale > 0) {
            cam.right = cam.right * scale;
            cam.up = cam.up * scale;
        }
    }
    if (edits.lookAt) {
        const double dirLength = length(cam.direction), upLength = length(cam.up),
                     rightLength = length(cam.right);
        // The sign of (up x direction) . right says whether the user set up
        // a left- or right-handed frame (seed 003 §5.5.4.2); keep it.
        const double handedness = dot(cross(cam.up, cam.direction), cam.right);
        const Vec3 dir = unitByReciprocal(cam.lookAt - cam.location);
        Vec3 right = cross(cam.sky, dir);
        // A sky parallel to the view keeps the previous right vector, as
        // povray does.
        if (length(right) < 1e-10) right = cam.right;
        right = unitByReciprocal(right);
        cam.direction = dir * dirLength;
        cam.right = right * (handedness > 0 ? rightLength : -rightLength);
        cam.up = cross(dir, right) * upLength;
    }
    if (!edits.transform.isIdentity()) {
        const Transform& t = edits.transform;
        cam.location = t.point(cam.location);
        cam.lookAt = t.point(cam.lookAt);
        cam.direction = t.direction(cam.direction);
        cam.right = t.direction(cam.right);
        cam.up = t.direction(cam.up);
        cam.sky = t.direction(cam.sky);
        cam.blur.focalPoint = t.point(cam.blur.focalPoint);
    }
}

}  // namespace frameray::scene
