// Physics of a cohesive-frictional contact with moments (Law2_ScGeom6D_CohFrictPhys_CohesionMoment):
// rotational stiffnesses, a breakable (fragile) or plastic bond, and the moments it carries.
#pragma once
#include <pkg/dem/cohesive/RotStiffFrictPhys.hpp>

namespace yade {

class CohFrictPhys : public RotStiffFrictPhys {
public:
    static constexpr const char* classDoc =
            "Contact physics of Law2_ScGeom6D_CohFrictPhys_CohesionMoment: RotStiffFrictPhys with a cohesive bond (normalAdhesion, "
            "shearAdhesion) that breaks (fragile) or yields (plastic normal displacement unp) when its strength is exceeded, and the rolling "
            "and twisting moments.";
    bool cohesionDisablesFriction = false, cohesionBroken = true, fragile = true, momentRotationLaw = false, initCohesion = false;
    Real maxRollPl = 0, maxTwistPl = 0, normalAdhesion = 0, shearAdhesion = 0, unp = 0, unpMax = 0, creep_viscosity = -1;
    Vector3r moment_twist = Vector3r::Zero(), moment_bending = Vector3r::Zero();
    template <class V> void visit(V& v) {
        RotStiffFrictPhys::visit(v);
        v.attr("cohesionDisablesFriction", cohesionDisablesFriction, "While the bond holds, the shear strength is shearAdhesion alone "
                                                                     "(true) or shearAdhesion + Fn·tan φ (false)");
        v.attr("cohesionBroken", cohesionBroken, "Whether the contact has no (more) bond: false for a cohesive contact, true once a fragile "
                                                 "bond broke");
        v.attr("fragile", fragile, "Whether the bond breaks when its strength is exceeded (else perfectly plastic)");
        v.attr("maxRollPl", maxRollPl, "Rolling strength: the rolling moment is capped at maxRollPl·Fn; negative: elastic [m]");
        v.attr("maxTwistPl", maxTwistPl, "Twisting strength: the twisting moment is capped at maxTwistPl·Fn; negative: elastic [m]");
        v.attr("normalAdhesion", normalAdhesion, "Tensile strength of the bond [N]");
        v.attr("shearAdhesion", shearAdhesion, "Cohesive part of the shear strength [N] (friction may add to it, see cohesionDisablesFriction)");
        v.attr("unp", unp, "Plastic normal displacement (negative in extension), for a bond that is not fragile [m]");
        v.attr("unpMax", unpMax, "Largest plastic normal displacement |unp| before a bond that is not fragile breaks (the contact ends); "
                                 "negative: no limit [m]");
        v.attr("momentRotationLaw", momentRotationLaw, "Whether the contact carries moments (both materials' momentRotationLaw)");
        v.attr("initCohesion", initCohesion, "Make this contact cohesive at the next step, its current state being the bond's rest state "
                                             "(Ip2_CohFrictMat_CohFrictMat_CohFrictPhys.setCohesionNow for one contact)");
        v.attr("creep_viscosity", creep_viscosity, "Creep viscosity [Pa·s/m] (kept for compatibility; the law's creep_viscosity is used)");
        v.attr("moment_twist", moment_twist, "Twisting moment (along the normal) [N·m]");
        v.attr("moment_bending", moment_bending, "Rolling (bending) moment (perpendicular to the normal) [N·m]");
    }
    YADE_INDEXABLE(CohFrictPhys)
};

} // namespace yade
