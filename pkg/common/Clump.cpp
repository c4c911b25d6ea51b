#include <pkg/common/Clump.hpp>
#include <pkg/common/ClumpInertia.hpp>
#include <core/Scene.hpp>
#include <pkg/common/Sphere.hpp>
#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace yade {

static std::string bodyName(Body::id_t id) { return "body #" + std::to_string(id); }

Clump& Clump::of(Scene& s, Body::id_t id) {
    if (!s.bodies.exists(id)) throw std::invalid_argument(bodyName(id) + " does not exist");
    Clump* c = dynamic_cast<Clump*>(s.bodies[id]->shape.get());
    if (!c || !s.bodies[id]->isClump() || !c->clumpMembers()) throw std::invalid_argument(bodyName(id) + " is not a clump");
    return *c;
}

// A body's mass and inertia are finite and not negative.
static void checkMass(const Body& b, const std::string& name, const char* what) {
    const State& st = *b.state;
    if (!(std::isfinite(st.mass()) && st.mass() >= 0 && st.inertia().allFinite() && (st.inertia().array() >= 0).all()))
        throw std::invalid_argument(std::string(what) + ": " + name + " has a non-finite or negative mass or inertia");
}

// A body that may become a member: it exists, is standalone, and its state is usable.
static Body& standalone(Scene& s, Body::id_t id, const char* what) {
    if (!s.bodies.exists(id)) throw std::invalid_argument(std::string(what) + ": " + bodyName(id) + " does not exist");
    Body& b = *s.bodies[id];
    if (b.isClump()) throw std::invalid_argument(std::string(what) + ": " + bodyName(id) + " is a clump");
    if (b.isClumpMember())
        throw std::invalid_argument(std::string(what) + ": " + bodyName(id) + " is already a member of clump #" + std::to_string(b.clumpId)
                + " (a body belongs to one clump at most; releaseFromClump first)");
    checkMass(b, bodyName(id), what);
    return b;
}

static ClumpPart partOf(const Body& b) {
    const State& st = *b.state;
    const auto* sphere = dynamic_cast<const Sphere*>(b.shape.get());
    return ClumpPart{st.pos(), st.ori(), st.mass(), st.inertia(), sphere ? sphere->radius : NaN, b.material ? b.material->density : NaN};
}

// The clump's properties from the parts, checked before anything is changed.
struct ClumpFrame {
    MassProperties m;
    PrincipalAxes axes;
};
static ClumpFrame frameOf(const std::vector<ClumpPart>& parts, int discretization) {
    if (discretization < 0) throw std::invalid_argument("discretization must be 0 (sum the members) or positive, got " + std::to_string(discretization));
    ClumpFrame f;
    f.m = discretization > 0 ? gridMassProperties(parts, discretization) : summedMassProperties(parts);
    f.axes = principalAxes(f.m.inertia);
    if (!(std::isfinite(f.m.mass) && f.m.mass > 0))
        throw std::invalid_argument("a clump must have a positive finite mass (its members' masses sum to " + std::to_string(f.m.mass) + ")");
    if (!(f.axes.moments.allFinite() && (f.axes.moments.array() > 0).all()))
        throw std::invalid_argument("a clump must have positive finite principal moments of inertia (its members give "
                + std::to_string(f.axes.moments[0]) + ", " + std::to_string(f.axes.moments[1]) + ", " + std::to_string(f.axes.moments[2]) + ")");
    return f;
}

// The members' parts: every id once, each a possible member.
static std::vector<ClumpPart> partsOf(Scene& s, const std::vector<Body::id_t>& ids, const char* what) {
    std::set<Body::id_t> seen;
    std::vector<ClumpPart> parts;
    for (Body::id_t id : ids) {
        if (!seen.insert(id).second) throw std::invalid_argument(std::string(what) + ": " + bodyName(id) + " is listed twice");
        parts.push_back(partOf(standalone(s, id, what)));
    }
    return parts;
}

// Writes the frame into the clump and the members' places into its shape; the members take the clump's bit.
static void setUp(Scene& s, Body& clump, std::vector<Body::id_t> ids, const ClumpFrame& f) {
    std::sort(ids.begin(), ids.end());
    State& cs = *clump.state;
    cs.pos() = f.m.centroid;
    cs.ori() = f.axes.ori;
    cs.mass() = f.m.mass;
    cs.inertia() = f.axes.moments;
    Clump& c = static_cast<Clump&>(*clump.shape);
    c.memberIds.assign(ids.begin(), ids.end());
    c.relPos.clear();
    c.relOri.clear();
    const Quaternionr toLocal = f.axes.ori.conjugate();
    for (Body::id_t id : ids) {
        Body& m = *s.bodies[id];
        c.relPos.push_back(toLocal * (m.state->pos() - f.m.centroid));
        c.relOri.push_back((toLocal * m.state->ori()).normalized());
        m.clumpId = clump.id;
        m.state->blockedDOFsMask() |= State::clumpedBit;
    }
    // members of one clump do not interact: their interactions end
    for (size_t i = 0; i < ids.size(); ++i)
        for (size_t j = i + 1; j < ids.size(); ++j) s.interactions.erase(ids[i], ids[j]);
}

void Clump::checkNewMembers(const std::vector<const Body*>& members, int discretization) {
    if (members.empty()) throw std::invalid_argument("appendClumped: a clump needs at least one member (the list is empty)");
    std::vector<ClumpPart> parts;
    for (size_t k = 0; k < members.size(); ++k) {
        checkMass(*members[k], "body " + std::to_string(k) + " of the list", "appendClumped");
        parts.push_back(partOf(*members[k]));
    }
    frameOf(parts, discretization);
}

Body::id_t Clump::make(Scene& s, const std::vector<Body::id_t>& ids, int discretization) {
    if (ids.empty()) throw std::invalid_argument("a clump needs at least one member (the list of ids is empty)");
    const ClumpFrame f = frameOf(partsOf(s, ids, "clump"), discretization);
    auto clump = std::make_shared<Body>();
    clump->shape = std::make_shared<Clump>();
    clump->bounded = false;
    const Body::id_t id = s.appendBody(clump);
    clump->clumpId = id;
    setUp(s, *clump, ids, f);
    s.bodies.clumps.push_back(id); // (the largest id so far)
    return id;
}

void Clump::add(Scene& s, const std::vector<Body::id_t>& ids, Body::id_t clumpId, int discretization) {
    Clump& c = of(s, clumpId);
    // the new members: standalone bodies, and the members of the clumps listed (which end)
    std::vector<Body::id_t> joining, absorbed;
    for (Body::id_t id : ids) {
        if (id == clumpId) throw std::invalid_argument("addToClump: clump #" + std::to_string(id) + " cannot be added to itself");
        if (s.bodies.exists(id) && s.bodies[id]->isClump()) {
            absorbed.push_back(id);
            const Clump& other = of(s, id);
            joining.insert(joining.end(), other.memberIds.begin(), other.memberIds.end());
        } else
            joining.push_back(id);
    }
    std::set<Body::id_t> seen(c.memberIds.begin(), c.memberIds.end());
    std::vector<ClumpPart> parts;
    for (Body::id_t id : c.memberIds) parts.push_back(partOf(*s.bodies[id]));
    for (Body::id_t id : joining) {
        if (!seen.insert(id).second) throw std::invalid_argument("addToClump: " + bodyName(id) + " is listed twice or already in clump #" + std::to_string(clumpId));
        const bool fromAbsorbed = s.bodies.exists(id) && s.bodies[id]->isClumpMember()
                && std::find(absorbed.begin(), absorbed.end(), s.bodies[id]->clumpId) != absorbed.end();
        parts.push_back(partOf(fromAbsorbed ? *s.bodies[id] : standalone(s, id, "addToClump")));
    }
    const ClumpFrame f = frameOf(parts, discretization);
    // checked: now change the scene
    for (Body::id_t a : absorbed) {
        for (Body::id_t m : of(s, a).memberIds) {
            s.bodies[m]->clumpId = -1;
            s.bodies[m]->state->blockedDOFsMask() &= ~State::clumpedBit;
        }
        s.eraseBody(a);
    }
    std::vector<Body::id_t> all = c.memberIds;
    all.insert(all.end(), joining.begin(), joining.end());
    setUp(s, *s.bodies[clumpId], all, f);
}

bool Clump::release(Scene& s, Body::id_t id, Body::id_t clumpId, int discretization) {
    Clump& c = of(s, clumpId);
    auto it = std::find(c.memberIds.begin(), c.memberIds.end(), id);
    if (it == c.memberIds.end()) throw std::invalid_argument("releaseFromClump: " + bodyName(id) + " is not a member of clump #" + std::to_string(clumpId));
    if (c.memberIds.size() <= 2) return false;
    std::vector<Body::id_t> rest;
    std::vector<ClumpPart> parts;
    for (Body::id_t m : c.memberIds)
        if (m != id) rest.push_back(m), parts.push_back(partOf(*s.bodies[m]));
    const ClumpFrame f = frameOf(parts, discretization);
    Body& b = *s.bodies[id];
    b.clumpId = -1;
    b.state->blockedDOFsMask() &= ~State::clumpedBit;
    setUp(s, *s.bodies[clumpId], rest, f);
    return true;
}

Real Clump::roundness(Scene& s, const std::vector<Body::id_t>& excluded) {
    const std::set<Body::id_t> skip(excluded.begin(), excluded.end());
    Real sum = 0;
    long count = 0;
    for (const auto& b : s.bodies) {
        if (!b || skip.count(b->id) || b->isClumpMember()) continue;
        if (b->isStandalone() && dynamic_cast<const Sphere*>(b->shape.get())) {
            sum += 1;
            ++count;
        } else if (b->isClump()) {
            Real volume = 0, reach = 0;
            const Vector3r& centroid = b->state->pos();
            for (Body::id_t m : of(s, b->id).memberIds) {
                const auto* sphere = dynamic_cast<const Sphere*>(s.bodies[m]->shape.get());
                if (!sphere) throw std::invalid_argument("getRoundness: member #" + std::to_string(m) + " of clump #" + std::to_string(b->id) + " is not a Sphere");
                volume += 4. / 3. * M_PI * std::pow(sphere->radius, 3);
                reach = std::max(reach, (s.bodies[m]->state->pos() - centroid).norm() + sphere->radius);
            }
            sum += std::cbrt(3 * volume / (4 * M_PI)) / reach;
            ++count;
        }
    }
    return count ? sum / count : 0;
}

void Clump::erase(Scene& s, Body::id_t clumpId, bool eraseMembers) {
    const std::vector<int> members = of(s, clumpId).memberIds;
    for (Body::id_t m : members) {
        Body& b = *s.bodies[m];
        b.clumpId = -1;
        b.state->blockedDOFsMask() &= ~State::clumpedBit;
    }
    s.eraseBody(clumpId);
    if (eraseMembers)
        for (Body::id_t m : members) s.eraseBody(m);
}

// The clump shape of clump cid in a step (a Python script may have replaced it: a clear error, not a crash).
static const Clump& clumpInStep(const Scene& s, Body::id_t cid) {
    const Shape* sh = s.bodies[cid]->shape.get();
    const Clump* c = sh ? sh->asClump() : nullptr;
    if (!c || !c->clumpMembers()) throw std::runtime_error("clump #" + std::to_string(cid) + " no longer has a Clump shape with its members");
    return *c;
}

void Clump::sumForces(Scene& s) {
    Vector3r* F = s.forces.forceTotals();
    Vector3r* T = s.forces.torqueTotals();
    const BodyStore::Columns h = s.bodies.hot().columns();
    for (Body::id_t cid : s.bodies.clumps) {
        const Clump& c = clumpInStep(s, cid);
        Vector3r f = F[cid], t = T[cid];
        for (Body::id_t m : c.memberIds) {
            f += F[m];
            t += T[m] + (h.pos[m] - h.pos[cid]).cross(F[m]);
        }
        F[cid] = f;
        T[cid] = t;
    }
}

void Clump::moveMembers(Scene& s, const Vector3r* reference, Real& maxV2, Real& maxMoved2) {
    const BodyStore::Columns h = s.bodies.hot().columns();
    for (Body::id_t cid : s.bodies.clumps) {
        const Clump& c = clumpInStep(s, cid);
        const Vector3r pos = h.pos[cid], vel = h.vel[cid], angVel = h.angVel[cid];
        const Quaternionr ori = h.ori[cid];
        for (size_t k = 0; k < c.memberIds.size(); ++k) {
            const Body::id_t m = c.memberIds[k];
            const Vector3r arm = ori * c.relPos[k];
            h.pos[m] = pos + arm;
            h.ori[m] = ori * c.relOri[k];
            h.vel[m] = vel + angVel.cross(arm);
            h.angVel[m] = angVel;
            maxV2 = std::max(maxV2, h.vel[m].squaredNorm());
            if (reference) maxMoved2 = std::max(maxMoved2, (h.pos[m] - reference[m]).squaredNorm());
        }
    }
}

} // namespace yade
