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

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "util/color.h"
#include "util/pixel_buffer.h"
#include "util/vec3.h"

namespace frameray::scene {

enum class ImageMapping { Planar = 0, Spherical = 1, Cylindrical = 2, Torus = 5 };

enum class ImageInterpolation { None = 0, Bilinear = 2, Bicubic = 3, NormalizedDistance = 4 };

// The texels of one image as a pigment, pattern or bump map reads them:
// the file's pixels as stored (shared with every other map of the same
// file) and how a texel becomes a colour or a scalar, computed at each
// lookup (a table per level for the gamma), so a map costs no more memory
// than its file's pixels. Row 0 is the image's top row.
class ImageTexels {
  public:
    // What image_pattern, bump_map and material_map read from a texel.
    enum class Scalar : std::uint8_t {
        Grey,          // grey() (util/color.h) of the file values (no gamma)
        Alpha,         // 1 - alpha (use_alpha)
        Index,         // the palette index itself (bump_map use_index)
        MaterialIndex  // material_map's texture index (see materialIndex)
    };
    // How image_map turns file values into colours.
    struct ColorDecoding {
        bool asStored = false;  // the values as they are (no gamma at all)
        double fileGamma = 1;   // the file's gamma; 0: sRGB
        double workingGamma = 1;
        bool premultiplied = false;
        double filterAll = 0, transmitAll = 0;
        // Palette images: filter and transmit per entry.
        std::array<double, 256> paletteFilter{}, paletteTransmit{};
    };

    // image_map texels.
    ImageTexels(std::shared_ptr<const util::PixelBuffer> pixels, const ColorDecoding& decoding);
    // image_pattern / bump_map / material_map texels.
    ImageTexels(std::shared_ptr<const util::PixelBuffer> pixels, Scalar scalar);

    int width() const { return pixels_->width(); }
    int height() const { return pixels_->height(); }
    bool hasColors() const { return colors_; }
    bool hasValues() const { return !colors_; }

    // Texel p (row-major from the top): colour, filter and transmit.
    Color color(std::size_t p) const;
    // Texel p's scalar.
    double value(std::size_t p) const;

  private:
    double decode(double fileValue) const;
    double channel(std::size_t p, int c) const;

    std::shared_ptr<const util::PixelBuffer> pixels_;
    bool colors_ = false;
    Scalar scalar_ = Scalar::Grey;
    ColorDecoding decoding_;
    std::vector<double> levels_;        // integer samples: each level decoded
    std::vector<Color> paletteColors_;  // palette images: each entry decoded
};

// The texture material_map picks at pixel p of `pixels` before the list
// length is applied: the palette index of palette images, the 8-bit red
// value of colour images and, for grey images, the grey value taken through
// povray's single-precision grey weighting (greySingle) times 255,
// truncated (so 111 gives 110: measured over all 256 grey levels).
double materialIndex(const util::PixelBuffer& pixels, std::size_t p);

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
