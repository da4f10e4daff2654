#include "util/json.h"

#include <fmt/format.h>

#include <charconv>
#include <stdexcept>

namespace frameray::util {

JsonValue JsonValue::number(std::string text) {
    JsonValue v;
    v.kind = Kind::Number;
    v.text = std::move(text);
    return v;
}

JsonValue JsonValue::string(std::string text) {
    JsonValue v;
    v.kind = Kind::String;
    v.text = std::move(text);
    return v;
}

JsonValue JsonValue::array(std::vector<JsonValue> items) {
    JsonValue v;
    v.kind = Kind::Array;
    v.items = std::move(items);
    return v;
}

JsonValue JsonValue::object(std::vector<std::pair<std::string, JsonValue>> members) {
    JsonValue v;
    v.kind = Kind::Object;
    v.members = std::move(members);
    return v;
}

const JsonValue* JsonValue::find(std::string_view key) const {
    if (kind != Kind::Object) return nullptr;
    for (const auto& [k, v] : members)
        if (k == key) return &v;
    return nullptr;
}

std::optional<double> JsonValue::asDouble() const {
    if (kind != Kind::Number) return std::nullopt;
    double d = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), d);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return d;
}

std::optional<std::int64_t> JsonValue::asInteger() const {
    if (kind != Kind::Number) return std::nullopt;
    std::int64_t n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return n;
}

namespace {

class Parser {
  public:
    explicit Parser(std::string_view text) : s_(text) {}

    JsonValue document() {
        JsonValue v = value(0);
        space();
        if (i_ != s_.size()) error("text after the value");
        return v;
    }

  private:
    [[noreturn]] void error(const std::string& what) const {
        throw std::runtime_error(fmt::format("JSON: {} at byte {}", what, i_));
    }

    void space() {
        while (i_ < s_.size() &&
               (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t'))
            ++i_;
    }

    bool take(char c) {
        space();
        if (i_ < s_.size() && s_[i_] == c) {
            ++i_;
            return true;
        }
        return false;
    }

    void expect(char c) {
        if (!take(c)) error(fmt::format("'{}' expected", c));
    }

    bool word(std::string_view w) {
        if (s_.substr(i_, w.size()) != w) return false;
        i_ += w.size();
        return true;
    }

    JsonValue value(int depth) {
        if (depth > 64) error("nesting too deep");
        space();
        if (i_ >= s_.size()) error("a value expected");
        const char c = s_[i_];
        if (c == '{') return object(depth);
        if (c == '[') return array(depth);
        if (c == '"') return JsonValue::string(string());
        JsonValue v;
        if (word("null")) return v;
        if (word("true")) {
            v.kind = JsonValue::Kind::Bool;
            v.boolean = true;
            return v;
        }
        if (word("false")) {
            v.kind = JsonValue::Kind::Bool;
            return v;
        }
        return number();
    }

    JsonValue object(int depth) {
        ++i_;
        JsonValue v = JsonValue::object();
        if (take('}')) return v;
        do {
            space();
            if (i_ >= s_.size() || s_[i_] != '"') error("a key expected");
            std::string key = string();
            expect(':');
            v.members.emplace_back(std::move(key), value(depth + 1));
        } while (take(','));
        expect('}');
        return v;
    }

    JsonValue array(int depth) {
        ++i_;
        JsonValue v = JsonValue::array();
        if (take(']')) return v;
        do v.items.push_back(value(depth + 1));
        while (take(','));
        expect(']');
        return v;
    }

    JsonValue number() {
        const size_t start = i_;
        if (i_ < s_.size() && s_[i_] == '-') ++i_;
        auto digits = [&] {
            const size_t from = i_;
            while (i_ < s_.size() && s_[i_] >= '0' && s_[i_] <= '9') ++i_;
            return i_ > from;
        };
        if (!digits()) error("a value expected");
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            if (!digits()) error("digits expected after '.'");
        }
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            ++i_;
            if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
            if (!digits()) error("digits expected in the exponent");
        }
        return JsonValue::number(std::string(s_.substr(start, i_ - start)));
    }

    static void appendUtf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    unsigned hex4() {
        if (i_ + 4 > s_.size()) error("4 hex digits expected");
        unsigned cp = 0;
        const auto [end, ec] = std::from_chars(s_.data() + i_, s_.data() + i_ + 4, cp, 16);
        if (ec != std::errc() || end != s_.data() + i_ + 4) error("4 hex digits expected");
        i_ += 4;
        return cp;
    }

    std::string string() {
        ++i_;  // the opening quote
        std::string out;
        while (true) {
            if (i_ >= s_.size()) error("unterminated string");
            const char c = s_[i_++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) error("control character in a string");
            if (c != '\\') {
                out += c;
                continue;
            }
            if (i_ >= s_.size()) error("unterminated string");
            switch (const char e = s_[i_++]) {
                case '"':
                case '\\':
                case '/':
                    out += e;
                    break;
                case 'b':
                    out += '\b';
                    break;
                case 'f':
                    out += '\f';
                    break;
                case 'n':
                    out += '\n';
                    break;
                case 'r':
                    out += '\r';
                    break;
                case 't':
                    out += '\t';
                    break;
                case 'u': {
                    unsigned cp = hex4();
                    if (cp >= 0xD800 && cp < 0xDC00 && word("\\u")) {
                        const unsigned low = hex4();
                        if (low < 0xDC00 || low > 0xDFFF) error("a lone surrogate");
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                    } else if (cp >= 0xD800 && cp < 0xE000) {
                        error("a lone surrogate");
                    }
                    appendUtf8(out, cp);
                    break;
                }
                default:
                    error("unknown escape");
            }
        }
    }

    std::string_view s_;
    size_t i_ = 0;
};

void writeString(std::string& out, const std::string& text) {
    out += jsonQuoted(text);
}

void write(std::string& out, const JsonValue& v) {
    switch (v.kind) {
        case JsonValue::Kind::Null:
            out += "null";
            break;
        case JsonValue::Kind::Bool:
            out += v.boolean ? "true" : "false";
            break;
        case JsonValue::Kind::Number:
            out += v.text;
            break;
        case JsonValue::Kind::String:
            writeString(out, v.text);
            break;
        case JsonValue::Kind::Array:
            out += '[';
            for (size_t i = 0; i < v.items.size(); ++i) {
                if (i) out += ", ";
                write(out, v.items[i]);
            }
            out += ']';
            break;
        case JsonValue::Kind::Object:
            out += '{';
            for (size_t i = 0; i < v.members.size(); ++i) {
                if (i) out += ", ";
                writeString(out, v.members[i].first);
                out += ": ";
                write(out, v.members[i].second);
            }
            out += '}';
            break;
    }
}

}  // namespace

JsonValue parseJson(std::string_view text) {
    return Parser(text).document();
}

std::string writeJsonInline(const JsonValue& value) {
    std::string out;
    write(out, value);
    return out;
}

std::string jsonQuoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20)
                    out += fmt::format("\\u{:04x}", static_cast<int>(c));
                else
                    out += c;
        }
    }
    return out + "\"";
}

}  // namespace frameray::util
