// The drawing functors (manual "3d view"): one per class of shape, bound, interaction geometry,
// interaction physics or state, chosen by the 3D view as every functor is chosen by its dispatcher.
// Their settings are class-wide (Gl1_Sphere.quality = 2 changes every sphere), as in the reference.
// This file holds the families; each Gl1_* class lives beside the class it draws.
#pragma once
#include <core/Functor.hpp>
#include <core/Shape.hpp>
#include <core/State.hpp>

namespace yade {

// What the view needs of one body besides its position, orientation and color: its shape's own numbers and,
// for a shape drawn as triangles (a facet), their corners in world coordinates.
struct DisplayItem {
    Vector3r size = Vector3r::Zero(); // e.g. a sphere's radius, a box's half-extents, a wall's axis and sense
    std::vector<Vector3r>* triangles = nullptr; // append 3 corners per triangle
};

// Draws one class of shape: the 3D view chooses it by the shape's class (its `bases`), as a dispatcher does,
// gathers the numbers with it (py/wrapper/DisplayWrapper.cpp), and draws them with the drawer of the same
// name (py/yade/qt/drawing.py).
class GlShapeFunctor : public Functor {
public:
    static constexpr const char* classDoc = "Draws one class of shape in the 3D view.";
    template <class V> void visit(V& v) { Functor::visit(v); }
    virtual void gather(const Shape&, const State&, DisplayItem&) const {}
};

#define YADE_GL_FUNCTOR_FAMILY(Family, what)                                                        \
    class Family : public Functor {                                                                 \
    public:                                                                                         \
        static constexpr const char* classDoc = "Draws one class of " what " in the 3D view.";     \
        template <class V> void visit(V& v) { Functor::visit(v); }                                  \
    };
YADE_GL_FUNCTOR_FAMILY(GlBoundFunctor, "bound")
YADE_GL_FUNCTOR_FAMILY(GlIGeomFunctor, "interaction geometry")
YADE_GL_FUNCTOR_FAMILY(GlIPhysFunctor, "interaction physics")
YADE_GL_FUNCTOR_FAMILY(GlStateFunctor, "state")
#undef YADE_GL_FUNCTOR_FAMILY

// A drawing functor of family Family for objects of class Drawn (its `bases`, as other functors' argTypes).
template <class Family, class Drawn> class GlFunctorOf : public Family {
public:
    std::vector<std::string> argTypes() const override { return {registeredName<Drawn>()}; }
};

} // namespace yade
