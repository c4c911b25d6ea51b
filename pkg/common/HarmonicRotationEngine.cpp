#include <core/Scene.hpp>
#include <pkg/common/HarmonicRotationEngine.hpp>

namespace yade {

void HarmonicRotationEngine::apply(const std::vector<int>& bodyIds) {
    const Real w = 2 * M_PI * f;
    angularVelocity = -A * w * std::sin(w * scene->time + fi);
    RotationEngine::apply(bodyIds);
}

} // namespace yade
