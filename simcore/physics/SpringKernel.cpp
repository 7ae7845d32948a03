#include "simcore/physics/SpringKernel.h"

#include "simcore/physics/NodeLanes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>

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
/// The x, y and z of the nodes at the ends `end` (0: i, 1: j) of four springs, lane 0 the first.
__attribute__((target("avx2"))) inline lanes::Rows ends(const double* q, const PackedSpring* p, int end)
{
    return end == 0 ? lanes::nodes(q, p[0].i, p[1].i, p[2].i, p[3].i)
                    : lanes::nodes(q, p[0].j, p[1].j, p[2].j, p[3].j);
}

/// springForce() of four springs at once; returns how many springs it did (a
/// multiple of 4). `shortSprings` grows by one for each four with a spring
/// without length (nonzero when there is any).
__attribute__((target("avx2"))) size_t byFour(std::span<const PackedSpring> springs, const double* x,
                                              const double* v, double* l2Out, double* fxOut, double* fyOut,
                                              double* fzOut, int& shortSprings)
{
    const __m256d minimum = _mm256_set1_pd(kMinSpringLength * kMinSpringLength);
    size_t e = 0;
    for (; e + 4 <= springs.size(); e += 4) {
        const PackedSpring* p = springs.data() + e;
        const lanes::Rows xi = ends(x, p, 0);
        const lanes::Rows xj = ends(x, p, 1);
        const __m256d dx = _mm256_sub_pd(xj.r0, xi.r0);
        const __m256d dy = _mm256_sub_pd(xj.r1, xi.r1);
        const __m256d dz = _mm256_sub_pd(xj.r2, xi.r2);
        const __m256d l2 =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
        const __m256d invL = _mm256_div_pd(_mm256_set1_pd(1.0), _mm256_sqrt_pd(l2));
        const lanes::Rows vi = ends(v, p, 0);
        const lanes::Rows vj = ends(v, p, 1);
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
        const lanes::Rows rka = lanes::transpose(a0, a1, a2, a3);
        const __m256d across = lanes::fourthRow(a0, a1, a2, a3);
        const __m256d stretch = _mm256_sub_pd(_mm256_mul_pd(l2, invL), rka.r0);
        const __m256d tension = _mm256_add_pd(_mm256_mul_pd(rka.r1, stretch), _mm256_mul_pd(rka.r2, speed));
        const __m256d s = _mm256_mul_pd(tension, invL);
        _mm256_storeu_pd(l2Out + e, l2);
        shortSprings += _mm256_movemask_pd(_mm256_cmp_pd(l2, minimum, _CMP_LT_OQ)) != 0 ? 1 : 0;
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
    m_ends.clear();
    for (const PackedSpring& p : springs) {
        m_ends.push_back(p.i);
        m_ends.push_back(p.j);
    }
    constexpr double kSigns[] = {1.0, -1.0};  // the first end takes the force, the second its negative
    m_nodes.build(m_ends, kSigns);
    m_l2.resize(springs.size());
    m_fx.resize(springs.size());
    m_fy.resize(springs.size());
    m_fz.resize(springs.size());
}

void addSpringForces(std::span<const PackedSpring> springs, SpringGather& gather, const double* x,
                     const double* v, double* f, SpringLanes width)
{
    assert(gather.numSprings() == springs.size());
    double* l2 = gather.m_l2.data();
    double* fx = gather.m_fx.data();
    double* fy = gather.m_fy.data();
    double* fz = gather.m_fz.data();
    int shortSprings = 0;  // springs without length (nonzero when there is any)
    size_t e = 0;
#if defined(__x86_64__)
    if (width == SpringLanes::Widest && lanes::available()) {
        e = byFour(springs, x, v, l2, fx, fy, fz, shortSprings);
    }
#else
    (void)width;
#endif
    for (; e < springs.size(); ++e) {
        springForce(springs[e], x, v, e, l2, fx, fy, fz);
        shortSprings += l2[e] < kMinSpringLength * kMinSpringLength ? 1 : 0;
    }
    // Only where a spring has no length need the sums look at the lengths.
    gather.m_nodes.sumInto(f, fx, fy, fz, shortSprings > 0 ? l2 : nullptr,
                           kMinSpringLength * kMinSpringLength);
}

}  // namespace colonosim::physics
