// The pass over existing sphere-sphere contacts whose law is Law2_ScGeom_FrictPhys_CundallStrack,
// the commonest contact of a granular scene: Ig2_Sphere_Sphere_ScGeom::go() (the contact geometry
// and ScGeom::precompute(), 3.3) followed by Law2_ScGeom_FrictPhys_CundallStrack::go() (3.4),
// written out for two contacts at a time, one in each lane of an SSE2 register (x86-64's
// baseline; elsewhere two scalars). Every product, sum, quotient and square root is the one of those functions, in the
// same order (Eigen sums x + y + z from the left, as here), and each lane rounds as scalar code
// does, so the results are the same bits; tests/test_fused_pass.py compares the two paths bit for
// bit. The forces are added contact by contact in the batch's order. Change the physics in the
// functors first, then here.
#include <core/Scene.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>
#include <pkg/dem/Law2_ScGeom_FrictPhys_CundallStrack.hpp>
#include <pkg/dem/Law2_ScGeom_MindlinPhys_Mindlin.hpp>
#include <typeinfo>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace yade {

bool Ig2_Sphere_Sphere_ScGeom::fusesWith(const LawFunctor& law) const {
    return typeid(law) == typeid(Law2_ScGeom_FrictPhys_CundallStrack) || typeid(law) == typeid(Law2_ScGeom_MindlinPhys_Mindlin);
}

namespace {
#ifdef __SSE2__
// A value of each of the two contacts (lane 0: the first, lane 1: the second).
struct Two {
    __m128d v;
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
#else // (other processors: the same arithmetic on two scalars)
struct Two {
    Real a, b;
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
} // namespace

void Ig2_Sphere_Sphere_ScGeom::goBatchWithLaw(const BodyColumns& b, Contact* c, size_t n, LawFunctor& law, char* keep) {
    if (typeid(law) == typeid(Law2_ScGeom_MindlinPhys_Mindlin)) {
        goBatchWithMindlin(b, c, n, static_cast<Law2_ScGeom_MindlinPhys_Mindlin&>(law), keep);
        return;
    }
    const auto& cundallStrack = static_cast<const Law2_ScGeom_FrictPhys_CundallStrack&>(law);
    if (scene->trackEnergy) { // (the law's energy terms: the two batches, one after the other)
        goBatch(b, c, n, keep);
        law.goBatch(c, n, keep);
        return;
    }
    const BodyStore::Columns cols = b.store;
    const Real* radius = b.radius;
    const Two dt(scene->dt), halfDt(scene->dt * 0.5), half(0.5), zero(0.0);
    const bool neverErase = cundallStrack.neverErase;
    ForceContainer& forces = scene->forces;
    Vector3r* const force = forces.inPlaceForces(); // (one thread: adds in place, as addContact would)
    Vector3r* const torque = forces.inPlaceTorques();
    ScGeom spareGeom; // (the second lane of an odd last contact writes here)
    FrictPhys sparePhys;
    for (size_t j = 0; j < n; j += 2) {
        for (size_t ahead = j + lookahead; ahead < std::min(n, j + lookahead + 2); ++ahead) { // (what the contacts a few steps on read)
            const Contact& x = c[ahead];
            prefetchLines(x.geom, 3);
            prefetchLines(x.phys, 2);
            for (const Body::id_t id : {x.id1, x.id2}) {
                __builtin_prefetch(&cols.pos[id]);
                __builtin_prefetch(&cols.vel[id]);
                __builtin_prefetch(&cols.angVel[id]);
            }
        }
        const bool two = j + 1 < n;
        const Contact& xa = c[j];
        const Contact& xb = two ? c[j + 1] : c[j];
        ScGeom& ga = static_cast<ScGeom&>(*xa.geom);
        ScGeom& gb = two ? static_cast<ScGeom&>(*xb.geom) : (spareGeom = ga);
        FrictPhys& pa = static_cast<FrictPhys&>(*xa.phys);
        FrictPhys& pb = two ? static_cast<FrictPhys&>(*xb.phys) : (sparePhys = pa);
        const Two r1(radius[xa.id1], radius[xb.id1]), r2(radius[xa.id2], radius[xb.id2]);
        const Vector3r &p1a = cols.pos[xa.id1], &p1b = cols.pos[xb.id1], &p2a = cols.pos[xa.id2], &p2b = cols.pos[xb.id2];
        // Ig2_Sphere_Sphere_ScGeom::go (shift2 = 0)
        const Two p10 = component(p1a, p1b, 0), p11 = component(p1a, p1b, 1), p12 = component(p1a, p1b, 2);
        Two n0 = (component(p2a, p2b, 0) + zero) - p10, n1 = (component(p2a, p2b, 1) + zero) - p11, n2 = (component(p2a, p2b, 2) + zero) - p12;
        const Two sumR = r1 + r2;
        const Two dist = sqrt((n0 * n0 + n1 * n1) + n2 * n2);
        n0 = n0 / dist;
        n1 = n1 / dist;
        n2 = n2 / dist;
        const Two depth = sumR - dist;
        const Two toPoint = r1 - half * depth;
        depth.store(ga.penetrationDepth, gb.penetrationDepth);
        store(ga.contactPoint, gb.contactPoint, p10 + toPoint * n0, p11 + toPoint * n1, p12 + toPoint * n2);
        r1.store(ga.refR1, gb.refR1);
        r2.store(ga.refR2, gb.refR2);
        // ScGeom::precompute (an existing contact, avoidRatcheting)
        const Vector3r &v1a = cols.vel[xa.id1], &v1b = cols.vel[xb.id1], &v2a = cols.vel[xa.id2], &v2b = cols.vel[xb.id2];
        const Vector3r &w1a = cols.angVel[xa.id1], &w1b = cols.angVel[xb.id1], &w2a = cols.angVel[xa.id2], &w2b = cols.angVel[xb.id2];
        const Two w10 = component(w1a, w1b, 0), w11 = component(w1a, w1b, 1), w12 = component(w1a, w1b, 2);
        const Two w20 = component(w2a, w2b, 0), w21 = component(w2a, w2b, 1), w22 = component(w2a, w2b, 2);
        const Two o0 = component(ga.normal, gb.normal, 0), o1 = component(ga.normal, gb.normal, 1), o2 = component(ga.normal, gb.normal, 2);
        const Two a0 = o1 * n2 - o2 * n1, a1 = o2 * n0 - o0 * n2, a2 = o0 * n1 - o1 * n0; // orthonormalAxis
        const Two spin = halfDt * ((o0 * (w10 + w20) + o1 * (w11 + w21)) + o2 * (w12 + w22));
        const Two t0 = spin * o0, t1 = spin * o1, t2 = spin * o2; // twistAxis
        store(ga.orthonormalAxis, gb.orthonormalAxis, a0, a1, a2);
        store(ga.twistAxis, gb.twistAxis, t0, t1, t2);
        store(ga.normal, gb.normal, n0, n1, n2);
        const Two c10 = r1 * n0, c11 = r1 * n1, c12 = r1 * n2;
        const Two minusR2 = -r2;
        const Two c20 = minusR2 * n0, c21 = minusR2 * n1, c22 = minusR2 * n2;
        const Two alpha = (r1 + r2) / (r1 + r2 - depth);
        const Two dv0 = component(v2a, v2b, 0) - component(v1a, v1b, 0), dv1 = component(v2a, v2b, 1) - component(v1a, v1b, 1),
                  dv2 = component(v2a, v2b, 2) - component(v1a, v1b, 2);
        Two u0 = (dv0 * alpha + (w21 * c22 - w22 * c21)) - (w11 * c12 - w12 * c11);
        Two u1 = (dv1 * alpha + (w22 * c20 - w20 * c22)) - (w12 * c10 - w10 * c12);
        Two u2 = (dv2 * alpha + (w20 * c21 - w21 * c20)) - (w10 * c11 - w11 * c10);
        const Two along = (n0 * u0 + n1 * u1) + n2 * u2;
        u0 = u0 - along * n0;
        u1 = u1 - along * n1;
        u2 = u2 - along * n2;
        const Two s0 = u0 * dt, s1 = u1 * dt, s2 = u2 * dt; // shearInc
        store(ga.shearInc, gb.shearInc, s0, s1, s2);
        // Law2_ScGeom_FrictPhys_CundallStrack::go, for both lanes (a lane whose bodies separated is
        // handled below, and nothing of its law's arithmetic is kept)
        const Two kDepth = Two(pa.kn, pb.kn) * depth;
        const Two f0 = kDepth * n0, f1 = kDepth * n1, f2 = kDepth * n2; // normalForce
        // the old shear force turned with the contact plane (ScGeom::rotated), minus ks·shearInc
        const Two q0 = component(pa.shearForce, pb.shearForce, 0), q1 = component(pa.shearForce, pb.shearForce, 1),
                  q2 = component(pa.shearForce, pb.shearForce, 2);
        const Two m0 = q0 - (q1 * a2 - q2 * a1), m1 = q1 - (q2 * a0 - q0 * a2), m2 = q2 - (q0 * a1 - q1 * a0);
        const Two rot0 = m0 - (m1 * t2 - m2 * t1), rot1 = m1 - (m2 * t0 - m0 * t2), rot2 = m2 - (m0 * t1 - m1 * t0);
        const Two ks(pa.ks, pb.ks);
        Two e0 = rot0 - ks * s0, e1 = rot1 - ks * s1, e2 = rot2 - ks * s2;
        const Two tanPhi(pa.tangensOfFrictionAngle, pb.tangensOfFrictionAngle);
        const Two maxFs2 = ((f0 * f0 + f1 * f1) + f2 * f2) * tanPhi * tanPhi;
        const Two fs2 = (e0 * e0 + e1 * e1) + e2 * e2;
        const Mask sliding = greater(fs2, maxFs2); // Mohr-Coulomb return where set
        const Two scale = sqrt(maxFs2) / sqrt(fs2);
        e0 = select(sliding, e0 * scale, e0);
        e1 = select(sliding, e1 * scale, e1);
        e2 = select(sliding, e2 * scale, e2);
        const Two F0 = -f0 - e0, F1 = -f1 - e1, F2 = -f2 - e2; // on body 1
        const Two arm0 = n1 * F2 - n2 * F1, arm1 = n2 * F0 - n0 * F2, arm2 = n0 * F1 - n1 * F0;
        const Two l1 = r1 - half * depth, l2 = r2 - half * depth;
        const Two T10 = l1 * arm0, T11 = l1 * arm1, T12 = l1 * arm2, T20 = l2 * arm0, T21 = l2 * arm1, T22 = l2 * arm2;
        // lane by lane, in order: the forces of the first contact are added before the second's
        for (int lane = 0; lane < (two ? 2 : 1); ++lane) {
            const Contact& x = lane ? xb : xa;
            FrictPhys& p = lane ? pb : pa;
            auto at = [lane](Two v) { return lane ? v.second() : v.first(); };
            if (at(depth) < 0) { // the bodies separated
                keep[j + lane] = neverErase;
                if (neverErase) p.normalForce = p.shearForce = Vector3r::Zero();
                continue;
            }
            p.normalForce = Vector3r(at(f0), at(f1), at(f2));
            p.shearForce = Vector3r(at(e0), at(e1), at(e2));
            const Vector3r F(at(F0), at(F1), at(F2)), T1(at(T10), at(T11), at(T12)), T2(at(T20), at(T21), at(T22));
            if (force) {
                force[x.id1] += F;
                torque[x.id1] += T1;
                force[x.id2] -= F;
                torque[x.id2] += T2;
            } else
                forces.addContact(x.id1, x.id2, F, T1, T2);
            keep[j + lane] = true;
        }
    }
    if (force && n) forces.markAdded();
}

// With Law2_ScGeom_MindlinPhys_Mindlin: contact by contact, go() then the law's go() (the very
// functions), with the records and bodies of the contacts a few places ahead loaded in advance:
// bodies read from a file are in no spatial order, and each contact's reads then missed the caches.
void Ig2_Sphere_Sphere_ScGeom::goBatchWithMindlin(const BodyColumns& b, Contact* c, size_t n, Law2_ScGeom_MindlinPhys_Mindlin& law, char* keep) {
    const BodyStore::Columns cols = b.store;
    const Real* radius = b.radius;
    Vector3r* const force = scene->forces.inPlaceForces();
    Vector3r* const torque = scene->forces.inPlaceTorques();
    for (size_t j = 0; j < n; ++j) {
        if (j + lookahead < n) {
            const Contact& x = c[j + lookahead];
            prefetchLines(x.geom, 3);
            prefetchLines(x.phys, 5);
            for (const Body::id_t id : {x.id1, x.id2}) {
                __builtin_prefetch(&cols.pos[id]);
                __builtin_prefetch(&cols.vel[id]);
                __builtin_prefetch(&cols.angVel[id]);
                __builtin_prefetch(&cols.mass[id]);
                __builtin_prefetch(&cols.blockedDOFsMask[id]);
                __builtin_prefetch(&radius[id]);
                if (force) {
                    __builtin_prefetch(&force[id], 1);
                    __builtin_prefetch(&torque[id], 1);
                }
            }
        }
        Contact& x = c[j];
        go(radius[x.id1], radius[x.id2], cols.kinematics(x.id1), cols.kinematics(x.id2), Vector3r::Zero(), false, x);
        keep[j] = law.go(static_cast<ScGeom&>(*x.geom), static_cast<MindlinPhys&>(*x.phys), x);
    }
}

} // namespace yade
