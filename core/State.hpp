// Kinematic state of a body: position, orientation, velocities, mass (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class State : public Serializable {
public:
    // Degrees of freedom that the integrator leaves untouched (bits of blockedDOFs).
    enum DOF : int { DOF_NONE = 0, DOF_X = 1, DOF_Y = 2, DOF_Z = 4, DOF_RX = 8, DOF_RY = 16, DOF_RZ = 32, DOF_ALL = 63 };
    Vector3r pos = Vector3r::Zero();
    Quaternionr ori = Quaternionr::Identity();
    Vector3r vel = Vector3r::Zero();
    Vector3r angVel = Vector3r::Zero();
    Vector3r angMom = Vector3r::Zero();
    Real mass = 0;
    Vector3r inertia = Vector3r::Zero();
    Vector3r refPos = Vector3r::Zero();
    Quaternionr refOri = Quaternionr::Identity();
    int blockedDOFsMask = DOF_NONE;
    bool isDamped = true;
    Real densityScaling = 1;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("pos", pos, "Position of the center of mass [m]", Attr::finite);
        v.attr("ori", ori, "Orientation (unit quaternion)");
        v.attr("vel", vel, "Linear velocity [m/s]", Attr::finite);
        v.attr("angVel", angVel, "Angular velocity [rad/s]", Attr::finite);
        v.attr("angMom", angMom, "Angular momentum (aspherical bodies)", Attr::finite);
        v.attr("mass", mass, "Mass [kg]", Attr::nonNegative);
        v.attr("inertia", inertia, "Principal moments of inertia [kg·m²]", Attr::nonNegative);
        v.attr("refPos", refPos, "Reference position (displ() is measured from it)", Attr::finite);
        v.attr("refOri", refOri, "Reference orientation (rot() is measured from it)");
        v.attr("blockedDOFsMask", blockedDOFsMask, "Bit mask of blockedDOFs (x=1 y=2 z=4 X=8 Y=16 Z=32)", Attr::hidden);
        v.attr("isDamped", isDamped, "Whether NewtonIntegrator damping applies to this body");
        v.attr("densityScaling", densityScaling, "Density scaling factor (1: none)", Attr::positive);
    }
    Vector3r displ() const { return pos - refPos; }
    // Rotation from refOri to ori, as axis times angle.
    Vector3r rot() const;
    std::string blockedDOFs() const;
    void setBlockedDOFs(const std::string& dofs); // throws std::invalid_argument on a bad letter
    YADE_INDEXABLE_ROOT(State)
};

} // namespace yade
