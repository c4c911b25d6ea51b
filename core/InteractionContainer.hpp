// O.interactions: a flat array of interactions plus, per body, the list of its partners.
#pragma once
#include <core/Interaction.hpp>
#include <core/LawDispatcher.hpp>
#include <vector>

namespace yade {

class InteractionContainer {
public:
    using id_t = Body::id_t;
    using Ptr = std::shared_ptr<Interaction>;
    // Finds the interaction between a and b in either order; nullptr if none.
    const Ptr& find(id_t a, id_t b) const;
    bool insert(const Ptr& I); // false if the pair already exists
    bool erase(id_t a, id_t b);
    void clear();
    size_t size() const { return linIntrs.size(); }
    size_t countReal() const;
    const Ptr& operator[](size_t i) const { return linIntrs[i]; }
    auto begin() const { return linIntrs.begin(); }
    auto end() const { return linIntrs.end(); }
    // Interactions of one body (potential and real).
    std::vector<Ptr> withBody(id_t id) const;
    // The same without copying: (other body id, interaction) pairs.
    const std::vector<std::pair<id_t, Interaction*>>& partnersOf(id_t id) const {
        static const std::vector<std::pair<id_t, Interaction*>> empty;
        return id >= 0 && (size_t)id < partners.size() ? partners[id] : empty;
    }
    // Keeps the per-body lists as long as the body container.
    void resizeBodies(size_t n) {
        if (n > partners.size()) partners.resize(n);
    }
    void eraseBody(id_t id); // every interaction of this body

    // Copies kept contiguous for the hot loop (entry k describes linIntrs[k]): the two ids, and
    // whether the interaction was real after the last InteractionLoop pass (the loop keeps it up
    // to date), so that distant potential pairs are skipped without touching the objects.
    std::vector<id_t> pairIds; // 2 per interaction
    std::vector<char> wasReal;
    // The interaction's geometry and physics objects (null when absent), so that the batched
    // functors reach them without reading the Interaction: kept up to date by the interaction
    // loop, which calls syncObjects() after anything was set from Python.
    // With them, the Law2 functor chosen for the pair (null: not chosen yet), valid while
    // lawTable is the dispatch table of the loop that chose it (InteractionLoop clears it else).
    struct Objects {
        IGeom* geom = nullptr;
        IPhys* phys = nullptr;
        LawFunctor* law = nullptr;
    };
    long long lawTable = -1;
    std::vector<Objects> objects;
    void syncObjects(); // from every interaction's geom and phys
    long long objectsWrites = -1; // externalWrites() at the last syncObjects()
    // Incremented by every insert, erase and clear (the order of linIntrs changed).
    long long changes = 0;

private:
    std::vector<Ptr> linIntrs;
    std::vector<std::vector<std::pair<id_t, Interaction*>>> partners; // per body: (other id, interaction)
    static const Ptr none;
    void unlinkPartner(id_t from, id_t other);
};

} // namespace yade
