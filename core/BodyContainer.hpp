// O.bodies: bodies indexed by id; an erased body leaves a hole (ids are never reused).
#pragma once
#include <core/Body.hpp>
#include <vector>

namespace yade {

class BodyContainer {
public:
    using id_t = Body::id_t;
    BodyContainer() = default;
    BodyContainer(const BodyContainer&) = delete;
    BodyContainer& operator=(const BodyContainer&) = delete;
    ~BodyContainer(); // the bodies' states keep their values (unbound)
    // Appends a body that is not yet in a scene; returns its new id.
    id_t insert(const std::shared_ptr<Body>& b);
    // Puts a body that is not yet in a scene at the given free id (a hole, or past the end: the
    // ids between become holes); returns it.
    id_t insertAtId(const std::shared_ptr<Body>& b, id_t id);
    bool exists(id_t id) const { return id >= 0 && (size_t)id < bodies.size() && bodies[id]; }
    const std::shared_ptr<Body>& operator[](id_t id) const { return bodies[id]; }
    size_t size() const { return bodies.size(); } // including holes left by erase
    void erase(id_t id);                          // the scene removes the body's interactions first
    // Replaces the whole content (loading a file): entry i must be null or have id i.
    void restore(std::vector<std::shared_ptr<Body>> all, long long changeCount);
    void clear();
    // The hot state of every body, indexed by id (State objects of bodies here are views of it).
    BodyStore& hot() { return *store; }
    const BodyStore& hot() const { return *store; }
    const std::shared_ptr<BodyStore>& hotStore() const { return store; }
    // Incremented by every insert, erase and clear (colliders rebuild their lists when it changes).
    long long changes = 0;
    // The ids of the clumps (pkg/common/Clump.hpp), ascending: kept by Clump's operations, erase, clear
    // and restore; empty in scenes without clumps (the integrator then does nothing for them).
    std::vector<id_t> clumps;
    auto begin() const { return bodies.begin(); }
    auto end() const { return bodies.end(); }

private:
    std::vector<std::shared_ptr<Body>> bodies;
    std::shared_ptr<BodyStore> store = std::make_shared<BodyStore>();
    void attach(Body& b); // binds its state to record b.id
    void detach(Body& b);
    void checkInsertable(const std::shared_ptr<Body>& b) const;
    void unbindAll();
    static void checkClumps(const std::vector<std::shared_ptr<Body>>& all);
};

} // namespace yade
