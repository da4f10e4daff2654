// Arrays of up to five dimensions: declaration with optional initializer,
// indexing, element assignment and the seed's typing rules.
#include <fmt/format.h>

#include <cmath>

#include "sdl/reader.h"

namespace frameray::sdl {

Value Reader::parseArrayDeclaration() {
    const Token at = next();  // array
    auto array = std::make_shared<ArrayValue>();
    size_t total = 1;
    // rawPeek: a directive after the declaration (`#declare A[0] = 1` on
    // the next line, as in shapes.inc's HF_Square) must not run before the
    // array is bound.
    while (rawPeek().is(Sym::LBracket)) {
        const Token open = next();
        const double size = parseFloat();
        expect(Sym::RBracket, "']'");
        // Refused before allocating (and before converting to an int): a
        // scene asking for more is almost surely a mistake, and povray
        // itself hangs on such declarations.
        if (!(size >= 1)) fail(open, fmt::format("array size {} must be at least 1", size));
        if (array->dims.size() == 5) fail(open, "arrays have at most 5 dimensions");
        if (size > double(frame_.limits.arrayElements) ||
            total * static_cast<size_t>(size) > frame_.limits.arrayElements)
            fail(open, fmt::format("array of more than {} elements", frame_.limits.arrayElements));
        const int n = static_cast<int>(size);
        total *= static_cast<size_t>(n);
        array->dims.push_back(n);
    }
    if (array->dims.empty()) fail(at, "expected '[' with the array size after 'array'");
    chargeArrayElements(total, at);
    array->reset(total);
    if (rawPeek().is(Sym::LBrace)) {
        size_t next = 0;
        parseArrayInitializer(*array, 0, next);
    }
    return array;
}

void Reader::parseArrayInitializer(ArrayValue& array, size_t dim, size_t& nextIndex) {
    const Token open = peek();
    expect(Sym::LBrace, "'{' starting an array initializer");
    const int size = array.dims[dim];
    int count = 0;
    // POV-Ray allows a trailing comma before '}' and omitted commas.
    while (!peek().is(Sym::RBrace)) {
        if (count == size)
            fail(peek(),
                 fmt::format("too many elements in the array initializer (dimension {} has {})",
                             dim + 1, size));
        if (dim + 1 < array.dims.size()) {
            parseArrayInitializer(array, dim + 1, nextIndex);
        } else {
            const Token at = peek();
            Value v = parseRValue();
            setArrayElement(array, nextIndex++, std::move(v), at);
        }
        ++count;
        accept(Sym::Comma);  // optional in povray (`{ A, B C }`), silently
    }
    if (count < size)
        fail(open, fmt::format("too few elements in the array initializer: {} of {}", count, size));
    expect(Sym::RBrace, "'}' closing the array initializer");
}

size_t Reader::parseArrayIndex(const ArrayValue& array, const Token& at) {
    size_t index = 0;
    for (size_t d = 0; d < array.dims.size(); ++d) {
        if (!peek().is(Sym::LBracket))
            fail(at, fmt::format("this array has {} dimensions; {} index{} given",
                                 array.dims.size(), d, d == 1 ? "" : "es"));
        const Token open = next();
        const double i = parseFloat();
        expect(Sym::RBracket, "']'");
        // Checked as a float first: a huge index has no integer value.
        if (!(i > -1 && i < array.dims[d]))
            fail(open, fmt::format("array index {} out of range 0..{}", std::trunc(i) + 0.0,
                                   array.dims[d] - 1));
        const long n = static_cast<long>(i);
        index = index * static_cast<size_t>(array.dims[d]) + static_cast<size_t>(n);
    }
    return index;
}

void Reader::setArrayElement(ArrayValue& array, size_t index, Value value, const Token& at) {
    if (const char* kind = array.kind(); kind && std::string_view(kind) != valueKindName(value))
        fail(at,
             fmt::format("array elements are {}s; cannot store a {}", kind, valueKindName(value)));
    if (auto* nested = std::get_if<ArrayPtr>(&value)) {
        chargeArrayElements((*nested)->size(), at);
        value = std::make_shared<ArrayValue>(**nested);
    }
    array.set(index, std::move(value));
}

}  // namespace frameray::sdl
