#include <algorithm>
#include <core/BodyStore.hpp>
#include <core/Scene.hpp>
#include <pkg/dem/Law2_ScGeom_FrictViscoPhys_CundallStrackVisco.hpp>

namespace yade {

void Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::prepare() {
    if (scene->trackEnergy || traceEnergy) elastId = scene->energy.term("elastPotential", false);
    if (scene->trackEnergy && !traceEnergy) plastId = scene->energy.term("plastDissip", true);
}

Real Law2_ScGeom_FrictViscoPhys_CundallStrackVisco::elasticEnergy(const Scene& scene) {
    const InteractionContainer& ic = scene.interactions;
    Real e = 0;
    for (size_t k = 0; k < ic.size(); ++k)
        if (ic.isReal(k))
            if (const auto* p = dynamic_cast<const FrictViscoPhys*>(ic.phys(k)))
                e += 0.5 * (p->normalForce.squaredNorm() / p->kn + (p->ks > 0 ? p->shearForce.squaredNorm() / p->ks : 0));
    return e;
}

} // namespace yade
