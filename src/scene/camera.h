// The camera (seed 003 §5.5, POV-Ray 3.7 camera types): parsed settings,
// and how angle, look_at and transformations turn them into the final
// frame of vectors that primary rays are built from (render/camera_rays.h).
#pragma once

#include <memory>
#include <optional>

#include "scene/normals.h"
#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

enum class Projection {
    Perspective,
    Orthographic,
    Fisheye,
    UltraWideAngle,
    Omnimax,
    Panoramic,
    Cylinder1,  // vertical cylinder, fixed viewpoint
    Cylinder2,  // horizontal cylinder, fixed viewpoint
    Cylinder3,  // vertical cylinder, viewpoint moving along the axis
    Cylinder4,  // horizontal cylinder, viewpoint moving along the axis
    Spherical,
    Mesh,  // mesh_camera: rays from mesh faces (scene/mesh_camera.h)
};

struct MeshCamera;

// focal_blur settings. Blur is on when aperture > 0 and blurSamples > 0.
struct FocalBlur {
    double aperture = 0;
    int minSamples = 0;   // `blur_samples MIN, MAX`: at least this many
    int blurSamples = 0;  // at most this many rays per sample
    Vec3 focalPoint{0, 0, 0};
    // Without focal_point povray focuses at the direction vector's length.
    bool focalPointGiven = false;
    double confidence = 0.9;
    double variance = 1.0 / 10000;  // povray 3.7 camera default (its docs say 1/128)

    bool enabled() const { return aperture > 0 && blurSamples > 0; }
};

struct Camera {
    Projection projection = Projection::Perspective;
    // POV-Ray's defaults; finalizeCamera() applies angle, look_at and the
    // transformations once the block is read.
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 up{0, 1, 0};
    Vec3 right{1.33, 0, 0};
    Vec3 sky{0, 1, 0};
    Vec3 lookAt{0, 0, 1};  // kept: an orthographic `angle` measures from here
    // Field of view in degrees for the angular projections (fisheye,
    // ultra_wide_angle, cylinders; spherical's horizontal angle).
    double angle = 90;
    double verticalAngle = 0;  // spherical only; 0 means half of `angle`
    FocalBlur blur;
    // `normal { }` in the camera: bends every primary ray as a surface
    // normal is bent, with the pattern evaluated on the image plane.
    std::shared_ptr<const Normal> normal;
    // mesh_camera's meshes and settings (Projection::Mesh only).
    std::shared_ptr<const MeshCamera> mesh;
};

// What a camera { } block set, beyond the plain vectors stored directly.
struct CameraEdits {
    std::optional<double> angle;  // `angle` given in this block
    bool lookAt = false;          // `look_at` given in this block
    // `right` or `up` given in this block, or the camera is a declared one:
    // an orthographic view keeps the size they give.
    bool sized = false;
    Transform transform;  // every transformation, in order
};

// The default field angle of each projection when none is given.
double defaultAngle(Projection projection);

// Applies what POV-Ray 3.7 applies after reading the block, in its order
// whatever the order in the file: the angle (perspective: direction
// length; orthographic: right and up lengths, which without angle, right
// and up are scaled to the perspective view's size at the look_at
// distance), then look_at (keeping the
// handedness of up/direction/right), then the transformations.
void finalizeCamera(Camera& camera, const CameraEdits& edits);

}  // namespace frameray::scene
