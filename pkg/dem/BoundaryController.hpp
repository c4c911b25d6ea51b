// Base of the engines that drive the boundary of a sample (walls or the periodic cell) towards
// a prescribed stress or strain: PeriTriaxController, PeriIsoCompressor (doc/periodic.md).
#pragma once
#include <core/Engine.hpp>

namespace yade {

class BoundaryController : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Base of the engines that move the boundary of a sample (walls, or the periodic cell) to reach a prescribed stress or strain.";
    template <class V> void visit(V& v) { GlobalEngine::visit(v); }
};

} // namespace yade
