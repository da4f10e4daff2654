// The scene-language interpreter: one per frame, owning all parse state
// (DESIGN.md: nothing global, so frames can overlap). It reads tokens from
// the shared TokenCache and builds a scene::Scene. The work is split in
// two (DESIGN.md "The language core and the builders"):
//   reader.h      the language core: token stream, directives, macros,
//                 identifiers, expressions;
//   builders.h    the statement builders, free functions registered by
//                 keyword in one table (builders.cpp), which read scene
//                 items through the reader and return what they build.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "sdl/diagnostics.h"
#include "sdl/frame_context.h"
#include "sdl/token_cache.h"
#include "sdl/value.h"

namespace frameray::sdl {

class Reader;
struct BuildContext;
class SceneValueBuilders;

class Interpreter {
  public:
    Interpreter(const FrameContext& frame, TokenCache& cache, MessageSink& messages);
    ~Interpreter();
    Interpreter(const Interpreter&) = delete;
    Interpreter& operator=(const Interpreter&) = delete;

    // Parses a scene file into a Scene. Throws SdlError on the first error.
    scene::Scene parseFile(const std::filesystem::path& sceneFile);
    // The files the parse read (the scene, includes, images, fonts, data
    // read with #fopen) and wrote (#fopen write/append), in order, as
    // found: what the frame was made from, for the resume journal.
    const std::vector<std::filesystem::path>& filesRead() const;
    const std::vector<std::filesystem::path>& filesWritten() const;
    // Parses scene text (tests, one-liners); `name` is used in messages.
    scene::Scene parseText(const std::string& name, const std::string& text);

    // Identifier lookup after parsing (tests).
    const Value* lookup(std::string_view name) const;

  private:
    scene::Scene run(const std::shared_ptr<const TokenizedFile>& file, std::string inputFileName);

    TokenCache& cache_;
    MessageSink& messages_;
    // The scene keeps fonts and images the context holds: both live as
    // long as the interpreter.
    std::unique_ptr<Reader> reader_;
    std::unique_ptr<BuildContext> context_;
    std::unique_ptr<SceneValueBuilders> builders_;
};

}  // namespace frameray::sdl
