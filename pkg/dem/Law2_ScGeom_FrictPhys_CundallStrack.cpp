#include <pkg/dem/Law2_ScGeom_FrictPhys_CundallStrack.hpp>

namespace yade {

void Law2_ScGeom_FrictPhys_CundallStrack::prepare() {
    if (!scene->trackEnergy) return;
    elastId = scene->energy.term("elastPotential", false);
    plastId = scene->energy.term("plastDissip", true);
}

} // namespace yade
