// O.interactions: a flat array of interactions plus, per body, the list of its partners.
// A potential pair (bounds overlap, no contact yet) is only an entry of the columns: its
// Interaction object is made when Python or a functor asks for it (most pairs of a dense packing
// never become contacts, and an object per pair was most of the memory of a large scene).
#pragma once
#include <core/Interaction.hpp>
#include <core/LawDispatcher.hpp>
#include <cstdint>
#include <vector>

namespace yade {

class InteractionContainer {
public:
    using id_t = Body::id_t;
    using Ptr = std::shared_ptr<Interaction>;
    InteractionContainer() = default;
    InteractionContainer(const InteractionContainer&) = delete;
    InteractionContainer& operator=(const InteractionContainer&) = delete;
    ~InteractionContainer(); // (marks the objects someone still holds as erased)
    // Position of the pair (a, b), in either order, in the container; -1 if none.
    long findIndex(id_t a, id_t b) const;
    // The interaction of the pair (a, b) in either order (its object is made if it had none);
    // null if there is no such pair.
    const Ptr& find(id_t a, id_t b) const;
    bool insert(const Ptr& I); // false if the pair already exists
    bool insertPotential(id_t a, id_t b); // a pair without object (the collider); false if it exists
    bool erase(id_t a, id_t b);
    void eraseAt(size_t k);
    // Room for n interactions in every column (a collider that knows how many pairs it will add:
    // growing the columns one push_back at a time held up to twice their size, and the old and
    // new arrays at once while they moved).
    void reserve(size_t n);
    void clear();
    size_t size() const { return pairIds.size() / 2; }
    size_t countReal() const;
    // The object of entry k, made (from the ids) if the pair had none: for Python and the loader's
    // callers; the engines read object() and the columns instead.
    const Ptr& operator[](size_t k) const;
    // The object of entry k, or null: a potential pair whose object was never asked for.
    Interaction* object(size_t k) const { return linIntrs[k].get(); }
    bool isReal(size_t k) const {
        const Interaction* I = linIntrs[k].get();
        return I && I->isReal();
    }
    // A contact is over (InteractionLoop): back to a potential pair; its object is dropped unless
    // someone else (Python) holds it, then it is reset.
    void endContact(size_t k);
    // The objects of one body's interactions that have one (every contact has one).
    std::vector<Ptr> withBody(id_t id) const;
    // Partners of a body without copying: the other body and the position of the pair.
    struct Partner {
        id_t other;
        uint32_t k;
    };
    const std::vector<Partner>& partnersOf(id_t id) const {
        static const std::vector<Partner> empty;
        return id >= 0 && (size_t)id < partners.size() ? partners[id] : empty;
    }
    // Keeps the per-body lists as long as the body container.
    void resizeBodies(size_t n) {
        if (n > partners.size()) partners.resize(n);
    }
    void eraseBody(id_t id); // every interaction of this body

    // Columns kept contiguous for the hot loop (entry k): the two ids (authoritative for a pair
    // without object; the loop swaps them when the Ig2 functor takes the shapes in the other
    // order), and whether the interaction was real after the last InteractionLoop pass (the loop
    // keeps it up to date), so that distant potential pairs are skipped without touching objects.
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
    // Incremented by every insert, erase and clear (the order of the entries changed).
    long long changes = 0;

private:
    mutable std::vector<Ptr> linIntrs; // (null: a potential pair without object)
    std::vector<std::vector<Partner>> partners; // per body
    static const Ptr none;
    bool append(id_t a, id_t b, Ptr I);
    void unlinkPartner(id_t from, id_t other);
    void relinkPartner(id_t from, uint32_t oldK, uint32_t newK);
};

} // namespace yade
