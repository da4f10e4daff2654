#include "sdl/symbol_table.h"

#include <algorithm>

namespace frameray::sdl {

template <typename Key>
const Value* SymbolTable::lookupKey(const Key& name) const {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
        auto found = it->find(name);
        if (found == it->end()) continue;
        if (const auto* alias = std::get_if<IdentifierAlias>(&found->second)) {
            const Scope& target = scopes_[alias->scope];
            auto t = target.find(alias->name);
            return t == target.end() ? nullptr : &t->second;
        }
        return &found->second;
    }
    return nullptr;
}

// The two kinds of key the header's lookups use.
template const Value* SymbolTable::lookupKey<std::string_view>(const std::string_view&) const;
template const Value* SymbolTable::lookupKey<SymbolTable::HashedName>(const HashedName&) const;

void SymbolTable::declare(const std::string& name, Value value, bool local, size_t scopeCount,
                          uint32_t hash) {
    const HashedName key{name, hash ? hash : identifierHash(name)};
    // Only the scopes that existed when the directive began count: a macro
    // that produced the value (`#local M = MakeTransform()`) may still have
    // its own scope open when a value ending in '}' is complete.
    const size_t visible = std::min(scopeCount, scopes_.size());
    if (local) {
        Scope& scope = scopes_[visible - 1];
        if (auto found = scope.find(key); found == scope.end()) {
            scope.emplace(name, std::move(value));
        } else if (const auto* alias = std::get_if<IdentifierAlias>(&found->second)) {
            // A macro parameter passed by reference: povray's #local on it
            // assigns the caller's identifier too.
            const IdentifierAlias target = *alias;
            scopes_[target.scope][target.name] = std::move(value);
        } else {
            found->second = std::move(value);
        }
        return;
    }
    // #declare assigns the most local existing version, or creates a global;
    // through a by-reference macro parameter it assigns the caller's.
    for (auto it = scopes_.rend() - static_cast<std::ptrdiff_t>(visible); it != scopes_.rend();
         ++it) {
        auto found = it->find(key);
        if (found == it->end()) continue;
        if (const auto* alias = std::get_if<IdentifierAlias>(&found->second)) {
            const IdentifierAlias target = *alias;
            scopes_[target.scope][target.name] = std::move(value);
        } else {
            found->second = std::move(value);
        }
        return;
    }
    scopes_.front().insert_or_assign(name, std::move(value));
}

void SymbolTable::undefine(const std::string& name) {
    for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it)
        if (it->erase(name)) break;
}

std::optional<IdentifierAlias> SymbolTable::aliasFor(const std::string& name) const {
    IdentifierAlias alias{scopes_.size(), name};
    for (size_t i = scopes_.size(); i-- > 0;) {
        auto found = scopes_[i].find(name);
        if (found == scopes_[i].end()) continue;
        if (const auto* outer = std::get_if<IdentifierAlias>(&found->second))
            alias = *outer;
        else if (std::holds_alternative<MacroPtr>(found->second))
            return std::nullopt;  // a macro call, not a reference
        else
            alias.scope = i;
        break;
    }
    return alias;
}

std::vector<std::string_view> SymbolTable::names() const {
    std::vector<std::string_view> out;
    for (const Scope& scope : scopes_)
        for (const auto& entry : scope) out.push_back(entry.first);
    return out;
}

void SymbolTable::deprecate(const std::string& name, std::string message, bool once) {
    deprecated_[name] = {std::move(message), once, false};
}

const std::string* SymbolTable::findDeprecation(std::string_view name) {
    auto d = deprecated_.find(name);
    if (d == deprecated_.end() || (d->second.once && d->second.warned)) return nullptr;
    d->second.warned = true;
    return &d->second.message;
}

}  // namespace frameray::sdl
