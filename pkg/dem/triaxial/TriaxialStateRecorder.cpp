#include <core/Scene.hpp>
#include <pkg/dem/Shop.hpp>
#include <pkg/dem/triaxial/TriaxialStateRecorder.hpp>
#include <pkg/dem/triaxial/TriaxialStressController.hpp>
#include <iomanip>
#include <stdexcept>

namespace yade {

void TriaxialStateRecorder::action() {
    Scene& s = *scene;
    TriaxialStressController* triax = nullptr;
    for (const auto& e : s.getEngines())
        if ((triax = dynamic_cast<TriaxialStressController*>(e.get()))) break;
    if (!triax) throw std::runtime_error("TriaxialStateRecorder needs a TriaxialStressController (or TriaxialCompressionEngine) in O.engines");
    using T = TriaxialStressController;
    porosity = 1 - triax->particlesVolume / triax->boxVolume; // (the box of this step's start, as the controller measured it)
    std::ostream& o = out();
    if (!headerWritten) {
        o << "iteration s11 s22 s33 e11 e22 e33 unb_force porosity kineticE\n";
        headerWritten = true;
    }
    o << std::setprecision(17) << s.iter << " " << triax->stress[T::right][0] << " " << triax->stress[T::top][1] << " " << triax->stress[T::front][2] << " "
      << triax->strain[0] << " " << triax->strain[1] << " " << triax->strain[2] << " " << Shop::unbalancedForce(s, false) << " " << porosity << " "
      << Shop::kineticEnergy(s) << std::endl;
}

} // namespace yade
