// Two contacts at a time, one in each lane of an SSE2 register (x86-64's baseline; elsewhere two
// scalars): the arithmetic of the fused passes (Ig2_Sphere_Sphere_ScGeom_CundallStrack.cpp,
// Ig2_Sphere_Sphere_ScGeom_Mindlin.cpp). Each lane rounds as scalar code does: + - * / and sqrt are
// IEEE operations in both, so a lane gives the bits of the scalar expression written in the same order.
#pragma once
#include <lib/base/Math.hpp>
#include <algorithm>
#include <cmath>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace yade {
namespace lanes {
#ifdef __SSE2__
// A value of each of the two contacts (lane 0: the first, lane 1: the second).
struct Two {
    __m128d v;
    Two() = default;
    Two(__m128d x) : v(x) {}
    Two(Real a, Real b) : v(_mm_set_pd(b, a)) {}
    explicit Two(Real a) : v(_mm_set1_pd(a)) {}
    Real first() const { return _mm_cvtsd_f64(v); }
    Real second() const { return _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }
    void store(Real& a, Real& b) const {
        _mm_storel_pd(&a, v);
        _mm_storeh_pd(&b, v);
    }
};
inline Two operator+(Two a, Two b) { return _mm_add_pd(a.v, b.v); }
inline Two operator-(Two a, Two b) { return _mm_sub_pd(a.v, b.v); }
inline Two operator*(Two a, Two b) { return _mm_mul_pd(a.v, b.v); }
inline Two operator/(Two a, Two b) { return _mm_div_pd(a.v, b.v); }
inline Two operator-(Two a) { return _mm_xor_pd(a.v, _mm_set1_pd(-0.0)); } // (exact, as a scalar's -x)
inline Two sqrt(Two a) { return _mm_sqrt_pd(a.v); }
// where `mask` is set, a; elsewhere b
using Mask = __m128d;
inline Mask greater(Two a, Two b) { return _mm_cmpgt_pd(a.v, b.v); }
inline Two select(Mask mask, Two a, Two b) { return _mm_or_pd(_mm_and_pd(mask, a.v), _mm_andnot_pd(mask, b.v)); }
inline bool isSet(Mask mask, int lane) { return (_mm_movemask_pd(mask) >> lane) & 1; }
#else // (other processors: the same arithmetic on two scalars)
struct Two {
    Real a, b;
    Two() = default;
    Two(Real x, Real y) : a(x), b(y) {}
    explicit Two(Real x) : a(x), b(x) {}
    Real first() const { return a; }
    Real second() const { return b; }
    void store(Real& x, Real& y) const {
        x = a;
        y = b;
    }
};
inline Two operator+(Two x, Two y) { return Two(x.a + y.a, x.b + y.b); }
inline Two operator-(Two x, Two y) { return Two(x.a - y.a, x.b - y.b); }
inline Two operator*(Two x, Two y) { return Two(x.a * y.a, x.b * y.b); }
inline Two operator/(Two x, Two y) { return Two(x.a / y.a, x.b / y.b); }
inline Two operator-(Two x) { return Two(-x.a, -x.b); }
inline Two sqrt(Two x) { return Two(std::sqrt(x.a), std::sqrt(x.b)); }
struct Mask {
    bool a, b;
};
inline Mask greater(Two x, Two y) { return Mask{x.a > y.a, x.b > y.b}; }
inline Two select(Mask m, Two x, Two y) { return Two(m.a ? x.a : y.a, m.b ? x.b : y.b); }
inline bool isSet(Mask m, int lane) { return lane ? m.b : m.a; }
#endif
// component i of the vectors of both contacts
inline Two component(const Vector3r& a, const Vector3r& b, int i) { return Two(a[i], b[i]); }
constexpr size_t lookahead = 8; // contacts prefetched ahead in the pass
inline void prefetchLines(const void* p, int lines) {
    for (int l = 0; l < lines; ++l) __builtin_prefetch(static_cast<const char*>(p) + 64 * l);
}
inline void store(Vector3r& a, Vector3r& b, Two x, Two y, Two z) {
    x.store(a[0], b[0]);
    y.store(a[1], b[1]);
    z.store(a[2], b[2]);
}
} // namespace lanes
} // namespace yade
