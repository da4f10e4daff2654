// What the frame loop tells the interpreter about the frame being parsed:
// the values of the built-in identifiers, the library path, declarations
// from the options, and where messages go.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "sdl/file_access.h"

namespace frameray::sdl {

struct FrameContext {
    double clock = 0;
    double clockDelta = 0;
    bool clockOn = false;
    int frameNumber = 0;
    double initialClock = 0, finalClock = 1;
    int initialFrame = 1, finalFrame = 1;
    int imageWidth = 320, imageHeight = 240;
    std::vector<std::filesystem::path> libraryPaths;
    // Declare=Name=Value options: numbers become floats, others strings.
    std::vector<std::pair<std::string, std::string>> declares;
    double version = 3.7;  // Version option (+MV); #version overrides
    // Whether the Version option was given: povray then treats the scene as
    // declaring its version (no warning, and 3.7's gamma without #version).
    bool versionGiven = false;
    std::string includeHeader;  // Include_Header (+HI): included before the scene
    // Non-empty: #fopen ... write/append is an error with this message,
    // before the file is touched (a sharded run: frames that pass state
    // through files cannot be rendered apart). A file that cannot be
    // opened for reading adds it to its message too.
    std::string refuseFileWrites;
    // The files the scene may read and write (unrestricted by default;
    // the frame loop restricts it unless File_Restrictions=off).
    FileAccessPolicy fileAccess;

    // Resource limits: a scene that goes past one gets an error for its
    // frame instead of exhausting the stack, the memory or the time.
    struct Limits {
        // Loop iterations (#while, #for) and macro calls in one frame
        // (Max_Parse_Iterations; 0: no limit).
        size_t parseIterations = 100'000'000;
        // Nested expressions, objects, textures and directives. Each level
        // takes at most a few kilobytes of stack (measured: see
        // tests/fuzz/README.md), so this fits a 4 MB worker-thread stack.
        int nesting = 400;
        int macroCalls = 200;    // macro calls in progress at once
        int includeFiles = 100;  // #include files open at once
        // Array elements (8 bytes each for floats, about 56 for other kinds):
        // one array, and all arrays made or copied in the frame.
        size_t arrayElements = size_t(1) << 24;
        size_t totalArrayElements = size_t(1) << 26;
        size_t stringLength = size_t(1) << 24;  // bytes in one string value
        // Instructions one function evaluation may run (about a second;
        // CompiledFunction::operations), checked before evaluating it while
        // parsing and before a shape takes it.
        double functionOperations = 1e9;
        // Bytes of one file opened with #fopen ... read (read whole).
        size_t readFileBytes = size_t(1) << 28;
    } limits;
};

// The text streams of a frame (debug, warning...), routed by the frame
// loop to the console and the frame's own log.
enum class Stream { Debug, Warning, Render, Statistics, Fatal };

class MessageSink {
  public:
    virtual ~MessageSink() = default;
    virtual void message(Stream stream, const std::string& text) = 0;
};

}  // namespace frameray::sdl
