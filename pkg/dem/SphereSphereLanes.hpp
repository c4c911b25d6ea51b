// Ig2_Sphere_Sphere_ScGeom::go() for two existing contacts at once (one per lane, TwoLanes.hpp):
// the geometry and ScGeom::precompute() with avoidRatcheting, the very operations in the same
// order, so each lane has the bits of the scalar functor. Used by the fused passes
// (Ig2_Sphere_Sphere_ScGeom_CundallStrack.cpp, Ig2_Sphere_Sphere_ScGeom_Mindlin.cpp).
#pragma once
#include <core/BodyStore.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/TwoLanes.hpp>

namespace yade {
namespace lanes {

// What the laws read of the new geometry of both contacts (also stored in ga and gb).
struct SphereSphereGeom {
    Two r1, r2;        // refR1, refR2
    Two n0, n1, n2;    // normal
    Two depth;         // penetrationDepth
    Two c0, c1, c2;    // contactPoint
    Two a0, a1, a2;    // orthonormalAxis (tilt)
    Two t0, t1, t2;    // twistAxis
    Two s0, s1, s2;    // shearInc
    // v rotated with the contact plane (ScGeom::rotated)
    void rotated(Two& v0, Two& v1, Two& v2) const {
        const Two m0 = v0 - (v1 * a2 - v2 * a1), m1 = v1 - (v2 * a0 - v0 * a2), m2 = v2 - (v0 * a1 - v1 * a0);
        v0 = m0 - (m1 * t2 - m2 * t1);
        v1 = m1 - (m2 * t0 - m0 * t2);
        v2 = m2 - (m0 * t1 - m1 * t0);
    }
};

// The contacts' bodies are id1a/id2a and id1b/id2b; ga and gb their geometries (distinct objects).
inline SphereSphereGeom sphereSphereGeom(const BodyStore::Columns& cols, const Real* radius, long id1a, long id2a, long id1b, long id2b,
        ScGeom& ga, ScGeom& gb, Real dt) {
    SphereSphereGeom g;
    const Two halfDt(dt * 0.5), half(0.5), zero(0.0), dtTwo(dt);
    g.r1 = Two(radius[id1a], radius[id1b]);
    g.r2 = Two(radius[id2a], radius[id2b]);
    const Two r1 = g.r1, r2 = g.r2;
    const Vector3r &p1a = cols.pos[id1a], &p1b = cols.pos[id1b], &p2a = cols.pos[id2a], &p2b = cols.pos[id2b];
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
    g.c0 = p10 + toPoint * n0;
    g.c1 = p11 + toPoint * n1;
    g.c2 = p12 + toPoint * n2;
    depth.store(ga.penetrationDepth, gb.penetrationDepth);
    store(ga.contactPoint, gb.contactPoint, g.c0, g.c1, g.c2);
    r1.store(ga.refR1, gb.refR1);
    r2.store(ga.refR2, gb.refR2);
    // ScGeom::precompute (an existing contact, avoidRatcheting)
    const Vector3r &v1a = cols.vel[id1a], &v1b = cols.vel[id1b], &v2a = cols.vel[id2a], &v2b = cols.vel[id2b];
    const Vector3r &w1a = cols.angVel[id1a], &w1b = cols.angVel[id1b], &w2a = cols.angVel[id2a], &w2b = cols.angVel[id2b];
    const Two w10 = component(w1a, w1b, 0), w11 = component(w1a, w1b, 1), w12 = component(w1a, w1b, 2);
    const Two w20 = component(w2a, w2b, 0), w21 = component(w2a, w2b, 1), w22 = component(w2a, w2b, 2);
    const Two o0 = component(ga.normal, gb.normal, 0), o1 = component(ga.normal, gb.normal, 1), o2 = component(ga.normal, gb.normal, 2);
    g.a0 = o1 * n2 - o2 * n1;
    g.a1 = o2 * n0 - o0 * n2;
    g.a2 = o0 * n1 - o1 * n0;
    const Two spin = halfDt * ((o0 * (w10 + w20) + o1 * (w11 + w21)) + o2 * (w12 + w22));
    g.t0 = spin * o0;
    g.t1 = spin * o1;
    g.t2 = spin * o2;
    store(ga.orthonormalAxis, gb.orthonormalAxis, g.a0, g.a1, g.a2);
    store(ga.twistAxis, gb.twistAxis, g.t0, g.t1, g.t2);
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
    g.s0 = u0 * dtTwo;
    g.s1 = u1 * dtTwo;
    g.s2 = u2 * dtTwo;
    store(ga.shearInc, gb.shearInc, g.s0, g.s1, g.s2);
    g.n0 = n0;
    g.n1 = n1;
    g.n2 = n2;
    g.depth = depth;
    return g;
}

} // namespace lanes
} // namespace yade
