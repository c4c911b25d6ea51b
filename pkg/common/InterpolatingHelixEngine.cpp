#include <core/Scene.hpp>
#include <lib/base/Interpolation.hpp>
#include <pkg/common/InterpolatingHelixEngine.hpp>

namespace yade {

void InterpolatingHelixEngine::apply(const std::vector<int>& bodyIds) {
    angularVelocity = interpolateInTime(scene->time, times, angularVelocities, wrap, getClassName());
    linearVelocity = slope * angularVelocity;
    HelixEngine::apply(bodyIds);
}

} // namespace yade
