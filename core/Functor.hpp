// A function object chosen by a dispatcher according to the types of its arguments (1.2.1).
#pragma once
#include <lib/factory/ClassRegistry.hpp>

namespace yade {

class Scene;

class Functor : public Serializable {
public:
    static constexpr const char* classDoc = "Function object that a Dispatcher chooses according to the classes of its arguments (1.2.1).";
    std::string label;
    Scene* scene = nullptr; // set by the dispatcher before calls
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("label", label, "Name under which the functor is reachable from Python scripts");
    }
    // Class names of the types accepted (1 or 2) and of the type produced ("" if none).
    virtual std::vector<std::string> argTypes() const { return {}; }
    virtual std::string producedType() const { return ""; }
    // Called by the dispatching engine before each loop over bodies or interactions, outside
    // parallel regions (e.g. to register energy terms).
    virtual void prepare() {}
};

// Name of a registered class, for functors describing their argument types.
template <class T> std::string registeredName() { return ClassRegistry::instance().get(typeid(T)).name; }

} // namespace yade
