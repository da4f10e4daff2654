// The density_file pattern: a 3-D grid of densities read from a df3 file
// (three big-endian 16-bit sizes nx, ny, nz, then nx·ny·nz samples of 8,
// 16 or 32 bits, x fastest), spread over the unit cube; 0 outside it.
// Matched to povray 3.7 through pattern functions:
//  - interpolate 0: the sample of the cell floor(p · n);
//  - interpolate 1: trilinear between the samples at floor(p · n) and the
//    next ones, which wrap round to index 0 at the far side;
//  - interpolate 2: Catmull-Rom cubic over four samples per axis, clamped
//    to [0, 1]; povray computes it in single precision (values agree to
//    about 1e-7).
// Indices wrap as unsigned 32-bit numbers (density_file.cpp).
#pragma once

#include <filesystem>
#include <vector>

#include "util/vec3.h"

namespace frameray::scene {

class DensityFile {
  public:
    // Reads the file; throws std::runtime_error on a malformed one.
    static DensityFile read(const std::filesystem::path& path);

    // The density at pattern-space point p with interpolation mode 0, 1 or 2.
    double value(const Vec3& p, int interpolation) const;

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int nz() const { return nz_; }

  private:
    double at(int i, int j, int k) const;

    int nx_ = 0, ny_ = 0, nz_ = 0;
    std::vector<double> samples_;  // scaled to [0, 1]
};

}  // namespace frameray::scene
