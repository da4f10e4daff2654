#include "scene/density_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace frameray::scene {

namespace {

// povray wraps sample indices as unsigned 32-bit numbers: the index before
// 0 is (2^32 - 1) mod n, which is n - 1 only when n divides 2^32 (measured
// with 3 x 2 x 4 and 16^3 files: with n = 3 it is 0).
int wrapIndex(long long i, int n) {
    return static_cast<int>(static_cast<std::uint32_t>(i) % static_cast<std::uint32_t>(n));
}

// The Catmull-Rom cubic through b (t = 0) and c (t = 1), with a and d the
// samples before and after.
double catmullRom(double t, double a, double b, double c, double d) {
    const double sb = (c - a) * 0.5, sd = (d - b) * 0.5;
    const double e = 2.0 * (b - c) + sb + sd;
    const double f = -3.0 * (b - c) - 2.0 * sb - sd;
    return ((e * t + f) * t + sb) * t + b;
}

}  // namespace

DensityFile DensityFile::read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open density file '" + path.string() + "'");
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    if (bytes.size() < 6)
        throw std::runtime_error("density file '" + path.string() + "' has no df3 header");
    auto u16 = [&](std::size_t o) { return (static_cast<int>(bytes[o]) << 8) | bytes[o + 1]; };
    DensityFile f;
    f.nx_ = u16(0);
    f.ny_ = u16(2);
    f.nz_ = u16(4);
    const std::size_t count =
        static_cast<std::size_t>(f.nx_) * static_cast<std::size_t>(f.ny_) * f.nz_;
    if (count == 0) throw std::runtime_error("density file '" + path.string() + "' is empty");
    const std::size_t dataBytes = bytes.size() - 6;
    const std::size_t width = dataBytes / count;
    if (width != 1 && width != 2 && width != 4)
        throw std::runtime_error("density file '" + path.string() +
                                 "' does not hold 8, 16 or 32-bit samples for its size");
    f.samples_.resize(count);
    for (std::size_t s = 0; s < count; ++s) {
        const std::size_t o = 6 + s * width;
        std::uint64_t v = 0;
        for (std::size_t b = 0; b < width; ++b) v = (v << 8) | bytes[o + b];
        const double max = width == 1 ? 255.0 : width == 2 ? 65535.0 : 4294967295.0;
        f.samples_[s] = static_cast<double>(v) / max;
    }
    return f;
}

double DensityFile::at(int i, int j, int k) const {
    return samples_[static_cast<std::size_t>(i) +
                    static_cast<std::size_t>(nx_) *
                        (static_cast<std::size_t>(j) + static_cast<std::size_t>(ny_) * k)];
}

double DensityFile::value(const Vec3& p, int interpolation) const {
    if (p.x < 0 || p.x > 1 || p.y < 0 || p.y > 1 || p.z < 0 || p.z > 1) return 0.0;
    const double tx = p.x * nx_, ty = p.y * ny_, tz = p.z * nz_;
    const double fx = std::floor(tx), fy = std::floor(ty), fz = std::floor(tz);
    const auto ix = static_cast<long long>(fx), iy = static_cast<long long>(fy),
               iz = static_cast<long long>(fz);
    if (interpolation <= 0)
        return at(std::min<int>(static_cast<int>(ix), nx_ - 1),
                  std::min<int>(static_cast<int>(iy), ny_ - 1),
                  std::min<int>(static_cast<int>(iz), nz_ - 1));
    const double ux = tx - fx, uy = ty - fy, uz = tz - fz;
    if (interpolation == 1) {
        double sum = 0;
        for (int dz = 0; dz < 2; ++dz)
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const double w = (dx ? ux : 1 - ux) * (dy ? uy : 1 - uy) * (dz ? uz : 1 - uz);
                    sum += w * at(wrapIndex(ix + dx, nx_), wrapIndex(iy + dy, ny_),
                                  wrapIndex(iz + dz, nz_));
                }
        return sum;
    }
    // Cubic: along x, then y, then z.
    double zs[4];
    for (int dz = -1; dz <= 2; ++dz) {
        const int k = wrapIndex(iz + dz, nz_);
        double ys[4];
        for (int dy = -1; dy <= 2; ++dy) {
            const int j = wrapIndex(iy + dy, ny_);
            double xs[4];
            for (int dx = -1; dx <= 2; ++dx) {
                xs[dx + 1] = at(wrapIndex(ix + dx, nx_), j, k);
            }
            ys[dy + 1] = catmullRom(ux, xs[0], xs[1], xs[2], xs[3]);
        }
        zs[dz + 1] = catmullRom(uy, ys[0], ys[1], ys[2], ys[3]);
    }
    return std::clamp(catmullRom(uz, zs[0], zs[1], zs[2], zs[3]), 0.0, 1.0);
}

}  // namespace frameray::scene
