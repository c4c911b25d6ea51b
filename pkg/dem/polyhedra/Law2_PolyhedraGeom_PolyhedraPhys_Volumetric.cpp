#include <core/Scene.hpp>
#include <pkg/dem/polyhedra/Law2_PolyhedraGeom_PolyhedraPhys_Volumetric.hpp>
#include <cmath>

namespace yade {

bool Law2_PolyhedraGeom_PolyhedraPhys_Volumetric::go(PolyhedraGeom& geom, PolyhedraPhys& phys, Interaction& I) {
    if (!(geom.penetrationVolume > 0)) return false;
    const Vector3r& n = geom.normal;
    const Real fn = phys.kn * std::pow(geom.penetrationVolume, volumePower);
    phys.normalForce = fn * n;
    // the shear force turned with the contact plane, then the elastic increment, then Coulomb's cap
    Vector3r& fs = phys.shearForce;
    fs -= fs.cross(geom.orthonormal_axis);
    fs -= fs.cross(geom.twist_axis);
    fs -= phys.ks * geom.shearInc;
    const Real cap = fn * phys.tangensOfFrictionAngle;
    if (fs.squaredNorm() > cap * cap) {
        const Vector3r trial = fs;
        fs *= cap / fs.norm();
        if (traceEnergy && phys.ks > 0) {
            const Real lost = (trial - fs).dot(fs) / phys.ks;
#pragma omp atomic
            plasticDissipation += lost;
        }
    }
    // the force on body 2 (its opposite on body 1), applied at the contact point
    const Vector3r f = phys.normalForce + fs;
    const Vector3r x1 = scene->bodies[I.id1]->state->pos();
    Vector3r x2 = scene->bodies[I.id2]->state->pos();
    if (scene->isPeriodic) x2 += scene->cell->hSize * I.cellDist.cast<Real>();
    const Vector3r& c = geom.contactPoint;
    scene->forces.addContact(I.id1, I.id2, -f, (c - x1).cross(-f), (c - x2).cross(f));
    return true;
}

Real Law2_PolyhedraGeom_PolyhedraPhys_Volumetric::elasticEnergy(const Scene& scene) {
    Real e = 0;
    const InteractionContainer& ic = scene.interactions;
    for (size_t k = 0; k < ic.size(); ++k)
        if (ic.isReal(k))
            if (const auto* p = dynamic_cast<const PolyhedraPhys*>(ic.phys(k))) {
                if (p->kn > 0) e += 0.5 * p->normalForce.squaredNorm() / p->kn;
                if (p->ks > 0) e += 0.5 * p->shearForce.squaredNorm() / p->ks;
            }
    return e;
}

} // namespace yade
