// Elastic material with Coulomb friction.
#pragma once
#include <pkg/common/ElastMat.hpp>

namespace yade {

class FrictMat : public ElastMat {
public:
    static constexpr const char* classDoc = "Elastic material with Coulomb contact friction (frictionAngle), see ElastMat.";
    Real frictionAngle = 0.5;
    template <class V> void visit(V& v) {
        ElastMat::visit(v);
        v.attr("frictionAngle", frictionAngle, "Contact friction angle [rad]", Attr::nonNegative);
    }
    YADE_INDEXABLE(FrictMat)
};

} // namespace yade
