// A member kept out of line until it is first written: 8 bytes while it
// holds nothing, and copied with its owner (a deep copy, as the member
// itself would be). For the rarely used parts of values that exist by the
// million (the pattern of a pigment that is a plain colour, issue 23).
// Reading an empty box gives the default T.
#pragma once

#include <memory>

namespace frameray {

template <typename T>
class ValueBox {
  public:
    ValueBox() = default;
    ValueBox(const ValueBox& o) : p_(o.p_ ? std::make_unique<T>(*o.p_) : nullptr) {}
    ValueBox(ValueBox&&) noexcept = default;
    ValueBox& operator=(const ValueBox& o) {
        if (this != &o) p_ = o.p_ ? std::make_unique<T>(*o.p_) : nullptr;
        return *this;
    }
    ValueBox& operator=(ValueBox&&) noexcept = default;
    ~ValueBox() = default;

    bool holds() const { return p_ != nullptr; }
    // The value, or the default T while nothing was written.
    const T& get() const { return p_ ? *p_ : empty(); }
    // The value to write, created (as T{}) on first use.
    T& edit() {
        if (!p_) p_ = std::make_unique<T>();
        return *p_;
    }

  private:
    static const T& empty() {
        static const T value{};
        return value;
    }
    std::unique_ptr<T> p_;
};

}  // namespace frameray
