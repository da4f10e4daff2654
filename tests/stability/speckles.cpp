// frameray-speckles: counts the defects the numerical-stability suite looks
// for in a render, against a high-accuracy render of the same scene.
//
//     frameray-speckles TEST REFERENCE [--max-speckles N] [--tolerance T]
//
// nonfinite  pixels with a NaN or infinite sample (readable from EXR/HDR
//            output; 8-bit files cannot hold them);
// speckles   isolated pixels: differing from the reference by more than T
//            (0..255 scale, default 24) in some channel while at most one
//            of their 8 neighbours differs — single-pixel holes, acne and
//            stray hits, as opposed to a shifted edge, which differs along
//            a line of neighbours.
// Exits 1 when there is any non-finite pixel or more than N speckles.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Image {
    int width = 0, height = 0;
    std::vector<float> rgb;  // 0..255 scale
    const float* at(int x, int y) const {
        return &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
    }
};

bool load(const std::string& path, Image& image) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) {
        std::fprintf(stderr, "frameray-speckles: cannot read '%s'\n", path.c_str());
        return false;
    }
    const OIIO::ImageSpec& spec = input->spec();
    const int channels = spec.nchannels;
    std::vector<float> raw(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data())) {
        std::fprintf(stderr, "frameray-speckles: cannot decode '%s'\n", path.c_str());
        return false;
    }
    image.width = spec.width;
    image.height = spec.height;
    image.rgb.resize(static_cast<std::size_t>(spec.width) * spec.height * 3);
    for (std::size_t p = 0; p < static_cast<std::size_t>(spec.width) * spec.height; ++p)
        for (int c = 0; c < 3; ++c)
            image.rgb[p * 3 + c] = raw[p * channels + (channels < 3 ? 0 : c)] * 255.0f;
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(
            stderr, "usage: frameray-speckles TEST REFERENCE [--max-speckles N] [--tolerance T]\n");
        return 2;
    }
    long maxSpeckles = -1;
    double tolerance = 24;
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--max-speckles")
            maxSpeckles = std::atol(argv[i + 1]);
        else if (flag == "--tolerance")
            tolerance = std::atof(argv[i + 1]);
    }
    Image test, ref;
    if (!load(argv[1], test) || !load(argv[2], ref)) return 2;
    if (test.width != ref.width || test.height != ref.height) {
        std::fprintf(stderr, "frameray-speckles: sizes differ\n");
        return 2;
    }
    const int w = test.width, h = test.height;
    std::vector<char> differs(static_cast<std::size_t>(w) * h, 0);
    long nonfinite = 0, differing = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* a = test.at(x, y);
            const float* b = ref.at(x, y);
            bool bad = false, off = false;
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(a[c])) bad = true;
                // Compare clamped code values: overexposed floats beyond
                // white look the same.
                const double va = std::fmin(std::fmax(a[c], 0.0f), 255.0f);
                const double vb = std::fmin(std::fmax(b[c], 0.0f), 255.0f);
                if (!(std::fabs(va - vb) <= tolerance)) off = true;
            }
            nonfinite += bad;
            differs[static_cast<std::size_t>(y) * w + x] = off || bad;
            differing += off || bad;
        }
    long speckles = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!differs[static_cast<std::size_t>(y) * w + x]) continue;
            int neighbours = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if ((dx || dy) && nx >= 0 && ny >= 0 && nx < w && ny < h)
                        neighbours += differs[static_cast<std::size_t>(ny) * w + nx];
                }
            if (neighbours <= 1) ++speckles;
        }
    std::printf("%s: nonfinite %ld speckles %ld differing %ld\n", argv[1], nonfinite, speckles,
                differing);
    if (nonfinite > 0) return 1;
    if (maxSpeckles >= 0 && speckles > maxSpeckles) return 1;
    return 0;
}
