// The text object:
//
//     text { ttf "font.ttf" "string" thickness, offset  [object modifiers] }
//     text { internal N "string" thickness, offset  [object modifiers] }
//
// Fonts are found like include files and read once per interpreter (a
// frame's parse); the string becomes character codes by the charset of
// global_settings in force, as in POV-Ray 3.7.
#include <fmt/format.h>

#include <stdexcept>

#include "scene/text_shape.h"
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// POV-Ray 3.7's built-in fonts (`internal N`) are the four fonts it ships
// in its include folder: 1 timrom, 2 cyrvetic, 3 crystal, any other number
// povlogo (checked: each renders exactly as the file of that name).
const char* internalFontFile(int id) {
    switch (id) {
        case 1:
            return "timrom.ttf";
        case 2:
            return "cyrvetic.ttf";
        case 3:
            return "crystal.ttf";
        default:
            return "povlogo.ttf";
    }
}

// UTF-8 to the 16-bit codes POV-Ray 3.7 works with. The lead byte says
// how many bytes follow (without checking that they are continuation
// bytes, as povray does); the result keeps the low 16 bits.
std::u32string decodeUtf8(const std::string& bytes) {
    // Reference data from POV-Ray 3.7 (the usual UTF-8 decoding offsets):
    // what the byte sum of a sequence of 1..6 bytes exceeds its code by.
    static constexpr uint32_t kOffsets[6] = {0x00000000u, 0x00003080u, 0x000E2080u,
                                             0x03C82080u, 0xFA082080u, 0x82082080u};
    std::u32string out;
    for (size_t i = 0; i < bytes.size();) {
        const auto lead = static_cast<unsigned char>(bytes[i]);
        const int extra = lead < 0xC0   ? 0
                          : lead < 0xE0 ? 1
                          : lead < 0xF0 ? 2
                          : lead < 0xF8 ? 3
                          : lead < 0xFC ? 4
                                        : 5;
        if (extra > 0 && i + static_cast<size_t>(extra) >= bytes.size()) break;  // cut short
        uint32_t code = 0;
        for (int k = 0; k <= extra; ++k) {
            code += static_cast<unsigned char>(bytes[i + static_cast<size_t>(k)]);
            if (k < extra) code <<= 6;
        }
        code -= kOffsets[extra];
        out.push_back(static_cast<char32_t>(code & 0xFFFFu));
        i += static_cast<size_t>(extra) + 1;
    }
    return out;
}

}  // namespace

static std::u32string decodeTextString(BuildContext& c, const std::string& bytes, const Token& at) {
    Reader& r = c.reader;
    switch (c.textCharset) {
        case scene::TextCharset::Utf8:
            return decodeUtf8(bytes);
        case scene::TextCharset::System:
            // povray 3.7 on Unix has no system conversion and stops so.
            r.fail(at, "Cannot convert system specific text format to Unicode.");
        case scene::TextCharset::Ascii:
            break;
    }
    std::u32string out;
    for (const char ch : bytes) {
        const auto byte = static_cast<unsigned char>(ch);
        if (byte < 0x80 || r.version() < 3.5) {
            out.push_back(byte);
        } else {
            out.push_back(U' ');
            r.warn(at, "Non-ASCII character has been replaced by space character.");
        }
    }
    return out;
}

static std::shared_ptr<scene::TtfFont> openFont(BuildContext& c, const std::string& name,
                                                const Token& at) {
    Reader& r = c.reader;
    // povray keeps fonts by the name the scene gives; the charset in force
    // when a font is first opened picks its character map for good.
    if (const auto it = c.fonts.find(name); it != c.fonts.end()) return it->second;
    std::filesystem::path path = r.findIncludeFile(name);
    if (path.empty() && std::filesystem::path(name).extension().empty())
        path = r.findIncludeFile(name + ".ttf");
    if (path.empty()) r.fail(at, fmt::format("Cannot open font file '{}'.", name));
    r.checkReadable(path, name, at);
    std::shared_ptr<scene::TtfFont> font;
    try {
        font = std::make_shared<scene::TtfFont>(path, c.textCharset);
    } catch (const std::runtime_error& e) {
        r.fail(at, e.what());
    }
    c.fonts.emplace(name, font);
    return font;
}

void parseTextBody(BuildContext& c, const Token&, ObjectValue& object) {
    scene::Object& obj = *object.object;
    Reader& r = c.reader;
    const Token fontAt = r.peek();
    // povray's caution for old scenes, whose strings it reads as ASCII now.
    if (r.version() < 3.5 && c.textCharset == scene::TextCharset::Ascii)
        r.warn(fontAt,
               "Text may not be displayed as expected. Please refer to the user manual regarding "
               "changes in "
               "POV-Ray v3.5 and later.");
    std::shared_ptr<scene::TtfFont> font;
    if (r.accept(Keyword::kw_ttf)) {
        const Token nameAt = r.peek();
        font = openFont(c, r.parsePathname(), nameAt);
    } else if (r.accept(Keyword::kw_internal)) {
        const int id = static_cast<int>(r.parseFloat());
        // Named apart from file names so a scene's own "timrom.ttf" is
        // never taken for the built-in font.
        const std::string file = internalFontFile(id);
        if (const auto it = c.fonts.find("\n" + file); it != c.fonts.end()) {
            font = it->second;
        } else {
            const std::filesystem::path path = r.findIncludeFile(file);
            if (path.empty())
                r.fail(fontAt, fmt::format("Cannot find the built-in font {} ('{}').", id, file));
            r.checkReadable(path, file, fontAt);
            try {
                font = std::make_shared<scene::TtfFont>(path, c.textCharset);
            } catch (const std::runtime_error& e) {
                r.fail(fontAt, e.what());
            }
            c.fonts.emplace("\n" + file, font);
        }
    } else {
        r.fail(fontAt,
               fmt::format("expected 'ttf' or 'internal', found {}", describeToken(fontAt)));
    }
    r.accept(Sym::Comma);
    const Token textAt = r.peek();
    const std::u32string text = decodeTextString(c, r.parseString(), textAt);
    r.accept(Sym::Comma);
    const double thickness = r.parseFloat();
    r.accept(Sym::Comma);
    const Vec3 offset = r.parseVec3();

    obj.shape =
        std::make_shared<scene::TextShape>(scene::layoutText(*font, text, offset), thickness);
    // povray turns every text object by 0.001 degrees about each axis
    // before its modifiers (against cracks in text lying along an axis);
    // the turn shows, so it is kept.
    obj.transform = Transform::rotate(Vec3(0.001, 0.001, 0.001));
}

}  // namespace frameray::sdl
