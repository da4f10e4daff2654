// Images wrapped onto surfaces (seed 003 §5.4.1.4 and §5.4.2.6; POV-Ray
// 3.7 behaviour measured with the reference binary): `image_map` pigments,
// `bump_map` normals and the `image_pattern` pattern all map a point of
// pattern space to image coordinates (planar, spherical, cylindrical or
// torus), repeat the image or show it `once`, and look a texel up with or
// without interpolation.
//
// The texels are prepared when the scene is parsed: colours in the scene's
// working gamma with the image's filter and transmit applied, and a scalar
// per texel for patterns and bump maps. Evaluation is const, thread-safe
// and does not allocate.
#pragma once

#include <memory>
#include <vector>

#include "util/color.h"
#include "util/vec3.h"

namespace frameray::scene {

enum class ImageMapping { Planar = 0, Spherical = 1, Cylindrical = 2, Torus = 5 };

enum class ImageInterpolation { None = 0, Bilinear = 2, Bicubic = 3, NormalizedDistance = 4 };

// The prepared pixels of one image as a pigment, pattern or bump map uses
// them; row 0 is the image's top row.
struct ImageTexels {
    int width = 0;
    int height = 0;
    std::vector<Color> colors;  // image_map: colour, filter and transmit
    std::vector<float> values;  // image_pattern / bump_map: the scalar
};

class ImageMap {
  public:
    ImageMap() = default;
    ImageMap(std::shared_ptr<const ImageTexels> texels, ImageMapping mapping, bool once,
             ImageInterpolation interpolation)
        : texels_(std::move(texels)),
          mapping_(mapping),
          once_(once),
          interpolation_(interpolation) {}

    // Image coordinates of pattern-space point p: u across the image from
    // its left edge, v up from its bottom edge, both in [0,1) inside the
    // image. False where the image does not reach (outside the unit square
    // with `once`, or a point on the axis of a spherical or cylindrical map
    // where the angle is undefined is still mapped).
    bool imageCoordinates(const Vec3& p, double& u, double& v) const;

    // image_map: the colour at pattern-space point p; fully transmitting
    // where the image does not reach.
    Color colorAt(const Vec3& p) const;
    // image_pattern / bump_map: the texel scalar at p; 0 where the image
    // does not reach.
    double valueAt(const Vec3& p) const;
    // The same at image point (u, v) (texels wrap or clamp as the map
    // repeats; the None lookup clamps to the image).
    double valueAtImagePoint(double u, double v) const;

    // The scalar at texel (ix, iy), wrapped or clamped as the map repeats
    // (bump maps sample neighbouring texels).
    double texelValue(int ix, int iy) const;
    // The texel (x from the left, y from the top) that image point (u, v)
    // shows without interpolation.
    void nearestTexel(double u, double v, int& ix, int& iy) const;
    // Texel coordinates (in pixels, x from the left, y from the top) of
    // image point (u, v), before the half-pixel shift of interpolation.
    void texelCoordinates(double u, double v, double& x, double& y) const;

    const ImageTexels& texels() const { return *texels_; }
    ImageMapping mapping() const { return mapping_; }
    bool once() const { return once_; }
    ImageInterpolation interpolation() const { return interpolation_; }

  private:
    template <typename T, typename Fetch>
    T sample(double u, double v, Fetch fetch) const;
    int wrapX(int x) const;
    int wrapY(int y) const;

    std::shared_ptr<const ImageTexels> texels_;
    ImageMapping mapping_ = ImageMapping::Planar;
    bool once_ = false;
    ImageInterpolation interpolation_ = ImageInterpolation::None;
};

// imageCoordinates for a map with scalar texels; false without them.
bool imageCoordinatesOk(const ImageMap& map, const Vec3& p, double& u, double& v);

// How bump_map tilts a normal (normals.cpp calls it): the bump map's
// heights around pattern-space point p steer texture-space normal n.
Vec3 bumpMapNormal(const ImageMap& map, double bumpSize, const Vec3& p, const Vec3& n);

}  // namespace frameray::scene
