// A step of the simulation loop; O.engines runs them in order every iteration (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class Scene;

class Engine : public Serializable {
public:
    static constexpr const char* classDoc = "One step of the simulation loop; O.engines runs them in order every iteration (1.2.1).";
    bool dead = false;
    int ompThreads = -1;
    std::string label;
    Scene* scene = nullptr; // set by the scene before each call
    long long execTime = 0, execCount = 0; // filled while O.timingEnabled
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("dead", dead, "If true, this engine is skipped");
        v.attr("execTime", execTime, "Cumulative wall time of this engine's runs [ns] (counted while O.timingEnabled)", Attr::noSave);
        v.attr("execCount", execCount, "Number of runs counted in execTime", Attr::noSave);
        v.attr("ompThreads", ompThreads, "Threads this engine may use (-1: all available)");
        v.attr("label", label, "Name under which the engine is reachable from Python scripts");
    }
    virtual bool isActivated() { return true; }
    virtual void action() {}
    // Called once by the loop before the engine first runs after a change of O.engines.
    virtual void prepare() {}
};

class GlobalEngine : public Engine {
public:
    static constexpr const char* classDoc = "Engine acting on the whole scene (all bodies or all interactions) each time it runs.";
    template <class V> void visit(V& v) { Engine::visit(v); }
};

// Acts on selected bodies only.
class PartialEngine : public Engine {
public:
    static constexpr const char* classDoc = "Engine acting on a subset of bodies, given by their ids.";
    std::vector<int> ids;
    template <class V> void visit(V& v) {
        Engine::visit(v);
        v.attr("ids", ids, "Ids of the bodies this engine acts on");
    }
};

} // namespace yade
