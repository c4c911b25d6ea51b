#include <pkg/dem/grid/Ig2_GridNode_GridNode_GridNodeGeom6D.hpp>
#include <stdexcept>

namespace yade {

bool Ig2_GridNode_GridNode_GridNodeGeom6D::go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2,
        bool force, Interaction& I) {
    Contact c(I);
    return nodeContact(static_cast<const Sphere&>(s1).radius, static_cast<const Sphere&>(s2).radius, st1.kinematics(), st2.kinematics(),
            shift2, force, c);
}

void Ig2_GridNode_GridNode_GridNodeGeom6D::goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) {
    const BodyStore::Columns cols = b.store;
    for (size_t j = 0; j < n; ++j) {
        Contact& x = c[j];
        if (x.shift) {
            const Kinematics k2 = cols.kinematics(x.id2);
            const Vector3r pos2 = k2.pos + x.shift->shift2, vel2 = k2.vel + x.shift->shiftVel2;
            result[j] = nodeContact(b.radius[x.id1], b.radius[x.id2], cols.kinematics(x.id1), Kinematics{pos2, vel2, k2.angVel, k2.ori},
                    Vector3r::Zero(), false, x);
        } else
            result[j] = nodeContact(b.radius[x.id1], b.radius[x.id2], cols.kinematics(x.id1), cols.kinematics(x.id2), Vector3r::Zero(), false, x);
    }
}

bool Ig2_GridNode_GridNode_GridNodeGeom6D::nodeContact(Real r1, Real r2, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2,
        bool force, Contact& contact) {
    if (!contact.isReal() && !force) { // (nodes have no bound: this is a bond made by hand, or a node moved next to another)
        const Real reach = interactionDetectionFactor * (r1 + r2);
        if (((st2.pos + shift2) - st1.pos).squaredNorm() > reach * reach) return false;
    }
    GridNodeGeom6D* g = contact.geom ? dynamic_cast<GridNodeGeom6D*>(contact.geom) : nullptr;
    if (contact.geom && !g)
        throw std::runtime_error(getClassName() + ": nodes #" + std::to_string(contact.id1) + " and #" + std::to_string(contact.id2)
                + " already have a " + contact.geom->getClassName() + ", not a GridNodeGeom6D");
    const bool isNew = !g;
    if (isNew) g = &contact.makeGeom<GridNodeGeom6D>();
    kernel<Real>(r1, r2, motionOf(st1, st2), vec3(shift2), vec3(g->normal), isNew, scene->dt).store(*g);
    if (isNew) g->initRotations(st1.ori, st2.ori);
    else if (updateRotations) g->precomputeRotations(st1.ori, st2.ori, creep);
    return true;
}

} // namespace yade
