// The bodies' hot state in arrays indexed by body id: what the integrator, the collider and the
// interaction loop read and write every step (a BodyRow per body, and the orientations). A State
// in a scene is a view of its body's entries (State::pos() and its attributes read and write
// them); a State not (or no longer) in a scene keeps its own copy, a BodyHot. The arrays never move (StableArray),
// so Python views of `b.state.pos` and NumPy arrays over them stay valid while the store lives;
// bound States share its ownership.
#pragma once
#include <lib/base/Math.hpp>
#include <lib/base/StableArray.hpp>
#include <atomic>
#include <cstddef>

namespace yade {

// One body's hot state as one record: a State's own copy while not in a scene.
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

// One body's hot state but its orientation, as the scene stores it: two cache lines. A contact
// pass that reads a body anywhere in memory (spheres read from a file come in no spatial order)
// finds its position, velocities, mass and blocked DOFs in these two lines, where one column per
// attribute took six.
struct alignas(128) BodyRow {
    Vector3r pos = Vector3r::Zero();
    Vector3r vel = Vector3r::Zero();
    Real mass = 0;
    int blockedDOFsMask = 0; // State::DOF bits
    int mask = 1;
    Vector3r angVel = Vector3r::Zero(); // (the second line)
    Vector3r inertia = Vector3r::Zero();
    bool isDamped = true;
    bool exists = false;
};
static_assert(sizeof(BodyRow) == 128, "BodyRow is two cache lines");

// What the contact functors read of one body: references into the store (or into a State).
struct Kinematics {
    const Vector3r& pos;
    const Vector3r& vel;
    const Vector3r& angVel;
    const Quaternionr& ori;
};

class BodyStore {
public:
    // Address space for this many bodies is reserved (only the used part is memory; less where
    // the address space is limited, see StableArray).
    static constexpr size_t maxBodies = size_t(1) << 22;
    StableArray<BodyRow> rows{maxBodies}; // [id]
    StableArray<Quaternionr> ori{maxBodies};
    // Sphere radii (NaN: not a sphere), refreshed from the shapes when a NumPy view is taken (the
    // interaction loop keeps its own cache, which also marks facets).
    StableArray<Real> radius{maxBodies};
    // NumPy views of pos that may be written: while there are any, cached positions are not trusted.
    std::atomic<int> writableViews{0};

    // The arrays as plain pointers, for loops: taken once before the loop, they stay in registers
    // (through the StableArray members the compiler reloads each base after every store, since a
    // store might have changed it).
    struct Columns {
        BodyRow* rows;
        Quaternionr* ori;
        Kinematics kinematics(size_t id) const { return Kinematics{rows[id].pos, rows[id].vel, rows[id].angVel, ori[id]}; }
    };
    Columns columns() { return Columns{rows.data(), ori.data()}; }
    size_t size() const { return rows.size(); }
    void resize(size_t n); // new entries: holes
    BodyHot get(size_t id) const;
    void set(size_t id, const BodyHot& r);
    Kinematics kinematics(size_t id) const { return Kinematics{rows[id].pos, rows[id].vel, rows[id].angVel, ori[id]}; }
    // The entry of body id for a BodyHot member at `offset` in the record (a State's attribute).
    void* fieldAddress(std::ptrdiff_t offset, size_t id);
};

} // namespace yade
