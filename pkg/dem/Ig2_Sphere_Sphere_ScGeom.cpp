#include <core/Scene.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>

namespace yade {

bool Ig2_Sphere_Sphere_ScGeom::go(const Sphere& s1, const Sphere& s2, const BodyHot& st1, const BodyHot& st2,
        const Vector3r& shift2, bool force, Contact& contact) {
    Vector3r normal = (st2.pos + shift2) - st1.pos;
    const Real sumR = s1.radius + s2.radius;
    if (!contact.isReal() && !force) { // a potential contact: is it one yet?
        const Real reach = interactionDetectionFactor * sumR;
        if (normal.squaredNorm() > reach * reach) return false;
    }
    const bool isNew = !contact.geom;
    ScGeom& g = isNew ? contact.makeGeom<ScGeom>() : static_cast<ScGeom&>(*contact.geom);
    const Real dist = normal.norm();
    normal /= dist;
    g.penetrationDepth = sumR - dist;
    g.contactPoint = st1.pos + (s1.radius - 0.5 * g.penetrationDepth) * normal;
    g.refR1 = s1.radius;
    g.refR2 = s2.radius;
    g.precompute(st1, st2, scene->dt, normal, isNew, shift2, true);
    return true;
}

} // namespace yade
