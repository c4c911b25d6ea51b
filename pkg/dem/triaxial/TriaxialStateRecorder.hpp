// Writes the state of the triaxial sample (the TriaxialStressController of O.engines) to a text file,
// one line per run: iteration, the three normal stresses, the three strains, the unbalanced force,
// the porosity and the kinetic energy, under a header line naming them.
#pragma once
#include <pkg/common/Recorder.hpp>

namespace yade {

class TriaxialStateRecorder : public Recorder {
public:
    static constexpr const char* classDoc =
            "Engine recording triaxial variables to file (columns named in its first line: iteration s11 s22 s33 e11 e22 e33 unb_force porosity kineticE): "
            "the stresses of the right, top and front walls and the strains of the TriaxialStressController (or TriaxialCompressionEngine) found in O.engines, "
            "the unbalanced force, the porosity of the box between the walls' faces now, and the kinetic energy of the dynamic bodies.";
    Real porosity = 1;
    template <class V> void visit(V& v) {
        Recorder::visit(v);
        v.attr("porosity", porosity, "Porosity at the last run: 1 - particlesVolume / volume of the box between the walls' faces");
    }
    TriaxialStateRecorder() { initRun = true; }
    void action() override;

private:
    bool headerWritten = false;
};

} // namespace yade
