#include <core/Scene.hpp>
#include <pkg/common/HarmonicMotionEngine.hpp>

namespace yade {

void HarmonicMotionEngine::apply(const std::vector<int>& bodyIds) {
    const Real t = scene->time;
    Vector3r v;
    for (int i = 0; i < 3; ++i) {
        const Real w = 2 * M_PI * f[i];
        v[i] = -A[i] * w * std::sin(w * t + fi[i]);
    }
    for (int id : bodyIds) scene->bodies[id]->state->vel() += v;
}

} // namespace yade
