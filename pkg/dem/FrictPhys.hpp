// Contact physics: normal stiffness and force (NormPhys), shear (NormShearPhys), friction (FrictPhys).
#pragma once
#include <core/IPhys.hpp>

namespace yade {

class NormPhys : public IPhys {
public:
    static constexpr const char* classDoc = "Contact physics with a normal stiffness kn and normal force normalForce.";
    Real kn = 0;
    Vector3r normalForce = Vector3r::Zero();
    template <class V> void visit(V& v) {
        IPhys::visit(v);
        v.attr("kn", kn, "Normal stiffness [N/m]");
        v.attr("normalForce", normalForce, "Normal force applied on body 2 [N]");
    }
    YADE_INDEXABLE(NormPhys)
};

class NormShearPhys : public NormPhys {
public:
    static constexpr const char* classDoc = "Contact physics with normal and shear stiffnesses (kn, ks) and forces (normalForce, shearForce).";
    Real ks = 0;
    Vector3r shearForce = Vector3r::Zero();
    template <class V> void visit(V& v) {
        NormPhys::visit(v);
        v.attr("ks", ks, "Shear stiffness [N/m]");
        v.attr("shearForce", shearForce, "Shear force applied on body 2 [N]");
    }
    YADE_INDEXABLE(NormShearPhys)
};

class FrictPhys : public NormShearPhys {
public:
    static constexpr const char* classDoc = "Contact physics of the Cundall-Strack law: NormShearPhys with the tangent of the contact friction angle (tangensOfFrictionAngle).";
    Real tangensOfFrictionAngle = NaN;
    template <class V> void visit(V& v) {
        NormShearPhys::visit(v);
        v.attr("tangensOfFrictionAngle", tangensOfFrictionAngle, "Tangent of the contact friction angle");
    }
    YADE_INDEXABLE(FrictPhys)
};

} // namespace yade
