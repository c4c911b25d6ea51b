// Bond of two grid nodes: the six-degree-of-freedom geometry of two spheres (Ig2_Sphere_Sphere_ScGeom6D),
// made as a GridNodeGeom6D.
#pragma once
#include <pkg/dem/cohesive/Ig2_Sphere_Sphere_ScGeom6D.hpp>
#include <pkg/dem/grid/GridNode.hpp>
#include <pkg/dem/grid/GridNodeGeom6D.hpp>

namespace yade {

class Ig2_GridNode_GridNode_GridNodeGeom6D : public Ig2_Sphere_Sphere_ScGeom6D {
public:
    static constexpr const char* classDoc =
            "Ig2 functor: GridNodeGeom6D of two GridNodes, the geometry of Ig2_Sphere_Sphere_ScGeom6D (overlap, normal, shear, twist "
            "and bending of the two node spheres). The bond is made by yade.gridpfacet.gridConnection, whatever the nodes' distance.";
    bool avoidGranularRatcheting = true;
    template <class V> void visit(V& v) {
        Ig2_Sphere_Sphere_ScGeom6D::visit(v);
        v.attr("avoidGranularRatcheting", avoidGranularRatcheting,
                "Accepted for compatibility; the shear update is always that of ScGeom (3.3.2) here");
    }
    std::vector<std::string> argTypes() const override { return {registeredName<GridNode>(), registeredName<GridNode>()}; }
    std::string producedType() const override { return registeredName<GridNodeGeom6D>(); }
    bool go(const Shape& s1, const Shape& s2, const State& st1, const State& st2, const Vector3r& shift2, bool force, Interaction& I) override;
    void goBatch(const BodyColumns& b, Contact* c, size_t n, char* result) override;

private:
    bool nodeContact(Real r1, Real r2, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force, Contact& contact);
};

} // namespace yade
