// libFuzzer target: the INI-file and command-line option parser. The input
// is split at its first NUL byte: before it, a line of switches and
// Key=Value pairs (split as POVRAYOPT is); after it, the text of an INI
// file, read both as a trusted INI file and as one named on the command
// line. Either may be rejected with OptionError; nothing else may happen.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "options/option_table.h"
#include "options/options.h"

namespace {

// One scratch INI file per fuzzing process, rewritten for each input.
const std::filesystem::path& scratchIni() {
    static const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("frameray_fuzz_" + std::to_string(getpid()) + ".ini");
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace frameray::options;
    const std::string input(reinterpret_cast<const char*>(data), size);
    const size_t split = input.find('\0');
    const std::string switches = input.substr(0, split);
    const std::string ini = split == std::string::npos ? std::string() : input.substr(split + 1);

    RenderOptions options;
    try {
        std::vector<std::string> args = splitOptionString(switches);
        // Arguments naming files would read whatever the fuzzer guesses:
        // keep the ones that are options (switches or Key=Value).
        std::erase_if(args, [](const std::string& a) {
            return a.empty() || (a[0] != '+' && a[0] != '-' && a.find('=') == std::string::npos);
        });
        (void)applyArguments(options, args);
    } catch (const OptionError&) {
    }
    {
        std::ofstream out(scratchIni(), std::ios::binary | std::ios::trunc);
        out << ini;
    }
    try {
        (void)applyIniFile(options, scratchIni(), "", "fuzz");
        (void)createIniText(options);
        (void)firstUnsupported(options);
    } catch (const OptionError&) {
    }
    // The same INI file named on the command line: untrusted, so every
    // path it names is checked (options/ini_trust.h).
    try {
        RenderOptions untrusted;
        (void)applyArguments(untrusted, {scratchIni().string()});
    } catch (const OptionError&) {
    }
    return 0;
}
