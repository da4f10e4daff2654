// The typed, immutable result of all option sources (defaults, INI files,
// switches): what a run renders and how.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace frameray::options {

struct RenderOptions {
    // Input and output.
    std::string inputFile;
    std::string outputFile;        // empty: scene name in the working folder
    bool outputToFile = true;
    char outputType = 'N';         // N P T C E H J B (seed 003 / POV-Ray 3.7)
    int bitDepth = 8;
    double fileGamma = 0;          // <= 0: sRGB (POV-Ray 3.7's default)
    double displayGamma = 2.2;

    // Image.
    int width = 800;
    int height = 600;

    // Animation.
    double clock = 0;
    bool clockSet = false;
    int initialFrame = 1, finalFrame = 1;
    double initialClock = 0, finalClock = 1;
    bool cyclicAnimation = false;
    int subsetStartFrame = 0, subsetEndFrame = 0;  // 0: no subset

    // Quality.
    bool antialias = false;
    double antialiasThreshold = 0.3;
    int quality = 9;

    // Parsing.
    double version = 3.7;
    std::vector<std::filesystem::path> libraryPaths{"/usr/share/povray-3.7/include"};
    std::vector<std::pair<std::string, std::string>> declares;

    // Run.
    int workThreads = 0;  // 0: every core
    bool verbose = true;
    bool display = false;
    bool pauseWhenDone = false;
};

}  // namespace frameray::options
