#include <pkg/dem/CriticalTimeStep.hpp>
#include <pkg/dem/FrictPhys.hpp>
#include <pkg/dem/ScGeom.hpp>
#include <vector>

namespace yade {

namespace {
// Contribution (3.5.20) of a contact to the translational and rotational stiffness diagonals of
// its first (side 1) or second body: K_ii = Σ kn·n_i² + ks·(1 - n_i²); the shear spring acts
// on rotations through the lever arm.
// dynamic_cast<const T*>(p), remembered per class index (there are few classes; casts are slow).
template <class T, class Root> const T* castByIndex(const Root* p) {
    thread_local std::vector<signed char> memo; // per class index: -1 not known yet, 0 no, 1 yes
    if (!p) return nullptr;
    const size_t index = (size_t)p->getClassIndex();
    if (index >= memo.size()) memo.resize(index + 1, -1);
    if (memo[index] < 0) memo[index] = dynamic_cast<const T*>(p) != nullptr;
    return memo[index] ? static_cast<const T*>(p) : nullptr;
}

bool contribution(const IGeom* g, const IPhys* p, int side, Vector3r& kt, Vector3r& kr) {
    const auto* phys = castByIndex<NormShearPhys>(p);
    const auto* geom = castByIndex<GenericSpheresContact>(g);
    if (!phys || !geom) return false;
    const Vector3r n2 = geom->normal.cwiseProduct(geom->normal);
    const Real arm = side == 1 ? geom->refR1 : geom->refR2;
    kt = phys->kn * n2 + phys->ks * (Vector3r::Ones() - n2);
    kr = phys->ks * (Vector3r::Ones() - n2) * (arm * arm);
    return true;
}

void lowest(const Body& b, const Vector3r& kt, const Vector3r& kr, CriticalStep& best) {
    if ((kt.array() <= 0).all() && (kr.array() <= 0).all()) return; // no contact: nothing to read
    if (!b.isDynamic()) return;
    const State& s = *b.state;
    for (int i = 0; i < 6; ++i) {
        const Real K = i < 3 ? kt[i] : kr[i - 3];
        const Real m = i < 3 ? s.mass() : s.inertia()[i - 3];
        if (K <= 0 || (s.blockedDOFsMask() & (1 << i))) continue;
        const CriticalStep c{std::sqrt(2.0) * std::sqrt(m / K), b.id, i}; // (3.5.18)
        if (c.before(best)) best = c;
    }
}
} // namespace

void criticalStepOfBody(const Scene& scene, Body::id_t id, CriticalStep& best) {
    if (!scene.bodies.exists(id) || !scene.bodies[id]->isDynamic()) return; // (lowest() would find nothing: a facet's many partners are not read)
    Vector3r kt = Vector3r::Zero(), kr = Vector3r::Zero(), ct, cr;
    for (const auto& partner : scene.interactions.partnersOf(id)) {
        const InteractionContainer& intrs = scene.interactions;
        if (intrs.isReal(partner.k) && contribution(intrs.geom(partner.k), intrs.phys(partner.k), intrs.pairIds[2 * partner.k] == id ? 1 : 2, ct, cr)) {
            kt += ct;
            kr += cr;
        }
    }
    lowest(*scene.bodies[id], kt, kr, best);
}

CriticalStep criticalTimeStep(const Scene& scene, const std::vector<Body::id_t>& ids) {
    CriticalStep best;
    for (Body::id_t id : ids) criticalStepOfBody(scene, id, best);
    return best;
}

CriticalStep criticalTimeStep(const Scene& scene, bool asLastLoopSawThem) {
    const size_t n = scene.bodies.size();
    std::vector<Vector3r> kTrans(n, Vector3r::Zero()), kRot(n, Vector3r::Zero());
    Vector3r ct, cr;
    const InteractionContainer& intrs = scene.interactions;
    for (size_t k = 0; k < intrs.size(); ++k) {
        if (asLastLoopSawThem && !intrs.wasReal[k]) continue; // (a contiguous flag: most pairs are not touched)
        if (!intrs.isReal(k)) continue;
        for (int side = 1; side <= 2; ++side)
            if (contribution(intrs.geom(k), intrs.phys(k), side, ct, cr)) {
                const Body::id_t id = intrs.pairIds[2 * k + side - 1];
                kTrans[id] += ct;
                kRot[id] += cr;
            }
    }
    CriticalStep best;
    for (size_t id = 0; id < n; ++id)
        if (!kTrans[id].isZero(0) || !kRot[id].isZero(0)) // bodies without contacts: nothing to read
            if (const auto& b = scene.bodies[(Body::id_t)id]) lowest(*b, kTrans[id], kRot[id], best);
    return best;
}

} // namespace yade
