// frameray-compare: compares a rendered image with a golden image.
//
//     frameray-compare TEST.png GOLDEN.png [--min-match F] [--diff DIFF.png] [--blur R]
//
// --blur R compares the images' local means over (2R + 1)^2 windows, for
// scenes whose per-pixel randomness no two renders share (crand).
// Prints one line (match fraction, PSNR, max difference, PASS/FAIL) and
// exits 0 on pass, 1 on fail, 2 when the images cannot be read or compared.
// On fail, --diff writes an image marking the failing pixels in red.

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "compare_images.h"

namespace {

namespace conf = frameray::conformance;

constexpr int kExitPass = 0;
constexpr int kExitFail = 1;
constexpr int kExitError = 2;

void print_usage(std::FILE* to) {
    std::fprintf(to,
                 "usage: frameray-compare TEST.png GOLDEN.png [--min-match F] [--diff DIFF.png]"
                 " [--blur R]\n"
                 "  match = fraction of pixels whose every channel (R,G,B, and A when both\n"
                 "  images have it) is within 4/255 of the golden; passes when\n"
                 "  match >= F (default 0.99). --blur R first averages both images over\n"
                 "  (2R+1)^2 windows. Exit 0 pass, 1 fail, 2 error.\n");
}

// Loads any image OpenImageIO reads, as 0..255-scale samples. Grey images
// are widened to RGB(A) so that a grey render can still be checked against
// an RGB golden.
bool load_image(const std::string& path, conf::Image& image, std::string& error) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) {
        error = "cannot read '" + path + "': " + OIIO::geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = input->spec();
    const int file_channels = spec.nchannels;
    if (file_channels < 1 || file_channels > 4) {
        error = "'" + path + "' has " + std::to_string(file_channels) +
                " channels; expected grey, RGB or RGBA";
        return false;
    }
    std::vector<float> raw(static_cast<std::size_t>(spec.width) * spec.height * file_channels);
    if (!input->read_image(0, 0, 0, file_channels, OIIO::TypeDesc::FLOAT, raw.data())) {
        error = "cannot decode '" + path + "': " + input->geterror();
        return false;
    }
    input->close();

    const bool grey = file_channels <= 2;
    const bool alpha = file_channels == 2 || file_channels == 4;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = alpha ? 4 : 3;
    image.samples.clear();
    image.samples.reserve(static_cast<std::size_t>(spec.width) * spec.height * image.channels);
    for (std::size_t i = 0; i < raw.size(); i += file_channels) {
        for (int c = 0; c < 3; ++c) image.samples.push_back(raw[i + (grey ? 0 : c)] * 255.0f);
        if (alpha) image.samples.push_back(raw[i + file_channels - 1] * 255.0f);
    }
    return true;
}

bool save_image(const std::string& path, const conf::Image& image, std::string& error) {
    auto output = OIIO::ImageOutput::create(path);
    if (!output) {
        error = "cannot write '" + path + "': " + OIIO::geterror();
        return false;
    }
    OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::UINT8);
    std::vector<float> normalized(image.samples.size());
    for (std::size_t i = 0; i < normalized.size(); ++i) normalized[i] = image.samples[i] / 255.0f;
    if (!output->open(path, spec) ||
        !output->write_image(OIIO::TypeDesc::FLOAT, normalized.data()) || !output->close()) {
        error = "cannot write '" + path + "': " + output->geterror();
        return false;
    }
    return true;
}

// Parses a float option value, rejecting trailing garbage ("0.9x").
bool parse_fraction(std::string_view text, double& value) {
    std::string copy(text);
    char* end = nullptr;
    value = std::strtod(copy.c_str(), &end);
    return !copy.empty() && end == copy.c_str() + copy.size() && value >= 0.0 && value <= 1.0;
}

}  // namespace

int main(int argc, char** argv) {
    std::string test_path, golden_path, diff_path;
    conf::CompareOptions options;
    int blur = 0;

    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        std::string_view arg = argv[i];
        // Both "--opt value" and "--opt=value" are accepted.
        auto value_of = [&](std::string_view name, std::string_view& value) {
            if (arg == name) {
                if (i + 1 >= argc) return false;
                value = argv[++i];
                return true;
            }
            if (arg.size() > name.size() && arg.substr(0, name.size()) == name &&
                arg[name.size()] == '=') {
                value = arg.substr(name.size() + 1);
                return true;
            }
            return false;
        };
        std::string_view value;
        if (arg == "-h" || arg == "--help") {
            print_usage(stdout);
            return kExitPass;
        } else if (arg.starts_with("--min-match")) {
            if (!value_of("--min-match", value) || !parse_fraction(value, options.min_match)) {
                std::fprintf(stderr, "frameray-compare: --min-match needs a number in [0, 1]\n");
                return kExitError;
            }
        } else if (arg.starts_with("--diff")) {
            if (!value_of("--diff", value) || value.empty()) {
                std::fprintf(stderr, "frameray-compare: --diff needs a file name\n");
                return kExitError;
            }
            diff_path = value;
        } else if (arg.starts_with("--blur")) {
            double radius = 0;
            if (!value_of("--blur", value) || value.empty()) {
                std::fprintf(stderr, "frameray-compare: --blur needs a radius in pixels\n");
                return kExitError;
            }
            std::string copy(value);
            char* end = nullptr;
            radius = std::strtod(copy.c_str(), &end);
            if (end != copy.c_str() + copy.size() || radius < 0 || radius > 64 ||
                radius != static_cast<int>(radius)) {
                std::fprintf(stderr, "frameray-compare: --blur needs a radius in pixels (0-64)\n");
                return kExitError;
            }
            blur = static_cast<int>(radius);
        } else if (arg.starts_with("-") && arg.size() > 1) {
            std::fprintf(stderr, "frameray-compare: unknown option '%s'\n", argv[i]);
            print_usage(stderr);
            return kExitError;
        } else if (positional == 0) {
            test_path = arg;
            ++positional;
        } else if (positional == 1) {
            golden_path = arg;
            ++positional;
        } else {
            std::fprintf(stderr, "frameray-compare: too many arguments\n");
            print_usage(stderr);
            return kExitError;
        }
    }
    if (positional != 2) {
        print_usage(stderr);
        return kExitError;
    }

    conf::Image test, golden;
    std::string error;
    if (!load_image(test_path, test, error) || !load_image(golden_path, golden, error)) {
        std::fprintf(stderr, "frameray-compare: %s\n", error.c_str());
        return kExitError;
    }
    if (auto why = conf::incompatibility(test, golden)) {
        std::fprintf(stderr, "frameray-compare: %s vs %s: %s\n", test_path.c_str(),
                     golden_path.c_str(), why->c_str());
        return kExitError;
    }

    if (blur > 0) {
        test = conf::box_blur(test, blur);
        golden = conf::box_blur(golden, blur);
    }
    const conf::CompareResult result = conf::compare_images(test, golden, options);
    std::printf("%s: %s\n", test_path.c_str(), conf::format_result(result, options).c_str());

    if (!result.passed && !diff_path.empty()) {
        if (!save_image(diff_path, conf::make_diff_image(test, golden, options), error)) {
            std::fprintf(stderr, "frameray-compare: %s\n", error.c_str());
        } else {
            std::printf("%s: failing pixels marked red in %s\n", test_path.c_str(),
                        diff_path.c_str());
        }
    }
    return result.passed ? kExitPass : kExitFail;
}
