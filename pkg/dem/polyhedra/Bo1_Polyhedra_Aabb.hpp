// Aabb of a polyhedron: the extreme coordinates of its turned vertices.
#pragma once
#include <core/BoundDispatcher.hpp>
#include <pkg/common/Aabb.hpp>
#include <pkg/dem/polyhedra/Polyhedra.hpp>

namespace yade {

class Bo1_Polyhedra_Aabb : public BoundFunctorOf<Polyhedra, Aabb> {
public:
    static constexpr const char* classDoc = "Create/update the Aabb of a Polyhedra: the extreme coordinates of its vertices, enlarged by aabbEnlargeFactor.";
    Real aabbEnlargeFactor = -1;
    template <class V> void visit(V& v) {
        BoundFunctor::visit(v);
        v.attr("aabbEnlargeFactor", aabbEnlargeFactor, "Scale the box by this factor around its center (negative: no scaling); see Bo1_Sphere_Aabb.aabbEnlargeFactor");
    }
    void go(const Polyhedra& p, Aabb& aabb, const State& state, const Body& body) override;
};

} // namespace yade
