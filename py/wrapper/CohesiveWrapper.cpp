#include <core/Omega.hpp>
#include <pkg/dem/cohesive/Law2_ScGeom6D_CohFrictPhys_CohesionMoment.hpp>
#include <py/wrapper/CohesiveWrapper.hpp>
#include <py/wrapper/OmegaWrapper.hpp>

namespace py = pybind11;

namespace yade {

void bindCohesive(py::module_&) {
    using Law = Law2_ScGeom6D_CohFrictPhys_CohesionMoment;
    using S = Law::Spring;
    const auto energy = [](S which) { return [which](const Law&) { return Law::elasticEnergy(omega().scene(), which); }; };
    py::reinterpret_borrow<py::class_<Law>>(py::type::handle_of<Law>())
            .def("elasticEnergy", energy(S::all), "Elastic energy of the CohFrictPhys contacts: the sum of the four below [J]")
            .def("normElastEnergy", energy(S::normal), "Elastic energy of the normal springs, Σ |normalForce|²/(2kn) [J]")
            .def("shearElastEnergy", energy(S::shear), "Elastic energy of the shear springs, Σ |shearForce|²/(2ks) [J]")
            .def("bendingElastEnergy", energy(S::bending), "Elastic energy of the rolling springs, Σ |moment_bending|²/(2kr) [J]")
            .def("twistElastEnergy", energy(S::twist), "Elastic energy of the twisting springs, Σ |moment_twist|²/(2ktw) [J]")
            .def("plasticDissipation", [](const Law& l) { return l.plasticDissipation; },
                    "Energy dissipated by sliding in the contacts of this law, summed while traceEnergy or O.trackEnergy is set [J]")
            .def("initPlasticDissipation", [](Law& l, Real v) { l.plasticDissipation = v; }, py::arg("initVal") = 0.,
                    "Sets the summed plastic dissipation to a value (0 by default)");
}

} // namespace yade
