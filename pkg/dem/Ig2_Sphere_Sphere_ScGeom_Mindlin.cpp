// The pass over existing sphere-sphere contacts whose law is Law2_ScGeom_MindlinPhys_Mindlin (the
// Hertz-Mindlin spheres of the DEM8 drum): Ig2_Sphere_Sphere_ScGeom::go() followed by
// Law2_ScGeom_MindlinPhys_Mindlin::go(), two contacts at a time (TwoLanes.hpp). Every operation is
// the one of those functions in the same order, so each contact gets the bits of the two functors
// run one after the other (tests/test_fused_pass.py); forces are added contact by contact in the
// batch's order. With adhesion, moments or energy tracking the functors themselves run, contact by
// contact. Change the physics in the functors first, then here.
#include <core/Scene.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>
#include <pkg/dem/Law2_ScGeom_MindlinPhys_Mindlin.hpp>
#include <pkg/dem/SphereSphereLanes.hpp>

namespace yade {

using namespace lanes;

namespace {
// What the contacts a few places on will read: their records and their bodies' entries.
void prefetchContact(const Contact& x, const BodyStore::Columns& cols, const Real* radius, const Vector3r* force, const Vector3r* torque) {
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
// a × b, componentwise as Eigen's cross()
inline void cross(Two a0, Two a1, Two a2, Two b0, Two b1, Two b2, Two& r0, Two& r1, Two& r2) {
    r0 = a1 * b2 - a2 * b1;
    r1 = a2 * b0 - a0 * b2;
    r2 = a0 * b1 - a1 * b0;
}
} // namespace

void Ig2_Sphere_Sphere_ScGeom::goBatchWithMindlin(const BodyColumns& b, Contact* c, size_t n, Law2_ScGeom_MindlinPhys_Mindlin& law, char* keep) {
    const BodyStore::Columns cols = b.store;
    const Real* radius = b.radius;
    ForceContainer& forces = scene->forces;
    Vector3r* const force = forces.inPlaceForces(); // (one thread: adds in place, as addContact would)
    Vector3r* const torque = forces.inPlaceTorques();
    if (law.includeAdhesion || law.includeMoment || law.calcEnergy) { // (the functors, contact by contact)
        for (size_t j = 0; j < n; ++j) {
            if (j + lookahead < n) prefetchContact(c[j + lookahead], cols, radius, force, torque);
            Contact& x = c[j];
            go(radius[x.id1], radius[x.id2], cols.kinematics(x.id1), cols.kinematics(x.id2), Vector3r::Zero(), false, x);
            keep[j] = law.go(static_cast<ScGeom&>(*x.geom), static_cast<MindlinPhys&>(*x.phys), x);
        }
        return;
    }
    const Real dtScalar = scene->dt;
    const Two dt(dtScalar), zero(0.0), two(2.0), oneHalf(1.5);
    ScGeom spareGeom; // (the second lane of an odd last contact writes here)
    MindlinPhys sparePhys;
    for (size_t j = 0; j < n; j += 2) {
        for (size_t ahead = j + lookahead; ahead < std::min(n, j + lookahead + 2); ++ahead) prefetchContact(c[ahead], cols, radius, force, torque);
        const bool both = j + 1 < n;
        const Contact& xa = c[j];
        const Contact& xb = both ? c[j + 1] : c[j];
        ScGeom& ga = static_cast<ScGeom&>(*xa.geom);
        ScGeom& gb = both ? static_cast<ScGeom&>(*xb.geom) : (spareGeom = ga);
        MindlinPhys& pa = static_cast<MindlinPhys&>(*xa.phys);
        MindlinPhys& pb = both ? static_cast<MindlinPhys&>(*xb.phys) : (sparePhys = pa);
        const SphereSphereGeom g = sphereSphereGeom(cols, radius, xa.id1, xa.id2, xb.id1, xb.id2, ga, gb, dtScalar);
        const Two &n0 = g.n0, &n1 = g.n1, &n2 = g.n2, &u = g.depth, &s0 = g.s0, &s1 = g.s1, &s2 = g.s2;
        // Law2_ScGeom_MindlinPhys_Mindlin::go for both lanes (a lane whose bodies separated is
        // handled below, and nothing of its law's arithmetic is kept)
        const Vector3r &x1a = cols.pos[xa.id1], &x1b = cols.pos[xb.id1], &x2a = cols.pos[xa.id2], &x2b = cols.pos[xb.id2];
        const Two d10 = g.c0 - component(x1a, x1b, 0), d11 = g.c1 - component(x1a, x1b, 1), d12 = g.c2 - component(x1a, x1b, 2); // cp - x1
        const Two d20 = g.c0 - component(x2a, x2b, 0), d21 = g.c1 - component(x2a, x2b, 1), d22 = g.c2 - component(x2a, x2b, 2); // cp - x2
        const Two sqrtU = sqrt(u);
        const Two mbar(Law2_ScGeom_MindlinPhys_Mindlin::effectiveMass(cols, xa.id1, xa.id2),
                Law2_ScGeom_MindlinPhys_Mindlin::effectiveMass(cols, xb.id1, xb.id2));
        const Two kno(pa.kno, pb.kno), kso(pa.kso, pb.kso);
        const Two kn = oneHalf * kno * sqrtU, ks = kso * sqrtU;
        // normal: elastic (Hertz) minus viscous, cut at zero
        const Vector3r &w1a = cols.angVel[xa.id1], &w1b = cols.angVel[xb.id1], &w2a = cols.angVel[xa.id2], &w2b = cols.angVel[xb.id2];
        const Vector3r &v1a = cols.vel[xa.id1], &v1b = cols.vel[xb.id1], &v2a = cols.vel[xa.id2], &v2b = cols.vel[xb.id2];
        Two e10, e11, e12, e20, e21, e22; // angVel × (cp - x)
        cross(component(w1a, w1b, 0), component(w1a, w1b, 1), component(w1a, w1b, 2), d10, d11, d12, e10, e11, e12);
        cross(component(w2a, w2b, 0), component(w2a, w2b, 1), component(w2a, w2b, 2), d20, d21, d22, e20, e21, e22);
        const Two rv0 = (component(v2a, v2b, 0) + e20) - (component(v1a, v1b, 0) + e10);
        const Two rv1 = (component(v2a, v2b, 1) + e21) - (component(v1a, v1b, 1) + e11);
        const Two rv2 = (component(v2a, v2b, 2) + e22) - (component(v1a, v1b, 2) + e12);
        const Two vn = (rv0 * n0 + rv1 * n1) + rv2 * n2;
        const Two fnElastic = kno * u * sqrtU;
        const Two betan(pa.betan, pb.betan), betas(pa.betas, pb.betas);
        const Two cn = select(greater(betan, zero), two * betan * sqrt(mbar * kn), zero);
        const Two cnvn = cn * vn;
        Two fn = fnElastic - cnvn;
        fn = select(greater(zero, fn), zero, fn);
        // shear: incremental elastic part, Coulomb limit, viscous part while sticking
        Two fe0 = component(pa.shearElastic, pb.shearElastic, 0), fe1 = component(pa.shearElastic, pb.shearElastic, 1),
            fe2 = component(pa.shearElastic, pb.shearElastic, 2);
        g.rotated(fe0, fe1, fe2);
        fe0 = fe0 - ks * s0;
        fe1 = fe1 - ks * s1;
        fe2 = fe2 - ks * s2;
        Two ut0 = component(pa.usTotal, pb.usTotal, 0), ut1 = component(pa.usTotal, pb.usTotal, 1), ut2 = component(pa.usTotal, pb.usTotal, 2);
        g.rotated(ut0, ut1, ut2);
        Two ue0 = component(pa.usElastic, pb.usElastic, 0), ue1 = component(pa.usElastic, pb.usElastic, 1),
            ue2 = component(pa.usElastic, pb.usElastic, 2);
        g.rotated(ue0, ue1, ue2);
        ue0 = ue0 - s0;
        ue1 = ue1 - s1;
        ue2 = ue2 - s2;
        const Two maxFs = Two(pa.tangensOfFrictionAngle, pb.tangensOfFrictionAngle) * fn; // (fn >= 0 here: max(fn, 0) is fn)
        const Two fsNorm = sqrt((fe0 * fe0 + fe1 * fe1) + fe2 * fe2);
        const Mask sliding = greater(fsNorm, maxFs);
        const Two ratio = select(greater(fsNorm, zero), maxFs / fsNorm, zero);
        fe0 = select(sliding, fe0 * ratio, fe0);
        fe1 = select(sliding, fe1 * ratio, fe1);
        fe2 = select(sliding, fe2 * ratio, fe2);
        ue0 = select(sliding, ue0 * ratio, ue0);
        ue1 = select(sliding, ue1 * ratio, ue1);
        ue2 = select(sliding, ue2 * ratio, ue2);
        const Two cs = select(greater(betas, zero), two * betas * sqrt(mbar * ks), zero);
        const Two sv0 = select(sliding, zero, cs * (s0 / dt)), sv1 = select(sliding, zero, cs * (s1 / dt)), sv2 = select(sliding, zero, cs * (s2 / dt));
        const Two sf0 = select(sliding, fe0, fe0 - sv0), sf1 = select(sliding, fe1, fe1 - sv1), sf2 = select(sliding, fe2, fe2 - sv2);
        const Two nf0 = fn * n0, nf1 = fn * n1, nf2 = fn * n2;
        const Two F0 = -(nf0 + sf0), F1 = -(nf1 + sf1), F2 = -(nf2 + sf2); // on body 1
        Two T10, T11, T12, T20, T21, T22;
        cross(d10, d11, d12, F0, F1, F2, T10, T11, T12);
        cross(d20, d21, d22, -F0, -F1, -F2, T20, T21, T22);
        // lane by lane, in order: the forces of the first contact are added before the second's
        for (int lane = 0; lane < (both ? 2 : 1); ++lane) {
            const Contact& x = lane ? xb : xa;
            MindlinPhys& p = lane ? pb : pa;
            auto at = [lane](Two v) { return lane ? v.second() : v.first(); };
            auto vec = [&at](Two v0, Two v1, Two v2) { return Vector3r(at(v0), at(v1), at(v2)); };
            if (at(u) < 0) { // the bodies separated
                keep[j + lane] = law.neverErase;
                if (law.neverErase) {
                    p.normalForce = p.shearForce = p.normalViscous = p.shearViscous = Vector3r::Zero();
                    p.kn = p.ks = 0;
                }
                continue;
            }
            p.kn = at(kn);
            p.ks = at(ks);
            p.normalViscous = vec(cnvn * n0, cnvn * n1, cnvn * n2);
            p.normalForce = vec(nf0, nf1, nf2);
            p.usTotal = vec(ut0 - s0, ut1 - s1, ut2 - s2);
            p.isSliding = isSet(sliding, lane);
            p.shearViscous = vec(sv0, sv1, sv2);
            p.shearElastic = vec(fe0, fe1, fe2);
            p.usElastic = vec(ue0, ue1, ue2);
            p.shearForce = vec(sf0, sf1, sf2);
            const Vector3r F = vec(F0, F1, F2), T1 = vec(T10, T11, T12), T2 = vec(T20, T21, T22);
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

} // namespace yade
