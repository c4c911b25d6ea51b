// Ip2 functors compute the contact physics (IPhys) from two materials; IPhysDispatcher picks
// one per pair of material types (either order).
#pragma once
#include <core/Dispatcher.hpp>
#include <core/Interaction.hpp>

namespace yade {

class IPhysFunctor : public Functor {
public:
    static constexpr const char* classDoc = "Ip2 functor: computes the contact physics (IPhys) of a new contact from the two bodies' materials.";
    template <class V> void visit(V& v) { Functor::visit(v); }
    // Creates I.phys for a new contact (called once, when I.geom first appears).
    virtual void go(const std::shared_ptr<Material>& m1, const std::shared_ptr<Material>& m2, Interaction& I);
};

template <class M1, class M2, class P> class IPhysFunctorOf : public IPhysFunctor {
public:
    std::vector<std::string> argTypes() const override { return {registeredName<M1>(), registeredName<M2>()}; }
    std::string producedType() const override { return registeredName<P>(); }
};

class IPhysDispatcher : public Dispatcher {
public:
    static constexpr const char* classDoc = "Dispatcher of Ip2 functors: picks one per pair of Material classes (either order).";
    std::vector<std::shared_ptr<IPhysFunctor>> functors;
    template <class V> void visit(V& v) {
        Dispatcher::visit(v);
        v.attr("functors", functors, "Ip2 functors, one per pair of material types");
    }
    std::vector<std::shared_ptr<Functor>> functorsBase() const override { return {functors.begin(), functors.end()}; }
    void postLoad() override { table.invalidate(); }
    // Resolves all type pairs now (before a parallel loop reads the table); true if it had to.
    bool prepareTable() {
        if (table.isFilled()) return false;
        table.fill(functors, "Material", "Material", true);
        return true;
    }
    const DispatchTable2D<IPhysFunctor>::Entry& getFunctor(const Material& a, const Material& b) {
        return table.get(a.getClassIndex(), b.getClassIndex(), functors, "Material", "Material", true);
    }

private:
    DispatchTable2D<IPhysFunctor> table;
};

} // namespace yade
