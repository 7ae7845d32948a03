#include "simcore/physics/SpringKernel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace colonosim::physics {

namespace {

// byFour() reads a spring's rest length, stiffness and damping with one load.
static_assert(offsetof(PackedSpring, k) == offsetof(PackedSpring, rest) + sizeof(double));
static_assert(offsetof(PackedSpring, along) == offsetof(PackedSpring, rest) + 2 * sizeof(double));
static_assert(offsetof(PackedSpring, across) == offsetof(PackedSpring, rest) + 3 * sizeof(double));

/// Pass 1 for spring e, one at a time: its squared length (m^2) and its force
/// on its first end (N), into the scratch.
void springForce(const PackedSpring& p, const double* x, const double* v, size_t e, double* l2Out,
                 double* fxOut, double* fyOut, double* fzOut)
{
    const double* xi = x + 3 * p.i;
    const double* xj = x + 3 * p.j;
    const double* vi = v + 3 * p.i;
    const double* vj = v + 3 * p.j;
    const double dx = xj[0] - xi[0];
    const double dy = xj[1] - xi[1];
    const double dz = xj[2] - xi[2];
    const double l2 = (dx * dx + dy * dy) + dz * dz;
    const double invL = 1.0 / std::sqrt(l2);
    const double rx = vj[0] - vi[0];
    const double ry = vj[1] - vi[1];
    const double rz = vj[2] - vi[2];
    const double speed = ((dx * rx + dy * ry) + dz * rz) * invL;
    const double s = (p.k * (l2 * invL - p.rest) + p.along * speed) * invL;
    l2Out[e] = l2;
    fxOut[e] = s * dx + p.across * rx;
    fyOut[e] = s * dy + p.across * ry;
    fzOut[e] = s * dz + p.across * rz;
}

#if defined(__x86_64__)
/// Rows 0-2 of the 4 x 4 matrix whose columns are a0..a3: each row one
/// component of the four columns, lane 0 from a0 (a transpose; no arithmetic).
struct Rows {
    __m256d r0, r1, r2;
};
__attribute__((target("avx2"))) inline Rows transpose(__m256d a0, __m256d a1, __m256d a2, __m256d a3)
{
    const __m256d t0 = _mm256_unpacklo_pd(a0, a1);  // a0.0 a1.0 a0.2 a1.2
    const __m256d t1 = _mm256_unpackhi_pd(a0, a1);  // a0.1 a1.1 a0.3 a1.3
    const __m256d t2 = _mm256_unpacklo_pd(a2, a3);
    const __m256d t3 = _mm256_unpackhi_pd(a2, a3);
    return {_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
            _mm256_permute2f128_pd(t0, t2, 0x31)};
}

/// The x, y and z of the nodes at the ends `end` (0: i, 1: j) of four
/// springs, lane 0 the first. Each node's three components are read with one
/// masked load (the fourth lane is not read, so the last node's is safe).
__attribute__((target("avx2"))) inline __m256d node(const double* q, const PackedSpring& p, int end)
{
    return _mm256_maskload_pd(q + 3 * (end == 0 ? p.i : p.j), _mm256_set_epi64x(0, -1, -1, -1));
}
__attribute__((target("avx2"))) inline Rows ends(const double* q, const PackedSpring* p, int end)
{
    return transpose(node(q, p[0], end), node(q, p[1], end), node(q, p[2], end), node(q, p[3], end));
}

/// springForce() of four springs at once; returns how many springs it did (a multiple of 4).
__attribute__((target("avx2"))) size_t byFour(std::span<const PackedSpring> springs, const double* x,
                                              const double* v, double* l2Out, double* fxOut, double* fyOut,
                                              double* fzOut)
{
    size_t e = 0;
    for (; e + 4 <= springs.size(); e += 4) {
        const PackedSpring* p = springs.data() + e;
        const Rows xi = ends(x, p, 0);
        const Rows xj = ends(x, p, 1);
        const __m256d dx = _mm256_sub_pd(xj.r0, xi.r0);
        const __m256d dy = _mm256_sub_pd(xj.r1, xi.r1);
        const __m256d dz = _mm256_sub_pd(xj.r2, xi.r2);
        const __m256d l2 =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
        const __m256d invL = _mm256_div_pd(_mm256_set1_pd(1.0), _mm256_sqrt_pd(l2));
        const Rows vi = ends(v, p, 0);
        const Rows vj = ends(v, p, 1);
        const __m256d rx = _mm256_sub_pd(vj.r0, vi.r0);
        const __m256d ry = _mm256_sub_pd(vj.r1, vi.r1);
        const __m256d rz = _mm256_sub_pd(vj.r2, vi.r2);
        const __m256d speed = _mm256_mul_pd(
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, rx), _mm256_mul_pd(dy, ry)), _mm256_mul_pd(dz, rz)),
            invL);
        // rest, k, along and across lie side by side in each PackedSpring.
        const __m256d a0 = _mm256_loadu_pd(&p[0].rest);
        const __m256d a1 = _mm256_loadu_pd(&p[1].rest);
        const __m256d a2 = _mm256_loadu_pd(&p[2].rest);
        const __m256d a3 = _mm256_loadu_pd(&p[3].rest);
        const Rows rka = transpose(a0, a1, a2, a3);
        const __m256d across =
            _mm256_permute2f128_pd(_mm256_unpackhi_pd(a0, a1), _mm256_unpackhi_pd(a2, a3), 0x31);
        const __m256d stretch = _mm256_sub_pd(_mm256_mul_pd(l2, invL), rka.r0);
        const __m256d tension = _mm256_add_pd(_mm256_mul_pd(rka.r1, stretch), _mm256_mul_pd(rka.r2, speed));
        const __m256d s = _mm256_mul_pd(tension, invL);
        _mm256_storeu_pd(l2Out + e, l2);
        _mm256_storeu_pd(fxOut + e, _mm256_add_pd(_mm256_mul_pd(s, dx), _mm256_mul_pd(across, rx)));
        _mm256_storeu_pd(fyOut + e, _mm256_add_pd(_mm256_mul_pd(s, dy), _mm256_mul_pd(across, ry)));
        _mm256_storeu_pd(fzOut + e, _mm256_add_pd(_mm256_mul_pd(s, dz), _mm256_mul_pd(across, rz)));
    }
    return e;
}

#endif

}  // namespace

void SpringGather::build(std::span<const PackedSpring> springs)
{
    m_numSprings = springs.size();
    int nodes = 0;
    for (const PackedSpring& p : springs) {
        nodes = std::max({nodes, p.i + 1, p.j + 1});
    }
    // Count each node's ends, then place them spring by spring: within a
    // node the entries follow the springs' order.
    std::vector<int> count(static_cast<size_t>(nodes) + 1, 0);
    for (const PackedSpring& p : springs) {
        ++count[static_cast<size_t>(p.i)];
        ++count[static_cast<size_t>(p.j)];
    }
    m_nodes.clear();
    m_first.clear();
    std::vector<int> slot(static_cast<size_t>(nodes), 0);
    int entries = 0;
    for (int n = 0; n < nodes; ++n) {
        if (count[static_cast<size_t>(n)] > 0) {
            m_nodes.push_back(n);
            m_first.push_back(entries);
            slot[static_cast<size_t>(n)] = entries;
            entries += count[static_cast<size_t>(n)];
        }
    }
    m_first.push_back(entries);
    m_spring.resize(static_cast<size_t>(entries));
    m_sign.resize(static_cast<size_t>(entries));
    for (size_t e = 0; e < springs.size(); ++e) {
        const int a = slot[static_cast<size_t>(springs[e].i)]++;
        m_spring[static_cast<size_t>(a)] = static_cast<int>(e);
        m_sign[static_cast<size_t>(a)] = 1.0;
        const int b = slot[static_cast<size_t>(springs[e].j)]++;
        m_spring[static_cast<size_t>(b)] = static_cast<int>(e);
        m_sign[static_cast<size_t>(b)] = -1.0;
    }
    m_l2.resize(springs.size());
    m_fx.resize(springs.size());
    m_fy.resize(springs.size());
    m_fz.resize(springs.size());
}

void addSpringForces(std::span<const PackedSpring> springs, SpringGather& gather, const double* x,
                     const double* v, double* f, SpringLanes lanes)
{
    assert(gather.m_numSprings == springs.size());
    double* l2 = gather.m_l2.data();
    double* fx = gather.m_fx.data();
    double* fy = gather.m_fy.data();
    double* fz = gather.m_fz.data();
    size_t e = 0;
#if defined(__x86_64__)
    static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
    if (lanes == SpringLanes::Widest && avx2) {
        e = byFour(springs, x, v, l2, fx, fy, fz);
    }
#else
    (void)lanes;
#endif
    for (; e < springs.size(); ++e) {
        springForce(springs[e], x, v, e, l2, fx, fy, fz);
    }
    // Pass 2: each node's sum in the springs' order. sign * force is exact
    // (a negation or none), and a + (-b) is a - b in IEEE arithmetic, so each
    // addition is the one the spring-by-spring order makes.
    const int* spring = gather.m_spring.data();
    const double* sign = gather.m_sign.data();
    for (size_t k = 0; k < gather.m_nodes.size(); ++k) {
        double* fn = f + 3 * static_cast<size_t>(gather.m_nodes[k]);
        double sx = fn[0];
        double sy = fn[1];
        double sz = fn[2];
        const int last = gather.m_first[k + 1];
        for (int a = gather.m_first[k]; a < last; ++a) {
            const auto s = static_cast<size_t>(spring[a]);
            if (l2[s] < kMinSpringLength * kMinSpringLength) {
                continue;
            }
            sx += sign[a] * fx[s];
            sy += sign[a] * fy[s];
            sz += sign[a] * fz[s];
        }
        fn[0] = sx;
        fn[1] = sy;
        fn[2] = sz;
    }
}

}  // namespace colonosim::physics
