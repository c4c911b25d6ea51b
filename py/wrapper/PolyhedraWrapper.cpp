#include <core/Omega.hpp>
#include <core/State.hpp>
#include <pkg/dem/polyhedra/Law2_PolyhedraGeom_PolyhedraPhys_Volumetric.hpp>
#include <pkg/dem/polyhedra/Polyhedra.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <py/wrapper/PolyhedraWrapper.hpp>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace yade {

namespace {

Polyhedra& ready(Polyhedra& p) {
    p.ensureInitialized();
    return p;
}

// Extents of the polyhedron along its principal axes, sorted from the largest (SizeOfPolyhedra).
Vector3r sizes(Polyhedra& p) {
    Vector3r lo = Vector3r::Constant(INFINITY), hi = -lo;
    for (const auto& x : ready(p).v) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    Vector3r s = hi - lo;
    std::sort(s.data(), s.data() + 3, [](Real a, Real b) { return a > b; });
    return s;
}

} // namespace

void bindPolyhedra(py::module_& m) {
    py::reinterpret_borrow<py::class_<Polyhedra>>(py::type::handle_of<Polyhedra>())
            .def("Initialize", [](Polyhedra& p) { p.initialize(); }, "Initialization: the convex hull of v (or of random vertices from seed and size when v is empty), its centroid moved to the origin and its principal axes along x, y, z")
            .def("GetVolume", [](Polyhedra& p) { return ready(p).volume; }, "return polyhedra's volume [m³]")
            .def("GetInertia", [](Polyhedra& p) { return ready(p).inertia; }, "return polyhedra's principal moments of inertia per unit density [m⁵]")
            .def("GetCentroid", [](Polyhedra& p) { return ready(p).centroid; }, "return polyhedra's centroid: where it was in the vertices as given (the origin of v once initialized)")
            .def("GetOri", [](Polyhedra& p) { return ready(p).orientation; }, "return polyhedra's orientation: the turn from its principal frame (v) to the vertices as given")
            .def("GetSurfaces", [](Polyhedra& p) { return ready(p).faces; }, "get indices of surfaces' vertices (for postprocessing): one list per face, counter-clockwise seen from outside")
            .def("GetSurfaceTriangulation", [](Polyhedra& p) {
                    std::vector<int> t;
                    for (const auto& f : ready(p).faces)
                        for (size_t i = 1; i + 1 < f.size(); ++i) t.insert(t.end(), {f[0], f[i], f[i + 1]});
                    return t;
                }, "triangulation of facets (for plotting): vertex indices, three per triangle")
            .def("setVertices", [](Polyhedra& p, const std::vector<Vector3r>& v) { p.v = v; p.initialize(); }, py::arg("vertices"), "set vertices and update receiver. Takes a list/tuple of vertices as argument.")
            .def("setVertices4", [](Polyhedra& p, const Vector3r& a, const Vector3r& b, const Vector3r& c, const Vector3r& d) { p.v = {a, b, c, d}; p.initialize(); },
                    "set 4 vertices and update receiver. Each vertex is single argument.");
    using Law = Law2_PolyhedraGeom_PolyhedraPhys_Volumetric;
    py::reinterpret_borrow<py::class_<Law>>(py::type::handle_of<Law>())
            .def("elasticEnergy", [](const Law&) { return Law::elasticEnergy(omega().scene()); },
                    "Total elastic energy of the PolyhedraPhys contacts: the sum of (|normalForce|²/kn + |shearForce|²/ks)/2 [J]")
            .def("plasticDissipation", [](const Law& l) { return l.plasticDissipation; },
                    "Total energy dissipated in plastic slips at all contacts of this law, summed only while traceEnergy is set [J]")
            .def("initPlasticDissipation", [](Law& l, Real v) { l.plasticDissipation = v; }, py::arg("initVal") = 0.,
                    "Initialize cumulated plastic dissipation to a value (0 by default)");
    py::module_ u = m.def_submodule("_polyhedra_utils", "C++ helpers of yade.polyhedra_utils");
    u.def("SizeOfPolyhedra", [](Shape& s) {
            auto* p = dynamic_cast<Polyhedra*>(&s);
            if (!p) throw py::type_error("SizeOfPolyhedra needs a Polyhedra, got " + s.getClassName());
            return sizes(*p);
        }, "returns max, middle and min size in perpendicular directions (the extents along the principal axes)");
    u.def("SieveSize", [](Shape& s) {
            auto* p = dynamic_cast<Polyhedra*>(&s);
            if (!p) throw py::type_error("SieveSize needs a Polyhedra, got " + s.getClassName());
            const Vector3r x = sizes(*p);
            return std::sqrt(x[1] * x[1] + x[2] * x[2]); // the diagonal of the two smaller extents: the square mesh it passes
        }, "returns approximate sieve size of polyhedron: the diagonal of its two smaller principal extents");
}

} // namespace yade
