// A clump (3.5.3): a rigid aggregate of bodies, its members. The clump is a body of its own, one
// more row of the body columns, with this shape, no material and no bound; its state holds the
// aggregate's mass, centroid, principal inertia and orientation. The members keep their shapes
// and take part in collisions and contacts, except with each other; the integrator leaves them
// (State::clumpedBit), sums their forces into the clump (sumForces), moves the clump as any
// aspherical body, then puts each member where it sits in the clump's frame (moveMembers).
#pragma once
#include <core/Body.hpp>
#include <core/Shape.hpp>
#include <vector>

namespace yade {

class Scene;

class Clump : public Shape {
public:
    static constexpr const char* classDoc = "Shape of a clump (3.5.3): a rigid aggregate of bodies (its members), moved as one body; made by O.bodies.appendClumped or O.bodies.clump.";
    std::vector<int> memberIds;          // ids of the members, ascending
    std::vector<Vector3r> relPos;        // each member's position in the clump's frame
    std::vector<Quaternionr> relOri;     // each member's orientation relative to the clump's
    template <class V> void visit(V& v) {
        Shape::visit(v);
        v.attr("memberIds", memberIds, "Ids of the members", Attr::readonly);
        v.attr("relPos", relPos, "Position of each member in the clump's frame (principal axes, origin at the centroid)", Attr::readonly);
        v.attr("relOri", relOri, "Orientation of each member relative to the clump's", Attr::readonly);
    }
    YADE_INDEXABLE(Clump)
    const Clump* asClump() const override { return this; }
    const std::vector<int>* clumpMembers() const override {
        return relPos.size() == memberIds.size() && relOri.size() == memberIds.size() ? &memberIds : nullptr;
    }

    // --- making and changing clumps (each checks everything first: on an error the scene is as it was).
    // Each computes the clump's mass, centroid, inertia and orientation from its members again
    // (discretization 0: summed, else integrated on a grid: pkg/common/ClumpInertia.hpp) and the
    // members' places in its frame. ---
    // Makes a clump of existing standalone bodies; returns its id (the next free one).
    static Body::id_t make(Scene& s, const std::vector<Body::id_t>& ids, int discretization);
    // Adds standalone bodies, or all members of other clumps (those clumps are erased), to a clump.
    static void add(Scene& s, const std::vector<Body::id_t>& ids, Body::id_t clumpId, int discretization);
    // Makes a member standalone again; false (nothing done) when the clump would keep fewer than 2 members.
    static bool release(Scene& s, Body::id_t id, Body::id_t clumpId, int discretization);
    // Erases a clump: its members are erased with it, or made standalone.
    static void erase(Scene& s, Body::id_t clumpId, bool eraseMembers);

    // O.bodies.getRoundness: the mean over standalone spheres (1 each) and clumps of R1/R2, R1 the
    // radius of a sphere of the members' summed volume, R2 the largest distance of a member's surface
    // from the centroid (the radius of the sphere about the centroid that holds the clump); the ids
    // in `excluded` are left out; 0 when nothing is left.
    static Real roundness(Scene& s, const std::vector<Body::id_t>& excluded);

    // --- the integrator's step ---
    // Adds each member's force, and its torque and moment about the centroid, to its clump's.
    static void sumForces(Scene& s);
    // Each member at its place in the clump's frame, moving with the clump; the largest squared
    // velocity and (when reference is given) squared distance from reference are raised to theirs.
    static void moveMembers(Scene& s, const Vector3r* reference, Real& maxV2, Real& maxMoved2);

    // Throws what make() would throw for these bodies (not yet in a scene) as members.
    static void checkNewMembers(const std::vector<const Body*>& members, int discretization);
    // The clump shape of body id (std::invalid_argument if it is not a clump).
    static Clump& of(Scene& s, Body::id_t id);
};

} // namespace yade
