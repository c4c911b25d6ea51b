#include <core/Omega.hpp>
#include <pkg/dem/Law2_ScGeom_FrictViscoPhys_CundallStrackVisco.hpp>
#include <py/wrapper/FrictViscoWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>

namespace py = pybind11;

namespace yade {

void bindFrictVisco(py::module_&) {
    using Law = Law2_ScGeom_FrictViscoPhys_CundallStrackVisco;
    py::reinterpret_borrow<py::class_<Law>>(py::type::handle_of<Law>())
            .def("elasticEnergy", [](const Law&) { return Law::elasticEnergy(omega().scene()); },
                    "Total elastic energy of the FrictViscoPhys contacts: the sum of (|normalForce|²/kn + |shearForce|²/ks)/2 [J]")
            .def("plasticDissipation", [](const Law& l) { return l.plasticDissipation; },
                    "Total energy dissipated by sliding in the contacts of this law, summed only while traceEnergy is set [J]")
            .def("initPlasticDissipation", [](Law& l, Real v) { l.plasticDissipation = v; }, py::arg("initVal") = 0.,
                    "Sets the summed plastic dissipation to a value (0 by default)");
}

} // namespace yade
