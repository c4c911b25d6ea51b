#include <pkg/dem/cohesive/Ig2_Facet_Sphere_ScGeom6D.hpp>
#include <stdexcept>

namespace yade {

bool Ig2_Facet_Sphere_ScGeom6D::go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force,
        Interaction& I) {
    Contact c(I);
    return contact6D(static_cast<const Facet&>(s1), static_cast<const Sphere&>(s2).radius, st1.kinematics(), st2.kinematics(), shift2, force, c);
}

void Ig2_Facet_Sphere_ScGeom6D::goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) {
    const BodyStore::Columns cols = b.store;
    for (size_t j = 0; j < n; ++j) {
        Contact& x = c[j];
        result[j] = contact6D(static_cast<const Facet&>(*b.shape[x.id1]), b.radius[x.id2], cols.kinematics(x.id1), cols.kinematics(x.id2),
                Vector3r::Zero(), false, x);
    }
}

bool Ig2_Facet_Sphere_ScGeom6D::contact6D(const Facet& f, Real r, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2,
        bool force, Contact& contact) {
    ScGeom6D* g = contact.geom ? dynamic_cast<ScGeom6D*>(contact.geom) : nullptr;
    if (contact.geom && !g)
        throw std::runtime_error(getClassName() + ": bodies #" + std::to_string(contact.id1) + " and #" + std::to_string(contact.id2)
                + " already have a " + contact.geom->getClassName() + ", not a ScGeom6D (was the Ig2 functor changed during the simulation?)");
    const Facet* facet[1] = {&f};
    const Quaternionr* ori[1] = {&st1.ori};
    const bool isNew = !g;
    Real distance;
    const ScGeom::Values<Real> values = kernel<Real>(facet, ori, r, motionOf(st1, st2), vec3(shift2), isNew ? Vec3<Real>::zero() : vec3(g->normal),
            isNew, scene->dt, distance);
    if (!contact.isReal() && ((distance > r && !force) || values.penetrationDepth <= 0)) return false; // (a potential contact: not one yet)
    if (isNew) g = &contact.makeGeom<ScGeom6D>();
    values.store(*g);
    if (isNew) g->initRotations(st1.ori, st2.ori);
    else g->precomputeRotations(st1.ori, st2.ori, false);
    return true;
}

} // namespace yade
