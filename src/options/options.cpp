#include "options/options.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <set>

#include "options/ini_trust.h"
#include "options/option_table.h"
#include "util/file_paths.h"
#include "util/spelling.h"

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

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool endsWithIni(std::string_view name) {
    return name.size() >= 4 && lower(name.substr(name.size() - 4)) == ".ini";
}

// Options that widen the restrictions on scenes (sdl/file_access.h): a
// stranger's INI file, shipped with a scene, must not lift them.
bool widensRestrictions(std::string_view key) {
    return key == "Allow_Shell_Commands" || key == "File_Restrictions" || key == "Read_Path" ||
           key == "Write_Path";
}

struct Applier {
    RenderOptions& options;
    std::vector<std::string> warnings;
    int depth = 0;
    // INI files named on the command line (and those they name) may not
    // widen the restrictions; the startup sources and arguments may.
    bool namedIniUntrusted = false;
    bool inUntrustedIni = false;
    // While in an untrusted INI: the folders it may name paths in (README,
    // Restrictions; options/ini_trust.h).
    std::vector<fs::path> roots{};
    // Options whose lack of effect was said already (once per run).
    std::set<std::string_view> noted{};

    void apply(const OptionSpec& spec, const OptionInput& input, const std::string& where,
               std::string_view shownAs) {
        if (inUntrustedIni && widensRestrictions(spec.iniKey))
            throw OptionError(
                fmt::format("{}: option '{}' widens the restrictions on scenes, so it is read only "
                            "from the command line, "
                            "POVRAYOPT, a povray.ini outside the working folder or frameray.conf, "
                            "not from an INI file "
                            "named on the command line",
                            where, shownAs));
        const std::vector<NamedPath> before =
            inUntrustedIni ? namedPaths(options) : std::vector<NamedPath>{};
        OptionInput keyed = input;
        keyed.key = spec.iniKey;
        try {
            spec.apply(options, keyed);
        } catch (const std::invalid_argument& e) {
            throw OptionError(
                fmt::format("{}: bad value for option '{}': {}", where, shownAs, e.what()));
        }
        if (inUntrustedIni)
            if (const std::string refusal =
                    untrustedPathRefusal(before, namedPaths(options), roots, where);
                !refusal.empty())
                throw OptionError(refusal);
        options.explicitlySet.emplace(spec.iniKey);
        if (spec.noEffect)
            if (const char* why = spec.noEffect(keyed); why && noted.insert(spec.iniKey).second)
                warnings.push_back(
                    fmt::format("{}: option '{}' has no effect: {}", where, spec.iniKey, why));
    }

    void applySwitch(std::string_view text, const std::string& where) {
        const bool plus = text[0] == '+';
        std::string_view value;
        const OptionSpec* spec = findSwitch(text.substr(1), value);
        if (!spec) throw OptionError(fmt::format("{}: unknown switch '{}'", where, text));
        apply(*spec, {value, true, plus, {}}, where, text);
    }

    void applyKeyValue(std::string_view key, std::string_view value, const std::string& where,
                       const fs::path& base) {
        const OptionSpec* spec = findIniKey(trim(key));
        if (!spec) {
            std::vector<std::string_view> keys;
            for (const OptionSpec& o : optionTable()) keys.push_back(o.iniKey);
            const std::string best = util::closestSpelling(trim(key), keys, true);
            throw OptionError(
                fmt::format("{}: unknown option '{}'{}", where, trim(key),
                            best.empty() ? "" : fmt::format("; did you mean '{}'?", best)));
        }
        if (spec->type == OptionType::IniFile) {
            includeIni(trim(value), where, base, trim(key));
            return;
        }
        apply(*spec, {trim(value), false, true, {}}, where, trim(key));
    }

    // Include_Ini=file.ini[Section]: read there and then, as an INI file
    // named on that line would be.
    void includeIni(std::string_view value, const std::string& where, const fs::path& base,
                    std::string_view shownAs) {
        const std::string name = std::string(value);
        if (name.empty())
            throw OptionError(
                fmt::format("{}: option '{}' needs an INI file name", where, shownAs));
        applyFileName(name, where, base, true);
    }

    // An INI file named by an argument or an INI line: as given, else
    // beside the INI that names it, else in the library path.
    fs::path locateIni(const fs::path& name, const fs::path& base) const {
        std::error_code ec;
        if (name.is_absolute() || fs::exists(name, ec)) return name;
        if (!base.empty() && fs::exists(base / name, ec)) return base / name;
        for (const auto& dir : options.libraryPaths)
            if (fs::exists(dir / name, ec)) return dir / name;
        return name;
    }

    // An argument or INI line that is neither a switch nor Key=Value: an
    // INI file (optionally with [Section]) or the scene file.
    void applyFileName(std::string_view text, const std::string& where, const fs::path& base,
                       bool iniFile = false) {
        std::string name(text), section;
        if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
            name = name.substr(1, name.size() - 2);
        if (!name.empty() && name.back() == ']') {
            const auto open = name.find('[');
            if (open != std::string::npos) {
                section = name.substr(open + 1, name.size() - open - 2);
                name.resize(open);
            }
        }
        if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
            name = name.substr(1, name.size() - 2);
        if (iniFile || endsWithIni(name)) {
            const fs::path path = locateIni(name, base);
            const bool outer = inUntrustedIni;
            if (inUntrustedIni) {
                // An INI file named by an untrusted one is read only from
                // the same folders as any other path it names.
                if (!insideTrustRoots(resolvedPath(path), roots) &&
                    !insideTrustRoots(resolvedPath(path), {resolvedPath(kStandardIniFolder)}))
                    throw OptionError(
                        untrustedPathRefusal({}, {{"INI file", path.string()}}, roots, where));
            } else if (namedIniUntrusted) {
                inUntrustedIni = true;
                roots = trustRoots(path.parent_path());
            }
            readIni(path, section, where);
            inUntrustedIni = outer;
        } else {
            if (inUntrustedIni)
                if (const std::string refusal =
                        untrustedPathRefusal({}, {{"Input_File_Name", name}}, roots, where);
                    !refusal.empty())
                    throw OptionError(refusal);
            options.inputFile = name;
            options.explicitlySet.emplace("Input_File_Name");
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
            applyKeyValue(token.substr(0, eq), token.substr(eq + 1), where, base);
            return;
        }
        applyFileName(token, where, base);
    }

    // One INI line without its comment: `Key=Value` (the value runs to the
    // end of the line, blanks included), or blank-separated switches, INI
    // names and Key=Value words (`+kf0.1666 +kff20 +kc declare=fp=0`).
    void applyIniLine(std::string_view text, const std::string& where, const fs::path& base) {
        const bool startsWithSwitch = text[0] == '+' || text[0] == '-';
        const auto eq = text.find('=');
        const auto blank = text.find_first_of(" \t");
        if (!startsWithSwitch && eq != std::string_view::npos) {
            // "Key = Value": blanks may surround '='; the key has none.
            const std::string_view key = trim(text.substr(0, eq));
            if (key.find_first_of(" \t") == std::string_view::npos) {
                applyKeyValue(key, text.substr(eq + 1), where, base);
                return;
            }
        }
        if (!startsWithSwitch && blank == std::string_view::npos) {
            applyIniWord(text, where, base);
            return;
        }
        for (const std::string& tok : splitOptionString(std::string(text))) {
            if (tok[0] != '+' && tok[0] != '-' && tok.find('=') == std::string::npos)
                applyIniWord(tok, where, base);
            else
                applyToken(tok, where, base);
        }
    }

    // A word on an INI line that is neither a switch nor Key=Value: a file
    // name, or (as povray reads `res320` in its own allstill.ini) the name
    // of an INI file without its extension.
    void applyIniWord(std::string_view word, const std::string& where, const fs::path& base) {
        if (word.find('.') == std::string_view::npos && !findIniKey(word)) {
            std::error_code ec;
            const fs::path ini = locateIni(std::string(word) + ".ini", base);
            if (fs::is_regular_file(ini, ec)) {
                warnings.push_back(
                    fmt::format("{}: '{}' read as the INI file '{}'", where, word, ini.string()));
                applyFileName(ini.string(), where, base, true);
                return;
            }
        }
        checkIniWord(word, where);
        applyToken(word, where, base);
    }

    // A word on an INI line that is neither a switch nor Key=Value must be
    // a file name (a scene or another INI file); povray refuses the rest
    // ("Width 64", a key without its '=', a bare number).
    static void checkIniWord(std::string_view word, const std::string& where) {
        std::string_view name = word;
        if (name.size() >= 2 && name.front() == '"' && name.back() == '"') return;
        if (const OptionSpec* spec = findIniKey(name))
            throw OptionError(fmt::format("{}: option '{}' needs '=' and a value ({}=...)", where,
                                          name, spec->iniKey));
        if (name.find('.') == std::string_view::npos)
            throw OptionError(fmt::format("{}: '{}' is neither Key=Value, a switch nor a file name",
                                          where, name));
    }

    void readIni(const fs::path& path, const std::string& section, const std::string& origin) {
        if (++depth > kMaxIniDepth)
            throw OptionError(
                fmt::format("{}: INI files nested more than {} deep", origin, kMaxIniDepth));
        std::ifstream in(path);
        if (!in)
            throw OptionError(fmt::format("{}: cannot open INI file '{}'", origin, path.string()));
        std::string line;
        int lineNo = 0;
        // Without a section, only lines before the first header apply; with
        // one, only the lines under that header (names compare ignoring case).
        bool active = section.empty();
        bool sectionFound = section.empty();
        while (std::getline(in, line)) {
            ++lineNo;
            // A UTF-8 byte order mark (Windows editors write one) is not
            // part of the first key.
            if (lineNo == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);
            const std::string where = fmt::format("{}:{}", path.string(), lineNo);
            std::string_view text = trim(line);
            if (text.empty() || text[0] == ';') continue;
            if (text[0] == '[') {
                const auto close = text.find(']');
                const std::string_view name =
                    close == std::string_view::npos ? text.substr(1) : text.substr(1, close - 1);
                active = !section.empty() && lower(trim(name)) == lower(trim(section));
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
            if (text.empty()) continue;
            applyIniLine(text, where, path.parent_path());
        }
        // POV-Ray renders without complaint when the section is missing;
        // frameray says so.
        if (!sectionFound)
            warnings.push_back(
                fmt::format("{}: INI file '{}' has no section [{}]; nothing read from it", origin,
                            path.string(), section));
        --depth;
    }
};

}  // namespace

fs::path findSceneFile(const RenderOptions& options) {
    if (options.inputFile.empty()) return {};
    const fs::path name = options.inputFile;
    std::vector<fs::path> folders{fs::path()};
    if (name.is_relative())
        folders.insert(folders.end(), options.libraryPaths.begin(), options.libraryPaths.end());
    std::error_code ec;
    for (const fs::path& folder : folders)
        for (const fs::path& candidate : {name, fs::path(name.string() + ".pov")}) {
            fs::path path = folder.empty() ? candidate : folder / candidate;
            if (fs::is_regular_file(path, ec)) return path;
        }
    return {};
}

std::vector<std::string> splitOptionString(const std::string& text) {
    std::vector<std::string> out;
    std::string cur;
    bool quoted = false, any = false;
    for (char c : text) {
        if (c == '"') {
            quoted = !quoted;
            cur += c;
            any = true;
        } else if ((c == ' ' || c == '\t' || c == '\n' || c == '\r') && !quoted) {
            if (any) out.push_back(cur);
            cur.clear();
            any = false;
        } else {
            cur += c;
            any = true;
        }
    }
    if (any) out.push_back(cur);
    return out;
}

std::vector<std::string> applyArguments(RenderOptions& options,
                                        const std::vector<std::string>& args) {
    Applier a{options, {}};
    a.namedIniUntrusted = true;
    for (const std::string& arg : args) a.applyToken(arg, "command line", fs::path());
    return a.warnings;
}

std::vector<std::string> applyIniFile(RenderOptions& options, const fs::path& path,
                                      const std::string& section, const std::string& origin) {
    Applier a{options, {}};
    a.readIni(path, section, origin);
    return a.warnings;
}

StartupEnvironment processEnvironment() {
    StartupEnvironment env;
    env.getenv = [](const char* name) { return static_cast<const char*>(std::getenv(name)); };
    std::error_code ec;
    env.workingDir = fs::current_path(ec);
    return env;
}

fs::path findStartupIni(const StartupEnvironment& env) {
    std::vector<fs::path> candidates;
    if (const char* povini = env.getenv("POVINI"); povini && *povini)
        candidates.emplace_back(povini);
    candidates.push_back(env.workingDir / "povray.ini");
    const char* home = env.getenv("HOME");
    if (home && *home) candidates.push_back(fs::path(home) / ".povray" / "3.7" / "povray.ini");
    candidates.push_back(env.systemIni);
    if (home && *home) candidates.push_back(fs::path(home) / ".povrayrc");
    std::error_code ec;
    for (const auto& c : candidates)
        if (fs::is_regular_file(c, ec)) return c;
    return {};
}

fs::path findConfigFile(const StartupEnvironment& env) {
    fs::path config;
    if (const char* xdg = env.getenv("XDG_CONFIG_HOME"); xdg && *xdg)
        config = fs::path(xdg) / "frameray" / "frameray.conf";
    else if (const char* home = env.getenv("HOME"); home && *home)
        config = fs::path(home) / ".config" / "frameray" / "frameray.conf";
    std::error_code ec;
    return !config.empty() && fs::is_regular_file(config, ec) ? config : fs::path();
}

std::vector<std::string> applyStartupOptions(RenderOptions& options,
                                             const StartupEnvironment& env) {
    std::vector<std::string> warnings;
    Applier a{options, {}};
    // frameray.conf first: the user's standing policy, INI syntax.
    if (const fs::path config = findConfigFile(env); !config.empty())
        a.readIni(config, "", "frameray.conf");
    if (const char* opt = env.getenv("POVRAYOPT"); opt && *opt)
        for (const std::string& tok : splitOptionString(opt))
            a.applyToken(tok, "POVRAYOPT", fs::path());
    const fs::path ini = findStartupIni(env);
    // ./povray.ini may have come with a scene: it cannot widen the
    // restrictions; the others are the user's own.
    std::error_code ec;
    a.inUntrustedIni = !ini.empty() && fs::equivalent(ini, env.workingDir / "povray.ini", ec);
    if (a.inUntrustedIni) a.roots = trustRoots(env.workingDir);
    if (!ini.empty()) a.readIni(ini, "", "startup");
    a.inUntrustedIni = false;
    return a.warnings;
}

}  // namespace frameray::options
