#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>

namespace yade {

bool Ig2_Sphere_Sphere_ScGeom::go(const Sphere& s1, const Sphere& s2, const Kinematics& st1, const Kinematics& st2,
        const Vector3r& shift2, bool force, Contact& contact) {
    return go(s1.radius, s2.radius, st1, st2, shift2, force, contact);
}

void Ig2_Sphere_Sphere_ScGeom::goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) {
    const BodyStore::Columns cols = b.store; // (locals: the char stores to result may alias anything in memory)
    const Real* radius = b.radius;
    for (size_t j = 0; j < n; ++j) {
        Contact& x = c[j];
        if (__builtin_expect(x.shift != nullptr, 0)) { // (a periodic scene: body 2's image)
            const Kinematics k2 = cols.kinematics(x.id2);
            const Vector3r pos2 = k2.pos + x.shift->shift2, vel2 = k2.vel + x.shift->shiftVel2;
            result[j] = go(radius[x.id1], radius[x.id2], cols.kinematics(x.id1), Kinematics{pos2, vel2, k2.angVel, k2.ori}, Vector3r::Zero(), false, x);
        } else
            result[j] = go(radius[x.id1], radius[x.id2], cols.kinematics(x.id1), cols.kinematics(x.id2), Vector3r::Zero(), false, x);
    }
}

bool Ig2_Sphere_Sphere_ScGeom::go(Real r1, Real r2, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
        Contact& contact) {
    if (!contact.isReal() && !force) { // a potential contact: is it one yet?
        const Real reach = interactionDetectionFactor * (r1 + r2);
        if (((st2.pos + shift2) - st1.pos).squaredNorm() > reach * reach) return false;
    }
    const bool isNew = !contact.geom;
    ScGeom& g = isNew ? contact.makeGeom<ScGeom>() : static_cast<ScGeom&>(*contact.geom);
    kernel<Real>(r1, r2, motionOf(st1, st2), vec3(shift2), vec3(g.normal), isNew, scene->dt).store(g);
    return true;
}

} // namespace yade
