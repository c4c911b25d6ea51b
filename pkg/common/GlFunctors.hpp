// The drawing functors (manual "3d view"): one per class of shape, bound, interaction geometry,
// interaction physics or state, chosen by the 3D view as every functor is chosen by its dispatcher.
// Their settings are class-wide (Gl1_Sphere.quality = 2 changes every sphere), as in the reference.
// This file holds the families; each Gl1_* class lives beside the class it draws.
#pragma once
#include <core/Functor.hpp>

namespace yade {

#define YADE_GL_FUNCTOR_FAMILY(Family, what)                                                        \
    class Family : public Functor {                                                                 \
    public:                                                                                         \
        static constexpr const char* classDoc = "Draws one class of " what " in the 3D view.";     \
        template <class V> void visit(V& v) { Functor::visit(v); }                                  \
    };
YADE_GL_FUNCTOR_FAMILY(GlShapeFunctor, "shape")
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
