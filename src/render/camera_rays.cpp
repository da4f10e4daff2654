#include "render/camera_rays.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/mesh_camera.h"

namespace frameray::render {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kDegrees = kPi / 180.0;

// Omnimax: no formula is documented; fitted to povray 3.7's rays. The
// dome's centre sits kOmnimaxOffset (in units of the up vector's
// half-height) below the image centre and its rim is 1 + kOmnimaxOffset
// from it; the angle off the view axis is an odd quintic in the normalised
// radius (least-squares fit, max error 0.0006 radians; it reaches 90
// degrees at the rim).
constexpr double kOmnimaxOffset = 0.2834;
double omnimaxTheta(double rad) {
    const double r2 = rad * rad;
    return rad * (1.411269 + r2 * (-0.09439 + r2 * 0.25674));
}
}  // namespace

CameraRays::CameraRays(const scene::Camera& camera, int width, int height)
    : camera_(camera), width_(width), height_(height) {
    unitDirection_ = normalize(camera.direction);
    unitRight_ = normalize(camera.right);
    unitUp_ = normalize(camera.up);
    rightLength_ = length(camera.right);
    upLength_ = length(camera.up);
    aspect_ = upLength_ > 0 ? rightLength_ / upLength_ : 1.0;
    angleRadians_ = camera.angle * kDegrees;
    verticalAngleRadians_ =
        (camera.verticalAngle > 0 ? camera.verticalAngle : 0.5 * camera.angle) * kDegrees;
}

std::optional<scene::Ray> CameraRays::generate(double x, double y) const {
    return makeRay(x, y, true);
}

std::optional<scene::Ray> CameraRays::generateUnnormalized(double x, double y) const {
    return makeRay(x, y, false);
}

std::optional<scene::Ray> CameraRays::makeRay(double x, double y, bool unit) const {
    // Image-plane position centred on the image: [-0.5, 0.5], y up, with
    // povray's arithmetic to the last bit: its row coordinate counts from
    // the bottom, ((height - 1) - (y - 1)) / height - 0.5, and the
    // direction is made unit length at the end by multiplying with its
    // reciprocal length. A surface lying exactly on a pattern's cell
    // boundary (a plane at y = 0 under quilted) then falls on the side
    // povray's rounding puts it.
    const double cx = x / width_ - 0.5;
    const double cy = ((height_ - 1) - (y - 1)) / height_ - 0.5;
    std::optional<scene::Ray> ray = project(cx, cy);
    if (ray && unit) ray->direction = ray->direction * (1.0 / length(ray->direction));
    if (ray && camera_.normal) {
        // povray perturbs the unit ray direction like a surface normal, with
        // the normal pattern evaluated at the image-plane point (cx, cy, 0).
        const Vec3 unitDirection = normalize(ray->direction);
        ray->direction = camera_.normal->perturb(Vec3{cx, cy, 0}, unitDirection);
    }
    return ray;
}

bool CameraRays::meshRays(double x, double y, std::vector<scene::Ray>& rays) const {
    if (camera_.projection != scene::Projection::Mesh || !camera_.mesh) return false;
    camera_.mesh->pixelRays(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)),
                            static_cast<int>(width_), static_cast<int>(height_), rays);
    return true;
}

std::optional<scene::Ray> CameraRays::project(double cx, double cy) const {
    using scene::Projection;
    const scene::Camera& c = camera_;
    const Vec3 &d = unitDirection_, &r = unitRight_, &u = unitUp_;
    switch (c.projection) {
        case Projection::Perspective:
            return scene::Ray{c.location, c.direction + c.right * cx + c.up * cy};
        case Projection::Orthographic:
            return scene::Ray{c.location + c.right * cx + c.up * cy, c.direction};
        case Projection::Fisheye: {
            // A circle of the full angle's diameter, stretched by the right
            // and up lengths (measured: povray scales each axis by its
            // vector's length): the distance from the centre is the angle
            // off the view axis.
            const double px = 2 * cx * rightLength_, py = 2 * cy * upLength_;
            const double rad = std::hypot(px, py);
            if (rad > 1.0) return std::nullopt;
            const double phi = std::atan2(py, px);
            const double theta = rad * 0.5 * angleRadians_;
            const double st = std::sin(theta);
            return scene::Ray{c.location, d * std::cos(theta) + r * (st * std::cos(phi)) +
                                              u * (st * std::sin(phi))};
        }
        case Projection::UltraWideAngle: {
            const double ax = 2 * cx * 0.5 * angleRadians_;
            const double ay = 2 * cy * 0.5 * angleRadians_ / aspect_;
            return scene::Ray{c.location, d * (std::cos(ax) * std::cos(ay)) + r * std::sin(ax) +
                                              u * std::sin(ay)};
        }
        case Projection::Omnimax: {
            // Fitted to povray 3.7's output: a 180-degree dome. On a wide
            // image (right longer than up) its centre sits below the image
            // centre; on a square or tall one it is centred (measured).
            const double offset = rightLength_ > upLength_ ? kOmnimaxOffset : 0.0;
            const double px = 2 * cx * rightLength_;
            const double py = (2 * cy + offset) * upLength_;
            const double rad =
                std::hypot(px, py) / ((1 + offset) * std::min(rightLength_, upLength_));
            if (rad > 1.0) return std::nullopt;
            const double theta = omnimaxTheta(rad);
            const double phi = std::atan2(py, px);
            const double st = std::sin(theta);
            const double dirD = std::cos(theta), dirU = st * std::sin(phi);
            // Measured: nothing below the plane that bisects direction and
            // -up (the dome's floor, tilted 45 degrees).
            if (dirD + dirU < 0) return std::nullopt;
            return scene::Ray{c.location, d * dirD + r * (st * std::cos(phi)) + u * dirU};
        }
        case Projection::Panoramic: {
            // 180 degrees across, every row a cylinder section; right and
            // up keep their lengths.
            const double ax = (0.5 - cx) * kPi;
            const double ay = cy * kPi;
            const double cosY = std::cos(ay);
            if (std::abs(cosY) < 1e-10) return std::nullopt;
            return scene::Ray{c.location, c.direction * std::sin(ax) + c.right * std::cos(ax) +
                                              c.up * (std::sin(ay) / cosY)};
        }
        case Projection::Cylinder1: {
            const double ax = cx * angleRadians_;
            return scene::Ray{c.location, d * std::cos(ax) + r * std::sin(ax) + c.up * cy};
        }
        case Projection::Cylinder2: {
            const double ay = cy * angleRadians_;
            return scene::Ray{c.location, d * std::cos(ay) + c.right * cx + u * std::sin(ay)};
        }
        case Projection::Cylinder3: {
            const double ax = cx * angleRadians_;
            return scene::Ray{c.location + c.up * cy, d * std::cos(ax) + r * std::sin(ax)};
        }
        case Projection::Cylinder4: {
            const double ay = cy * angleRadians_;
            return scene::Ray{c.location + c.right * cx, d * std::cos(ay) + u * std::sin(ay)};
        }
        case Projection::Mesh:  // rays per pixel, not per image point: meshRays()
            return std::nullopt;
        case Projection::Spherical: {
            const double h = cx * angleRadians_;
            const double v = cy * verticalAngleRadians_;
            return scene::Ray{c.location,
                              (d * std::cos(h) + r * std::sin(h)) * std::cos(v) + u * std::sin(v)};
        }
    }
    return std::nullopt;
}

}  // namespace frameray::render
