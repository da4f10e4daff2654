#include "sdl/interpreter.h"

#include <fmt/format.h>

#include "sdl/build_context.h"
#include "sdl/builders.h"
#include "sdl/reader.h"

namespace frameray::sdl {

namespace fs = std::filesystem;

Interpreter::Interpreter(const FrameContext& frame, TokenCache& cache, MessageSink& messages)
    : cache_(cache),
      messages_(messages),
      reader_(std::make_unique<Reader>(frame, cache, messages)),
      context_(std::make_unique<BuildContext>(*reader_)),
      builders_(std::make_unique<SceneValueBuilders>(*context_)) {
    reader_->setBuilders(builders_.get());
}

Interpreter::~Interpreter() = default;

scene::Scene Interpreter::parseFile(const fs::path& sceneFile) {
    auto file = cache_.get(sceneFile);
    if (!file) throw SdlError({}, fmt::format("cannot open scene file '{}'", sceneFile.string()));
    reader_->noteFileRead(sceneFile);
    // povray gives the bare name as input_file_name.
    return run(file, sceneFile.filename().string());
}

scene::Scene Interpreter::parseText(const std::string& name, const std::string& text) {
    return run(TokenCache::fromText(name, text), {});
}

const std::vector<fs::path>& Interpreter::filesRead() const {
    return reader_->filesRead();
}

const std::vector<fs::path>& Interpreter::filesWritten() const {
    return reader_->filesWritten();
}

const Value* Interpreter::lookup(std::string_view name) const {
    return reader_->lookup(name);
}

scene::Scene Interpreter::run(const std::shared_ptr<const TokenizedFile>& file,
                              std::string inputFileName) {
    Reader& r = *reader_;
    r.begin(file, std::move(inputFileName));
    try {
        while (parseStatement(*context_)) {
        }
    } catch (const SdlError& e) {
        // The cursors still show how the parse got there.
        if (!e.notes().empty()) throw;
        throw SdlError(e.loc(), e.message(), r.includeChain(e.loc()));
    }
    r.end();
    scene::Scene& scene = context_->scene;
    scene.languageVersion = r.version();
    scene.versionDeclared = r.versionSeen();
    const std::string scenePath = file->source->path();
    if (scene.objects.empty())
        messages_.message(Stream::Warning, scenePath + ": warning: no objects in scene");
    if (!r.versionSeen())
        messages_.message(Stream::Warning,
                          scenePath +
                              ": warning: the scene has no #version directive; as of "
                              "POV-Ray 3.7 one is expected as its first declaration");
    else if (r.declarationBeforeVersion())
        messages_.message(Stream::Warning, scenePath +
                                               ": warning: declarations precede the first #version "
                                               "directive, which POV-Ray 3.7 expects first");
    // povray 3.7 warns about a missing assumed_gamma because the result
    // depends on the scene's version (image/gamma.cpp applies the rule).
    if (!scene.globals.assumedGammaSet) {
        const char* text =
            r.version() >= 3.7 - 1e-9 && r.versionSeen()
                ? "warning: assumed_gamma not specified in this POV-Ray 3.7 or later scene; "
                  "using 'assumed_gamma 1.0'"
                : "warning: assumed_gamma not specified, so gamma correction is turned off "
                  "for compatibility with this pre POV-Ray 3.7 scene";
        messages_.message(Stream::Warning, fmt::format("{}: {}", file->source->path(), text));
    }
    return std::move(scene);
}

}  // namespace frameray::sdl
