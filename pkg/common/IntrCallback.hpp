// Callbacks of InteractionLoop (InteractionLoop.callbacks): stepInit() when the loop starts a step,
// then go() for every real interaction once the loop has processed them all.
#pragma once
#include <core/IPhys.hpp>
#include <core/Interaction.hpp>
#include <lib/factory/ClassRegistry.hpp>
#include <stdexcept>

namespace yade {

class Scene;

class IntrCallback : public Serializable {
public:
    static constexpr const char* classDoc = "Abstract callback of InteractionLoop (InteractionLoop.callbacks): stepInit is called when the loop starts a step, then the callback is called for every real interaction after the loop processed it. Derived classes say what they do (SumIntrForcesCb).";
    template <class V> void visit(V& v) { Serializable::visit(v); }
    // When the interaction loop starts a step (the base class refuses to run, as in the reference).
    virtual void stepInit(Scene&) { throw std::runtime_error("Called IntrCallback::stepInit() of the base class? (use a derived callback, e.g. SumIntrForcesCb)"); }
    // For each real interaction, after the loop: its ids and physics.
    virtual void go(Body::id_t, Body::id_t, const IPhys&) {}
};

} // namespace yade
