// MindlinPhys of a new contact between two FrictMat bodies: the Hertz-Mindlin constants from the
// effective moduli and radius, the damping ratios from restitution coefficients or given directly.
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/MatchMaker.hpp>
#include <pkg/dem/MindlinPhys.hpp>

namespace yade {

class Ip2_FrictMat_FrictMat_MindlinPhys : public IPhysFunctorOf<FrictMat, FrictMat, MindlinPhys> {
public:
    static constexpr const char* classDoc =
            "Makes MindlinPhys (Hertz-Mindlin) for two FrictMat: E* = 1/((1-ν1²)/E1 + (1-ν2²)/E2), G* = 1/((2-ν1)/G1 + (2-ν2)/G2) with "
            "Gi = Ei/(2(1+νi)), R* = R1·R2/(R1+R2); kno = 4/3·E*·sqrt(R*), kso = 8·G*·sqrt(R*). Damping: the ratio betan (betas) given, or "
            "computed from the restitution coefficient en (es) for a Hertzian impact that ends when the normal force reaches zero; "
            "giving both en and betan is an error; without es/betas the normal values are used. Each of en, es, betan, betas, "
            "frictAngle is a MatchMaker (a number gives a constant one). The friction angle is the smaller of the materials' unless "
            "frictAngle is given.";
    std::shared_ptr<MatchMaker> en, es, betan, betas, frictAngle;
    Real gamma = 0, eta = 0, krot = 0, ktwist = 0;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("en", en, "Normal restitution coefficient (MatchMaker or number)");
        v.attr("es", es, "Shear restitution coefficient (MatchMaker or number; default: en)");
        v.attr("betan", betan, "Normal damping ratio (MatchMaker or number); not together with en");
        v.attr("betas", betas, "Shear damping ratio (MatchMaker or number; default: betan); not together with es");
        v.attr("frictAngle", frictAngle, "Contact friction angle per pair of materials [rad] (MatchMaker; default: the smaller one)");
        v.attr("gamma", gamma, "Surface energy [J/m²] for DMT adhesion (adhesionForce = 4·π·R*·gamma)", Attr::nonNegative);
        v.attr("eta", eta, "Coefficient of the plastic bending moment: MindlinPhys.maxBendPl is eta times the mean radius of the two bodies", Attr::nonNegative);
        v.attr("krot", krot, "Rolling stiffness (MindlinPhys.kr) [N·m/rad]", Attr::nonNegative);
        v.attr("ktwist", ktwist, "Twisting stiffness (MindlinPhys.ktw) [N·m/rad]", Attr::nonNegative);
    }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
};

} // namespace yade
