// The identifiers of one frame's parse: a stack of scopes (the global
// one, one per include file for its #local identifiers, one per macro call
// for its parameters and locals), with POV-Ray's rules for #declare and
// #local, by-reference macro parameters and deprecated identifiers.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "sdl/token.h"
#include "sdl/value.h"

namespace frameray::sdl {

class SymbolTable {
  public:
    // Identifiers are looked up by the string_view of their token with the
    // hash the lexer computed, without building a std::string each time.
    struct HashedName {
        std::string_view text;
        uint32_t hash;
    };
    struct NameHash {
        using is_transparent = void;
        size_t operator()(std::string_view s) const { return identifierHash(s); }
        size_t operator()(const HashedName& n) const { return n.hash; }
    };
    struct NameEqual {
        using is_transparent = void;
        bool operator()(std::string_view a, std::string_view b) const { return a == b; }
        bool operator()(const HashedName& a, std::string_view b) const { return a.text == b; }
        bool operator()(std::string_view a, const HashedName& b) const { return a == b.text; }
    };
    using Scope = std::unordered_map<std::string, Value, NameHash, NameEqual>;

    // The innermost binding of `name`, through a by-reference alias; null
    // when undeclared.
    const Value* lookup(std::string_view name) const { return lookupKey(name); }
    const Value* lookup(const Token& name) const {
        // nameHash shares its bytes with a Number token's value.
        return name.kind == TokenKind::Word && name.nameHash
                   ? lookupKey(HashedName{name.text, name.nameHash})
                   : lookupKey(name.text.view());
    }
    Value* find(std::string_view name) { return const_cast<Value*>(lookup(name)); }
    // Binds name in the innermost of the first scopeCount scopes (#local) or
    // assigns or creates it as #declare does. `hash`: the name's
    // identifierHash when known (0: computed here).
    void declare(const std::string& name, Value value, bool local,
                 size_t scopeCount = std::numeric_limits<size_t>::max(), uint32_t hash = 0);
    // #undef: removes the innermost binding.
    void undefine(const std::string& name);
    // A macro argument passed as the bare identifier `name`: the scope
    // holding it (following an outer alias); size() when undeclared, and
    // nullopt when it names a macro (a call, not a reference).
    std::optional<IdentifierAlias> aliasFor(const std::string& name) const;

    void push(Scope scope = {}) { scopes_.push_back(std::move(scope)); }
    void resize(size_t count) { scopes_.resize(count); }
    void reset() { scopes_.assign(1, Scope{}); }
    size_t size() const { return scopes_.size(); }
    Scope& global() { return scopes_.front(); }
    // Every name declared in any scope (spelling suggestions).
    std::vector<std::string_view> names() const;

    // `#declare deprecated [once] "message" X = ...`: warned on use.
    void deprecate(const std::string& name, std::string message, bool once);
    // The warning `name`'s use gives now, or null (once: only the first).
    const std::string* deprecationWarning(std::string_view name) {
        return deprecated_.empty() ? nullptr : findDeprecation(name);
    }

  private:
    template <typename Key>
    const Value* lookupKey(const Key& key) const;
    const std::string* findDeprecation(std::string_view name);

    std::vector<Scope> scopes_;
    struct Deprecation {
        std::string message;
        bool once = false;
        bool warned = false;
    };
    std::unordered_map<std::string, Deprecation, NameHash, NameEqual> deprecated_;
};

}  // namespace frameray::sdl
