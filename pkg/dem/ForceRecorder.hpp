// Writes the total force on a set of bodies to a file, periodically.
#pragma once
#include <pkg/common/Recorder.hpp>
#include <vector>

namespace yade {

class ForceRecorder : public Recorder {
public:
    static constexpr const char* classDoc =
            "Writes the resultant force on the bodies in ids (the sum of their forces this step: contacts and engines) to file, "
            "one line per run: iteration, the three components and the norm (e.g. the force on a bulldozer blade).";
    std::vector<int> ids;
    Vector3r totalForce = Vector3r::Zero();
    template <class V> void visit(V& v) {
        Recorder::visit(v);
        v.attr("ids", ids, "Ids of the bodies whose forces are summed");
        v.attr("totalForce", totalForce, "The resultant force at the last run [N]", Attr::readonly);
    }
    ForceRecorder() { initRun = true; }
    void action() override;
};

} // namespace yade
