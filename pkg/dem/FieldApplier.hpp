// Base of the engines that apply a body force field (a force proportional to each body's mass).
#pragma once
#include <core/Engine.hpp>

namespace yade {

class FieldApplier : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Base of the engines applying a force field to the bodies (a force proportional to their mass).";
    template <class V> void visit(V& v) { GlobalEngine::visit(v); }
};

} // namespace yade
