// The interaction callback that sums the magnitudes of the contact forces of a step.
#pragma once
#include <pkg/common/IntrCallback.hpp>

namespace yade {

class SumIntrForcesCb : public IntrCallback {
public:
    static constexpr const char* classDoc = "Interaction callback summing the magnitudes |normalForce + shearForce| of the forces of all real interactions (their physics must derive from NormShearPhys); at the start of each step it prints the last step's sum and count to stderr as (sum,count), as the reference does.";
    template <class V> void visit(V& v) { IntrCallback::visit(v); }
    void stepInit(Scene&) override;
    void go(Body::id_t id1, Body::id_t id2, const IPhys& phys) override;

private:
    Real sum = 0;
    long count = 0;
};

} // namespace yade
