#include "scene/clip_list.h"

#include "scene/object.h"

namespace frameray::scene {

ClipList::ClipList(std::vector<ObjectRef> clips) {
    if (clips.empty()) return;
    Bounds box = Bounds::infinite();
    for (const ObjectRef& clip : clips)
        if (!clip->inverse) box = box.intersected(clip->surfaceBounds());
    data_ = std::make_shared<const Data>(Data{std::move(clips), box});
}

const std::vector<ObjectRef>& ClipList::objects() const {
    static const std::vector<ObjectRef> kNone;
    return data_ ? data_->clips : kNone;
}

const Bounds& ClipList::box() const {
    static const Bounds kInfinite = Bounds::infinite();
    return data_ ? data_->box : kInfinite;
}

}  // namespace frameray::scene
