#include "simcore/physics/SpringKernel.h"

#include <cmath>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace colonosim::physics {

namespace {

/// A spring's squared length (m^2) and its force on its first end (N).
struct SpringForce {
    double l2;
    double x, y, z;
};

SpringForce springForce(const PackedSpring& p, const double* x, const double* v)
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
    return {l2, s * dx + p.across * rx, s * dy + p.across * ry, s * dz + p.across * rz};
}

void apply(double* f, const PackedSpring& p, const SpringForce& fs)
{
    if (fs.l2 < kMinSpringLength * kMinSpringLength) {
        return;
    }
    double* fi = f + 3 * p.i;
    double* fj = f + 3 * p.j;
    fi[0] += fs.x;
    fi[1] += fs.y;
    fi[2] += fs.z;
    fj[0] -= fs.x;
    fj[1] -= fs.y;
    fj[2] -= fs.z;
}

#if defined(__x86_64__)
/// Component k of the nodes at the ends `end` (0: i, 1: j) of four springs, lane 0 the first.
__attribute__((target("avx2"))) inline __m256d lanes(const double* q, const PackedSpring* p, int end, int k)
{
    const auto at = [&](int s) { return q[3 * (end == 0 ? p[s].i : p[s].j) + k]; };
    return _mm256_set_pd(at(3), at(2), at(1), at(0));
}

/// The same for a field of the springs.
__attribute__((target("avx2"))) inline __m256d lanes(const PackedSpring* p, double PackedSpring::*field)
{
    return _mm256_set_pd(p[3].*field, p[2].*field, p[1].*field, p[0].*field);
}

/// springForce() of four springs at once; returns how many springs it did (a multiple of 4).
__attribute__((target("avx2"))) size_t byFour(std::span<const PackedSpring> springs, const double* x,
                                              const double* v, double* f)
{
    size_t e = 0;
    for (; e + 4 <= springs.size(); e += 4) {
        const PackedSpring* p = springs.data() + e;
        const __m256d dx = _mm256_sub_pd(lanes(x, p, 1, 0), lanes(x, p, 0, 0));
        const __m256d dy = _mm256_sub_pd(lanes(x, p, 1, 1), lanes(x, p, 0, 1));
        const __m256d dz = _mm256_sub_pd(lanes(x, p, 1, 2), lanes(x, p, 0, 2));
        const __m256d l2 =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
        const __m256d invL = _mm256_div_pd(_mm256_set1_pd(1.0), _mm256_sqrt_pd(l2));
        const __m256d rx = _mm256_sub_pd(lanes(v, p, 1, 0), lanes(v, p, 0, 0));
        const __m256d ry = _mm256_sub_pd(lanes(v, p, 1, 1), lanes(v, p, 0, 1));
        const __m256d rz = _mm256_sub_pd(lanes(v, p, 1, 2), lanes(v, p, 0, 2));
        const __m256d speed = _mm256_mul_pd(
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, rx), _mm256_mul_pd(dy, ry)), _mm256_mul_pd(dz, rz)),
            invL);
        const __m256d stretch = _mm256_sub_pd(_mm256_mul_pd(l2, invL), lanes(p, &PackedSpring::rest));
        const __m256d tension = _mm256_add_pd(_mm256_mul_pd(lanes(p, &PackedSpring::k), stretch),
                                              _mm256_mul_pd(lanes(p, &PackedSpring::along), speed));
        const __m256d s = _mm256_mul_pd(tension, invL);
        const __m256d across = lanes(p, &PackedSpring::across);
        alignas(32) double out[4][4];
        _mm256_store_pd(out[0], l2);
        _mm256_store_pd(out[1], _mm256_add_pd(_mm256_mul_pd(s, dx), _mm256_mul_pd(across, rx)));
        _mm256_store_pd(out[2], _mm256_add_pd(_mm256_mul_pd(s, dy), _mm256_mul_pd(across, ry)));
        _mm256_store_pd(out[3], _mm256_add_pd(_mm256_mul_pd(s, dz), _mm256_mul_pd(across, rz)));
        for (int lane = 0; lane < 4; ++lane) {
            apply(f, p[lane], {out[0][lane], out[1][lane], out[2][lane], out[3][lane]});
        }
    }
    return e;
}
#endif

}  // namespace

void addSpringForces(std::span<const PackedSpring> springs, const double* x, const double* v, double* f,
                     SpringLanes lanes)
{
    size_t e = 0;
#if defined(__x86_64__)
    static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
    if (lanes == SpringLanes::Widest && avx2) {
        e = byFour(springs, x, v, f);
    }
#else
    (void)lanes;
#endif
    for (; e < springs.size(); ++e) {
        apply(f, springs[e], springForce(springs[e], x, v));
    }
}

}  // namespace colonosim::physics
