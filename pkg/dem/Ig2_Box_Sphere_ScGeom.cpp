#include <core/Scene.hpp>
#include <pkg/dem/Ig2_Box_Sphere_ScGeom.hpp>

namespace yade {

bool Ig2_Box_Sphere_ScGeom::go(const Box& b, const Sphere& s, const Kinematics& st1, const Kinematics& st2,
        const Vector3r& shift2, bool force, Contact& contact) {
    const Real r = s.radius;
    const Vector3r center = st2.pos + shift2;
    const Vector3r local = st1.ori.conjugate() * (center - st1.pos); // sphere center in the box frame
    const Vector3r& l = b.extents;
    Vector3r closest = local.cwiseMax(-l).cwiseMin(l); // closest point of the box volume
    const bool inside = closest == local;
    Vector3r normal; // from the box towards the sphere, global
    Real penetrationDepth;
    if (inside) { // the center is inside: push out through the nearest face
        int ax = 0;
        Real gap = l[0] - std::abs(local[0]);
        for (int i = 1; i < 3; ++i)
            if (l[i] - std::abs(local[i]) < gap) {
                gap = l[i] - std::abs(local[i]);
                ax = i;
            }
        Vector3r n = Vector3r::Zero();
        n[ax] = local[ax] > 0 ? 1 : -1; // (exactly on the mid-plane, e.g. in a plate of zero thickness: -1, as in the reference)
        normal = st1.ori * n;
        penetrationDepth = r + gap;
    } else {
        normal = center - (st1.pos + st1.ori * closest);
        penetrationDepth = r - normal.norm();
        if (penetrationDepth <= 0 && !contact.isReal() && !force) return false;
        normal.normalize();
    }
    const bool isNew = !contact.geom;
    ScGeom& g = isNew ? contact.makeGeom<ScGeom>() : static_cast<ScGeom&>(*contact.geom);
    g.contactPoint = center - (r - 0.5 * penetrationDepth) * normal;
    g.penetrationDepth = penetrationDepth;
    g.refR1 = g.refR2 = r;
    g.precompute(st1, st2, scene->dt, normal, isNew, shift2, false);
    return true;
}

} // namespace yade
