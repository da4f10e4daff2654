// camera { } blocks (POV-Ray 3.7 syntax): an optional camera identifier to
// start from, an optional projection keyword (only first, as povray
// requires), then vectors, angle, look_at, focal blur settings and
// transformations in any order. What povray applies after the block
// (angle, look_at, transformations) is scene::finalizeCamera().
#include <fmt/format.h>

#include "scene/mesh_camera.h"
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// The projection a keyword names, if it is one (cylinder needs its number).
std::optional<scene::Projection> projectionKeyword(Keyword kw) {
    using scene::Projection;
    switch (kw) {
        case Keyword::kw_perspective:
            return Projection::Perspective;
        case Keyword::kw_orthographic:
            return Projection::Orthographic;
        case Keyword::kw_fisheye:
            return Projection::Fisheye;
        case Keyword::kw_ultra_wide_angle:
            return Projection::UltraWideAngle;
        case Keyword::kw_omnimax:
            return Projection::Omnimax;
        case Keyword::kw_panoramic:
            return Projection::Panoramic;
        case Keyword::kw_cylinder:
            return Projection::Cylinder1;
        case Keyword::kw_spherical:
            return Projection::Spherical;
        default:
            return std::nullopt;
    }
}

bool isUnsupportedCameraWord(const Token& t) {
    return t.text == "bokeh";
}

// camera { CAMERA_IDENTIFIER transformations }, at the identifier.
scene::Camera parseDeclaredCamera(Reader& r, const Token& first) {
    r.next();
    const Value v = r.identifierValue(first);
    const auto* cp = std::get_if<CameraPtr>(&v);
    if (!cp) r.fail(first, fmt::format("'{}' is a {}, not a camera", first.text, valueKindName(v)));
    scene::Camera cam = **cp;
    // povray 3.7 accepts only transformations after a camera identifier.
    scene::CameraEdits edits;
    edits.sized = true;  // the declared camera has its final size
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        Transform step;
        if (!r.parseTransformation(step)) {
            const Token t = r.peek();
            r.fail(t, fmt::format("only transformations may follow a camera identifier, found {}",
                                  describeToken(t)));
        }
        edits.transform = edits.transform.then(step);
    }
    scene::finalizeCamera(cam, edits);
    return cam;
}

}  // namespace

scene::Camera parseCamera(BuildContext& c) {
    Reader& r = c.reader;
    r.next();  // camera
    r.expect(Sym::LBrace, "'{' after 'camera'");
    scene::Camera cam;
    const Token first = r.peek();
    if (first.isIdentifier() && !isUnsupportedCameraWord(first) && first.text != "mesh_camera")
        return parseDeclaredCamera(r, first);
    const Token typeToken = r.peek();
    if (isUnsupportedCameraWord(typeToken)) r.unsupported(typeToken, std::string(typeToken.text));
    std::shared_ptr<scene::MeshCamera> meshCamera;
    if (typeToken.text == "mesh_camera") {
        r.next();
        meshCamera = parseMeshCamera(c, typeToken);
        cam.projection = scene::Projection::Mesh;
    } else if (const auto projection = projectionKeyword(typeToken.kw)) {
        r.next();
        cam.projection = *projection;
        if (*projection == scene::Projection::Cylinder1) {
            const double kind = r.parseFloat();
            const int n = static_cast<int>(kind);
            if (n < 1 || n > 4 || n != kind)
                r.fail(typeToken, "cylinder camera type must be 1, 2, 3 or 4");
            cam.projection = static_cast<scene::Projection>(
                static_cast<int>(scene::Projection::Cylinder1) + n - 1);
        }
        cam.angle = scene::defaultAngle(cam.projection);
        cam.verticalAngle = 0;
    }

    scene::CameraEdits edits;
    Token closing = r.peek();
    for (;;) {
        closing = r.peek();
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            edits.transform = edits.transform.then(step);
            continue;
        }
        if (isUnsupportedCameraWord(t)) r.unsupported(t, fmt::format("{} in camera", t.text));
        if (t.is(Keyword::kw_normal)) {
            cam.normal = parseNormal(c, cam.normal.get());
            continue;
        }
        r.next();
        if (projectionKeyword(t.kw))
            r.fail(t, "the camera type must come first in the camera block");
        switch (t.kw) {
            case Keyword::kw_location:
                cam.location = r.parseVec3();
                break;
            case Keyword::kw_direction:
                cam.direction = r.parseVec3();
                break;
            case Keyword::kw_right:
                cam.right = r.parseVec3();
                edits.sized = true;
                break;
            case Keyword::kw_up:
                cam.up = r.parseVec3();
                edits.sized = true;
                break;
            case Keyword::kw_sky:
                cam.sky = r.parseVec3();
                break;
            case Keyword::kw_look_at:
                cam.lookAt = r.parseVec3();
                edits.lookAt = true;
                break;
            case Keyword::kw_angle: {
                const double angle = r.parseFloat();
                if (angle <= 0) r.fail(t, "camera angle must be positive");
                if (cam.projection == scene::Projection::Perspective && angle >= 180)
                    r.fail(t, "a perspective camera's angle must be smaller than 180 degrees");
                edits.angle = angle;
                cam.angle = angle;
                cam.verticalAngle = 0;
                // spherical: `angle H, V`.
                if (r.accept(Sym::Comma)) {
                    const double vertical = r.parseFloat();
                    if (vertical <= 0) r.fail(t, "camera angle must be positive");
                    cam.verticalAngle = vertical;
                }
                break;
            }
            case Keyword::kw_aperture:
                cam.blur.aperture = r.parseFloat();
                break;
            case Keyword::kw_blur_samples: {
                // `blur_samples [MIN,] MAX`.
                int value = static_cast<int>(r.parseFloat());
                cam.blur.minSamples = 0;
                if (r.accept(Sym::Comma)) {
                    cam.blur.minSamples = value;
                    value = static_cast<int>(r.parseFloat());
                }
                if (value < 0 || cam.blur.minSamples > value) r.fail(t, "invalid blur_samples");
                cam.blur.blurSamples = value;
                break;
            }
            case Keyword::kw_focal_point:
                cam.blur.focalPoint = r.parseVec3();
                cam.blur.focalPointGiven = true;
                break;
            case Keyword::kw_confidence:
                cam.blur.confidence = r.parseFloat();
                break;
            case Keyword::kw_variance:
                cam.blur.variance = r.parseFloat();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in camera", t.text));
                r.fail(t,
                       fmt::format("expected a camera item or '}}', found {}", describeToken(t)));
        }
    }
    if (edits.lookAt && length(cam.lookAt - cam.location) < 1e-10)
        r.fail(closing, "camera location and look_at point must be different");
    if (meshCamera) {
        // Only location's and direction's z count, as written (measured).
        meshCamera->startOffset = cam.location.z;
        meshCamera->reverse = cam.direction.z < 0;
        cam.mesh = std::move(meshCamera);
    }
    scene::finalizeCamera(cam, edits);
    return cam;
}

}  // namespace frameray::sdl
