// O.interactions: a flat array of interactions plus, per body, the list of its partners.
// A potential pair (bounds overlap, no contact yet) is only an entry of the columns: its
// Interaction object is made when Python or a functor asks for it (most pairs of a dense packing
// never become contacts, and an object per pair was most of the memory of a large scene).
#pragma once
#include <core/Interaction.hpp>
#include <core/LawDispatcher.hpp>
#include <atomic>
#include <cstdint>
#include <mutex>
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
    // The object of entry k, made (from the ids and the record) if the pair had none: for Python
    // and the loader's callers; the engines read the records instead.
    const Ptr& operator[](size_t k) const;
    // The object of entry k, or null: a pair whose object nobody asked for.
    Interaction* object(size_t k) const {
        const Record* r = record(k);
        return r ? r->object.get() : nullptr;
    }
    // The object of entry k if it has one, else a new one with the same values that the container
    // does not keep (the writer of saved files: no object is left behind).
    Ptr snapshot(size_t k) const;
    bool isReal(size_t k) const {
        const Record* r = record(k);
        return r && r->geom && r->phys;
    }
    // Geometry and physics of entry k (null: none).
    IGeom* geom(size_t k) const {
        const Record* r = record(k);
        return r ? r->geom.get() : nullptr;
    }
    IPhys* phys(size_t k) const {
        const Record* r = record(k);
        return r ? r->phys.get() : nullptr;
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
    // A pair that is a contact, or whose Interaction object someone asked for, has a record: its
    // geometry and physics (owned here; the object, if any, holds the same ones), the Law2 functor
    // chosen for them (null: not chosen yet; valid while lawTable is the dispatch table of the loop
    // that chose it, InteractionLoop clears it else), the step it became real and its object.
    // Most pairs of a dense packing are potential: they have none (4 bytes instead of a record).
    struct Record {
        std::shared_ptr<IGeom> geom;
        std::shared_ptr<IPhys> phys;
        LawFunctor* law = nullptr;
        Ptr object;
        long long iterMadeReal = -1;
    };
    static constexpr uint32_t noRecord = 0xffffffffu;
    mutable std::vector<uint32_t> recordOf; // per pair: its record, or noRecord
    Record* record(size_t k) { return recordOf[k] == noRecord ? nullptr : &records[recordOf[k]]; }
    const Record* record(size_t k) const { return recordOf[k] == noRecord ? nullptr : &records[recordOf[k]]; }
    // The record of pair k, made if it had none. Thread-safe between prepareRecords() and the next
    // insert, erase or clear (records never move then): the interaction loop makes them in parallel.
    Record& ensureRecord(size_t k) const;
    void prepareRecords(); // room for a record per pair, so that ensureRecord() moves none
    // A new geometry for pair k (an Ig2 functor's first contact), and the physics (Ip2), kept in
    // the object too if it has one.
    void setGeom(size_t k, std::shared_ptr<IGeom> g);
    void setPhys(size_t k, std::shared_ptr<IPhys> p, long long iter);
    long long lawTable = -1;
    void clearLaws(); // every record's Law2 functor
    // After Python set attributes of objects: their geom and phys become the records'; objects
    // that only the container holds any more are dropped (the next request makes a new one).
    void syncObjects();
    long long objectsWrites = -1; // externalWrites() at the last syncObjects()
    mutable std::atomic<size_t> objectsMade{0}; // objects made since the last syncObjects()
    // Drops the object of pair k if it is `which` and nobody else holds it (its geom and phys
    // kept): what iterating O.interactions made is dropped as the iteration moves on.
    void releaseObject(size_t k, const Interaction* which);
    // Incremented by every insert, erase and clear (the order of the entries changed).
    long long changes = 0;

private:
    mutable std::vector<Record> records; // (never shrinks; free ones are listed in freeRecords)
    mutable std::vector<uint32_t> freeRecords;
    mutable std::mutex recordsMutex;
    std::vector<std::vector<Partner>> partners; // per body
    static const Ptr none;
    bool append(id_t a, id_t b, Ptr I);
    void freeRecord(size_t k); // pair k has no record any more (its object is dropped or marked)
    void unlinkPartner(id_t from, id_t other);
    void relinkPartner(id_t from, uint32_t oldK, uint32_t newK);
};

} // namespace yade
