// A particle: shape, material, state and bound, plus id and collision mask (1.2.1).
#pragma once
#include <core/Bound.hpp>
#include <core/Material.hpp>
#include <core/Shape.hpp>
#include <core/State.hpp>

namespace yade {

class Body : public Serializable {
public:
    static constexpr const char* classDoc = "A particle (the manual's Body, 1.2.1): shape, material, state and bound, with its id in O.bodies, a collision mask and a group id when clumped.";
    using id_t = int;
    id_t id = -1;
    int mask = 1; // bodies collide only when (mask1 & mask2) != 0
    int clumpId = -1;
    bool bounded = true; // whether the collider gives it a bound (a clump has none: its members have theirs)
    long long iterBorn = -1; // the step (O.iter) and time (O.time) at which it was appended
    Real timeBorn = -1;
    std::shared_ptr<Shape> shape;
    std::shared_ptr<Material> material;
    std::shared_ptr<State> state = std::make_shared<State>();
    std::shared_ptr<Bound> bound;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("id", id, "Index in O.bodies (-1 while not appended)", Attr::readonly);
        v.attr("mask", mask, "Collision mask: two bodies may interact only if (mask1 & mask2) != 0");
        v.attr("clumpId", clumpId, "Id of the clump this body belongs to (-1: none)", Attr::readonly);
        v.attr("bounded", bounded, "Whether the collider gives this body a bound (False: it takes no part in collisions; a clump's own body)");
        v.attr("iterBorn", iterBorn, "Step number (O.iter) at which the body was appended to O.bodies (-1: not yet)");
        v.attr("timeBorn", timeBorn, "Time (O.time) at which the body was appended to O.bodies (-1: not yet)");
        v.attr("shape", shape, "Geometry of the particle");
        v.attr("material", material, "Material (may be shared with other bodies)");
        v.attr("state", state, "Physical state (position, velocity...)");
        v.attr("bound", bound, "Bounding volume for collision detection (None: no collisions)");
    }
    // A body is dynamic unless all six degrees of freedom are blocked (Body.dynamic in Python
    // sets or clears State.blockedDOFs accordingly).
    bool isDynamic() const { return (state->blockedDOFsMask() & State::DOF_ALL) != State::DOF_ALL; }
    void setDynamic(bool d) { state->blockedDOFsMask() = (d ? State::DOF_NONE : State::DOF_ALL) | (state->blockedDOFsMask() & State::clumpedBit); }
    bool isClump() const { return clumpId >= 0 && clumpId == id; }
    bool isClumpMember() const { return clumpId >= 0 && clumpId != id; }
    bool isStandalone() const { return clumpId < 0; }
    // After an attribute was set from Python: a new state of a body in a scene takes over the
    // body's record (the old one keeps its values); the mask is copied into the record.
    void postLoad() override;
    // The store of the scene the body is in (null when in none), set by BodyContainer.
    std::shared_ptr<BodyStore> store;
    std::weak_ptr<State> boundState; // the state bound to the record
    // `b.state = None` (as in the reference, allowed until the next step, which refuses it): the
    // body keeps a stand-in State so that nothing reading it can crash, and Python sees None.
    std::shared_ptr<State> stateStandIn;
    bool stateIsNone() const { return state && state == stateStandIn; }
    static long standInsAlive(); // stand-ins in existence, all scenes (a step looks for them only then)
    // Two bodies may collide when their masks share a bit and at least one of them moves.
    static bool mayCollide(const Body& a, const Body& b) {
        return (a.mask & b.mask) != 0 && a.id != b.id && (a.isDynamic() || b.isDynamic()) && !(a.clumpId >= 0 && a.clumpId == b.clumpId);
    }
};

} // namespace yade
