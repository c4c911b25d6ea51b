#include <core/Scene.hpp>
#include <lib/base/Interpolation.hpp>
#include <pkg/dem/InterpolatingDirectedForceEngine.hpp>
#include <stdexcept>

namespace yade {

void InterpolatingDirectedForceEngine::action() {
    if (!(direction.norm() > 0)) throw std::invalid_argument(getClassName() + ".direction must not be zero");
    force = direction.normalized() * interpolateInTime(scene->time, times, magnitudes, wrap, getClassName());
    ForceEngine::action();
}

} // namespace yade
