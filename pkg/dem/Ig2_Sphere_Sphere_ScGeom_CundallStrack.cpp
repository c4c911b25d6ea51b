// The pass over existing sphere-sphere contacts whose law is Law2_ScGeom_FrictPhys_CundallStrack,
// the commonest contact of a granular scene: Ig2_Sphere_Sphere_ScGeom::go() (the contact geometry
// and ScGeom::precompute(), 3.3) followed by Law2_ScGeom_FrictPhys_CundallStrack::go() (3.4),
// written out in scalars kept in registers. Every product, sum and reduction is the one of those
// functions, in the same order (Eigen sums x + y + z from the left, as here), so the results are
// the same bits; tests/test_fused_pass.py compares the two paths bit for bit. Change the physics
// in those functions first, then here.
#include <core/Scene.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>
#include <pkg/dem/Law2_ScGeom_FrictPhys_CundallStrack.hpp>
#include <typeinfo>

namespace yade {

bool Ig2_Sphere_Sphere_ScGeom::fusesWith(const LawFunctor& law) const { return typeid(law) == typeid(Law2_ScGeom_FrictPhys_CundallStrack); }

void Ig2_Sphere_Sphere_ScGeom::goBatchWithLaw(const BodyColumns& b, Contact* c, size_t n, LawFunctor& law, char* keep) {
    const auto& cundallStrack = static_cast<const Law2_ScGeom_FrictPhys_CundallStrack&>(law);
    if (scene->trackEnergy) { // (the law's energy terms: the two batches, one after the other)
        goBatch(b, c, n, keep);
        law.goBatch(c, n, keep);
        return;
    }
    const BodyStore::Columns cols = b.store;
    const Real* radius = b.radius;
    const Real dt = scene->dt;
    const bool neverErase = cundallStrack.neverErase;
    ForceContainer& forces = scene->forces;
    Vector3r* const force = forces.inPlaceForces(); // (one thread: adds in place, as addContact would)
    Vector3r* const torque = forces.inPlaceTorques();
    for (size_t j = 0; j < n; ++j) {
        const Contact& x = c[j];
        ScGeom& g = static_cast<ScGeom&>(*x.geom);
        FrictPhys& p = static_cast<FrictPhys&>(*x.phys);
        const Real r1 = radius[x.id1], r2 = radius[x.id2];
        const Vector3r &p1 = cols.pos[x.id1], &p2 = cols.pos[x.id2];
        // Ig2_Sphere_Sphere_ScGeom::go (shift2 = 0)
        Real n0 = (p2[0] + 0.0) - p1[0], n1 = (p2[1] + 0.0) - p1[1], n2 = (p2[2] + 0.0) - p1[2];
        const Real sumR = r1 + r2;
        const Real dist = std::sqrt((n0 * n0 + n1 * n1) + n2 * n2);
        n0 /= dist;
        n1 /= dist;
        n2 /= dist;
        const Real depth = sumR - dist;
        const Real toPoint = r1 - 0.5 * depth;
        g.penetrationDepth = depth;
        g.contactPoint = Vector3r(p1[0] + toPoint * n0, p1[1] + toPoint * n1, p1[2] + toPoint * n2);
        g.refR1 = r1;
        g.refR2 = r2;
        // ScGeom::precompute (an existing contact, avoidRatcheting)
        const Vector3r &v1 = cols.vel[x.id1], &v2 = cols.vel[x.id2], &w1 = cols.angVel[x.id1], &w2 = cols.angVel[x.id2];
        const Real o0 = g.normal[0], o1 = g.normal[1], o2 = g.normal[2];
        const Real a0 = o1 * n2 - o2 * n1, a1 = o2 * n0 - o0 * n2, a2 = o0 * n1 - o1 * n0; // orthonormalAxis
        const Real spin = dt * 0.5 * ((o0 * (w1[0] + w2[0]) + o1 * (w1[1] + w2[1])) + o2 * (w1[2] + w2[2]));
        const Real t0 = spin * o0, t1 = spin * o1, t2 = spin * o2; // twistAxis
        g.orthonormalAxis = Vector3r(a0, a1, a2);
        g.twistAxis = Vector3r(t0, t1, t2);
        g.normal = Vector3r(n0, n1, n2);
        const Real c10 = r1 * n0, c11 = r1 * n1, c12 = r1 * n2;
        const Real c20 = -r2 * n0, c21 = -r2 * n1, c22 = -r2 * n2;
        const Real alpha = (r1 + r2) / (r1 + r2 - depth);
        Real u0 = ((v2[0] - v1[0]) * alpha + (w2[1] * c22 - w2[2] * c21)) - (w1[1] * c12 - w1[2] * c11);
        Real u1 = ((v2[1] - v1[1]) * alpha + (w2[2] * c20 - w2[0] * c22)) - (w1[2] * c10 - w1[0] * c12);
        Real u2 = ((v2[2] - v1[2]) * alpha + (w2[0] * c21 - w2[1] * c20)) - (w1[0] * c11 - w1[1] * c10);
        const Real along = (n0 * u0 + n1 * u1) + n2 * u2;
        u0 -= along * n0;
        u1 -= along * n1;
        u2 -= along * n2;
        const Real s0 = u0 * dt, s1 = u1 * dt, s2 = u2 * dt; // shearInc
        g.shearInc = Vector3r(s0, s1, s2);
        // Law2_ScGeom_FrictPhys_CundallStrack::go
        if (depth < 0) { // the bodies separated
            if (!neverErase) {
                keep[j] = false;
                continue;
            }
            p.normalForce = p.shearForce = Vector3r::Zero();
            keep[j] = true;
            continue;
        }
        const Real kDepth = p.kn * depth;
        const Real f0 = kDepth * n0, f1 = kDepth * n1, f2 = kDepth * n2; // normalForce
        p.normalForce = Vector3r(f0, f1, f2);
        // the old shear force turned with the contact plane (ScGeom::rotated), minus ks·shearInc
        const Real q0 = p.shearForce[0], q1 = p.shearForce[1], q2 = p.shearForce[2];
        const Real m0 = q0 - (q1 * a2 - q2 * a1), m1 = q1 - (q2 * a0 - q0 * a2), m2 = q2 - (q0 * a1 - q1 * a0);
        const Real r0 = m0 - (m1 * t2 - m2 * t1), rr1 = m1 - (m2 * t0 - m0 * t2), rr2 = m2 - (m0 * t1 - m1 * t0);
        Real e0 = r0 - p.ks * s0, e1 = rr1 - p.ks * s1, e2 = rr2 - p.ks * s2;
        const Real tanPhi = p.tangensOfFrictionAngle;
        const Real maxFs2 = ((f0 * f0 + f1 * f1) + f2 * f2) * tanPhi * tanPhi;
        const Real fs2 = (e0 * e0 + e1 * e1) + e2 * e2;
        if (fs2 > maxFs2) { // sliding: Mohr-Coulomb return
            const Real scale = std::sqrt(maxFs2) / std::sqrt(fs2);
            e0 *= scale;
            e1 *= scale;
            e2 *= scale;
        }
        p.shearForce = Vector3r(e0, e1, e2);
        const Real F0 = -f0 - e0, F1 = -f1 - e1, F2 = -f2 - e2; // on body 1
        const Real arm0 = n1 * F2 - n2 * F1, arm1 = n2 * F0 - n0 * F2, arm2 = n0 * F1 - n1 * F0;
        const Real l1 = r1 - 0.5 * depth, l2 = r2 - 0.5 * depth;
        const Vector3r F(F0, F1, F2), T1(l1 * arm0, l1 * arm1, l1 * arm2), T2(l2 * arm0, l2 * arm1, l2 * arm2);
        if (force) {
            force[x.id1] += F;
            torque[x.id1] += T1;
            force[x.id2] -= F;
            torque[x.id2] += T2;
        } else
            forces.addContact(x.id1, x.id2, F, T1, T2);
        keep[j] = true;
    }
    if (force && n) forces.markAdded();
}

} // namespace yade
