#include "options/options.h"

#include <fmt/format.h>

#include <fstream>

#include "options/option_table.h"

namespace frameray::options {

namespace fs = std::filesystem;

namespace {

constexpr int kMaxIniDepth = 16;

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

bool endsWithIni(std::string_view name) {
    if (name.size() < 4) return false;
    std::string ext(name.substr(name.size() - 4));
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".ini";
}

struct Applier {
    RenderOptions& options;
    int depth = 0;

    void apply(const OptionSpec& spec, const OptionInput& input, const std::string& where,
               std::string_view shownAs) {
        try {
            spec.apply(options, input);
        } catch (const std::invalid_argument& e) {
            throw OptionError(fmt::format("{}: bad value for option '{}': {}", where, shownAs, e.what()));
        }
    }

    void applySwitch(std::string_view text, const std::string& where) {
        const bool plus = text[0] == '+';
        std::string_view value;
        const OptionSpec* spec = findSwitch(text.substr(1), value);
        if (!spec) throw OptionError(fmt::format("{}: unknown switch '{}'", where, text));
        apply(*spec, {value, true, plus}, where, text);
    }

    void applyKeyValue(std::string_view key, std::string_view value, const std::string& where) {
        const OptionSpec* spec = findIniKey(trim(key));
        if (!spec) throw OptionError(fmt::format("{}: unknown option '{}'", where, trim(key)));
        apply(*spec, {trim(value), false, true}, where, trim(key));
    }

    // An argument or INI line that is neither a switch nor Key=Value: an
    // INI file (optionally with [Section]) or the scene file.
    void applyFileName(std::string_view text, const std::string& where, const fs::path& base) {
        std::string name(text), section;
        if (!name.empty() && name.back() == ']') {
            const auto open = name.find('[');
            if (open != std::string::npos) {
                section = name.substr(open + 1, name.size() - open - 2);
                name.resize(open);
            }
        }
        if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
        if (endsWithIni(name)) {
            fs::path path(name);
            if (path.is_relative() && !fs::exists(path) && !base.empty() && fs::exists(base / path))
                path = base / path;
            readIni(path, section, where);
        } else {
            options.inputFile = name;
        }
    }

    void applyToken(std::string_view token, const std::string& where, const fs::path& base) {
        if (token.empty()) return;
        if ((token[0] == '+' || token[0] == '-') && token.size() > 1) {
            applySwitch(token, where);
            return;
        }
        const auto eq = token.find('=');
        if (eq != std::string_view::npos) {
            applyKeyValue(token.substr(0, eq), token.substr(eq + 1), where);
            return;
        }
        applyFileName(token, where, base);
    }

    void readIni(const fs::path& path, const std::string& section, const std::string& origin) {
        if (++depth > kMaxIniDepth)
            throw OptionError(fmt::format("{}: INI files nested more than {} deep", origin, kMaxIniDepth));
        std::ifstream in(path);
        if (!in) throw OptionError(fmt::format("{}: cannot open INI file '{}'", origin, path.string()));
        std::string line;
        int lineNo = 0;
        // Without a section, only lines before the first header apply; with
        // one, only the lines under that header.
        bool active = section.empty();
        bool sectionFound = section.empty();
        while (std::getline(in, line)) {
            ++lineNo;
            const std::string where = fmt::format("{}:{}", path.string(), lineNo);
            std::string_view text = trim(line);
            if (text.empty() || text[0] == ';' || text[0] == '#') continue;
            if (text[0] == '[') {
                const auto close = text.find(']');
                const std::string_view name = close == std::string_view::npos ? text.substr(1) : text.substr(1, close - 1);
                active = !section.empty() && trim(name) == trim(section);
                sectionFound = sectionFound || active;
                continue;
            }
            if (!active) continue;
            // A ';' starts a comment unless it is inside quotes.
            bool quoted = false;
            for (size_t i = 0; i < text.size(); ++i) {
                if (text[i] == '"') quoted = !quoted;
                if (text[i] == ';' && !quoted) {
                    text = trim(text.substr(0, i));
                    break;
                }
            }
            if (text[0] == '+' || text[0] == '-') {
                // Several switches may share a line.
                size_t pos = 0;
                while (pos < text.size()) {
                    const auto end = text.find_first_of(" \t", pos);
                    const std::string_view tok = text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
                    applyToken(tok, where, path.parent_path());
                    if (end == std::string_view::npos) break;
                    pos = text.find_first_not_of(" \t", end);
                    if (pos == std::string_view::npos) break;
                }
            } else {
                applyToken(text, where, path.parent_path());
            }
        }
        if (!sectionFound)
            throw OptionError(fmt::format("{}: INI file '{}' has no section [{}]", origin, path.string(), section));
        --depth;
    }
};

}  // namespace

void applyArguments(RenderOptions& options, const std::vector<std::string>& args) {
    Applier a{options};
    for (const std::string& arg : args) a.applyToken(arg, "command line", fs::path());
}

void applyIniFile(RenderOptions& options, const fs::path& path, const std::string& section,
                  const std::string& origin) {
    Applier a{options};
    a.readIni(path, section, origin);
}

}  // namespace frameray::options
