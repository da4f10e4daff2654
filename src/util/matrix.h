// 4x4 affine matrices in double precision and the Transform pair
// (matrix + inverse) that every scene object and camera carries.
#pragma once

#include <array>

#include "util/vec3.h"

namespace frameray {

// Row-vector convention as in POV-Ray's `matrix` keyword: a point p maps to
// p * M, so composing "first A then B" is A * B.
struct Matrix4 {
    std::array<std::array<double, 4>, 4> m{};

    static Matrix4 identity();
    static Matrix4 translation(const Vec3& t);
    static Matrix4 scaling(const Vec3& s);
    // Rotation about x, then y, then z by the given angles in degrees, with
    // POV-Ray's left-handed sense.
    static Matrix4 rotation(const Vec3& degrees);
    // The 12 values of POV-Ray's `matrix < ... >` (4 rows of 3; last column
    // implied 0,0,0,1).
    static Matrix4 fromPovMatrix(const std::array<double, 12>& v);

    Matrix4 operator*(const Matrix4& o) const;
    // Inline: every ray test of a transformed object runs both.
    Vec3 transformPoint(const Vec3& p) const {
        return {p.x * m[0][0] + p.y * m[1][0] + p.z * m[2][0] + m[3][0],
                p.x * m[0][1] + p.y * m[1][1] + p.z * m[2][1] + m[3][1],
                p.x * m[0][2] + p.y * m[1][2] + p.z * m[2][2] + m[3][2]};
    }
    Vec3 transformDirection(const Vec3& d) const {
        return {d.x * m[0][0] + d.y * m[1][0] + d.z * m[2][0],
                d.x * m[0][1] + d.y * m[1][1] + d.z * m[2][1],
                d.x * m[0][2] + d.y * m[1][2] + d.z * m[2][2]};
    }
    // Transforms a normal given the INVERSE matrix of the object transform:
    // n' = n * (M^-1)^T.
    Vec3 transformNormalByInverse(const Vec3& n) const;
    // General inverse; returns false when singular.
    bool invert(Matrix4& out) const;
};

// A transformation with its inverse kept alongside, composed as objects are
// transformed in the scene file.
class Transform {
  public:
    Transform() : fwd_(Matrix4::identity()), inv_(Matrix4::identity()) {}
    Transform(const Matrix4& fwd, const Matrix4& inv) : fwd_(fwd), inv_(inv) {}

    static Transform translate(const Vec3& t);
    static Transform scale(const Vec3& s);
    static Transform rotate(const Vec3& degrees);
    // Returns false (and leaves out untouched) for a singular matrix.
    static bool fromMatrix(const Matrix4& m, Transform& out);

    // "this, then next".
    Transform then(const Transform& next) const;
    Transform inverse() const { return {inv_, fwd_}; }
    bool isIdentity() const;

    Vec3 point(const Vec3& p) const { return fwd_.transformPoint(p); }
    Vec3 direction(const Vec3& d) const { return fwd_.transformDirection(d); }
    Vec3 normal(const Vec3& n) const { return inv_.transformNormalByInverse(n); }
    Vec3 inversePoint(const Vec3& p) const { return inv_.transformPoint(p); }
    Vec3 inverseDirection(const Vec3& d) const { return inv_.transformDirection(d); }

    const Matrix4& matrix() const { return fwd_; }
    const Matrix4& inverseMatrix() const { return inv_; }

  private:
    Matrix4 fwd_, inv_;
};

}  // namespace frameray
