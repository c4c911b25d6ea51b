#include <core/Scene.hpp>
#include <pkg/dem/Ig2_Wall_Sphere_ScGeom.hpp>

namespace yade {

bool Ig2_Wall_Sphere_ScGeom::go(const Wall& w, const Sphere& s, const Kinematics& st1, const Kinematics& st2,
        const Vector3r& shift2, bool force, Contact& contact) {
    const int ax = w.axis;
    const Vector3r center = st2.pos + shift2;
    const Real dist = center[ax] - st1.pos[ax]; // signed distance from the plane
    if (!contact.isReal() && std::abs(dist) > s.radius && !force) return false;
    Vector3r normal = Vector3r::Zero();
    normal[ax] = w.sense == 0 ? (dist > 0 ? 1 : -1) : w.sense;
    const bool isNew = !contact.geom;
    ScGeom& g = isNew ? contact.makeGeom<ScGeom>() : static_cast<ScGeom&>(*contact.geom);
    g.contactPoint = center;
    g.contactPoint[ax] = st1.pos[ax]; // the center projected on the wall
    g.penetrationDepth = s.radius - std::abs(dist);
    g.refR1 = g.refR2 = s.radius;
    g.precompute(st1, st2, scene->dt, normal, isNew, shift2, true);
    return true;
}

} // namespace yade
