#include <cmath>
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <pkg/dem/concrete/CpmPhys.hpp>
#include <pkg/dem/concrete/CpmState.hpp>
#include <pkg/dem/concrete/CpmStateUpdater.hpp>
#include <vector>

namespace yade {

namespace {
struct BodySums {
    int contacts = 0;
    Real damage = 0;
    Matrix3r damageTensor = Matrix3r::Zero(), stress = Matrix3r::Zero();
};
} // namespace

void CpmStateUpdater::action() {
    const BodyContainer& bodies = scene->bodies;
    const InteractionContainer& ic = scene->interactions;
    std::vector<BodySums> sums(bodies.size());
    Real residual = 0, omegaMax = NaN;
    long cohesive = 0;
    for (size_t k = 0; k < ic.size(); ++k) { // the contacts
        if (!ic.isReal(k)) continue;
        const auto* phys = dynamic_cast<const CpmPhys*>(ic.phys(k));
        const auto* geom = dynamic_cast<const ScGeom*>(ic.geom(k));
        if (!phys || !geom || !phys->isCohesive) continue;
        ++cohesive;
        residual += phys->relResidualStrength;
        if (!(phys->omega <= omegaMax)) omegaMax = phys->omega;
        const Vector3r& n = geom->normal;
        const Real d = 1 - phys->relResidualStrength;
        const Matrix3r nn = n * n.transpose();
        const Matrix3r fs = phys->Fs * n.transpose();
        const Matrix3r stress = (phys->refLength / 2) * (phys->Fn * nn + (fs + fs.transpose()) / 2);
        const Matrix3r damage = d * (67.5 * nn - 13.5 * Matrix3r::Identity());
        for (const Body::id_t id : {ic.pairIds[2 * k], ic.pairIds[2 * k + 1]}) {
            BodySums& s = sums[(size_t)id];
            ++s.contacts;
            s.damage += d;
            s.damageTensor += damage;
            s.stress += stress;
        }
    }
    for (size_t id = 0; id < bodies.size(); ++id) { // the bodies
        if (!bodies.exists((Body::id_t)id)) continue;
        auto* state = dynamic_cast<CpmState*>(bodies[(Body::id_t)id]->state.get());
        if (!state) continue;
        const BodySums& s = sums[id];
        const int all = s.contacts + state->numBrokenCohesive;
        state->numContacts = s.contacts;
        state->normDmg = all > 0 ? (s.damage + state->numBrokenCohesive) / all : 0;
        state->damageTensor = s.contacts > 0 ? Matrix3r(s.damageTensor / s.contacts) : Matrix3r::Zero();
        const auto* sphere = dynamic_cast<const Sphere*>(bodies[(Body::id_t)id]->shape.get());
        const Real volume = sphere ? 4. / 3. * Mathr_PI * std::pow(sphere->radius, 3) / 0.62 : NaN; // (packing fraction 0.62)
        state->stress = sphere ? Matrix3r(s.stress / volume) : Matrix3r::Zero();
    }
    long broken2 = 0; // the broken contacts, counted on both their bodies
    for (size_t id = 0; id < bodies.size(); ++id)
        if (bodies.exists((Body::id_t)id))
            if (const auto* state = dynamic_cast<const CpmState*>(bodies[(Body::id_t)id]->state.get())) broken2 += state->numBrokenCohesive;
    const Real all = cohesive + broken2 / 2.; // (a broken contact counts with residual strength 0, as in the reference)
    avgRelResidual = all > 0 ? residual / all : NaN;
    maxOmega = omegaMax;
}

} // namespace yade
