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
#include <pkg/dem/SphereSphereLanes.hpp>
#include <typeinfo>

namespace yade {

bool Ig2_Sphere_Sphere_ScGeom::fusesWith(const LawFunctor& law) const {
    return typeid(law) == typeid(Law2_ScGeom_FrictPhys_CundallStrack) || typeid(law) == typeid(Law2_ScGeom_MindlinPhys_Mindlin);
}

using namespace lanes;

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
    const Two half(0.5);
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
        const SphereSphereGeom g = sphereSphereGeom(cols, radius, xa.id1, xa.id2, xb.id1, xb.id2, ga, gb, scene->dt);
        const Two &r1 = g.r1, &r2 = g.r2, &n0 = g.n0, &n1 = g.n1, &n2 = g.n2, &depth = g.depth, &s0 = g.s0, &s1 = g.s1, &s2 = g.s2;
        // Law2_ScGeom_FrictPhys_CundallStrack::go, for both lanes (a lane whose bodies separated is
        // handled below, and nothing of its law's arithmetic is kept)
        const Two kDepth = Two(pa.kn, pb.kn) * depth;
        const Two f0 = kDepth * n0, f1 = kDepth * n1, f2 = kDepth * n2; // normalForce
        // the old shear force turned with the contact plane (ScGeom::rotated), minus ks·shearInc
        const Two q0 = component(pa.shearForce, pb.shearForce, 0), q1 = component(pa.shearForce, pb.shearForce, 1),
                  q2 = component(pa.shearForce, pb.shearForce, 2);
        Two rot0 = q0, rot1 = q1, rot2 = q2;
        g.rotated(rot0, rot1, rot2);
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

} // namespace yade
