// Contact of an infinite axis-aligned wall and a sphere.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/common/Wall.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Ig2_Wall_Sphere_ScGeom : public IGeomFunctorBatched<Ig2_Wall_Sphere_ScGeom, Wall, Sphere, ScGeom> {
public:
    static constexpr const char* classDoc = "Ig2 functor: ScGeom of an infinite axis-aligned Wall and a Sphere.";
    template <class V> void visit(V& v) { IGeomFunctor::visit(v); }
    bool go(const Wall& w, const Sphere& s, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
            Contact& contact);
};

} // namespace yade
