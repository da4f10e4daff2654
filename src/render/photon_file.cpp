#include "render/photon_file.h"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "scene/photon_settings.h"
#include "util/durable_file.h"

namespace frameray::render {

namespace {

constexpr size_t kFloatsPerPhoton = 9;
constexpr size_t kPhotonBytes = kFloatsPerPhoton * 4 + 1;  // with its split axis

void putU32(std::string& out, std::uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8)
        out.push_back(static_cast<char>((v >> shift) & 0xFF));
}

void putU64(std::string& out, std::uint64_t v) {
    for (int shift = 0; shift < 64; shift += 8)
        out.push_back(static_cast<char>((v >> shift) & 0xFF));
}

std::uint64_t getLittleEndian(std::string_view bytes, size_t at, int size) {
    std::uint64_t v = 0;
    for (int i = 0; i < size; ++i)
        v |= static_cast<std::uint64_t>(
                 static_cast<unsigned char>(bytes[at + static_cast<size_t>(i)]))
             << (8 * i);
    return v;
}

void putMap(std::string& out, const PhotonMap& map) {
    for (const Photon& p : map.photons()) {
        const float* fields[] = {p.position, p.power, p.direction};
        for (const float* f : fields)
            for (int i = 0; i < 3; ++i) putU32(out, std::bit_cast<std::uint32_t>(f[i]));
    }
    for (std::uint8_t axis : map.axes()) out.push_back(static_cast<char>(axis));
}

PhotonMap getMap(std::string_view bytes, size_t& at, std::uint64_t count) {
    std::vector<Photon> photons(count);
    for (Photon& p : photons) {
        float* fields[] = {p.position, p.power, p.direction};
        for (float* f : fields)
            for (int i = 0; i < 3; ++i, at += 4)
                f[i] =
                    std::bit_cast<float>(static_cast<std::uint32_t>(getLittleEndian(bytes, at, 4)));
    }
    std::vector<std::uint8_t> axes(count);
    for (std::uint8_t& axis : axes) axis = static_cast<std::uint8_t>(bytes[at++]);
    return PhotonMap::fromTree(std::move(photons), std::move(axes));
}

}  // namespace

std::string encodePhotonFile(const PhotonMap& surface, const PhotonMap& media) {
    std::string out(scene::kPhotonFileMagic);
    out.reserve(out.size() + 16 + (surface.size() + media.size()) * kPhotonBytes);
    putU64(out, surface.size());
    putU64(out, media.size());
    putMap(out, surface);
    putMap(out, media);
    return out;
}

PhotonMaps decodePhotonFile(std::string_view bytes, const std::string& shownAs) {
    const std::string_view magic = scene::kPhotonFileMagic;
    if (!bytes.starts_with(magic))
        throw std::runtime_error(fmt::format(
            "'{}' is not a frameray photon map (frameray reads only the maps it saves with "
            "save_file, not povray's)",
            shownAs));
    size_t at = magic.size();
    if (bytes.size() < at + 16)
        throw std::runtime_error(fmt::format("'{}': the photon map file is cut short", shownAs));
    const std::uint64_t surfaceCount = getLittleEndian(bytes, at, 8);
    const std::uint64_t mediaCount = getLittleEndian(bytes, at + 8, 8);
    at += 16;
    // Checked before anything is allocated: a damaged count cannot ask
    // for more memory than the file's own size.
    const std::uint64_t room = (bytes.size() - at) / kPhotonBytes;
    if (surfaceCount > room || mediaCount > room - surfaceCount ||
        bytes.size() - at != (surfaceCount + mediaCount) * kPhotonBytes)
        throw std::runtime_error(fmt::format(
            "'{}': the photon map file is damaged (its size does not match its photon counts)",
            shownAs));
    try {
        PhotonMaps maps;
        maps.surface = getMap(bytes, at, surfaceCount);
        maps.media = getMap(bytes, at, mediaCount);
        return maps;
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(
            fmt::format("'{}': the photon map file is damaged ({})", shownAs, e.what()));
    }
}

void writePhotonFile(const std::filesystem::path& file, const PhotonMap& surface,
                     const PhotonMap& media) {
    try {
        util::replaceFileDurably(file, encodePhotonFile(surface, media));
    } catch (const std::exception& e) {
        throw std::runtime_error(
            fmt::format("cannot save the photon map to '{}': {}", file.string(), e.what()));
    }
}

}  // namespace frameray::render
