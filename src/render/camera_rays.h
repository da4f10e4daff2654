// Primary ray generation for every POV-Ray 3.7 projection. Built once per
// frame from the finished camera (scene/camera.h): the vectors each
// projection needs (normalised or not, as povray uses them) are prepared
// here so that generating a ray is a few multiplications.
#pragma once

#include <optional>
#include <vector>

#include "scene/camera.h"
#include "scene/ray.h"

namespace frameray::render {

class CameraRays {
  public:
    CameraRays(const scene::Camera& camera, int width, int height);

    // The ray through image-plane position (x, y), in pixels from the
    // image's top-left corner (pixel (i, j) spans [i, i+1) x [j, j+1)).
    // Empty where the projection traces nothing (outside a fisheye's
    // circle, at a panoramic's poles).
    std::optional<scene::Ray> generate(double x, double y) const;
    // The same ray before its direction is made unit length (a perspective
    // ray then reaches the image plane at parameter 1; focal blur aims
    // through it).
    std::optional<scene::Ray> generateUnnormalized(double x, double y) const;

    const scene::Camera& camera() const { return camera_; }

    // mesh_camera: the rays of the pixel holding image point (x, y) (none
    // past the faces); false for every other projection.
    bool meshRays(double x, double y, std::vector<scene::Ray>& rays) const;

  private:
    std::optional<scene::Ray> makeRay(double x, double y, bool unit) const;
    // The projection's ray, before a camera normal bends it; (cx, cy) is
    // the image-plane position centred on the image, in [-0.5, 0.5], y up.
    std::optional<scene::Ray> project(double cx, double cy) const;

    scene::Camera camera_;
    double width_, height_;
    // Unit direction, right and up; and |right| / |up|, the image aspect
    // the angular projections correct for.
    Vec3 unitDirection_, unitRight_, unitUp_;
    double rightLength_ = 1, upLength_ = 1, aspect_ = 1;
    double angleRadians_ = 0, verticalAngleRadians_ = 0;
};

}  // namespace frameray::render
