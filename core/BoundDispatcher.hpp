// Bo1 functors compute a body's Bound from its Shape; BoundDispatcher picks one per shape type.
#pragma once
#include <core/Body.hpp>
#include <core/Dispatcher.hpp>

namespace yade {

class BoundFunctor : public Functor {
public:
    static constexpr const char* classDoc = "Bo1 functor: computes a body's Bound from its Shape (called by BoundDispatcher).";
    template <class V> void visit(V& v) { Functor::visit(v); }
    // Creates or updates `bound` for `shape` placed at `state`.
    virtual void go(const Shape& shape, std::shared_ptr<Bound>& bound, const State& state, const Body& body);
};

// A Bo1 functor for shape class S producing bound class B.
template <class S, class B> class BoundFunctorOf : public BoundFunctor {
public:
    std::vector<std::string> argTypes() const override { return {registeredName<S>()}; }
    std::string producedType() const override { return registeredName<B>(); }
    void go(const Shape& shape, std::shared_ptr<Bound>& bound, const State& state, const Body& body) final {
        if (!bound || bound->getClassIndex() != B::classIndexStatic()) bound = std::make_shared<B>();
        go(static_cast<const S&>(shape), static_cast<B&>(*bound), state, body);
    }
    virtual void go(const S& shape, B& bound, const State& state, const Body& body) = 0;
};

class BoundDispatcher : public Dispatcher {
public:
    static constexpr const char* classDoc = "Dispatcher of Bo1 functors: picks for each body the functor that handles its Shape class and updates its Bound.";
    std::vector<std::shared_ptr<BoundFunctor>> functors;
    template <class V> void visit(V& v) {
        Dispatcher::visit(v);
        v.attr("functors", functors, "Bo1 functors, one per shape type");
    }
    std::vector<std::shared_ptr<Functor>> functorsBase() const override { return {functors.begin(), functors.end()}; }
    void postLoad() override { table.invalidate(); }
    BoundFunctor* getFunctor(const Shape& s) { return table.get(s.getClassIndex(), functors, "Shape"); }
    void prepareTable() { table.fill(functors, "Shape"); } // then getFunctor() only reads
    void action() override; // updates the bounds of all bodies

private:
    DispatchTable1D<BoundFunctor> table;
};

} // namespace yade
