#include "scene/image_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frameray::scene {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Angle of (x, z) around the y axis in turns, 0 on +x growing towards +z
// (POV-Ray's "west to east in a -y rotation").
double turnsAroundY(double x, double z) {
    const double len = std::sqrt(x * x + z * z);
    if (len == 0) return 0;
    double angle = std::acos(std::clamp(x / len, -1.0, 1.0));
    if (z < 0) angle = kTwoPi - angle;
    return angle / kTwoPi;
}

Color blend(const Color& a, const Color& b, double t) {
    const double s = 1.0 - t;
    return Color(a.rgb * s + b.rgb * t, a.filter * s + b.filter * t,
                 a.transmit * s + b.transmit * t);
}

Color scaled(const Color& c, double w) {
    return Color(c.rgb * w, c.filter * w, c.transmit * w);
}

void accumulate(Color& sum, const Color& c) {
    sum.rgb += c.rgb;
    sum.filter += c.filter;
    sum.transmit += c.transmit;
}

double blend(double a, double b, double t) {
    return a + (b - a) * t;
}
double scaled(double v, double w) {
    return v * w;
}
void accumulate(double& sum, double v) {
    sum += v;
}

// A point up to about 1e-10 pixel short of a texel boundary already takes
// the next texel (see nearestTexel).
constexpr double kNudge = 1e-10;

bool pastLastTexel(double t, int size) {
    return t * size + kNudge >= size;
}

double srgbDecode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

}  // namespace

ImageTexels::ImageTexels(std::shared_ptr<const util::PixelBuffer> pixels,
                         const ColorDecoding& decoding)
    : pixels_(std::move(pixels)), colors_(true), decoding_(decoding) {
    const util::PixelBuffer& px = *pixels_;
    if (px.isPalette()) {
        // Every entry once: colour, filter and transmit (alpha included).
        paletteColors_.resize(256);
        for (std::size_t i = 0; i < 256; ++i) {
            const auto& entry = px.palette()[i];
            auto unit = [&](int c) {
                return static_cast<double>(
                    util::PixelBuffer::kByteToUnit[entry[static_cast<std::size_t>(c)]]);
            };
            RGB rgb(decode(unit(0)), decode(unit(1)), decode(unit(2)));
            const double alpha = px.hasAlpha() ? unit(3) : 1.0;
            if (decoding_.premultiplied && alpha > 0) rgb *= 1.0 / alpha;
            paletteColors_[i] = Color(rgb, decoding_.paletteFilter[i],
                                      decoding_.paletteTransmit[i] + (1.0 - alpha));
        }
    } else if (px.sample() != util::PixelBuffer::Sample::F32) {
        const std::size_t levels = px.sample() == util::PixelBuffer::Sample::U8 ? 256 : 65536;
        // Each level as PixelBuffer::value gives it, decoded.
        const float scale = levels == 256 ? 1.0f / 255.0f : 1.0f / 65535.0f;
        levels_.resize(levels);
        for (std::size_t l = 0; l < levels; ++l)
            levels_[l] = decode(static_cast<double>(static_cast<float>(l) * scale));
        // povray keeps an 8-bit grey image (no alpha, no palette) in an
        // 8-bit buffer after decoding it, truncating the decoded value
        // (measured over all 256 levels of a grey PNG, sRGB, gamma 2.2 and
        // gAMA 2.2: povray's colours are floor(decoded * 255) / 255;
        // 16-bit grey, grey with alpha and colour images keep every value).
        const bool neutral = decoding_.asStored || decoding_.fileGamma == decoding_.workingGamma;
        if (levels == 256 && px.channels() == 1 && !neutral)
            for (double& v : levels_) v = std::floor(v * 255.0 + 1e-7) / 255.0;
    }
}

ImageTexels::ImageTexels(std::shared_ptr<const util::PixelBuffer> pixels, Scalar scalar)
    : pixels_(std::move(pixels)), colors_(false), scalar_(scalar) {}

double ImageTexels::decode(double v) const {
    // File values -> linear light -> the working gamma.
    if (decoding_.asStored) return v;
    const double g = decoding_.fileGamma;
    const double linear = g == 0 ? srgbDecode(v) : g == 1 ? v : std::pow(v, g);
    const double w = decoding_.workingGamma;
    return w == 1.0 ? linear : std::pow(linear, 1.0 / w);
}

double ImageTexels::channel(std::size_t p, int c) const {
    return static_cast<double>(pixels_->value(p, c));
}

Color ImageTexels::color(std::size_t p) const {
    const util::PixelBuffer& px = *pixels_;
    if (px.isPalette()) return paletteColors_[px.index(p)];
    const int ch = px.channels();
    const int g = ch < 3 ? 0 : 1, b = ch < 3 ? 0 : 2;
    RGB rgb;
    if (levels_.empty())
        rgb = RGB(decode(channel(p, 0)), decode(channel(p, g)), decode(channel(p, b)));
    else
        rgb = RGB(levels_[px.level(p, 0)], levels_[px.level(p, g)], levels_[px.level(p, b)]);
    const double alpha = px.hasAlpha() ? channel(p, ch - 1) : 1.0;
    if (decoding_.premultiplied && alpha > 0) rgb *= 1.0 / alpha;
    return Color(rgb, decoding_.filterAll, decoding_.transmitAll + (1.0 - alpha));
}

double ImageTexels::value(std::size_t p) const {
    const util::PixelBuffer& px = *pixels_;
    double v;
    switch (scalar_) {
        case Scalar::Index:
            return px.index(p);  // the raw index (measured: a step of 1 per entry)
        case Scalar::MaterialIndex:
            return materialIndex(px, p);
        case Scalar::Alpha:
            v = 1.0 - (px.hasAlpha() ? channel(p, px.channels() - 1) : 1.0);
            break;
        case Scalar::Grey:
        default: {
            const bool greyImage = px.channels() < 3;
            v = grey(channel(p, 0), channel(p, greyImage ? 0 : 1), channel(p, greyImage ? 0 : 2));
        }
    }
    // Single precision, as the scalar has always been kept.
    return static_cast<double>(static_cast<float>(v));
}

double materialIndex(const util::PixelBuffer& px, std::size_t p) {
    if (px.isPalette()) return px.index(p);
    const double byte = std::floor(static_cast<double>(px.value(p, 0)) * 255.0 + 0.5);
    if (px.channels() >= 3) return byte;
    const float g = static_cast<float>(byte) / 255.0f;
    return std::floor(static_cast<double>(greySingle(g, g, g)) * 255.0);
}

bool imageCoordinatesOk(const ImageMap& map, const Vec3& p, double& u, double& v) {
    return map.texels().hasValues() && map.imageCoordinates(p, u, v);
}

bool ImageMap::imageCoordinates(const Vec3& p, double& u, double& v) const {
    switch (mapping_) {
        case ImageMapping::Planar:
            u = p.x;
            v = p.y;
            break;
        case ImageMapping::Spherical: {
            const double len = length(p);
            if (len == 0) {
                u = v = 0;
                return true;
            }
            u = turnsAroundY(p.x, p.z);
            // Latitude: 0 at the south pole, 1 at the north pole.
            v = 0.5 + std::asin(std::clamp(p.y / len, -1.0, 1.0)) / std::numbers::pi;
            return true;
        }
        case ImageMapping::Cylindrical:
            u = turnsAroundY(p.x, p.z);
            v = p.y;
            if (once_ && (v < 0 || v > 1)) return false;
            v -= std::floor(v);
            return !(once_ && pastLastTexel(v, texels_->height()));
        case ImageMapping::Torus: {
            // Around the y axis for u; around the tube of major radius 1 for
            // v: 0 on the inner rim, 1/4 underneath, 1/2 on the outer rim
            // (measured).
            u = turnsAroundY(p.x, p.z);
            const double radial = std::sqrt(p.x * p.x + p.z * p.z) - 1.0;
            v = 0.5 + std::atan2(p.y, radial) / kTwoPi;
            if (v >= 1.0) v -= 1.0;
            return true;
        }
    }
    // `once` (povray 3.7, measured): 1 itself is inside and wraps to the
    // first texel, while a point just short of 1 that the texel lookup
    // rounds past the last texel is outside.
    if (once_ && (u < 0 || u > 1 || v < 0 || v > 1)) return false;
    u -= std::floor(u);
    v -= std::floor(v);
    return !(once_ && (pastLastTexel(u, texels_->width()) || pastLastTexel(v, texels_->height())));
}

void ImageMap::texelCoordinates(double u, double v, double& x, double& y) const {
    x = u * texels_->width();
    y = (1.0 - v) * texels_->height();
}

void ImageMap::nearestTexel(double u, double v, int& ix, int& iy) const {
    // povray 3.7 (measured with pigment functions on 8 and 256 pixel
    // images): a point up to about 1e-10 pixel short of a texel boundary
    // already takes the next texel, in both directions, wrapping at the
    // image's edge. So a box face at exactly x = 1 shows column 0 however
    // the hit point rounds. Rows are counted up from the bottom and then
    // flipped.
    const int w = texels_->width(), h = texels_->height();
    ix = wrapX(static_cast<int>(std::floor(u * w + kNudge)));
    iy = h - 1 - wrapY(static_cast<int>(std::floor(v * h + kNudge)));
}

int ImageMap::wrapX(int x) const {
    const int w = texels_->width();
    if (once_) return std::clamp(x, 0, w - 1);
    x %= w;
    return x < 0 ? x + w : x;
}

int ImageMap::wrapY(int y) const {
    const int h = texels_->height();
    if (once_) return std::clamp(y, 0, h - 1);
    y %= h;
    return y < 0 ? y + h : y;
}

template <typename T, typename Fetch>
T ImageMap::sample(double u, double v, Fetch fetch) const {
    double x, y;
    texelCoordinates(u, v, x, y);
    if (interpolation_ == ImageInterpolation::None) {
        int ix, iy;
        nearestTexel(u, v, ix, iy);
        return fetch(ix, iy);
    }
    // Interpolation works between texel centres (measured: a texel's own
    // colour is reached exactly at its centre).
    x -= 0.5;
    y -= 0.5;
    const double fx0 = std::floor(x), fy0 = std::floor(y);
    const double fx = x - fx0, fy = y - fy0;
    const int x0 = wrapX(static_cast<int>(fx0)), x1 = wrapX(static_cast<int>(fx0) + 1);
    const int y0 = wrapY(static_cast<int>(fy0)), y1 = wrapY(static_cast<int>(fy0) + 1);
    if (interpolation_ == ImageInterpolation::Bicubic) {
        // interpolate 3 (undocumented; measured with pigment functions):
        // Catmull-Rom through the 4 x 4 texel centres around the point.
        auto weights = [](double t, double w[4]) {
            const double t2 = t * t, t3 = t2 * t;
            w[0] = 0.5 * (-t + 2 * t2 - t3);
            w[1] = 0.5 * (2 - 5 * t2 + 3 * t3);
            w[2] = 0.5 * (t + 4 * t2 - 3 * t3);
            w[3] = 0.5 * (-t2 + t3);
        };
        double wx[4], wy[4];
        weights(fx, wx);
        weights(fy, wy);
        const int bx = static_cast<int>(fx0), by = static_cast<int>(fy0);
        T sum{};
        for (int j = 0; j < 4; ++j) {
            const int yy = wrapY(by - 1 + j);
            for (int i = 0; i < 4; ++i)
                accumulate(sum, scaled(fetch(wrapX(bx - 1 + i), yy), wx[i] * wy[j]));
        }
        return sum;
    }
    if (interpolation_ == ImageInterpolation::Bilinear) {
        const T top = blend(fetch(x0, y0), fetch(x1, y0), fx);
        const T bottom = blend(fetch(x0, y1), fetch(x1, y1), fx);
        return blend(top, bottom, fy);
    }
    // Normalized distance: the four texels weighted by the inverse square
    // of their distance (measured from povray's renders).
    const int xs[4] = {x0, x1, x0, x1}, ys[4] = {y0, y0, y1, y1};
    const double dxs[4] = {fx, 1 - fx, fx, 1 - fx}, dys[4] = {fy, fy, 1 - fy, 1 - fy};
    T sum{};
    double weights = 0;
    for (int i = 0; i < 4; ++i) {
        const double d2 = dxs[i] * dxs[i] + dys[i] * dys[i];
        if (d2 == 0) return fetch(xs[i], ys[i]);
        const double w = 1.0 / d2;
        accumulate(sum, scaled(fetch(xs[i], ys[i]), w));
        weights += w;
    }
    return scaled(sum, 1.0 / weights);
}

Color ImageMap::colorAt(const Vec3& p) const {
    double u = 0, v = 0;
    if (!texels_ || !texels_->hasColors() || !imageCoordinates(p, u, v))
        return Color(RGB(1.0), 0.0, 1.0);
    const ImageTexels& t = *texels_;
    const auto w = static_cast<std::size_t>(t.width());
    return sample<Color>(u, v, [&t, w](int x, int y) {
        return t.color(static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x));
    });
}

double ImageMap::texelValue(int ix, int iy) const {
    const ImageTexels& t = *texels_;
    return t.value(static_cast<std::size_t>(wrapY(iy)) * static_cast<std::size_t>(t.width()) +
                   static_cast<std::size_t>(wrapX(ix)));
}

double ImageMap::valueAt(const Vec3& p) const {
    double u = 0, v = 0;
    if (!texels_ || !texels_->hasValues() || !imageCoordinates(p, u, v)) return 0.0;
    return valueAtImagePoint(u, v);
}

double ImageMap::valueAtImagePoint(double u, double v) const {
    const ImageTexels& t = *texels_;
    const auto w = static_cast<std::size_t>(t.width());
    return sample<double>(u, v, [&t, w](int x, int y) {
        return t.value(static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x));
    });
}

Vec3 bumpMapNormal(const ImageMap& map, double bumpSize, const Vec3& p, const Vec3& n) {
    double u = 0, v = 0;
    if (!imageCoordinatesOk(map, p, u, v)) return n;
    // povray 3.7 (measured): the normal of the triangle through the heights
    // at this texel (A) and at the texels one row down and one column to
    // either side (B right, C left), heights scaled by bump_size...
    const ImageTexels& t = map.texels();
    double a, b, c;
    if (map.interpolation() == ImageInterpolation::None) {
        int ix, iy;
        map.nearestTexel(u, v, ix, iy);
        a = map.texelValue(ix, iy);
        b = map.texelValue(ix + 1, iy + 1);
        c = map.texelValue(ix - 1, iy + 1);
    } else {
        const double du = 1.0 / t.width(), dv = 1.0 / t.height();
        a = map.valueAtImagePoint(u, v);
        b = map.valueAtImagePoint(u + du, v - dv);
        c = map.valueAtImagePoint(u - du, v - dv);
    }
    const double across = -bumpSize * (b - c) * 0.5;
    const double down = -bumpSize * (a - (b + c) * 0.5);
    // ...set on the surface in a frame built from the normal: across along
    // n x y (x when the normal is vertical), down along across x n.
    Vec3 uAxis = cross(n, Vec3(0, 1, 0));
    const double len = length(uAxis);
    uAxis = len < 1e-9 ? Vec3(1, 0, 0) : uAxis * (1.0 / len);
    const Vec3 vAxis = cross(uAxis, n);
    return normalize(n + uAxis * across + vAxis * down);
}

}  // namespace frameray::scene
