// Per-thread scratch vectors for hit lists, handed out as a stack so that
// nested queries (a bounding object tested inside a CSG child's query, a
// shape's first hit inside another's) never share one. Keeps the ray
// callbacks free of allocations once warm.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace frameray::scene {

template <typename T>
class ScratchVector {
  public:
    ScratchVector() : items_(acquire()) {}
    ~ScratchVector() { --depth(); }
    ScratchVector(const ScratchVector&) = delete;
    ScratchVector& operator=(const ScratchVector&) = delete;
    std::vector<T>& get() { return items_; }

  private:
    static std::vector<std::unique_ptr<std::vector<T>>>& pool() {
        thread_local std::vector<std::unique_ptr<std::vector<T>>> p;
        return p;
    }
    static std::size_t& depth() {
        thread_local std::size_t d = 0;
        return d;
    }
    static std::vector<T>& acquire() {
        auto& p = pool();
        std::size_t& d = depth();
        if (d == p.size()) p.push_back(std::make_unique<std::vector<T>>());
        auto& v = *p[d++];
        v.clear();
        return v;
    }

    std::vector<T>& items_;
};

}  // namespace frameray::scene
