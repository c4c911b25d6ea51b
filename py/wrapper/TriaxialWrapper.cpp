#include <core/Omega.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <pkg/dem/triaxial/TriaxialCompressionEngine.hpp>
#include <pkg/dem/triaxial/TriaxialTest.hpp>
#include <py/wrapper/Math.hpp>
#include <py/wrapper/TriaxialWrapper.hpp>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace yade {

void bindTriaxial(py::module_&) {
    using T = TriaxialStressController;
    py::reinterpret_borrow<py::class_<T>>(py::type::handle_of<T>())
            .def("stress",
                    [](const T& t, int id) {
                        if (id < 0 || id > 5) throw py::index_error("TriaxialStressController.stress: id must be 0..5 (left, right, bottom, top, back, front), got " + std::to_string(id));
                        return t.stress[id];
                    },
                    py::arg("id"), "The average stress on boundary id (0..5: left, right, bottom, top, back, front): the wall's force over its area, compression negative, at the last computation")
            .def("strainRate", &T::strainRate, "Current strain rate d/dt(exx, eyy, ezz): the walls' relative velocity over the box's size")
            .def_property_readonly("strain", [](const T& t) { return t.strain; }, "Current strain (exx, eyy, ezz), true (logarithmic) strain log(size/size0)")
            .def_property_readonly("porosity", [](const T& t) { return t.porosity; }, "Porosity of the packing, 1 - particlesVolume/boxVolume")
            .def_property_readonly("boxVolume", [](const T& t) { return t.boxVolume; }, "Total packing volume, width·height·depth [m³]")
            .def_property_readonly("particlesVolume", [](const T& t) { return t.particlesVolume; }, "Total volume of the dynamic spheres (and clumped ones) [m³]")
            .def_property_readonly("spheresVolume", [](const T& t) { return t.particlesVolume; }, "Shorthand for particlesVolume [m³]")
            .def_property_readonly("max_vel1", [](const T& t) { return t.maxVel[0]; }, "Largest velocity of the walls along x: max_vel times width over the mean size [m/s]")
            .def_property_readonly("max_vel2", [](const T& t) { return t.maxVel[1]; }, "Largest velocity of the walls along y [m/s]")
            .def_property_readonly("max_vel3", [](const T& t) { return t.maxVel[2]; }, "Largest velocity of the walls along z [m/s]");
    py::reinterpret_borrow<py::class_<TriaxialCompressionEngine>>(py::type::handle_of<TriaxialCompressionEngine>())
            .def("setContactProperties", [](TriaxialCompressionEngine&, Real deg) { TriaxialCompressionEngine::setContactProperties(omega().scene(), deg); }, py::arg("frictionDegree"),
                    "Assign a new friction angle (degrees) to the dynamic bodies' materials and to the contacts between two dynamic bodies");
    // (the scene is built in Python, from the generator's attributes: py/yade/_triaxial.py)
    py::reinterpret_borrow<py::class_<TriaxialTest>>(py::type::handle_of<TriaxialTest>())
            .def("load", [](py::object self) { py::module_::import("yade._triaxial").attr("load")(self); },
                    "Build the triaxial test described by the attributes into O (replacing the current scene)")
            .def("generate", [](py::object self, const std::string& fileName) { py::module_::import("yade._triaxial").attr("generate")(self, fileName); },
                    py::arg("fileName"), "Build the scene as load() does (it becomes O's scene) and save it to fileName");
}

} // namespace yade
