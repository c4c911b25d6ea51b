#include <core/Scene.hpp>
#include <pkg/common/TranslationEngine.hpp>

namespace yade {

void TranslationEngine::postLoad() {
    normalizeDirection(translationAxis);
}

void TranslationEngine::apply(const std::vector<int>& bodyIds) {
    const Vector3r v = velocity * translationAxis;
    for (int id : bodyIds) scene->bodies[id]->state->vel() += v;
}

} // namespace yade
