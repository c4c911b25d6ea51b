#include <core/BodyContainer.hpp>
#include <algorithm>
#include <stdexcept>

namespace yade {

BodyContainer::~BodyContainer() {
    unbindAll();
    store->views.invalidate(); // (a NumPy view may keep the store)
}

void BodyContainer::attach(Body& b) {
    b.store = store;
    b.state->bind(store, b.id, b.mask);
    b.boundState = b.state;
}

void BodyContainer::detach(Body& b) {
    if (b.state) b.state->unbind();
    b.store.reset();
    b.boundState.reset();
}

void BodyContainer::unbindAll() {
    for (const auto& b : bodies)
        if (b) detach(*b);
}

void BodyContainer::checkInsertable(const std::shared_ptr<Body>& b) const {
    if (!b) throw std::invalid_argument("cannot append None to O.bodies");
    if (b->id >= 0)
        throw std::out_of_range("Body already has id " + std::to_string(b->id) + " set; appending such body (for the second time) is not allowed.");
    if (!b->state) b->postLoad(); // (a body built without a State: it gets a stand-in, as after b.state = None)
}

BodyContainer::id_t BodyContainer::insert(const std::shared_ptr<Body>& b) {
    checkInsertable(b);
    b->id = static_cast<id_t>(bodies.size());
    try {
        attach(*b); // (may find the store full)
    } catch (const std::length_error& e) {
        b->store.reset();
        b->id = -1;
        throw std::length_error(std::string("cannot append to O.bodies: ") + e.what());
    }
    bodies.push_back(b);
    ++changes;
    store->views.invalidate();
    return b->id;
}

BodyContainer::id_t BodyContainer::insertAtId(const std::shared_ptr<Body>& b, id_t id) {
    checkInsertable(b);
    if (id < 0) throw std::out_of_range("O.bodies.insertAtId: invalid id " + std::to_string(id) + " (must be 0 or more)");
    if (exists(id)) throw std::out_of_range("O.bodies.insertAtId: id " + std::to_string(id) + " is taken by another body (erase it first)");
    if ((size_t)id >= BodyStore::maxBodies)
        throw std::length_error("O.bodies.insertAtId: id " + std::to_string(id) + " is beyond the largest possible id " + std::to_string(BodyStore::maxBodies - 1));
    b->id = id;
    attach(*b);
    if ((size_t)id >= bodies.size()) bodies.resize((size_t)id + 1);
    bodies[id] = b;
    ++changes;
    store->views.invalidate();
    return id;
}

void BodyContainer::erase(id_t id) {
    if (!exists(id)) throw std::out_of_range("Body #" + std::to_string(id) + " does not exist.");
    if (bodies[id]->isClump()) clumps.erase(std::remove(clumps.begin(), clumps.end(), id), clumps.end());
    detach(*bodies[id]);
    bodies[id]->id = -1;
    bodies[id].reset();
    ++changes;
    store->views.invalidate();
}

void BodyContainer::clear() {
    unbindAll();
    bodies.clear();
    clumps.clear();
    store->resize(0);
    ++changes;
    store->views.invalidate();
}

// A loaded scene's clumps agree with their members (a corrupt file is refused before the scene changes).
void BodyContainer::checkClumps(const std::vector<std::shared_ptr<Body>>& all) {
    auto fail = [](const std::string& why) { throw std::invalid_argument("inconsistent clump: " + why); };
    const auto at = [&](id_t id) -> const Body* { return id >= 0 && (size_t)id < all.size() ? all[id].get() : nullptr; };
    for (size_t i = 0; i < all.size(); ++i) {
        const Body* b = all[i].get();
        if (!b) continue;
        const std::string name = "body #" + std::to_string(i);
        const bool clumped = (b->state->blockedDOFsMask() & State::clumpedBit) != 0;
        if (b->clumpId < 0) {
            if (clumped) fail(name + " is marked as a clump member but belongs to no clump");
            continue;
        }
        if (b->isClump()) {
            const std::vector<int>* members = b->shape ? b->shape->clumpMembers() : nullptr;
            if (!members || members->empty()) fail(name + " is a clump without a Clump shape listing its members");
            std::vector<int> seen;
            for (int m : *members) {
                const Body* mb = at(m);
                if (!mb || m == (int)i || mb->clumpId != (id_t)i) fail(name + " lists member #" + std::to_string(m) + ", which is not its member");
                seen.push_back(m);
            }
            std::sort(seen.begin(), seen.end());
            if (std::adjacent_find(seen.begin(), seen.end()) != seen.end()) fail(name + " lists a member twice");
            if (clumped) fail(name + " is a clump marked as a clump member");
            continue;
        }
        const Body* c = at(b->clumpId);
        const std::vector<int>* members = c && c->isClump() && c->shape ? c->shape->clumpMembers() : nullptr;
        if (!members || std::find(members->begin(), members->end(), (int)i) == members->end())
            fail(name + " belongs to clump #" + std::to_string(b->clumpId) + ", which does not list it");
        if (!clumped) fail(name + " is a clump member not marked as one");
    }
}

void BodyContainer::restore(std::vector<std::shared_ptr<Body>> all, long long changeCount) {
    for (size_t i = 0; i < all.size(); ++i) {
        if (all[i] && all[i]->id != (id_t)i)
            throw std::invalid_argument("body at position " + std::to_string(i) + " has id " + std::to_string(all[i]->id));
        if (all[i] && !all[i]->state) throw std::invalid_argument("body #" + std::to_string(i) + " has no state");
    }
    checkClumps(all);
    unbindAll();
    bodies = std::move(all);
    store->resize(0);
    store->resize(bodies.size());
    clumps.clear();
    for (const auto& b : bodies)
        if (b) {
            attach(*b);
            if (b->isClump()) clumps.push_back(b->id);
        }
    changes = changeCount;
    store->views.invalidate();
}

} // namespace yade
