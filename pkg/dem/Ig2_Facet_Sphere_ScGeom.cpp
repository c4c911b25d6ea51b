#include <pkg/dem/Ig2_Facet_Sphere_ScGeom.hpp>

namespace yade {

bool Ig2_Facet_Sphere_ScGeom::go(const Facet& f, const Sphere& s, const Kinematics& st1, const Kinematics& st2,
        const Vector3r& shift2, bool force, Contact& contact) {
    return go(f, s.radius, st1, st2, shift2, force, contact);
}

void Ig2_Facet_Sphere_ScGeom::goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) {
    const BodyStore::Columns cols = b.store; // (locals: the char stores to result may alias anything in memory)
    const Shape* const* shape = b.shape;
    const Real* radius = b.radius;
    for (size_t j = 0; j < n; ++j) {
        Contact& x = c[j];
        result[j] = go(static_cast<const Facet&>(*shape[x.id1]), radius[x.id2], cols.kinematics(x.id1), cols.kinematics(x.id2), Vector3r::Zero(),
                false, x);
    }
}

bool Ig2_Facet_Sphere_ScGeom::go(const Facet& f, Real r, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
        Contact& contact) {
    const Facet* facet[1] = {&f};
    const Quaternionr* ori[1] = {&st1.ori};
    const bool isNew = !contact.geom;
    Real distance;
    const ScGeom::Values<Real> g = kernel<Real>(facet, ori, r, motionOf(st1, st2), vec3(shift2),
            isNew ? Vec3<Real>::zero() : vec3(static_cast<const ScGeom&>(*contact.geom).normal), isNew, scene->dt, distance);
    if (!contact.isReal() && ((distance > r && !force) || g.penetrationDepth <= 0)) return false; // (a potential contact: not one yet)
    g.store(isNew ? contact.makeGeom<ScGeom>() : static_cast<ScGeom&>(*contact.geom));
    return true;
}

} // namespace yade
