#include <cmath>
#include <pkg/dem/cohesive/ScGeom6D.hpp>

namespace yade {

void ScGeom6D::initRotations(const Quaternionr& ori1, const Quaternionr& ori2) {
    initialOrientation1 = ori1;
    initialOrientation2 = ori2;
    twistCreep = Quaternionr::Identity();
    twist = 0;
    bending = Vector3r::Zero();
}

void ScGeom6D::precomputeRotations(const Quaternionr& ori1, const Quaternionr& ori2, bool creep) {
    // the rotation of body 1 since the start, followed by the inverse of body 2's
    Quaternionr delta = (ori1 * initialOrientation1.conjugate()) * (initialOrientation2 * ori2.conjugate());
    if (creep) delta = delta * twistCreep;
    const Eigen::AngleAxis<Real> aa(delta);
    Real angle = aa.angle();
    if (angle > M_PI) angle -= 2 * M_PI; // the shorter way round
    const Vector3r rotation = angle * aa.axis();
    twist = rotation.dot(normal);
    bending = rotation - twist * normal;
}

} // namespace yade
