// Contact of a box and a sphere: with the closest point of the box surface.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <pkg/common/Box.hpp>
#include <pkg/common/Sphere.hpp>
#include <pkg/dem/ScGeom.hpp>

namespace yade {

class Ig2_Box_Sphere_ScGeom : public IGeomFunctorBatched<Ig2_Box_Sphere_ScGeom, Box, Sphere, ScGeom> {
public:
    static constexpr const char* classDoc = "Ig2 functor: ScGeom of a Box and a Sphere, the contact being with the closest point of the box's surface.";
    template <class V> void visit(V& v) { IGeomFunctor::visit(v); }
    bool go(const Box& b, const Sphere& s, const Kinematics& st1, const Kinematics& st2, const Vector3r& shift2, bool force,
            Contact& contact);
};

} // namespace yade
