#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/dem/StepDisplacer.hpp>
#include <stdexcept>

namespace yade {

void StepDisplacer::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    if (!(rot.coeffs().squaredNorm() > 0) || !rot.coeffs().allFinite())
        throw std::invalid_argument("StepDisplacer.rot must be a finite, non-zero quaternion");
    const Quaternionr q = rot.normalized();
    if (setVelocities) {
        if (!(scene->dt > 0)) throw std::invalid_argument("StepDisplacer.setVelocities needs O.dt > 0");
        Eigen::AngleAxis<Real> turn(q);
        const Vector3r angVel = turn.axis() * (turn.angle() / scene->dt);
        for (int id : ids) {
            State& st = *scene->bodies[id]->state;
            st.vel() = mov / scene->dt;
            st.angVel() = angVel;
        }
        return;
    }
    for (int id : ids) {
        State& st = *scene->bodies[id]->state;
        st.pos() += mov;
        st.ori() = q * st.ori();
    }
    scene->motion.invalidate(); // (not the integrator's move: the collider and the loop check the positions again)
}

} // namespace yade
