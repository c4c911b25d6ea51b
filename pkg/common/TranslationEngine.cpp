#include <core/Scene.hpp>
#include <pkg/common/TranslationEngine.hpp>

namespace yade {

void TranslationEngine::postLoad() {
    if (translationAxis.squaredNorm() > 0) translationAxis.normalize();
}

void TranslationEngine::apply(const std::vector<int>& bodyIds) {
    const Vector3r v = velocity * translationAxis;
    for (int id : bodyIds) scene->bodies[id]->state->vel() += v;
}

} // namespace yade
