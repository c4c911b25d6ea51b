// The bodies' hot state, one packed record per body id, contiguous: what the integrator, the
// collider and the interaction loop read and write every step. A State in a scene is a view of
// its body's record (State::hot()); a State not (or no longer) in a scene keeps its own copy.
// The records never move (StableArray), so Python views of `b.state.pos` and NumPy arrays over
// the columns stay valid while the store lives; bound States share its ownership.
#pragma once
#include <lib/base/Math.hpp>
#include <lib/base/StableArray.hpp>
#include <cstddef>

namespace yade {

struct BodyHot {
    Vector3r pos = Vector3r::Zero();
    Vector3r vel = Vector3r::Zero();
    Vector3r angVel = Vector3r::Zero();
    Quaternionr ori = Quaternionr::Identity();
    Vector3r inertia = Vector3r::Zero();
    Real mass = 0;
    int blockedDOFsMask = 0; // State::DOF bits
    int mask = 1;            // Body.mask (kept here so that loops over bodies need not visit Body)
    bool isDamped = true;
    bool exists = false;     // a body of the scene has this id (false: a hole left by erase)
};

class BodyStore {
public:
    // Address space for this many bodies is reserved (only the used part is memory).
    static constexpr size_t maxBodies = size_t(1) << 25;
    BodyStore() : records(maxBodies) {}
    StableArray<BodyHot> records; // [body id]
    size_t size() const { return records.size(); }
    BodyHot& operator[](size_t id) { return records[id]; }
    const BodyHot& operator[](size_t id) const { return records[id]; }
    BodyHot* data() { return records.data(); }
    const BodyHot* data() const { return records.data(); }
};

} // namespace yade
