// The objects that clip an object (clipped_by), with the box a ray must
// meet to see any of the clipped surface: the common part of the boxes of
// the clips that are not inverted, computed once when the list is made
// (issue 23: warp1 spent 17 % of its time re-transforming the clip's box
// for every ray). 16 bytes; an empty list allocates nothing.
#pragma once

#include <initializer_list>
#include <memory>
#include <vector>

#include "scene/ray.h"

namespace frameray::scene {

struct Object;
using ObjectRef = std::shared_ptr<const Object>;

class ClipList {
  public:
    ClipList() = default;
    ClipList(std::vector<ObjectRef> clips);  // NOLINT(google-explicit-constructor)
    ClipList(std::initializer_list<ObjectRef> clips) : ClipList(std::vector<ObjectRef>(clips)) {}

    bool empty() const { return !data_; }
    size_t size() const { return data_ ? data_->clips.size() : 0; }
    const ObjectRef* begin() const { return data_ ? data_->clips.data() : nullptr; }
    const ObjectRef* end() const {
        return data_ ? data_->clips.data() + data_->clips.size() : nullptr;
    }
    const std::vector<ObjectRef>& objects() const;

    // The clips' common box (Bounds::infinite() when every clip is
    // inverted, or there is none): their surfaceBounds() intersected in
    // the list's order.
    const Bounds& box() const;

  private:
    struct Data {
        std::vector<ObjectRef> clips;
        Bounds box;
    };
    std::shared_ptr<const Data> data_;
};

}  // namespace frameray::scene
