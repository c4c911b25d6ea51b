#include <core/Scene.hpp>
#include <pkg/common/RotationEngine.hpp>
#include <stdexcept>

namespace yade {

void RotationEngine::postLoad() {
    normalizeDirection(rotationAxis);
}

void RotationEngine::apply(const std::vector<int>& bodyIds) {
    const Scene& s = *scene;
    if (angularVelocity != 0 && !(rotationAxis.squaredNorm() > 0))
        throw std::invalid_argument(getClassName() + ".rotationAxis is zero: give the direction of the rotation axis");
    const Vector3r omega = angularVelocity * rotationAxis;
    // the turn of one step: positions then lie on the circle after every step, whatever dt (applied as a
    // quaternion, not as a matrix: the velocity (turn·r - r)/dt then has the reference's bits)
    const Quaternionr turn(AngleAxisr(angularVelocity * s.dt, rotationAxis));
    for (int id : bodyIds) {
        State& st = *s.bodies[id]->state;
        st.angVel() += omega;
        if (!rotateAroundZero) continue;
        const Vector3r r = st.pos() - zeroPoint;
        st.vel() += s.dt > 0 ? Vector3r((turn * r - r) / s.dt) : Vector3r(omega.cross(r)); // (O.dt = 0: the limit)
    }
}

} // namespace yade
