// ViscElPhys of a new contact between two ViscElMat bodies: the linear visco-elastic constants from a
// contact time and restitution coefficients (Pournin et al. 2001), from stiffnesses and viscous
// constants, or from Young's modulus (doc/contact-laws.md).
#pragma once
#include <core/IPhysDispatcher.hpp>
#include <pkg/dem/MatchMaker.hpp>
#include <pkg/dem/ViscElMat.hpp>
#include <pkg/dem/ViscElPhys.hpp>

namespace yade {

class Ip2_ViscElMat_ViscElMat_ViscElPhys : public IPhysFunctorOf<ViscElMat, ViscElMat, ViscElPhys> {
public:
    static constexpr const char* classDoc =
            "Makes ViscElPhys for two ViscElMat, the materials' constants connected in series. With a contact time tc and restitution "
            "coefficients en, et (the two materials' means, or this functor's MatchMakers): kn = m*·(π² + ln²en)/tc², cn = -2·m*·ln(en)/tc, "
            "ks = 2/7·m*·(π² + ln²et)/tc², cs = -2/7·2·m*·ln(et)/tc, m* = m1·m2/(m1+m2) (a body of mass 0 counts as the other's mass). "
            "Otherwise each of kn, ks, cn, cs is a1·a2/(a1+a2) of the materials' values, where kn = young·(2·radius) and ks = poisson·kn "
            "when kn, ks are not given; with young and en instead of cn, cn is the constant that gives the restitution coefficient en "
            "(the normal force cut at zero) and cs = 0. The friction angle is the smaller one (or the MatchMaker frictAngle); mR is "
            "2·mR1·mR2/(mR1+mR2).";
    std::shared_ptr<MatchMaker> tc, en, et, frictAngle;
    template <class V> void visit(V& v) {
        IPhysFunctor::visit(v);
        v.attr("tc", tc, "Contact time per pair of materials [s] (MatchMaker or number; default: the materials' mean)");
        v.attr("en", en, "Normal restitution coefficient per pair of materials (MatchMaker or number; default: the materials' mean)");
        v.attr("et", et, "Tangential restitution coefficient per pair of materials (MatchMaker or number; default: the materials' mean)");
        v.attr("frictAngle", frictAngle, "Contact friction angle per pair of materials [rad] (MatchMaker; default: the smaller one)");
    }
    void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I) override;
    // The viscous constant of a linear spring k between masses of reduced mass m that gives the
    // restitution coefficient e in (0, 1] when the normal force is cut at zero (Schwager & Pöschel 2007).
    static Real linearDampingForRestitution(Real e, Real k, Real m);
};

} // namespace yade
