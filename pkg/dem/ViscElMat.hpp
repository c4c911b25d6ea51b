// Material of the linear visco-elastic contact (Pournin et al. 2001): the contact's constants given
// by a contact time and restitution coefficients, by stiffnesses and viscous constants, or by
// Young's modulus with viscous constants or a restitution coefficient (Ip2_ViscElMat_ViscElMat_ViscElPhys).
#pragma once
#include <pkg/common/FrictMat.hpp>

namespace yade {

class ViscElMat : public FrictMat {
public:
    static constexpr const char* classDoc =
            "Material for the linear visco-elastic contact (Law2_ScGeom_ViscElPhys_Basic), Pournin et al. 2001: give either tc, en "
            "and et, or kn, ks, cn and cs, or young and poisson with cn and cs (or with en: the damping then gives the restitution "
            "coefficient en).";
    Real tc = NaN, en = NaN, et = NaN;
    Real kn = NaN, ks = NaN, cn = NaN, cs = NaN;
    Real mR = 0;
    int mRtype = 1;
    bool lubrication = false;
    Real roughnessScale = 1e-3, viscoDyn = 1e-3;
    template <class V> void visit(V& v) {
        FrictMat::visit(v);
        v.attr("tc", tc, "Contact time [s] (with en and et)");
        v.attr("en", en, "Restitution coefficient in the normal direction");
        v.attr("et", et, "Restitution coefficient in the tangential direction");
        v.attr("kn", kn, "Normal elastic stiffness [N/m] (not together with tc, en, et)");
        v.attr("ks", ks, "Shear elastic stiffness [N/m] (not together with tc, en, et)");
        v.attr("cn", cn, "Normal viscous constant [N·s/m] (not together with tc, en, et)");
        v.attr("cs", cs, "Shear viscous constant [N·s/m] (not together with tc, en, et)");
        v.attr("mR", mR, "Rolling resistance coefficient (Zhou et al. 1999)", Attr::nonNegative);
        v.attr("mRtype", mRtype, "Rolling resistance type: 1 (torque against the relative rotation, proportional to the normal force), "
                                 "2 (the same, also proportional to the spin's magnitude times the radius)");
        v.attr("lubrication", lubrication, "Lubrication forces from young, poisson and en (not available in this build: an error at the first contact)");
        v.attr("roughnessScale", roughnessScale, "Roughness scale of the lubrication model [m]");
        v.attr("viscoDyn", viscoDyn, "Dynamic viscosity of the surrounding fluid in the lubrication model [Pa·s]");
    }
    YADE_INDEXABLE(ViscElMat)
};

} // namespace yade
