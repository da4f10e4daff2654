// A small JSON reader and writer for the files frameray itself writes
// (sequence.json and its shards' files): values keep the order of an
// object's keys and a number's text, so what is read is written back as it
// was.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frameray::util {

struct JsonValue {
    enum class Kind { Null, Bool, Number, String, Array, Object };
    Kind kind = Kind::Null;
    bool boolean = false;
    std::string text;  // a number's text as written, or a string's characters
    std::vector<JsonValue> items;
    std::vector<std::pair<std::string, JsonValue>> members;  // in file order

    static JsonValue number(std::string text);
    static JsonValue string(std::string text);
    static JsonValue array(std::vector<JsonValue> items = {});
    static JsonValue object(std::vector<std::pair<std::string, JsonValue>> members = {});

    // The member named `key` of an object; nullptr when absent (or not an
    // object).
    const JsonValue* find(std::string_view key) const;
    // A number as a double; nullopt for anything else.
    std::optional<double> asDouble() const;
    // A number written without fraction or exponent, as an integer.
    std::optional<std::int64_t> asInteger() const;
};

// Throws std::runtime_error naming the byte offset of the first error.
JsonValue parseJson(std::string_view text);

// On one line: {"a": 1, "b": [2, 3]}.
std::string writeJsonInline(const JsonValue& value);

// `text` as a JSON string literal, quotes included, escaped.
std::string jsonQuoted(const std::string& text);

}  // namespace frameray::util
