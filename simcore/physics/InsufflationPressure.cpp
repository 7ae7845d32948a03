#include "simcore/physics/InsufflationPressure.h"

#include "simcore/physics/NodeLanes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace colonosim::physics {

InsufflationPressure::InsufflationPressure(std::vector<std::array<int, 3>> triangles, double pressure)
    : m_triangles(std::move(triangles)), m_pressure(pressure)
{
    onActiveSetChanged({});
}

namespace {

#if defined(__x86_64__)
/// The nodal force scale (x1 - x0) x (x2 - x0) of the active triangles, four
/// at once, lane k from triangle e + k, with the operations of Eigen's cross
/// product in each lane; returns how many it did (a multiple of 4).
__attribute__((target("avx2"))) size_t pressureByFour(const std::vector<std::array<int, 3>>& triangles,
                                                      const std::vector<int>& active, const double* x,
                                                      double scale, double* fx, double* fy, double* fz)
{
    const __m256d s = _mm256_set1_pd(scale);
    size_t e = 0;
    for (; e + 4 <= active.size(); e += 4) {
        const auto& t0 = triangles[static_cast<size_t>(active[e])];
        const auto& t1 = triangles[static_cast<size_t>(active[e + 1])];
        const auto& t2 = triangles[static_cast<size_t>(active[e + 2])];
        const auto& t3 = triangles[static_cast<size_t>(active[e + 3])];
        const lanes::Rows p0 = lanes::nodes(x, t0[0], t1[0], t2[0], t3[0]);
        const lanes::Rows p1 = lanes::nodes(x, t0[1], t1[1], t2[1], t3[1]);
        const lanes::Rows p2 = lanes::nodes(x, t0[2], t1[2], t2[2], t3[2]);
        const __m256d a0 = _mm256_sub_pd(p1.r0, p0.r0);
        const __m256d a1 = _mm256_sub_pd(p1.r1, p0.r1);
        const __m256d a2 = _mm256_sub_pd(p1.r2, p0.r2);
        const __m256d b0 = _mm256_sub_pd(p2.r0, p0.r0);
        const __m256d b1 = _mm256_sub_pd(p2.r1, p0.r1);
        const __m256d b2 = _mm256_sub_pd(p2.r2, p0.r2);
        const __m256d c0 = _mm256_sub_pd(_mm256_mul_pd(a1, b2), _mm256_mul_pd(a2, b1));
        const __m256d c1 = _mm256_sub_pd(_mm256_mul_pd(a2, b0), _mm256_mul_pd(a0, b2));
        const __m256d c2 = _mm256_sub_pd(_mm256_mul_pd(a0, b1), _mm256_mul_pd(a1, b0));
        _mm256_storeu_pd(fx + e, _mm256_mul_pd(s, c0));
        _mm256_storeu_pd(fy + e, _mm256_mul_pd(s, c1));
        _mm256_storeu_pd(fz + e, _mm256_mul_pd(s, c2));
    }
    return e;
}
#endif

}  // namespace

void InsufflationPressure::addForce(const Positions& x, Forces& f) const
{
    const double scale = m_pressure / 6.0;  // p/3 times the 1/2 of the area vector
    size_t e = 0;
#if defined(__x86_64__)
    if (lanes::available()) {
        e = pressureByFour(m_triangles, m_active, x.data(), scale, m_fx.data(), m_fy.data(), m_fz.data());
    }
#endif
    for (; e < m_active.size(); ++e) {
        const auto& tri = m_triangles[static_cast<size_t>(m_active[e])];
        const Eigen::Vector3d x0 = x.col(tri[0]);
        const Eigen::Vector3d fn = scale * (x.col(tri[1]) - x0).cross(x.col(tri[2]) - x0);
        m_fx[e] = fn.x();
        m_fy[e] = fn.y();
        m_fz[e] = fn.z();
    }
    m_gather.sumInto(f.data(), m_fx.data(), m_fy.data(), m_fz.data());
}

void InsufflationPressure::addStiffnessProduct(const Positions& x, const Eigen::Matrix3Xd& dx,
                                               Eigen::Matrix3Xd& df) const
{
    const double scale = m_pressure / 6.0;
    for (const int t : m_active) {
        const auto& tri = m_triangles[static_cast<size_t>(t)];
        const Eigen::Vector3d e1 = x.col(tri[1]) - x.col(tri[0]);
        const Eigen::Vector3d e2 = x.col(tri[2]) - x.col(tri[0]);
        const Eigen::Vector3d de1 = dx.col(tri[1]) - dx.col(tri[0]);
        const Eigen::Vector3d de2 = dx.col(tri[2]) - dx.col(tri[0]);
        const Eigen::Vector3d dfn = scale * (de1.cross(e2) + e1.cross(de2));
        df.col(tri[0]) += dfn;
        df.col(tri[1]) += dfn;
        df.col(tri[2]) += dfn;
    }
}

void InsufflationPressure::addStiffnessBound(const Positions& x, Eigen::VectorXd& kRow,
                                             Eigen::VectorXd& /*cRow*/) const
{
    // Each 3x3 block of the differential is (p/6) [e]x for an edge e of the
    // triangle, of norm (p/6)|e|; a node's row holds three such blocks per
    // incident triangle. Evaluated at the current shape.
    for (size_t t = 0; t < m_triangles.size(); ++t) {
        const auto& tri = m_triangles[t];
        // The root of the largest squared edge: the largest of the edges' norms,
        // bit for bit (the root is monotone and correctly rounded), with one root.
        double longest2 = 0.0;
        for (int k = 0; k < 3; ++k) {
            longest2 = std::max(longest2, (x.col(tri[(k + 1) % 3]) - x.col(tri[k])).squaredNorm());
        }
        const double longest = std::sqrt(longest2);
        const double rowSum = 3.0 * std::abs(m_pressure) / 6.0 * longest;
        for (const int node : m_triangles[t]) {
            kRow[node] += rowSum;
        }
    }
}

void InsufflationPressure::onActiveSetChanged(const std::vector<std::uint8_t>& awake)
{
    m_active.clear();
    for (size_t t = 0; t < m_triangles.size(); ++t) {
        const auto& tri = m_triangles[t];
        const bool any = awake.empty() || awake[static_cast<size_t>(tri[0])] ||
                         awake[static_cast<size_t>(tri[1])] || awake[static_cast<size_t>(tri[2])];
        if (any) {
            m_active.push_back(static_cast<int>(t));
        }
    }
    m_corners.clear();
    for (const int t : m_active) {
        const auto& tri = m_triangles[static_cast<size_t>(t)];
        m_corners.insert(m_corners.end(), tri.begin(), tri.end());
    }
    constexpr double kSigns[] = {1.0, 1.0, 1.0};  // each corner takes the same force
    m_gather.build(m_corners, kSigns);
    m_fx.resize(m_active.size());
    m_fy.resize(m_active.size());
    m_fz.resize(m_active.size());
}

}  // namespace colonosim::physics
