// Whole-scene helpers of yade.utils that run in C++ (no Python loop over bodies).
#include <pkg/dem/Shop.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <py/wrapper/ShopWrapper.hpp>

namespace py = pybind11;

namespace yade {

void bindShop(py::module_& m) {
    m.def("PWaveTimeStep", [] { return Shop::PWaveTimeStep(omega().scene()); },
            "Critical time step estimated from the P-wave speed (3.5.22): min over spheres of r/sqrt(E/ρ)");
}

} // namespace yade
