// The Ig2 functors whose ScGeom is a kernel (core/ContactKernel.hpp): every Law2 kernel on ScGeom
// gets a fast pass with each of them. A new geometry kernel of ScGeom is added to this list.
#pragma once
#include <core/ContactKernel.hpp>
#include <pkg/dem/Ig2_Facet_Sphere_ScGeom.hpp>
#include <pkg/dem/Ig2_Sphere_Sphere_ScGeom.hpp>

namespace yade {

template <> struct GeomKernels<ScGeom> {
    using List = KernelList<Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom>;
};

} // namespace yade
