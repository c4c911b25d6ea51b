// Kinematic state of a body: position, orientation, velocities, mass (1.2.1). The hot part
// (BodyHot) lives in the scene's BodyStore while the body is in a scene: this object is then a
// view of the record of its body's id (hot()), and its attributes read and write the record.
#pragma once
#include <core/BodyStore.hpp>
#include <lib/factory/ClassRegistry.hpp>
#include <memory>

namespace yade {

class State : public Serializable {
public:
    // Degrees of freedom that the integrator leaves untouched (bits of blockedDOFs).
    enum DOF : int { DOF_NONE = 0, DOF_X = 1, DOF_Y = 2, DOF_Z = 4, DOF_RX = 8, DOF_RY = 16, DOF_RZ = 32, DOF_ALL = 63 };
    State() = default;
    State(const State& o) : Serializable(o), local(o.hot()), angMom(o.angMom), refPos(o.refPos), refOri(o.refOri), densityScaling(o.densityScaling) {}
    State& operator=(const State&) = delete;

    // The record: the store's while bound to a body of a scene, else this object's own.
    BodyHot& hot() { return slot >= 0 ? (*store)[(size_t)slot] : local; }
    const BodyHot& hot() const { return slot >= 0 ? (*store)[(size_t)slot] : local; }
    Vector3r& pos() { return hot().pos; }
    const Vector3r& pos() const { return hot().pos; }
    Vector3r& vel() { return hot().vel; }
    const Vector3r& vel() const { return hot().vel; }
    Vector3r& angVel() { return hot().angVel; }
    const Vector3r& angVel() const { return hot().angVel; }
    Quaternionr& ori() { return hot().ori; }
    const Quaternionr& ori() const { return hot().ori; }
    Real& mass() { return hot().mass; }
    Real mass() const { return hot().mass; }
    Vector3r& inertia() { return hot().inertia; }
    const Vector3r& inertia() const { return hot().inertia; }
    int& blockedDOFsMask() { return hot().blockedDOFsMask; }
    int blockedDOFsMask() const { return hot().blockedDOFsMask; }
    bool& isDamped() { return hot().isDamped; }
    bool isDamped() const { return hot().isDamped; }

    // Moves the values into record `id` of `s` (BodyContainer, when the body enters the scene),
    // or back into this object (when it leaves). The store stays owned after unbind(): Python
    // views taken while bound still point into it.
    void bind(const std::shared_ptr<BodyStore>& s, long id, int bodyMask);
    void unbind();
    bool isBound() const { return slot >= 0; }
    long boundSlot() const { return slot; }
    const BodyStore* boundStore() const { return slot >= 0 ? store.get() : nullptr; }

    BodyHot local; // the values while not in a scene
    Vector3r angMom = Vector3r::Zero();
    Vector3r refPos = Vector3r::Zero();
    Quaternionr refOri = Quaternionr::Identity();
    Real densityScaling = 1;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("pos", local.pos, "Position of the center of mass [m]", Attr::finite);
        v.attr("ori", local.ori, "Orientation (unit quaternion)");
        v.attr("vel", local.vel, "Linear velocity [m/s]", Attr::finite);
        v.attr("angVel", local.angVel, "Angular velocity [rad/s]", Attr::finite);
        v.attr("angMom", angMom, "Angular momentum (aspherical bodies)", Attr::finite);
        v.attr("mass", local.mass, "Mass [kg]", Attr::nonNegative);
        v.attr("inertia", local.inertia, "Principal moments of inertia [kg·m²]", Attr::nonNegative);
        v.attr("refPos", refPos, "Reference position (displ() is measured from it)", Attr::finite);
        v.attr("refOri", refOri, "Reference orientation (rot() is measured from it)");
        v.attr("blockedDOFsMask", local.blockedDOFsMask, "Bit mask of blockedDOFs (x=1 y=2 z=4 X=8 Y=16 Z=32)", Attr::hidden);
        v.attr("isDamped", local.isDamped, "Whether NewtonIntegrator damping applies to this body");
        v.attr("densityScaling", densityScaling, "Density scaling factor (1: none)", Attr::positive);
    }
    // For AttrCollector: attributes declared on members of `local` are read and written in hot().
    static constexpr bool hasHotRecord = true;
    Vector3r displ() const { return pos() - refPos; }
    // Rotation from refOri to ori, as axis times angle.
    Vector3r rot() const;
    std::string blockedDOFs() const;
    void setBlockedDOFs(const std::string& dofs); // throws std::invalid_argument on a bad letter
    YADE_INDEXABLE_ROOT(State)

private:
    std::shared_ptr<BodyStore> store;
    long slot = -1;
};

} // namespace yade
