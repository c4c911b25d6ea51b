// Whole-scene helpers of yade.utils that run in C++ (no Python loop over bodies).
#include <pkg/dem/Shop.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <py/wrapper/ShopWrapper.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace yade {

void bindShop(py::module_& m) {
    m.def("PWaveTimeStep", [] { return Shop::PWaveTimeStep(omega().scene()); },
            "Critical time step estimated from the P-wave speed (3.5.22): min over spheres of r/sqrt(E/ρ)");
    m.def("unbalancedForce", [](bool useMaxForce) { return Shop::unbalancedForce(omega().scene(), useMaxForce); },
            py::arg("useMaxForce") = false,
            "Mean (or maximum) resultant force on dynamic bodies (with NewtonIntegrator's gravity) over the mean contact force");
    m.def("kineticEnergy", [](bool findMaxId) -> pybind11::object {
        if (!findMaxId) return pybind11::cast(Shop::kineticEnergy(omega().scene()));
        long maxId;
        const Real e = Shop::kineticEnergy(omega().scene(), &maxId);
        return pybind11::make_tuple(e, maxId);
    }, pybind11::arg("findMaxId") = false,
            "Translational and rotational kinetic energy of dynamic bodies; with findMaxId, (energy, id of the body with the largest)");
    m.def("aabbExtremaOfSpheres", [](bool centers) { return Shop::aabbExtremaOfSpheres(omega().scene(), centers); },
            py::arg("centers") = false, "(min, max) corners of the box around all spheres");
    m.def("getSpheresVolume", [](int mask) { return Shop::spheresVolume(omega().scene(), mask); }, py::arg("mask") = -1,
            "Total volume of spheres (with mask sharing a bit with `mask`; 0 or -1: all)");
    m.def("coordinations", [](const Vector3r& lo, const Vector3r& hi) { return Shop::coordinations(omega().scene(), lo, hi); },
            "Number of real interactions of each body whose position is in [lo, hi]");
    m.def("getSpheresMass", [](int mask) { return Shop::spheresMass(omega().scene(), mask); }, py::arg("mask") = -1,
            "Total mass of spheres (with mask sharing a bit with `mask`; 0 or -1: all)");
    m.def("_sphereColumns", [](int mask) {
        const Shop::SphereColumns c = Shop::sphereColumns(omega().scene(), mask);
        const py::ssize_t n = (py::ssize_t)c.ids.size();
        py::array_t<Real> pos({n, (py::ssize_t)3});
        auto p = pos.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) p(i, k) = c.pos[i][k];
        return py::make_tuple(py::array_t<int>(n, c.ids.data()), pos, py::array_t<Real>(n, c.radius.data()), py::array_t<int>(n, c.matIds.data()));
    }, py::arg("mask") = -1, "(ids, centers N×3, radii, material indices) of the spheres whose mask shares a bit with `mask` (-1: all); for yade.export");
}

} // namespace yade
