// The number types of the contact kernels: a kernel is written once as a template on T and runs
// on one contact (T = Real) or on two at a time (T = Two, one contact in each lane of an SSE2
// register: x86-64's baseline; elsewhere two scalars). + - * / and sqrt are IEEE operations in
// both, so each lane of Two rounds as the scalar expression written in the same order: the two
// instantiations give the same bits by construction. Branches are written as selects
// (select(mask, a, b)); a branch that depends only on a functor's settings stays an `if`.
#pragma once
#include <lib/base/Math.hpp>
#include <cmath>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

// On a kernel and what it calls: one pass over two contacts is then one function, its values in
// registers (as separate functions, the kernels passed their vectors of Two through memory).
#define YADE_KERNEL __attribute__((always_inline)) inline

namespace yade {

using std::abs; // (the scalar forms beside Two's, so that a kernel reads the same for both)
using std::sqrt;

#ifdef __SSE2__
// A value of each of two contacts (lane 0: the first, lane 1: the second).
struct Two {
    __m128d v;
    Two() = default;
    Two(__m128d x) : v(x) {}
    Two(Real a, Real b) : v(_mm_set_pd(b, a)) {}
    Two(Real a) : v(_mm_set1_pd(a)) {} // (a constant in both lanes)
    Real lane(int i) const { return i ? _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)) : _mm_cvtsd_f64(v); }
};
inline Two operator+(Two a, Two b) { return _mm_add_pd(a.v, b.v); }
inline Two operator-(Two a, Two b) { return _mm_sub_pd(a.v, b.v); }
inline Two operator*(Two a, Two b) { return _mm_mul_pd(a.v, b.v); }
inline Two operator/(Two a, Two b) { return _mm_div_pd(a.v, b.v); }
inline Two operator-(Two a) { return _mm_xor_pd(a.v, _mm_set1_pd(-0.0)); } // (exact, as a scalar's -x)
inline Two sqrt(Two a) { return _mm_sqrt_pd(a.v); }
inline Two abs(Two a) { return _mm_andnot_pd(_mm_set1_pd(-0.0), a.v); }
struct TwoMask {
    __m128d m;
    bool lane(int i) const { return (_mm_movemask_pd(m) >> i) & 1; }
};
inline TwoMask greater(Two a, Two b) { return {_mm_cmpgt_pd(a.v, b.v)}; }
inline TwoMask equal(Two a, Two b) { return {_mm_cmpeq_pd(a.v, b.v)}; }
inline TwoMask operator|(TwoMask a, TwoMask b) { return {_mm_or_pd(a.m, b.m)}; }
inline TwoMask operator&(TwoMask a, TwoMask b) { return {_mm_and_pd(a.m, b.m)}; }
inline TwoMask operator!(TwoMask a) { return {_mm_xor_pd(a.m, _mm_castsi128_pd(_mm_set1_epi32(-1)))}; }
inline Two select(TwoMask mask, Two a, Two b) { return _mm_or_pd(_mm_and_pd(mask.m, a.v), _mm_andnot_pd(mask.m, b.v)); }
#else // (other processors: the same arithmetic on two scalars)
struct Two {
    Real a, b;
    Two() = default;
    Two(Real x, Real y) : a(x), b(y) {}
    Two(Real x) : a(x), b(x) {}
    Real lane(int i) const { return i ? b : a; }
};
inline Two operator+(Two x, Two y) { return Two(x.a + y.a, x.b + y.b); }
inline Two operator-(Two x, Two y) { return Two(x.a - y.a, x.b - y.b); }
inline Two operator*(Two x, Two y) { return Two(x.a * y.a, x.b * y.b); }
inline Two operator/(Two x, Two y) { return Two(x.a / y.a, x.b / y.b); }
inline Two operator-(Two x) { return Two(-x.a, -x.b); }
inline Two sqrt(Two x) { return Two(std::sqrt(x.a), std::sqrt(x.b)); }
inline Two abs(Two x) { return Two(std::abs(x.a), std::abs(x.b)); }
struct TwoMask {
    bool a, b;
    bool lane(int i) const { return i ? b : a; }
};
inline TwoMask greater(Two x, Two y) { return {x.a > y.a, x.b > y.b}; }
inline TwoMask equal(Two x, Two y) { return {x.a == y.a, x.b == y.b}; }
inline TwoMask operator|(TwoMask x, TwoMask y) { return {x.a || y.a, x.b || y.b}; }
inline TwoMask operator&(TwoMask x, TwoMask y) { return {x.a && y.a, x.b && y.b}; }
inline TwoMask operator!(TwoMask x) { return {!x.a, !x.b}; }
inline Two select(TwoMask m, Two x, Two y) { return Two(m.a ? x.a : y.a, m.b ? x.b : y.b); }
#endif

// The scalar forms, so that a kernel reads the same for both.
inline Real lane(Real x, int) { return x; }
inline Real lane(Two x, int i) { return x.lane(i); }
inline bool lane(bool m, int) { return m; }
inline bool lane(TwoMask m, int i) { return m.lane(i); }
inline bool greater(Real a, Real b) { return a > b; }
inline bool equal(Real a, Real b) { return a == b; }
inline Real select(bool mask, Real a, Real b) { return mask ? a : b; }

template <class T> struct LaneTraits;
template <> struct LaneTraits<Real> {
    using Mask = bool;
    static constexpr int lanes = 1;
};
template <> struct LaneTraits<Two> {
    using Mask = TwoMask;
    static constexpr int lanes = 2;
};
template <class T> using MaskOf = typename LaneTraits<T>::Mask;
template <class T> constexpr int lanesOf = LaneTraits<T>::lanes;

// a mask set in every lane; whether any lane of a mask is set
template <class T> inline MaskOf<T> allSet() { return equal(T(0.0), T(0.0)); }
inline bool anySet(bool m) { return m; }
inline bool anySet(TwoMask m) { return m.lane(0) || m.lane(1); }

// std::max(x, 0) with its bits (x when x is NaN or -0)
template <class T> inline T maxZero(T x) { return select(greater(T(0.0), x), T(0.0), x); }
// A scalar function applied lane by lane (pow and the like, which have no SSE2 form).
template <class F> inline Real perLane(Real x, F f) { return f(x); }
template <class F> inline Two perLane(Two x, F f) { return Two(f(x.lane(0)), f(x.lane(1))); }

// A 3-vector of lanes, with the products and sums in Eigen's order (a dot product sums x + y + z
// from the left, a cross product is (a1 b2 - a2 b1, a2 b0 - a0 b2, a0 b1 - a1 b0)).
template <class T> struct Vec3 {
    T x, y, z;
    Vec3() = default;
    Vec3(T a, T b, T c) : x(a), y(b), z(c) {}
    static Vec3 zero() { return Vec3(T(0.0), T(0.0), T(0.0)); }
    Vector3r lane(int i) const { return Vector3r(yade::lane(x, i), yade::lane(y, i), yade::lane(z, i)); }
};
template <class T> inline Vec3<T> operator+(const Vec3<T>& a, const Vec3<T>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T> inline Vec3<T> operator-(const Vec3<T>& a, const Vec3<T>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> inline Vec3<T> operator-(const Vec3<T>& a) { return {-a.x, -a.y, -a.z}; }
template <class T> inline Vec3<T> operator*(T s, const Vec3<T>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class T> inline Vec3<T> operator*(const Vec3<T>& a, T s) { return {a.x * s, a.y * s, a.z * s}; }
template <class T> inline Vec3<T> operator/(const Vec3<T>& a, T s) { return {a.x / s, a.y / s, a.z / s}; }
template <class T> inline T dot(const Vec3<T>& a, const Vec3<T>& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
template <class T> inline T squaredNorm(const Vec3<T>& a) { return dot(a, a); }
template <class T> inline T norm(const Vec3<T>& a) { return sqrt(squaredNorm(a)); }
template <class T> inline Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> inline Vec3<T> select(MaskOf<T> m, const Vec3<T>& a, const Vec3<T>& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
inline Vec3<Real> vec3(const Vector3r& v) { return {v[0], v[1], v[2]}; }
inline Vector3r eigen(const Vec3<Real>& v) { return Vector3r(v.x, v.y, v.z); }

// The positions and velocities of a contact's two bodies.
template <class T> struct PairMotion {
    Vec3<T> pos1, pos2, vel1, vel2, angVel1, angVel2;
};

// The ids of the contacts' objects (bodies, records) in each lane.
template <class T> struct LaneIds;
template <> struct LaneIds<Real> {
    long i[1];
};
template <> struct LaneIds<Two> {
    long i[2];
};

// An entry of a column for each lane.
YADE_KERNEL Real gather(const Real* column, const LaneIds<Real>& id) { return column[id.i[0]]; }
YADE_KERNEL Two gather(const Real* column, const LaneIds<Two>& id) { return Two(column[id.i[0]], column[id.i[1]]); }
template <class T> YADE_KERNEL Vec3<T> gather(const Vector3r* column, const LaneIds<T>& id) {
    if constexpr (lanesOf<T> == 1) return vec3(column[id.i[0]]);
    else {
        const Vector3r &a = column[id.i[0]], &b = column[id.i[1]];
        return {Two(a[0], b[0]), Two(a[1], b[1]), Two(a[2], b[2])};
    }
}
// A value made lane by lane by a scalar function of the lane's index.
template <class T, class F> YADE_KERNEL T eachLane(F f) {
    if constexpr (lanesOf<T> == 1) return f(0);
    else return Two(f(0), f(1));
}

// A Vec3 of lanes from a scalar function giving each lane's Vector3r.
template <class T, class F> YADE_KERNEL Vec3<T> lanesOfVec(F f) {
    if constexpr (lanesOf<T> == 1) return vec3(f(0));
    else {
        const Vector3r a = f(0), b = f(1);
        return {Two(a[0], b[0]), Two(a[1], b[1]), Two(a[2], b[2])};
    }
}

// The records (objects of class O) of the contacts of each lane, read and written by member:
// rows.get(&O::member) is the member of each lane's record as a T (or a Vec3<T>), rows.set() writes
// it in the lanes that are live (a lane left out keeps its record untouched).
template <class O, class T> class Rows {
public:
    O* p[lanesOf<T>];
    bool live[lanesOf<T>];
    O& operator[](int i) const { return *p[i]; }
    template <class B> YADE_KERNEL T get(Real B::*m) const {
        return eachLane<T>([&](int i) { return p[i]->*m; });
    }
    template <class B> YADE_KERNEL Vec3<T> get(Vector3r B::*m) const {
        return {eachLane<T>([&](int i) { return (p[i]->*m)[0]; }), eachLane<T>([&](int i) { return (p[i]->*m)[1]; }),
                eachLane<T>([&](int i) { return (p[i]->*m)[2]; })};
    }
    // a value reached through a function of the record (e.g. in an out-of-line part of it, which
    // the function may make): called for the live lanes only, the others read 0
    template <class F> YADE_KERNEL T getVia(F f) const {
        return eachLane<T>([&](int i) { return live[i] ? (Real)f(*p[i]) : Real(0); });
    }
    template <class F> YADE_KERNEL Vec3<T> getVecVia(F f) const {
        Vector3r v[lanesOf<T>];
        for (int i = 0; i < lanesOf<T>; ++i) v[i] = live[i] ? Vector3r(f(*p[i])) : Vector3r::Zero();
        return {eachLane<T>([&](int i) { return v[i][0]; }), eachLane<T>([&](int i) { return v[i][1]; }),
                eachLane<T>([&](int i) { return v[i][2]; })};
    }
    // f(lane) for each live lane, in lane order
    template <class F> YADE_KERNEL void forLive(F f) const {
        for (int i = 0; i < lanesOf<T>; ++i)
            if (live[i]) f(i);
    }
    template <class B> YADE_KERNEL void set(Real B::*m, T v) {
        for (int i = 0; i < lanesOf<T>; ++i)
            if (live[i]) p[i]->*m = lane(v, i);
    }
    template <class B> YADE_KERNEL void set(Vector3r B::*m, const Vec3<T>& v) {
        for (int i = 0; i < lanesOf<T>; ++i)
            if (live[i]) p[i]->*m = v.lane(i);
    }
    template <class B> YADE_KERNEL void set(bool B::*m, MaskOf<T> v) {
        for (int i = 0; i < lanesOf<T>; ++i)
            if (live[i]) p[i]->*m = lane(v, i);
    }
    // written in every lane, live or not (a record the caller owns in all of them)
    template <class B> YADE_KERNEL void put(Real B::*m, T v) {
        for (int i = 0; i < lanesOf<T>; ++i) p[i]->*m = lane(v, i);
    }
    template <class B> YADE_KERNEL void put(Vector3r B::*m, const Vec3<T>& v) {
        for (int i = 0; i < lanesOf<T>; ++i) p[i]->*m = v.lane(i);
    }
    template <class F> YADE_KERNEL void setVecVia(F f, const Vec3<T>& v) {
        for (int i = 0; i < lanesOf<T>; ++i)
            if (live[i]) f(*p[i]) = v.lane(i);
    }
    bool anyLive() const {
        for (int i = 0; i < lanesOf<T>; ++i)
            if (live[i]) return true;
        return false;
    }
};

} // namespace yade
