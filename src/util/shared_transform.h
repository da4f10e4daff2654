// A Transform held by reference: 16 bytes instead of the 256 of a
// Transform's two matrices, for the transformation every object and
// texture carries while most of them keep the identity (10^6 spheres each
// with its own texture, issue 23). Copies share the one immutable
// Transform; assigning a new value allocates it, except the identity, which
// all share without an allocation or a reference count.
#pragma once

#include <cmath>
#include <memory>

#include "util/matrix.h"

namespace frameray {

class SharedTransform {
  public:
    SharedTransform() : t_(std::shared_ptr<const Transform>(), &identityTransform()) {}
    // Implicit: `x.transform = Transform::scale(...)` reads as for a Transform.
    SharedTransform(const Transform& t)  // NOLINT(google-explicit-constructor)
        : t_(isExactIdentity(t) ? std::shared_ptr<const Transform>(
                                      std::shared_ptr<const Transform>(), &identityTransform())
                                : std::make_shared<const Transform>(t)) {}

    // The transformation itself, for whatever takes a Transform.
    const Transform& get() const { return *t_; }
    operator const Transform&() const { return *t_; }  // NOLINT(google-explicit-constructor)

    // Transform's queries, forwarded.
    Transform then(const Transform& next) const { return t_->then(next); }
    Transform inverse() const { return t_->inverse(); }
    bool isIdentity() const { return t_->isIdentity(); }
    Vec3 point(const Vec3& p) const { return t_->point(p); }
    Vec3 direction(const Vec3& d) const { return t_->direction(d); }
    Vec3 normal(const Vec3& n) const { return t_->normal(n); }
    Vec3 inversePoint(const Vec3& p) const { return t_->inversePoint(p); }
    Vec3 inverseDirection(const Vec3& d) const { return t_->inverseDirection(d); }
    const Matrix4& matrix() const { return t_->matrix(); }
    const Matrix4& inverseMatrix() const { return t_->inverseMatrix(); }

  private:
    // Both matrices exactly the identity's (an identity reached by
    // transformations that cancel may carry rounding in its inverse, or a
    // -0: kept, so that every product stays bit for bit the same).
    static bool isExactIdentity(const Transform& t) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                const double id = i == j ? 1.0 : 0.0;
                const double a = t.matrix().m[i][j], b = t.inverseMatrix().m[i][j];
                if (a != id || b != id || std::signbit(a) || std::signbit(b)) return false;
            }
        return true;
    }
    // The one identity every default SharedTransform points at (immutable).
    static const Transform& identityTransform() {
        static const Transform identity;
        return identity;
    }
    std::shared_ptr<const Transform> t_;  // never null
};

}  // namespace frameray
