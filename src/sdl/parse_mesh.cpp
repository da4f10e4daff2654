// Triangle-based objects (seed 000 / 003 §5.2):
//
//     mesh { triangle { a, b, c [texture { T }] } smooth_triangle { ... } ...
//            [inside_vector V] [hierarchy B] [object modifiers] }
//     mesh2 { vertex_vectors { n, v... } [normal_vectors { n, v... }]
//             [uv_vectors { n, uv... }] [texture_list { n, texture {...}... }]
//             face_indices { n, <a,b,c> [, t]... } [normal_indices { n, ... }]
//             [uv_indices { n, ... }] [inside_vector V] [object modifiers] }
//     height_field { png "file" | function W, H { f(x, y, z) }
//                    [smooth] [water_level L] [hierarchy B] [modifiers] }
//     bicubic_patch { type 0|1 [flatness F] [u_steps U] [v_steps V] 16 points }
//
// A mesh whose triangles carry their own textures becomes a union of one
// primitive per texture, all sharing the mesh's geometry (MeshShape over a
// group); the triangles without a texture take the mesh object's.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/image_io.h"
#include "scene/bicubic_patch.h"
#include "scene/height_field.h"
#include "scene/mesh.h"
#include "sdl/builders.h"
#include "sdl/function_value.h"

namespace frameray::sdl {

// What a mesh or mesh2 collects before it is built.
struct MeshParts {
    std::vector<Vec3> vertices;
    std::vector<Vec3> normals;
    std::vector<scene::MeshTriangle> triangles;
    std::vector<std::array<double, 2>> uvs;  // uv_vectors, for uv_mapping
    std::vector<std::shared_ptr<const scene::Texture>> textures;
    bool hasInsideVector = false;
    Vec3 insideVector;
};

static void buildMeshObject(scene::Object& obj, MeshParts& parts) {
    auto built = std::make_shared<scene::TriangleMesh>(
        std::move(parts.vertices), std::move(parts.normals), std::move(parts.triangles));
    built->setUvs(std::move(parts.uvs));
    const std::shared_ptr<const scene::TriangleMesh> mesh = std::move(built);
    if (mesh->groupCount() <= 1) {
        const int32_t tex = mesh->groupCount() == 1 ? mesh->groupTexture(0) : -1;
        obj.shape = std::make_shared<scene::MeshShape>(mesh, scene::TriangleMesh::kAllGroups,
                                                       parts.hasInsideVector, parts.insideVector);
        if (tex >= 0) {
            // Every triangle has the same texture: the mesh is one
            // primitive inside a union, so the object's own texture (if
            // any) still reaches no triangle.
            auto child = std::make_shared<scene::Object>();
            child->shape = obj.shape;
            child->texture = parts.textures[static_cast<size_t>(tex)];
            obj.shape.reset();
            obj.op = scene::CsgOp::Union;
            obj.children.push_back(child);
        }
        return;
    }
    obj.op = scene::CsgOp::Union;
    for (size_t g = 0; g < mesh->groupCount(); ++g) {
        auto child = std::make_shared<scene::Object>();
        child->shape = std::make_shared<scene::MeshShape>(
            mesh, static_cast<int>(g), parts.hasInsideVector, parts.insideVector);
        const int32_t tex = mesh->groupTexture(g);
        if (tex >= 0) child->texture = parts.textures[static_cast<size_t>(tex)];
        obj.children.push_back(child);
    }
}

static bool parseMeshSetting(BuildContext& c, MeshParts& parts) {
    Reader& r = c.reader;
    const Token t = r.peek();
    if (t.is(Keyword::kw_inside_vector)) {
        r.next();
        parts.insideVector = r.parseVec3();
        parts.hasInsideVector = length(parts.insideVector) > 0;
        return true;
    }
    if (t.is(Keyword::kw_hierarchy)) {
        r.next();
        r.parseOptionalBool();
        return true;
    }
    return false;
}

// A triangle's texture inside mesh { }: texture { } (texture_list with
// three textures, interpolated over the triangle, is not built).
static void parseMeshTriangleItems(BuildContext& c, MeshParts& parts, scene::MeshTriangle& tri) {
    Reader& r = c.reader;
    for (;;) {
        if (r.accept(Sym::RBrace)) return;
        const Token t = r.peek();
        if (t.is(Keyword::kw_texture)) {
            // povray takes only a declared texture here: texture { T }.
            r.next();
            r.expect(Sym::LBrace, "'{' after 'texture'");
            const Token id = r.next();
            const Value v = id.isIdentifier() ? r.identifierValue(id) : Value{};
            const auto* tp = std::get_if<TexturePtr>(&v);
            if (!tp)
                r.fail(id, fmt::format("Expected 'texture identifier', {} found instead",
                                       describeToken(id)));
            r.expect(Sym::RBrace, "'}' after the texture identifier");
            parts.textures.push_back(*tp);
            tri.texture = static_cast<int32_t>(parts.textures.size() - 1);
        } else if (t.is(Keyword::kw_uv_vectors)) {
            // The corners' uv for uv_mapping textures.
            r.next();
            for (int i = 0; i < 3; ++i) {
                if (i) r.accept(Sym::Comma);
                const Token at = r.peek();
                const VectorValue uv = r.toVector(r.parseExpression(), at, 2);
                tri.uv[static_cast<size_t>(i)] = static_cast<int32_t>(parts.uvs.size());
                parts.uvs.push_back({uv.v[0], uv.v[1]});
            }
        } else if (t.is(Keyword::kw_texture_list)) {
            r.unsupported(t, "texture_list in a mesh triangle (interpolated textures)");
        } else {
            r.fail(t, fmt::format("expected a texture or '}}' in a mesh triangle, found {}",
                                  describeToken(t)));
        }
    }
}

namespace {

// A mesh object: its shape, or (triangles with their own textures) a union
// of its texture groups.
bool isMeshObject(const scene::Object& obj) {
    if (obj.shape) return dynamic_cast<const scene::MeshShape*>(obj.shape.get()) != nullptr;
    return !obj.children.empty() &&
           std::all_of(obj.children.begin(), obj.children.end(),
                       [](const scene::ObjectRef& c) { return c && isMeshObject(*c); });
}

}  // namespace

void parseMeshBody(BuildContext& c, const Token&, ObjectValue& object) {
    Reader& r = c.reader;
    // mesh { DECLARED_MESH modifiers } copies the declared mesh as object { }
    // would (povray 3.7; no triangles may follow).
    if (const Token id = r.peek(); id.isIdentifier()) {
        r.next();
        const Value v = r.identifierValue(id);
        const auto* src = std::get_if<ObjectPtr>(&v);
        if (!src || !isMeshObject(*(*src)->object))
            r.fail(id, fmt::format("'{}' is not a mesh", id.text));
        object.object = std::make_shared<scene::Object>(*(*src)->object);
        return;
    }
    scene::Object& obj = *object.object;
    MeshParts parts;
    for (;;) {
        const Token t = r.peek();
        if (t.is(Keyword::kw_triangle) || t.is(Keyword::kw_smooth_triangle)) {
            r.next();
            const bool smooth = t.is(Keyword::kw_smooth_triangle);
            r.expect(Sym::LBrace, smooth ? "'{' after 'smooth_triangle'" : "'{' after 'triangle'");
            scene::MeshTriangle tri;
            for (int i = 0; i < 3; ++i) {
                if (i) r.accept(Sym::Comma);
                tri.vertex[static_cast<size_t>(i)] = static_cast<uint32_t>(parts.vertices.size());
                parts.vertices.push_back(r.parseVec3());
                if (smooth) {
                    r.accept(Sym::Comma);
                    tri.normal[static_cast<size_t>(i)] = static_cast<int32_t>(parts.normals.size());
                    parts.normals.push_back(r.parseVec3());
                }
            }
            parseMeshTriangleItems(c, parts, tri);
            parts.triangles.push_back(tri);
            continue;
        }
        if (parseMeshSetting(c, parts)) continue;
        break;
    }
    if (parts.triangles.empty()) r.fail(r.peek(), "Mesh contains no triangles.");
    buildMeshObject(obj, parts);
}

// `{ n, item, item, ... }` of a mesh2 list; `item` reads one entry.
template <typename ReadItem>
static size_t parseMesh2List(BuildContext& c, const Token& kw, ReadItem readItem) {
    Reader& r = c.reader;
    r.next();
    r.expect(Sym::LBrace, fmt::format("'{{' after '{}'", kw.text).c_str());
    const double count = r.parseFloat();
    if (count < 0 || count != std::floor(count))
        r.fail(kw, fmt::format("bad number of items in {}", kw.text));
    const auto n = static_cast<size_t>(count);
    for (size_t i = 0; i < n; ++i) {
        r.accept(Sym::Comma);
        readItem(i);
    }
    r.accept(Sym::Comma);
    r.expect(Sym::RBrace,
             fmt::format("'}}' closing '{}' (more items than its count?)", kw.text).c_str());
    return n;
}

void parseMesh2Body(BuildContext& c, const Token&, ObjectValue& object) {
    scene::Object& obj = *object.object;
    Reader& r = c.reader;
    MeshParts parts;
    std::vector<std::array<int64_t, 3>> faces, normalFaces;
    std::vector<int64_t> faceTextures;
    // Where each face starts, for messages: the first face's token, and
    // every face's line and column (a million faces: 8 bytes each).
    Token firstFace;
    std::vector<std::array<uint32_t, 2>> faceAt;
    const auto faceToken = [&](size_t i) {
        Token at = firstFace;
        at.line = faceAt[i][0];
        at.column = faceAt[i][1];
        return at;
    };
    bool haveNormalIndices = false;
    std::vector<std::array<int64_t, 3>> uvFaces;
    bool haveUvIndices = false;
    for (;;) {
        const Token t = r.peek();
        switch (t.kw) {
            case Keyword::kw_vertex_vectors:
                parseMesh2List(c, t, [&](size_t) { parts.vertices.push_back(r.parseVec3()); });
                continue;
            case Keyword::kw_normal_vectors:
                parseMesh2List(c, t, [&](size_t) { parts.normals.push_back(r.parseVec3()); });
                continue;
            case Keyword::kw_uv_vectors:
                parseMesh2List(c, t, [&](size_t) {
                    const Token at = r.peek();
                    const VectorValue uv = r.toVector(r.parseExpression(), at, 2);
                    parts.uvs.push_back({uv.v[0], uv.v[1]});
                });
                continue;
            case Keyword::kw_uv_indices:
                haveUvIndices = true;
                parseMesh2List(c, t, [&](size_t) {
                    const Vec3 f = r.parseVec3();
                    uvFaces.push_back({std::llround(f.x), std::llround(f.y), std::llround(f.z)});
                });
                continue;
            case Keyword::kw_texture_list:
                parseMesh2List(c, t, [&](size_t) {
                    const Token at = r.peek();
                    if (!at.is(Keyword::kw_texture))
                        r.fail(at, fmt::format("expected a texture in texture_list, found {}",
                                               describeToken(at)));
                    parts.textures.push_back(parseTexture(c, nullptr));
                });
                continue;
            case Keyword::kw_face_indices:
                parseMesh2List(c, t, [&](size_t) {
                    const Token at = r.peek();
                    if (faceAt.empty()) firstFace = at;
                    faceAt.push_back({at.line, at.column});
                    const Vec3 f = r.parseVec3();
                    faces.push_back({std::llround(f.x), std::llround(f.y), std::llround(f.z)});
                    int64_t tex = -1;
                    if (!parts.textures.empty()) {
                        r.accept(Sym::Comma);
                        tex = std::llround(r.parseFloat());
                        // Three indices: a texture interpolated over the
                        // triangle, unless they are all the same.
                        const Token afterIndex = r.peek();
                        if (afterIndex.is(Sym::Comma)) {
                            r.next();
                            const Token second = r.peek();
                            if (!second.is(Sym::Less)) {
                                const int64_t t2 = std::llround(r.parseFloat());
                                r.accept(Sym::Comma);
                                const int64_t t3 = std::llround(r.parseFloat());
                                if (t2 != tex || t3 != tex)
                                    r.unsupported(second, "mesh2 faces with three texture indices");
                            }
                        }
                    }
                    faceTextures.push_back(tex);
                });
                continue;
            case Keyword::kw_normal_indices:
                haveNormalIndices = true;
                parseMesh2List(c, t, [&](size_t) {
                    const Vec3 f = r.parseVec3();
                    normalFaces.push_back(
                        {std::llround(f.x), std::llround(f.y), std::llround(f.z)});
                });
                continue;
            default:
                break;
        }
        if (parseMeshSetting(c, parts)) continue;
        break;
    }
    if (faces.empty()) r.fail(r.peek(), "Mesh contains no triangles.");
    // Without normal_indices, normals are per vertex when there are as many.
    const bool perVertexNormals = !haveNormalIndices && !parts.normals.empty();
    if (perVertexNormals && parts.normals.size() != parts.vertices.size())
        r.fail(firstFace,
               "Number of normals does not match the number of vertices (normal_indices needed).");
    if (haveNormalIndices && normalFaces.size() != faces.size())
        r.fail(firstFace, "Number of normal indices does not match the number of faces.");
    if (haveUvIndices && uvFaces.size() != faces.size())
        r.fail(firstFace, "Number of uv indices does not match the number of faces.");
    parts.triangles.reserve(faces.size());
    for (size_t i = 0; i < faces.size(); ++i) {
        scene::MeshTriangle tri;
        for (size_t k = 0; k < 3; ++k) {
            if (faces[i][k] < 0 || faces[i][k] >= static_cast<int64_t>(parts.vertices.size()))
                r.fail(faceToken(i), "Mesh face index out of range.");
            tri.vertex[k] = static_cast<uint32_t>(faces[i][k]);
            if (perVertexNormals) tri.normal[k] = static_cast<int32_t>(faces[i][k]);
            if (haveNormalIndices) {
                if (normalFaces[i][k] < 0 ||
                    normalFaces[i][k] >= static_cast<int64_t>(parts.normals.size()))
                    r.fail(faceToken(i), "Mesh normal index out of range.");
                tri.normal[k] = static_cast<int32_t>(normalFaces[i][k]);
            }
            // uv per face, else per vertex (an index past the list leaves
            // the triangle without uv).
            const int64_t uvIndex = haveUvIndices ? uvFaces[i][k] : faces[i][k];
            if (uvIndex >= 0 && uvIndex < static_cast<int64_t>(parts.uvs.size()))
                tri.uv[k] = static_cast<int32_t>(uvIndex);
        }
        if (faceTextures[i] >= static_cast<int64_t>(parts.textures.size()))
            r.fail(faceToken(i), "Texture index out of range in mesh2.");
        tri.texture = static_cast<int32_t>(faceTextures[i]);
        parts.triangles.push_back(tri);
    }
    // Freed before the mesh and its BVH are built (the peak).
    for (auto* list : {&faces, &normalFaces, &uvFaces})
        std::vector<std::array<int64_t, 3>>().swap(*list);
    std::vector<int64_t>().swap(faceTextures);
    std::vector<std::array<uint32_t, 2>>().swap(faceAt);
    buildMeshObject(obj, parts);
}

namespace {

// povray 3.7's heights from an image's pixels (measured with trace()):
// grey values as 16 bits (8-bit v as v * 257), colour pixels as red * 256 +
// green for 8-bit images.
std::vector<uint16_t> heightsFromImage(const util::PixelBuffer& img) {
    std::vector<uint16_t> out(img.pixelCount());
    if (img.isPalette()) {
        // Palette images (GIF, palette PNG): the colour index is the
        // height, as the high byte (seed 003: index 0 lowest, 255 highest).
        for (size_t p = 0; p < out.size(); ++p) out[p] = static_cast<uint16_t>(img.index(p) * 256);
        return out;
    }
    const bool grey = img.channels() < 3;
    if (img.sample() == util::PixelBuffer::Sample::U8) {
        for (size_t p = 0; p < out.size(); ++p) {
            const uint32_t r = img.level(p, 0), g = grey ? r : img.level(p, 1);
            out[p] = static_cast<uint16_t>(r * 256 + g);
        }
    } else {
        // 16 bits and floats (clamped to [0,1], scaled to 16 bits).
        for (size_t p = 0; p < out.size(); ++p) out[p] = static_cast<uint16_t>(img.level(p, 0));
    }
    return out;
}

}  // namespace

void parseHeightFieldBody(BuildContext& c, const Token&, ObjectValue& object) {
    scene::Object& obj = *object.object;
    Reader& r = c.reader;
    const Token source = r.peek();
    int width = 0, height = 0;
    std::vector<uint16_t> heights;
    if (source.is(Keyword::kw_function)) {
        r.next();
        const Token sizeAt = r.peek();
        const double w = r.parseFloat();
        r.accept(Sym::Comma);
        const double h = r.parseFloat();
        if (!(w >= 2 && h >= 2))
            r.fail(sizeAt, "height_field function needs a resolution of at least 2 x 2");
        // Checked before the samples are allocated (and the sizes made ints).
        if (w * h > double(r.frame().limits.arrayElements))
            r.fail(sizeAt,
                   fmt::format("height_field function resolution {} x {} has more than {} samples",
                               w, h, r.frame().limits.arrayElements));
        width = static_cast<int>(w);
        height = static_cast<int>(h);
        const std::shared_ptr<const CompiledFunction> fn = r.parseXyzFunction(source, true);
        heights.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
        // Sample (i, j) sees x = i / (W - 1), y = j / (H - 1) (j = 0 is the
        // row at z = 1, as an image's top row); the value is kept as povray
        // keeps it: times 65535, truncated, wrapped to 16 bits.
        for (int j = 0; j < height; ++j)
            for (int i = 0; i < width; ++i) {
                double args[3] = {static_cast<double>(i) / (width - 1),
                                  static_cast<double>(j) / (height - 1), 0.0};
                double value;
                try {
                    value = fn->eval(args);
                } catch (const std::runtime_error& e) {
                    r.fail(source, e.what());
                }
                const auto level = static_cast<long long>(value * 65535.0);
                heights[static_cast<size_t>(j) * static_cast<size_t>(width) +
                        static_cast<size_t>(i)] =
                    static_cast<uint16_t>(static_cast<unsigned long long>(level) & 0xFFFFu);
            }
    } else {
        switch (source.kw) {
            case Keyword::kw_png:
            case Keyword::kw_tga:
            case Keyword::kw_pgm:
            case Keyword::kw_ppm:
            case Keyword::kw_jpeg:
            case Keyword::kw_tiff:
            case Keyword::kw_exr:
            case Keyword::kw_hdr:
            case Keyword::kw_sys:
            case Keyword::kw_gif:
            case Keyword::kw_pot:
                r.next();
                break;
            case Keyword::kw_iff:
                r.unsupported(source, "iff height fields");
            default:
                // povray 3.7 takes a bare file name too, its type read from
                // the file (the example advanced/crater/crater.pov); a
                // literal only, not a string identifier (measured).
                if (source.kind == TokenKind::String) break;
                r.fail(source,
                       fmt::format("expected an image type or 'function' in height_field, found {}",
                                   describeToken(source)));
        }
        const bool pot = source.is(Keyword::kw_pot);
        const Token nameAt = r.peek();
        const std::string name = r.parsePathname();
        // The same per-frame image cache as image maps (parse_image_map.cpp).
        const image::SourceImage& source = loadSourceImage(c, name, nameAt);
        if (source.width() < 2 || source.height() < 2)
            r.fail(nameAt, "a height_field image must be at least 2 x 2 pixels");
        width = source.width();
        height = source.height();
        if (pot) {
            // Fractint's continuous-potential file: a GIF twice as wide as
            // the field, each row's left half the heights' high bytes and
            // its right half their low bytes (seed 003: "a GIF file with a
            // 16 bit palette").
            if (!source.isPalette() || source.width() % 2 != 0)
                r.fail(nameAt, "a pot file must be a GIF image of even width");
            const util::PixelBuffer& px = *source.pixels;
            width = source.width() / 2;
            heights.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
            for (int j = 0; j < height; ++j)
                for (int i = 0; i < width; ++i) {
                    const size_t row = static_cast<size_t>(j) * static_cast<size_t>(px.width());
                    heights[static_cast<size_t>(j) * static_cast<size_t>(width) +
                            static_cast<size_t>(i)] =
                        static_cast<uint16_t>(px.index(row + static_cast<size_t>(i)) * 256 +
                                              px.index(row + static_cast<size_t>(i + width)));
                }
        } else {
            heights = heightsFromImage(*source.pixels);
        }
    }
    bool smooth = false;
    double waterLevel = 0;
    for (;;) {
        const Token t = r.peek();
        if (t.is(Keyword::kw_smooth)) {
            r.next();
            smooth = r.parseOptionalBool();
        } else if (t.is(Keyword::kw_water_level)) {
            r.next();
            waterLevel = r.parseFloat();
        } else if (t.is(Keyword::kw_hierarchy)) {
            r.next();
            r.parseOptionalBool();
        } else {
            break;
        }
    }
    obj.shape =
        std::make_shared<scene::HeightField>(width, height, std::move(heights), smooth, waterLevel);
}

std::shared_ptr<const scene::Shape> parseBicubicPatch(BuildContext& c, const Token&) {
    Reader& r = c.reader;
    // The settings' numbers stop before a '<': "v_steps 3 <0, 0, 0>" is a
    // step count and the first point, not a comparison (as in povray).
    auto setting = [&]() {
        const Token at = r.peek();
        return r.toFloat(r.parseAdditive(), at);
    };
    int type = -1, uSteps = 0, vSteps = 0;
    double flatness = 0;
    scene::BicubicPatch::UvCorners uvCorners = scene::BicubicPatch::kUnitUvCorners;
    const Token start = r.peek();
    for (;;) {
        const Token t = r.peek();
        if (t.is(Keyword::kw_type)) {
            r.next();
            type = static_cast<int>(setting());
            if (type != 0 && type != 1) r.fail(t, "Patch type must be 0 or 1.");
        } else if (t.is(Keyword::kw_flatness)) {
            r.next();
            flatness = setting();
        } else if (t.is(Keyword::kw_u_steps)) {
            r.next();
            uSteps = static_cast<int>(setting());
        } else if (t.is(Keyword::kw_v_steps)) {
            r.next();
            vSteps = static_cast<int>(setting());
        } else if (t.is(Keyword::kw_uv_vectors)) {
            r.next();
            for (auto& corner : uvCorners) {
                r.accept(Sym::Comma);
                const VectorValue uv = r.parseVector();
                corner = {uv.v[0], uv.v[1]};
            }
        } else {
            break;
        }
    }
    if (type < 0) r.fail(start, "bicubic_patch needs 'type 0' or 'type 1'");
    // povray keeps u_steps and v_steps within 0..16 ... a depth that is
    // already 4 billion triangles; far less is sane.
    uSteps = std::clamp(uSteps, 0, 10);
    vSteps = std::clamp(vSteps, 0, 10);
    std::array<Vec3, 16> points;
    for (size_t i = 0; i < 16; ++i) {
        r.accept(Sym::Comma);  // commas are optional, also before the first point (povray)
        points[i] = r.parseVec3();
    }
    return std::make_shared<scene::BicubicPatch>(points, uSteps, vSteps, flatness, Transform(),
                                                 uvCorners);
}

}  // namespace frameray::sdl
