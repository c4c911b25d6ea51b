// Kinematic state of a body: position, orientation, velocities, mass (1.2.1). The hot part
// (BodyHot) lives in the scene's BodyStore columns while the body is in a scene: this object is
// then a view of its body's entries, and its attributes read and write them.
#pragma once
#include <core/BodyStore.hpp>
#include <lib/factory/ClassRegistry.hpp>
#include <memory>

namespace yade {

class State : public Serializable {
public:
    static constexpr const char* classDoc = "Kinematic state of a body (1.2.1): position, orientation, linear and angular velocity, mass, inertia and blocked degrees of freedom.";
    // Degrees of freedom that the integrator leaves untouched (bits of blockedDOFs).
    enum DOF : int { DOF_NONE = 0, DOF_X = 1, DOF_Y = 2, DOF_Z = 4, DOF_RX = 8, DOF_RY = 16, DOF_RZ = 32, DOF_ALL = 63 };
    // Not a degree of freedom: the bit of a clump member, which the integrator leaves to its clump
    // (pkg/common/Clump.hpp); blockedDOFs, dynamic and the laws see only the six bits above.
    static constexpr int clumpedBit = 64;
    State() = default;
    State(const State& o) : Serializable(o), local(std::make_unique<BodyHot>(o.hot())), angMom(o.angMom), refPos(o.refPos), refOri(o.refOri), densityScaling(o.densityScaling) {}
    State& operator=(const State&) = delete;

    // Each accessor reads the store's column while bound to a body of a scene, else this object's copy.
    Vector3r& pos() { return field(&BodyStore::pos, &BodyHot::pos); }
    const Vector3r& pos() const { return field(&BodyStore::pos, &BodyHot::pos); }
    Vector3r& vel() { return field(&BodyStore::vel, &BodyHot::vel); }
    const Vector3r& vel() const { return field(&BodyStore::vel, &BodyHot::vel); }
    Vector3r& angVel() { return field(&BodyStore::angVel, &BodyHot::angVel); }
    const Vector3r& angVel() const { return field(&BodyStore::angVel, &BodyHot::angVel); }
    Quaternionr& ori() { return field(&BodyStore::ori, &BodyHot::ori); }
    const Quaternionr& ori() const { return field(&BodyStore::ori, &BodyHot::ori); }
    Real& mass() { return field(&BodyStore::mass, &BodyHot::mass); }
    Real mass() const { return field(&BodyStore::mass, &BodyHot::mass); }
    Vector3r& inertia() { return field(&BodyStore::inertia, &BodyHot::inertia); }
    const Vector3r& inertia() const { return field(&BodyStore::inertia, &BodyHot::inertia); }
    int& blockedDOFsMask() { return field(&BodyStore::blockedDOFsMask, &BodyHot::blockedDOFsMask); }
    int blockedDOFsMask() const { return field(&BodyStore::blockedDOFsMask, &BodyHot::blockedDOFsMask); }
    bool& isDamped() { return field(&BodyStore::isDamped, &BodyHot::isDamped); }
    bool isDamped() const { return field(&BodyStore::isDamped, &BodyHot::isDamped); }
    // The whole record (a copy), and what the contact functors read.
    BodyHot hot() const { return slot >= 0 ? store->get((size_t)slot) : *local; }
    Kinematics kinematics() const { return Kinematics{pos(), vel(), angVel(), ori()}; }
    // For AttrCollector: attributes declared on members of `local` are read and written here.
    void* sideAddress(std::ptrdiff_t offset) {
        return slot >= 0 ? store->fieldAddress(offset, (size_t)slot) : reinterpret_cast<char*>(local.get()) + offset;
    }

    // Moves the values into record `id` of `s` (BodyContainer, when the body enters the scene),
    // or back into this object (when it leaves). The store stays owned after unbind(): Python
    // views taken while bound still point into it.
    void bind(const std::shared_ptr<BodyStore>& s, long id, int bodyMask);
    void unbind();
    bool isBound() const { return slot >= 0; }
    long boundSlot() const { return slot; }
    const BodyStore* boundStore() const { return slot >= 0 ? store.get() : nullptr; }

    // The values while not in a scene (none while bound: 160 bytes less per body).
    std::unique_ptr<BodyHot> local = std::make_unique<BodyHot>();
    using SideRecord = BodyHot;
    const BodyHot* sideRecord() const { return local.get(); } // (AttrCollector, on an unbound prototype)
    Vector3r angMom = Vector3r::Zero();
    Vector3r refPos = Vector3r::Zero();
    Quaternionr refOri = Quaternionr::Identity();
    Real densityScaling = 1;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("pos", local->pos, "Position of the center of mass [m] (read as a copy, as in the reference: `p0 = b.state.pos` keeps the value of that moment)", Attr::finite | Attr::readCopy);
        v.attr("ori", local->ori, "Orientation (unit quaternion; read as a copy, as pos)", Attr::readCopy);
        v.attr("vel", local->vel, "Linear velocity [m/s]", Attr::finite);
        v.attr("angVel", local->angVel, "Angular velocity [rad/s]", Attr::finite);
        v.attr("angMom", angMom, "Angular momentum (aspherical bodies)", Attr::finite);
        v.attr("mass", local->mass, "Mass [kg]", Attr::nonNegative);
        v.attr("inertia", local->inertia, "Principal moments of inertia [kg·m²]", Attr::nonNegative);
        v.attr("refPos", refPos, "Reference position (displ() is measured from it)", Attr::finite);
        v.attr("refOri", refOri, "Reference orientation (rot() is measured from it)");
        v.attr("blockedDOFsMask", local->blockedDOFsMask, "Bit mask of blockedDOFs (x=1 y=2 z=4 X=8 Y=16 Z=32)", Attr::hidden);
        v.attr("isDamped", local->isDamped, "Whether NewtonIntegrator damping applies to this body");
        v.attr("densityScaling", densityScaling, "Density scaling factor (1: none)", Attr::positive);
    }
    static constexpr bool hasSideRecord = true; // (AttrCollector: see sideAddress)
    Vector3r displ() const { return pos() - refPos; }
    // Rotation from refOri to ori, as axis times angle.
    Vector3r rot() const;
    std::string blockedDOFs() const;
    void setBlockedDOFs(const std::string& dofs); // throws std::invalid_argument on a bad letter
    YADE_INDEXABLE_ROOT(State)

private:
    std::shared_ptr<BodyStore> store;
    long slot = -1;
    template <class T> T& field(StableArray<T> BodyStore::*column, T BodyHot::*member) {
        return slot >= 0 ? (store.get()->*column)[(size_t)slot] : (*local).*member;
    }
    template <class T> const T& field(StableArray<T> BodyStore::*column, T BodyHot::*member) const {
        return slot >= 0 ? (store.get()->*column)[(size_t)slot] : (*local).*member;
    }
};

} // namespace yade
