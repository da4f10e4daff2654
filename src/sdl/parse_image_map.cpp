// Image maps: `image_map { }` in a pigment, `image_pattern { }` as a
// pattern, `bump_map { }` in a normal and `material_map { }` in a texture
// (seed 003 §5.4.1.4, §5.4.2.6, §5.4.4.2).
// The file is read once per frame (the interpreter caches it by path) and
// turned into texels here, following POV-Ray 3.7 as measured:
//   - colours are decoded with the file's gamma - the `gamma` given, else
//     the one a PNG declares, else sRGB for PNG, TGA, GIF, JPEG, IFF and
//     sys files and linear for PPM, PGM, TIFF, EXR and HDR - and re-encoded
//     in the scene's working gamma; before 3.7 a file of unknown gamma
//     (no `gamma`; no gAMA or sRGB chunk, or a scene without
//     assumed_gamma) gives its values as they are;
//   - alpha becomes transmit (1 - alpha) on top of `transmit all`; the
//     colour is taken as not premultiplied unless `premultiplied` says so;
//   - `filter N` / `transmit N` set palette entries of palette images (GIF)
//     and are errors on other images; `filter all` / `transmit all` set
//     every texel, later items overriding earlier ones;
//   - the scalar of image_pattern and bump_map is the grey value
//     (util/color.h) of the file values (no gamma), or with
//     use_alpha 1 - alpha; bump_map's use_index takes the palette index
//     itself (0, 1, 2 ..., not scaled to [0,1]);
//   - material_map's scalar is the index of the texture: the palette index
//     of palette images (GIF and palette PNG), the 8-bit red value of
//     colour images and, for grey images, the grey value taken through
//     povray's single-precision grey weighting (greySingle) times 255,
//     truncated (so 111 gives 110: measured over all 256 grey levels).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

#include "image/image_io.h"
#include "scene/image_map.h"
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// What the image block is for: it decides which texels are prepared and
// which items are allowed.
enum class ImageUse { Pigment, Pattern, Bump, Material };

bool isImageType(Keyword k) {
    switch (k) {
        case Keyword::kw_png:
        case Keyword::kw_tga:
        case Keyword::kw_gif:
        case Keyword::kw_iff:
        case Keyword::kw_ppm:
        case Keyword::kw_pgm:
        case Keyword::kw_jpeg:
        case Keyword::kw_tiff:
        case Keyword::kw_exr:
        case Keyword::kw_hdr:
        case Keyword::kw_sys:
            return true;
        default:
            return false;
    }
}

// The gamma a format is read with when neither the scene nor the file
// says (measured with povray 3.7): 0 stands for sRGB.
double defaultFileGamma(Keyword type, const std::string& name) {
    Keyword k = type;
    if (k == Keyword::None || k == Keyword::kw_sys) {
        std::string ext = name.substr(name.find_last_of('.') + 1);
        std::transform(ext.begin(), ext.end(), ext.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (ext == "ppm" || ext == "pgm" || ext == "pnm" || ext == "pbm") k = Keyword::kw_ppm;
        if (ext == "tif" || ext == "tiff") k = Keyword::kw_tiff;
        if (ext == "exr") k = Keyword::kw_exr;
        if (ext == "hdr") k = Keyword::kw_hdr;
    }
    switch (k) {
        case Keyword::kw_ppm:
        case Keyword::kw_pgm:
        case Keyword::kw_tiff:
        case Keyword::kw_exr:
        case Keyword::kw_hdr:
            return 1.0;
        default:
            return 0.0;
    }
}

struct ImageSettings {
    Keyword type = Keyword::None;
    std::string name;
    Token nameAt;
    std::optional<double> gamma;  // 0 = srgb
    bool premultiplied = false;
    scene::ImageMapping mapping = scene::ImageMapping::Planar;
    bool once = false;
    scene::ImageInterpolation interpolation = scene::ImageInterpolation::None;
    // filter / transmit items in the order written: index -1 is `all`.
    struct Amount {
        bool filter;
        int index;
        double value;
        Token at;
    };
    std::vector<Amount> amounts;
    bool useIndex = false;
    bool useAlpha = false;
    double bumpSize = 0;
    bool bumpSizeGiven = false;
};

}  // namespace

const image::SourceImage& loadSourceImage(BuildContext& c, const std::string& name,
                                          const Token& at) {
    Reader& r = c.reader;
    const std::filesystem::path path = r.findIncludeFile(name);
    if (path.empty()) r.fail(at, fmt::format("Cannot open file '{}'.", name));
    r.checkReadable(path, name, at);
    const std::string key = path.lexically_normal().string();
    auto found = c.images.find(key);
    if (found != c.images.end()) return *found->second;
    std::shared_ptr<const image::SourceImage> img;
    try {
        img = std::make_shared<const image::SourceImage>(image::readSource(path));
    } catch (const std::runtime_error& e) {
        r.fail(at, e.what());
    }
    if (img->width() <= 0 || img->height() <= 0)
        r.fail(at, fmt::format("image '{}' has no pixels", name));
    return *c.images.emplace(key, std::move(img)).first->second;
}

static image::SourceImage functionSourceImage(BuildContext& c, const Token& at) {
    Reader& r = c.reader;
    const Token sizeAt = r.peek();
    const double w = r.parseFloat();
    r.accept(Sym::Comma);
    const double h = r.parseFloat();
    if (!(w >= 2 && h >= 2))
        r.fail(sizeAt, "a function image needs a resolution of at least 2 x 2");
    if (w * h > double(r.frame().limits.arrayElements))
        r.fail(sizeAt, fmt::format("function image resolution {} x {} has more than {} samples", w,
                                   h, r.frame().limits.arrayElements));
    const std::shared_ptr<const CompiledFunction> fn = r.parseXyzFunction(at);
    const int width = static_cast<int>(w), height = static_cast<int>(h);
    auto pixels =
        std::make_shared<util::PixelBuffer>(width, height, 1, util::PixelBuffer::Sample::U16);
    // As a height_field function (measured with pigment functions): pixel
    // (i, j), j = 0 the top row, holds f(i / (W - 1), j / (H - 1), 0) as
    // 16 bits, truncated and wrapped (1.1 reads back as 0.1).
    for (int j = 0; j < height; ++j) {
        auto* row = reinterpret_cast<std::uint16_t*>(pixels->row(j));
        for (int i = 0; i < width; ++i) {
            double args[3] = {static_cast<double>(i) / (width - 1),
                              static_cast<double>(j) / (height - 1), 0.0};
            double value;
            try {
                value = fn->eval(args);
            } catch (const std::runtime_error& e) {
                r.fail(at, e.what());
            }
            const auto level = static_cast<long long>(value * 65535.0);
            row[i] = static_cast<std::uint16_t>(static_cast<unsigned long long>(level) & 0xFFFFu);
        }
    }
    image::SourceImage src;
    src.pixels = std::move(pixels);
    return src;
}

// One item of an image block (gamma, map_type, interpolate, filter...)
// into `s`; `keyword` names the block, a material_map's textures go to
// `materials`.
static void parseImageSetting(BuildContext& c, const Token& keyword, ImageUse use, ImageSettings& s,
                              std::vector<std::shared_ptr<const scene::Texture>>* materials) {
    Reader& r = c.reader;
    const Token item = r.peek();
    switch (item.kw) {
        case Keyword::kw_pattern:
            // povray 3.7 has no pattern images (measured).
            r.fail(item, "Expected 'map file spec', pattern found");
        case Keyword::kw_gamma: {
            r.next();
            if (r.accept(Keyword::kw_srgb)) {
                s.gamma = 0.0;
            } else {
                const double g = r.parseFloat();
                if (g <= 0) r.fail(item, "image gamma must be positive");
                s.gamma = g;
            }
            break;
        }
        case Keyword::kw_premultiplied:
            r.next();
            s.premultiplied = r.parseOptionalBool();
            break;
        case Keyword::kw_map_type: {
            r.next();
            const Token at = r.peek();
            const int m = static_cast<int>(r.parseFloat());
            // povray 3.7 (measured): image_map takes only 0, 1, 2 and 5;
            // image_pattern, bump_map and material_map map every other
            // value (3, 4, 6, 7 ...) as 0.
            if (m == 0 || m == 1 || m == 2 || m == 5)
                s.mapping = static_cast<scene::ImageMapping>(m);
            else if (use == ImageUse::Pigment)
                r.fail(at, "Invalid map_type value.");
            else
                s.mapping = scene::ImageMapping::Planar;
            break;
        }
        case Keyword::kw_once:
            r.next();
            s.once = true;
            break;
        case Keyword::kw_interpolate: {
            r.next();
            const Token at = r.peek();
            const int i = static_cast<int>(r.parseFloat());
            if (i == 2)
                s.interpolation = scene::ImageInterpolation::Bilinear;
            else if (i == 4)
                s.interpolation = scene::ImageInterpolation::NormalizedDistance;
            else if (i == 3)
                s.interpolation = scene::ImageInterpolation::Bicubic;
            else
                r.fail(at, "Invalid interpolate value.");
            break;
        }
        case Keyword::kw_texture:
            if (use != ImageUse::Material || !materials)
                r.fail(item, fmt::format("'texture' is not allowed in {}", keyword.text));
            materials->push_back(parseTexture(c, nullptr));
            break;
        case Keyword::kw_filter:
        case Keyword::kw_transmit: {
            r.next();
            if (use == ImageUse::Bump || use == ImageUse::Material)
                r.fail(item, fmt::format("'{}' is not allowed in bump_map", item.text));
            ImageSettings::Amount a{item.is(Keyword::kw_filter), -1, 0, item};
            if (!r.accept(Keyword::kw_all)) {
                const double index = r.parseFloat();
                if (index < 0 || index > 255)
                    r.fail(item, fmt::format("palette index {} out of range", index));
                a.index = static_cast<int>(index);
                r.accept(Sym::Comma);
            }
            a.value = r.parseFloat();
            s.amounts.push_back(a);
            break;
        }
        case Keyword::kw_use_index:
        case Keyword::kw_use_color:
        case Keyword::kw_use_colour:
            r.next();
            s.useIndex = item.is(Keyword::kw_use_index);
            break;
        case Keyword::kw_use_alpha:
            r.next();
            s.useAlpha = true;
            break;
        case Keyword::kw_bump_size:
            if (use != ImageUse::Bump)
                r.fail(item, fmt::format("'bump_size' is not allowed in {}", keyword.text));
            r.next();
            s.bumpSize = r.parseFloat();
            s.bumpSizeGiven = true;
            break;
        default:
            if (item.kind == TokenKind::Word && item.kw != Keyword::None)
                r.unsupported(item, fmt::format("'{}' in {}", item.text, keyword.text));
            r.fail(item, fmt::format("expected a {} item or '}}', found {}", keyword.text,
                                     describeToken(item)));
    }
}

// The texels of `src` for an image block: colours for an image_map (in the
// working gamma), scalars for the others, read from the file's pixels.
static std::shared_ptr<const scene::ImageTexels> imageTexels(BuildContext& c,
                                                             const image::SourceImage& src,
                                                             const ImageSettings& s, ImageUse use,
                                                             bool fromFunction) {
    if (use != ImageUse::Pigment) {
        using Scalar = scene::ImageTexels::Scalar;
        const Scalar scalar = use == ImageUse::Bump && s.useIndex && src.isPalette() ? Scalar::Index
                              : use == ImageUse::Material ? Scalar::MaterialIndex
                              : s.useAlpha                ? Scalar::Alpha
                                                          : Scalar::Grey;
        return std::make_shared<const scene::ImageTexels>(src.pixels, scalar);
    }
    // File values -> linear light -> the working gamma in force now.
    scene::ImageTexels::ColorDecoding d;
    // Before 3.7 a file whose gamma neither the scene (`gamma`) nor the
    // file (PNG gAMA or sRGB chunk) gives holds working-space values,
    // whatever the assumed_gamma (measured: #version 3.6, assumed_gamma 2.2
    // shows the file value v as v^2.2 of linear light); what the file
    // says counts only in a scene that sets assumed_gamma (measured: a
    // 3.6 scene without it shows gAMA 1/2.2 and 1/1.8 files as stored). A
    // PNG sRGB chunk is the sRGB curve, with or without gAMA (measured). A
    // function image's values are working-space values whatever the
    // assumed_gamma (measured).
    const bool pre37 = c.reader.version() < 3.7 - 1e-9;
    const bool fileSays = src.declaresSrgb || src.declaredGamma > 0;
    const bool fileGammaKnown =
        s.gamma || (fileSays && (!pre37 || c.scene.globals.assumedGammaSet));
    d.asStored = (!fileGammaKnown && pre37) || fromFunction;
    d.workingGamma = c.scene.globals.assumedGammaSet ? c.scene.globals.assumedGamma : 1.0;
    d.fileGamma = s.gamma                 ? *s.gamma
                  : src.declaresSrgb      ? 0.0
                  : src.declaredGamma > 0 ? src.declaredGamma
                                          : defaultFileGamma(s.type, s.name);
    d.premultiplied = s.premultiplied;
    // Palette images: filter and transmit per palette entry.
    for (const auto& a : s.amounts) {
        auto& table = a.filter ? d.paletteFilter : d.paletteTransmit;
        if (a.index >= 0) {
            table[static_cast<std::size_t>(a.index)] = a.value;
        } else {
            table.fill(a.value);
            (a.filter ? d.filterAll : d.transmitAll) = a.value;
        }
    }
    return std::make_shared<const scene::ImageTexels>(src.pixels, d);
}

std::shared_ptr<const scene::ImageMap> parseImageBlock(
    BuildContext& c, const Token& keyword, double* bumpSize,
    std::vector<std::shared_ptr<const scene::Texture>>* materials) {
    Reader& r = c.reader;
    const ImageUse use = keyword.is(Keyword::kw_image_map)       ? ImageUse::Pigment
                         : keyword.is(Keyword::kw_image_pattern) ? ImageUse::Pattern
                         : keyword.is(Keyword::kw_material_map)  ? ImageUse::Material
                                                                 : ImageUse::Bump;
    r.expectAfter(Sym::LBrace, "{", keyword.text);
    ImageSettings s;
    bool haveFile = false;
    std::optional<image::SourceImage> functionImage;  // `function W, H { }`
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token item = r.peek();
        if (!haveFile &&
            (isImageType(item.kw) || item.kind == TokenKind::String || item.isIdentifier())) {
            if (isImageType(item.kw)) {
                r.next();
                s.type = item.kw;
            }
            s.nameAt = r.peek();
            s.name = r.parsePathname();
            haveFile = true;
            continue;
        }
        if (!haveFile && item.is(Keyword::kw_function)) {
            r.next();
            functionImage = functionSourceImage(c, item);
            haveFile = true;
            continue;
        }
        parseImageSetting(c, keyword, use, s, materials);
    }
    if (!haveFile) r.fail(keyword, fmt::format("{} needs an image file", keyword.text));
    if (use == ImageUse::Material && materials->empty())
        r.fail(keyword, "material_map needs at least one texture");
    if (s.mapping == scene::ImageMapping::Spherical || s.mapping == scene::ImageMapping::Torus)
        s.once = false;  // the image covers these exactly once anyway

    const image::SourceImage& src =
        functionImage ? *functionImage : loadSourceImage(c, s.name, s.nameAt);
    for (const auto& a : s.amounts)
        if (a.index >= 0 && !src.isPalette())
            r.fail(a.at, fmt::format("Keyword '{}' cannot be used with non color-mapped image.",
                                     a.at.text));

    auto texels = imageTexels(c, src, s, use, functionImage.has_value());
    if (bumpSize && s.bumpSizeGiven) *bumpSize = s.bumpSize;
    return std::make_shared<const scene::ImageMap>(std::move(texels), s.mapping, s.once,
                                                   s.interpolation);
}

bool parseImagePigmentItem(BuildContext& c, scene::Pigment& pigment) {
    Reader& r = c.reader;
    const Token item = r.peek();
    if (item.is(Keyword::kw_image_map)) {
        r.next();
        pigment.setImageMap(parseImageBlock(c, item, nullptr));
        return true;
    }
    // Read through the const view: a plain colour's pigment keeps no
    // pattern part unless an item sets one (issue 23).
    scene::Pattern pattern = std::as_const(pigment).pattern();
    if (!parseImagePatternItem(c, pattern)) return false;
    pigment.setPattern(pattern);
    return true;
}

bool parseImagePatternItem(BuildContext& c, scene::Pattern& pattern) {
    Reader& r = c.reader;
    const Token item = r.peek();
    if (!item.is(Keyword::kw_image_pattern)) return false;
    r.next();
    pattern.kind = scene::PatternKind::Image;
    pattern.image = parseImageBlock(c, item, nullptr);
    return true;
}

bool parseImageNormalItem(BuildContext& c, scene::Normal& normal, scene::Pattern& pattern) {
    Reader& r = c.reader;
    const Token item = r.peek();
    if (item.is(Keyword::kw_bump_map)) {
        r.next();
        normal.bumpMap = parseImageBlock(c, item, &normal.amount);
        return true;
    }
    return parseImagePatternItem(c, pattern);
}

}  // namespace frameray::sdl
