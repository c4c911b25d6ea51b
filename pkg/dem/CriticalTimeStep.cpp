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

// (the body's mass, inertia and blocked DOFs from the store's columns: no visit to its Body and State)
void lowest(const BodyStore& h, Body::id_t id, const Vector3r& kt, const Vector3r& kr, CriticalStep& best) {
    if ((kt.array() <= 0).all() && (kr.array() <= 0).all()) return; // no contact: nothing to read
    const int blocked = h.blockedDOFsMask[(size_t)id];
    if (!h.exists[(size_t)id] || (blocked & State::DOF_ALL) == State::DOF_ALL) return; // (not dynamic)
    for (int i = 0; i < 6; ++i) {
        const Real K = i < 3 ? kt[i] : kr[i - 3];
        const Real m = i < 3 ? h.mass[(size_t)id] : h.inertia[(size_t)id][i - 3];
        if (K <= 0 || (blocked & (1 << i))) continue;
        const CriticalStep c{std::sqrt(2.0) * std::sqrt(m / K), id, i}; // (3.5.18)
        if (c.before(best)) best = c;
    }
}
} // namespace

namespace {
    bool isDynamic(const BodyStore& h, Body::id_t id) {
        return id >= 0 && (size_t)id < h.size() && h.exists[(size_t)id] && (h.blockedDOFsMask[(size_t)id] & State::DOF_ALL) != State::DOF_ALL;
    }
    // A body's stiffness diagonals from all its contacts.
    void sumsOfBody(const Scene& scene, Body::id_t id, bool asLastLoopSawThem, Vector3r& kt, Vector3r& kr) {
        const InteractionContainer& intrs = scene.interactions;
        Vector3r ct, cr;
        kt = kr = Vector3r::Zero();
        for (const auto& partner : intrs.partnersOf(id)) {
            if (asLastLoopSawThem && !intrs.wasReal[partner.k]) continue; // (a contiguous flag: cheaper than isReal)
            if (intrs.isReal(partner.k) && contribution(intrs.geom(partner.k), intrs.phys(partner.k), intrs.pairIds[2 * partner.k] == id ? 1 : 2, ct, cr)) {
                kt += ct;
                kr += cr;
            }
        }
    }
} // namespace

// Whether these stiffness diagonals give body id a critical step below dt (dt2 = dt²), without the square roots of
// lowest(): dt > sqrt(2)·sqrt(m/K) is K·dt² > 2m.
static bool overStep(const BodyStore& h, Body::id_t id, const Vector3r& kt, const Vector3r& kr, Real dt2) {
    const int blocked = h.blockedDOFsMask[(size_t)id];
    for (int i = 0; i < 6; ++i) {
        const Real K = i < 3 ? kt[i] : kr[i - 3];
        const Real m = i < 3 ? h.mass[(size_t)id] : h.inertia[(size_t)id][i - 3];
        if (K > 0 && !(blocked & (1 << i)) && K * dt2 > 2 * m) return true;
    }
    return false;
}

void criticalStepOfBody(const Scene& scene, Body::id_t id, CriticalStep& best, bool asLastLoopSawThem) {
    const BodyStore& h = scene.bodies.hot();
    if (!isDynamic(h, id)) return; // (lowest() would find nothing, and a facet's many partners are not read)
    Vector3r kt, kr;
    sumsOfBody(scene, id, asLastLoopSawThem, kt, kr);
    lowest(h, id, kt, kr, best);
}

CriticalStep criticalStepOfNewContacts(const Scene& scene, const std::vector<size_t>& contacts, std::vector<Vector3r>& kTrans,
        std::vector<Vector3r>& kRot) {
    const BodyStore& h = scene.bodies.hot();
    const InteractionContainer& intrs = scene.interactions;
    if (kTrans.size() < h.size()) kTrans.resize(h.size(), Vector3r::Zero());
    if (kRot.size() < h.size()) kRot.resize(h.size(), Vector3r::Zero());
    CriticalStep best;
    Vector3r ct, cr;
    const Real dt2 = scene.dt * scene.dt;
    for (size_t k : contacts) {
        if (k >= intrs.size() || !intrs.isReal(k)) continue;
        for (int side = 1; side <= 2; ++side) {
            const Body::id_t id = intrs.pairIds[2 * k + side - 1];
            if (!isDynamic(h, id) || !contribution(intrs.geom(k), intrs.phys(k), side, ct, cr)) continue;
            kTrans[id] += ct;
            kRot[id] += cr;
            if (!overStep(h, id, kTrans[id], kRot[id], dt2)) continue;
            sumsOfBody(scene, id, true, kTrans[id], kRot[id]); // (the sums may hold contacts that ended: all its contacts now)
            lowest(h, id, kTrans[id], kRot[id], best);
        }
    }
    return best;
}

CriticalStep criticalTimeStep(const Scene& scene, const std::vector<Body::id_t>& ids) {
    CriticalStep best;
    for (Body::id_t id : ids) criticalStepOfBody(scene, id, best);
    return best;
}

CriticalStep criticalTimeStep(const Scene& scene, bool asLastLoopSawThem) {
    std::vector<Vector3r> kTrans, kRot;
    return criticalTimeStep(scene, asLastLoopSawThem, kTrans, kRot);
}

CriticalStep criticalTimeStep(const Scene& scene, bool asLastLoopSawThem, std::vector<Vector3r>& kTrans, std::vector<Vector3r>& kRot) {
    const size_t n = scene.bodies.size();
    kTrans.assign(n, Vector3r::Zero());
    kRot.assign(n, Vector3r::Zero());
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
    const BodyStore& h = scene.bodies.hot();
    for (size_t id = 0; id < n && id < h.size(); ++id)
        if (!kTrans[id].isZero(0) || !kRot[id].isZero(0)) // bodies without contacts: nothing to read
            lowest(h, (Body::id_t)id, kTrans[id], kRot[id], best);
    return best;
}

} // namespace yade
