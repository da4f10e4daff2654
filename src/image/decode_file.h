// Reading an image file whole and decoding it from memory: the one place
// that names the file in every error of the byte decoders (PNM, TGA, GIF),
// which themselves only see bytes (so the unit tests and the fuzzers can
// feed them directly).
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace frameray::image {

// decode: const std::vector<std::uint8_t>& -> the image; its
// std::runtime_error comes back prefixed with "cannot read 'PATH': ".
template <class Decode>
auto decodeFile(const std::filesystem::path& path, Decode&& decode) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error(fmt::format("cannot read '{}'", path.string()));
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)),
                                          std::istreambuf_iterator<char>());
    try {
        return decode(bytes);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path.string(), e.what()));
    }
}

}  // namespace frameray::image
