#include "util/matrix.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace frameray {

Matrix4 Matrix4::identity() {
    Matrix4 r;
    for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
    return r;
}

Matrix4 Matrix4::translation(const Vec3& t) {
    Matrix4 r = identity();
    r.m[3][0] = t.x;
    r.m[3][1] = t.y;
    r.m[3][2] = t.z;
    return r;
}

Matrix4 Matrix4::scaling(const Vec3& s) {
    Matrix4 r = identity();
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

Matrix4 Matrix4::rotation(const Vec3& degrees) {
    // Each axis rotation in the row-vector convention; POV-Ray rotates about
    // x first, then y, then z.
    const double k = std::numbers::pi / 180.0;
    auto axis = [](int a, double rad) {
        Matrix4 r = identity();
        const double c = std::cos(rad), s = std::sin(rad);
        const int i = (a + 1) % 3, j = (a + 2) % 3;
        r.m[i][i] = c;
        r.m[i][j] = s;
        r.m[j][i] = -s;
        r.m[j][j] = c;
        return r;
    };
    return axis(0, degrees.x * k) * axis(1, degrees.y * k) * axis(2, degrees.z * k);
}

Matrix4 Matrix4::fromPovMatrix(const std::array<double, 12>& v) {
    Matrix4 r = identity();
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 3; ++col) r.m[row][col] = v[row * 3 + col];
    return r;
}

Matrix4 Matrix4::operator*(const Matrix4& o) const {
    Matrix4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Vec3 Matrix4::transformNormalByInverse(const Vec3& n) const {
    // Multiplying by the transpose of this (inverse) matrix.
    return {n.x * m[0][0] + n.y * m[0][1] + n.z * m[0][2],
            n.x * m[1][0] + n.y * m[1][1] + n.z * m[1][2],
            n.x * m[2][0] + n.y * m[2][1] + n.z * m[2][2]};
}

bool Matrix4::invert(Matrix4& out) const {
    // Gauss-Jordan with partial pivoting; 4x4 is small enough that clarity
    // wins over a cofactor expansion.
    std::array<std::array<double, 8>, 4> a{};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) a[i][j] = m[i][j];
        a[i][4 + i] = 1;
    }
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::fabs(a[r][col]) > std::fabs(a[pivot][col])) pivot = r;
        if (std::fabs(a[pivot][col]) < 1e-300) return false;
        std::swap(a[pivot], a[col]);
        const double inv = 1.0 / a[col][col];
        for (double& v : a[col]) v *= inv;
        for (int r = 0; r < 4; ++r) {
            if (r == col) continue;
            const double f = a[r][col];
            if (f == 0) continue;
            for (int j = 0; j < 8; ++j) a[r][j] -= f * a[col][j];
        }
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out.m[i][j] = a[i][4 + j];
    return true;
}

Transform Transform::translate(const Vec3& t) {
    return {Matrix4::translation(t), Matrix4::translation(-t)};
}

Transform Transform::scale(const Vec3& s) {
    return {Matrix4::scaling(s), Matrix4::scaling({1 / s.x, 1 / s.y, 1 / s.z})};
}

Transform Transform::rotate(const Vec3& degrees) {
    Matrix4 r = Matrix4::rotation(degrees);
    // A rotation's inverse is its transpose.
    Matrix4 t = Matrix4::identity();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) t.m[i][j] = r.m[j][i];
    return {r, t};
}

bool Transform::fromMatrix(const Matrix4& m, Transform& out) {
    Matrix4 inv;
    if (!m.invert(inv)) return false;
    out = Transform(m, inv);
    return true;
}

Transform Transform::then(const Transform& next) const {
    return {fwd_ * next.fwd_, next.inv_ * inv_};
}

bool Transform::isIdentity() const {
    const Matrix4 id = Matrix4::identity();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (fwd_.m[i][j] != id.m[i][j]) return false;
    return true;
}

}  // namespace frameray
