#include "render/radiosity_cache.h"

#include <algorithm>

namespace frameray::render {

namespace {

bool inCell(const Vec3& p, const Vec3& origin, double size) {
    return p.x >= origin.x && p.y >= origin.y && p.z >= origin.z && p.x < origin.x + size &&
           p.y < origin.y + size && p.z < origin.z + size;
}

}  // namespace

void RadiosityOctree::growToHold(const Vec3& p, double size) {
    if (nodes_.empty()) {
        size_ = std::max(size, 1e-9);
        origin_ = p - Vec3(size_ * 0.5);
        nodes_.emplace_back();
        return;
    }
    // Double the root toward p; the old root becomes one of the new root's
    // children, so every stored sample keeps its node.
    while (!inCell(p, origin_, size_) || size_ < size) {
        int k = 0;
        Vec3 o = origin_;
        if (p.x < origin_.x) {
            o.x -= size_;
            k |= 1;
        }
        if (p.y < origin_.y) {
            o.y -= size_;
            k |= 2;
        }
        if (p.z < origin_.z) {
            o.z -= size_;
            k |= 4;
        }
        Node root;
        root.child[k] = static_cast<std::int32_t>(nodes_.size());
        // The old root moves to the end; the new root takes slot 0.
        nodes_.push_back(std::move(nodes_[0]));
        nodes_[0] = std::move(root);
        origin_ = o;
        size_ *= 2;
    }
}

void RadiosityOctree::insert(std::uint32_t index, const Vec3& center, double reach) {
    growToHold(center, 2 * reach);
    std::int32_t node = 0;
    Vec3 origin = origin_;
    double size = size_;
    // The smallest cell whose loose bounds (half its size around it) hold
    // the whole reach.
    while (size * 0.25 >= reach) {
        const double half = size * 0.5;
        int k = 0;
        Vec3 o = origin;
        if (center.x >= origin.x + half) {
            k |= 1;
            o.x += half;
        }
        if (center.y >= origin.y + half) {
            k |= 2;
            o.y += half;
        }
        if (center.z >= origin.z + half) {
            k |= 4;
            o.z += half;
        }
        std::int32_t next = nodes_[static_cast<size_t>(node)].child[k];
        if (next < 0) {
            next = static_cast<std::int32_t>(nodes_.size());
            nodes_.emplace_back();
            nodes_[static_cast<size_t>(node)].child[k] = next;
        }
        node = next;
        origin = o;
        size = half;
    }
    nodes_[static_cast<size_t>(node)].samples.push_back(index);
}

}  // namespace frameray::render
