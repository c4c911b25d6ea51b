#include <core/Scene.hpp>
#include <pkg/common/KinematicEngine.hpp>
#include <pkg/dem/HarmonicForceEngine.hpp>
#include <cmath>

namespace yade {

void HarmonicForceEngine::action() {
    KinematicEngine::checkIds(*scene, ids, getClassName());
    Vector3r force;
    for (int i = 0; i < 3; ++i) force[i] = A[i] * std::sin(2 * Mathr_PI * f[i] * scene->time + fi[i]);
    for (int id : ids) scene->forces.addForce(id, force);
}

} // namespace yade
