// L3Geom of two spheres, updated incrementally; the update of the local frame (handleSpheresLikeContact)
// is shared by the wall, facet and L6Geom functors, which derive from this one as in the reference.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/dem/localframe/L3Geom.hpp>

namespace yade {

class Ig2_Sphere_Sphere_L3Geom : public IGeomFunctor {
public:
    static constexpr const char* classDoc =
            "Ig2 functor: L3Geom of two spheres, updated incrementally. A contact starts when |x2 - x1| < |distFactor|·(r1+r2); its local "
            "x axis is the normal n, y is n×e_y normalized when |n_y| < |n_z|, else n×e_z normalized, z = x×y. At each step the frame "
            "follows the rigid motion of the pair: rows 1 and 2 of trsf turn by o_r = n_prev×n (tilt) and o_t = n_mid(n_mid·(ω1+ω2)/2)Δt "
            "(twist), n_mid = (n_prev+n)/2 normalized; u += T_mid·v_r·Δt with v_r the shear part of the relative velocity at the contact "
            "and T_mid the slerp of the previous and current trsf at 1/2; u_x = |x2 - x1| - (r1+r2) is not incremental.";
    bool noRatch = true;
    Real distFactor = 1;
    int trsfRenorm = 100;
    int approxMask = 0;
    template <class V> void visit(V& v) {
        IGeomFunctor::visit(v);
        v.attr("noRatch", noRatch, "Branch vectors r1·n and -r2·n (no granular ratcheting) instead of from the bodies' centres to the contact point");
        v.attr("distFactor", distFactor, "Create the contact when the spheres are closer than |distFactor|·(r1+r2); when negative, the initial "
                                         "distance is the zero of the normal displacement (u0), otherwise the geometrical touching distance is");
        v.attr("trsfRenorm", trsfRenorm, "Every this many steps trsf is made orthonormal again (0 or less: never; the simulation may then be unstable)");
        v.attr("approxMask", approxMask, "Geometrical approximations (bitmask, 0: none): 1 use the previous trsf instead of the mid-step one "
                                         "(slerp at 1/2) to turn velocities; 2 use the previous normal instead of the mid-step one; 4 do not "
                                         "normalize the mid-step normal", Attr::nonNegative);
    }
    std::vector<std::string> argTypes() const override { return {"Sphere", "Sphere"}; }
    std::string producedType() const override { return "L3Geom"; }
    bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force, Interaction& I) final;
    void goBatch(const BodyColumns& bodies, Contact* c, size_t n, char* result) override;
    // One contact, body 2 (its image in a periodic scene) moving as k2.
    virtual bool goContact(const Shape& s1, const Shape& s2, const Kinematics& k1, const Kinematics& k2, bool force, Contact& c);

protected:
    // Creates (the first time) or updates the contact's L3Geom (or L6Geom) from the current normal, contact point and
    // normal displacement uN (negative in overlap); r1, r2 are the reference radii (0: a wall or a facet).
    void handleSpheresLikeContact(Contact& c, const Kinematics& k1, const Kinematics& k2, const Vector3r& normal, const Vector3r& contPt,
            Real uN, Real r1, Real r2) const;
    virtual bool makesL6() const { return false; }
    static Matrix3r initialTrsf(const Vector3r& normal);
};

} // namespace yade
