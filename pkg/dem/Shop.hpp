// Whole-scene measurements used from Python (utils): time steps, energies, forces.
#pragma once
#include <core/Scene.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <array>

namespace yade {
namespace Shop {
    // (3.5.22): min over spheres of r / sqrt(E/ρ), ρ = mass/volume; throws if no sphere has an elastic material.
    Real PWaveTimeStep(const Scene& scene);
    // Mean (or maximum) resultant force on dynamic bodies, gravity of the NewtonIntegrator
    // included, divided by the mean contact force; tends to 0 at static equilibrium.
    Real unbalancedForce(Scene& scene, bool useMaxForce);
    // Sum of ½mv² + ½ω·Iω over dynamic bodies (v: in a periodic cell, relative to the homogeneous field).
    // maxId (if given): the id of the body with the largest kinetic energy (-1: none)
    Real kineticEnergy(const Scene& scene, long* maxId = nullptr);
    // Box around all spheres (surfaces, or centers only).
    std::pair<Vector3r, Vector3r> aabbExtremaOfSpheres(const Scene& scene, bool centers);
    // Total volume of the spheres whose mask shares a bit with `mask` (0 or -1: all).
    Real spheresVolume(const Scene& scene, int mask);
    // Number of real interactions of each body whose position is inside [lo, hi].
    std::vector<int> coordinations(const Scene& scene, const Vector3r& lo, const Vector3r& hi);
    // The spheres whose mask shares a bit with `mask` (-1: all), in id order: id, center, radius and
    // the index of their material in O.materials (-1 if none); for yade.export.
    struct SphereColumns {
        std::vector<int> ids, matIds;
        std::vector<Vector3r> pos;
        std::vector<Real> radius;
    };
    SphereColumns sphereColumns(const Scene& scene, int mask);
    // Total mass of the spheres whose mask shares a bit with `mask` (0 or -1: all).
    Real spheresMass(const Scene& scene, int mask);

    // Visits every real contact whose physics is a NormShearPhys (FrictPhys...), in the order of
    // O.interactions: fn(f, l, n, phys) with f = normalForce + shearForce, the force on body 2; l the
    // branch vector from body 1 to body 2, or to its image in a periodic cell (pos2 + hSize·cellDist
    // - pos1); n the unit contact normal (of a GenericSpheresContact geometry, else l/|l|). The
    // Love-Weber stress of the cell is -1/V Σ f ⊗ l (doc/periodic.md). Not while the interaction
    // loop runs. The physics class is checked once per contact pool, not per contact.
    template <class Fn> void forEachContactForce(const Scene& scene, Fn&& fn);
} // namespace Shop

template <class Fn> void Shop::forEachContactForce(const Scene& scene, Fn&& fn) {
    const InteractionContainer& I = scene.interactions;
    const BodyStore& store = scene.bodies.hot();
    const Vector3r* pos = store.pos.data();
    const bool periodic = scene.isPeriodic && I.periodic;
    const Matrix3r& hSize = scene.cell->hSize;
    // per pool: 0 not looked at yet, 1 NormShearPhys with a GenericSpheresContact, 2 NormShearPhys
    // with another geometry, 3 other physics
    std::array<signed char, InteractionContainer::maxPools> kind{};
    for (size_t k = 0; k < I.size(); ++k) {
        const IPhys* p;
        const IGeom* g;
        signed char what;
        const uint32_t c = I.contactOf[k];
        if (c != InteractionContainer::noContact) {
            const ContactPool& pool = I.pool(c);
            const size_t slot = InteractionContainer::slotOf(c);
            if (pool.header(slot).ended) continue;
            p = pool.phys(slot);
            g = pool.geom(slot);
            signed char& kd = kind[InteractionContainer::poolOf(c)];
            if (!kd) kd = !dynamic_cast<const NormShearPhys*>(p) ? 3 : dynamic_cast<const GenericSpheresContact*>(g) ? 1 : 2;
            what = kd;
        } else {
            if (!I.isReal(k)) continue;
            p = I.phys(k);
            g = I.geom(k);
            what = !dynamic_cast<const NormShearPhys*>(p) ? 3 : dynamic_cast<const GenericSpheresContact*>(g) ? 1 : 2;
        }
        if (what == 3) continue;
        const auto& phys = *static_cast<const NormShearPhys*>(p);
        const Body::id_t id1 = I.pairIds[2 * k], id2 = I.pairIds[2 * k + 1];
        Vector3r l = pos[id2] - pos[id1];
        if (periodic) l += hSize * I.cellDist[k].cast<Real>();
        const Vector3r n = what == 1 ? static_cast<const GenericSpheresContact*>(g)->normal : Vector3r(l.normalized());
        fn(Vector3r(phys.normalForce + phys.shearForce), l, n, phys);
    }
}
} // namespace yade
