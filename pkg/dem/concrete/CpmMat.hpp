// Material of the concrete particle model (CPM, Šmilauer 2010): FrictMat with the cohesion sigmaT,
// the strain of the crack onset and the ductility of the damage law; its bodies get a CpmState.
#pragma once
#include <pkg/common/FrictMat.hpp>
#include <pkg/dem/concrete/CpmState.hpp>

namespace yade {

class CpmMat : public FrictMat {
public:
    static constexpr const char* classDoc =
            "Concrete material of the concrete particle model (CPM: CpmMat, Ip2_CpmMat_CpmMat_CpmPhys, CpmPhys, Law2_ScGeom_CpmPhys_Cpm, "
            "CpmState, CpmStateUpdater). FrictMat with the cohesion sigmaT, the strain epsCrackOnset where damage starts and the "
            "ductility relDuctility of the damage law (damLaw). Its density defaults to 4800 kg/m³ (about 2800 kg/m³ of packing at a "
            "packing fraction of 0.6); its bodies get a CpmState (newAssocState). As in the reference build, the public model: damage in "
            "tension and Mohr-Coulomb plasticity in shear; the rate-dependent attributes (dmgTau, plTau...) are stored but not used.";
    Real sigmaT = NaN, epsCrackOnset = NaN, relDuctility = NaN, equivStrainShearContrib = 0;
    Real dmgTau = -1, dmgRateExp = 0, plTau = -1, plRateExp = 0, isoPrestress = 0;
    bool neverDamage = false;
    int damLaw = 1;
    CpmMat() { density = 4800; }
    template <class V> void visit(V& v) {
        FrictMat::visit(v);
        v.attr("sigmaT", sigmaT, "Initial cohesion: the shear strength at zero normal stress and no damage [Pa] (must be given unless "
                                 "neverDamage)");
        v.attr("epsCrackOnset", epsCrackOnset, "Normal strain where damage starts (the limit of the elastic part) [-] (must be given "
                                               "unless neverDamage)");
        v.attr("relDuctility", relDuctility, "Relative ductility of the bonds in the normal direction: epsFracture = relDuctility·"
                                             "epsCrackOnset [-] (must be given unless neverDamage)");
        v.attr("neverDamage", neverDamage, "If true, no damage ever occurs (for testing)");
        v.attr("damLaw", damLaw, "Damage law in tension: 0 linear softening, 1 (default) exponential damage evolution");
        v.attr("dmgTau", dmgTau, "Characteristic time of the normal viscosity (not used: as in the reference's build, no rate dependence; "
                                 "negative: deactivated) [s]");
        v.attr("dmgRateExp", dmgRateExp, "Exponent of the normal viscosity function (not used, as dmgTau) [-]");
        v.attr("plTau", plTau, "Characteristic time of the visco-plasticity (not used, as dmgTau; negative: deactivated) [s]");
        v.attr("plRateExp", plRateExp, "Exponent of the visco-plasticity function (not used, as dmgTau) [-]");
        v.attr("isoPrestress", isoPrestress, "Isotropic prestress of the whole specimen: the normal stress of the contacts is "
                                             "E·(epsN + isoPrestress/E) - isoPrestress [Pa]");
        v.attr("equivStrainShearContrib", equivStrainShearContrib, "Coefficient of the shear contribution to the equivalent strain "
                                                                   "(not used, as dmgTau)");
    }
    // (Material.newAssocState) bodies of this material get a CpmState
    std::shared_ptr<State> newAssocState() const override { return std::make_shared<CpmState>(); }
    YADE_INDEXABLE(CpmMat)
};

} // namespace yade
