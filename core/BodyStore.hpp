// The bodies' hot state in columns indexed by body id (structure of arrays): what the integrator,
// the collider and the interaction loop read and write every step. A State in a scene is a view
// of its body's entries (State::pos() and its attributes read and write the columns); a State not
// (or no longer) in a scene keeps its own copy, a BodyHot. The columns never move (StableArray),
// so Python views of `b.state.pos` and NumPy arrays over them stay valid while the store lives;
// bound States share its ownership.
#pragma once
#include <lib/base/Math.hpp>
#include <lib/base/StableArray.hpp>
#include <lib/base/ViewRegistry.hpp>
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

// What the contact functors read of one body: references into the columns (or into a State).
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
    StableArray<Vector3r> pos{maxBodies}, vel{maxBodies}, angVel{maxBodies}, inertia{maxBodies};
    StableArray<Quaternionr> ori{maxBodies};
    StableArray<Real> mass{maxBodies};
    StableArray<int> blockedDOFsMask{maxBodies}, mask{maxBodies};
    StableArray<bool> isDamped{maxBodies}, exists{maxBodies};
    // Sphere radii (NaN: not a sphere), refreshed from the shapes when a NumPy view is taken (the
    // interaction loop keeps its own cache, which also marks facets).
    StableArray<Real> radius{maxBodies};
    // NumPy views of pos that may be written: while there are any, cached positions are not trusted.
    std::atomic<int> writableViews{0};
    // The NumPy views handed out, told when the set of bodies changes (insert, erase, clear,
    // restore) or the scene is dropped: they then refuse writes (py/wrapper/ArraysWrapper.cpp).
    ViewRegistry views;

    // The columns as plain pointers, for loops: taken once before the loop, they stay in registers
    // (through the StableArray members the compiler reloads each base after every store, since a
    // store might have changed it).
    struct Columns {
        Vector3r *pos, *vel, *angVel, *inertia;
        Quaternionr* ori;
        Real* mass;
        int *blockedDOFsMask, *mask;
        bool *isDamped, *exists;
        Kinematics kinematics(size_t id) const { return Kinematics{pos[id], vel[id], angVel[id], ori[id]}; }
    };
    Columns columns() {
        return Columns{pos.data(), vel.data(), angVel.data(), inertia.data(), ori.data(), mass.data(), blockedDOFsMask.data(), mask.data(),
                isDamped.data(), exists.data()};
    }
    size_t size() const { return pos.size(); }
    void resize(size_t n); // new entries: holes
    BodyHot get(size_t id) const;
    void set(size_t id, const BodyHot& r);
    Kinematics kinematics(size_t id) const { return Kinematics{pos[id], vel[id], angVel[id], ori[id]}; }
    // The entry of body id for a BodyHot member at `offset` in the record (a State's attribute).
    void* fieldAddress(std::ptrdiff_t offset, size_t id);
};

} // namespace yade
