#include <core/Scene.hpp>
#include <pkg/common/ForceResetter.hpp>

namespace yade {

void ForceResetter::action() {
    scene->forces.reset();
    scene->forces.lastReset = scene->iter;
}

} // namespace yade
