// O.interactions: a flat array of pairs (columns indexed by the pair's entry k), per body the list
// of its partners, and the contacts' geometry and physics in one ContactPool per (IGeom class,
// IPhys class). A potential pair (bounds overlap, no contact) is only an entry of the columns; an
// Interaction object exists only while Python holds one (or a file being written needs one), and
// its geom and phys are then views of the pool's record. Layout and ownership: doc/storage.md.
#pragma once
#include <core/ContactPool.hpp>
#include <core/Interaction.hpp>
#include <core/LawDispatcher.hpp>
#include <array>
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
    // O.interactions.erase (the reference's): a real interaction becomes a potential pair (its geometry
    // and physics dropped; the interaction loop tests it again at the next step); a potential pair
    // stays as it is. False if there is no such pair. Not while the loop runs.
    bool makePotential(id_t a, id_t b);
    void eraseAt(size_t k);
    // Room for n interactions in every column (a collider that knows how many pairs it will add:
    // growing the columns one push_back at a time held up to twice their size, and the old and
    // new arrays at once while they moved).
    void reserve(size_t n);
    // Room for more[id] more partners of each body (a collider that knows: lists grown one
    // push_back at a time took a third more memory).
    void reservePartners(const std::vector<uint32_t>& more);
    void clear();
    size_t size() const { return pairIds.size() / 2; }
    size_t countReal() const;

    // The object of entry k, made if the pair had none (its geom and phys then show the pool's
    // record): for Python and functors written in the one-contact form. The engines read the
    // pools and the columns instead.
    const Ptr& operator[](size_t k) const;
    // The object of entry k, or null: a pair whose object nobody asked for.
    Interaction* object(size_t k) const {
        const Record* r = record(k);
        return r ? r->object.get() : nullptr;
    }
    // The object of entry k if it has one, else a new one with copies of its geometry and physics,
    // that the container does not keep (the writer of saved files).
    Ptr snapshot(size_t k) const;
    bool isReal(size_t k) const { return contactOf[k] != noContact || (recordOf[k] != noRecord && unpooledReal(k)); }
    // Geometry and physics of entry k (null: none): the pool's objects for a contact.
    IGeom* geom(size_t k) const {
        if (contactOf[k] != noContact) return pool(contactOf[k]).geom(slotOf(contactOf[k]));
        const Record* r = record(k);
        return r ? r->geom.get() : nullptr;
    }
    IPhys* phys(size_t k) const {
        if (contactOf[k] != noContact) return pool(contactOf[k]).phys(slotOf(contactOf[k]));
        const Record* r = record(k);
        return r ? r->phys.get() : nullptr;
    }
    long long iterMadeReal(size_t k) const;

    // The interaction loop's steps for one pair (thread-safe for distinct pairs while the loop runs):
    // a new geometry made by an Ig2 functor that has no physics yet (kept with the pair)...
    void keepGeom(size_t k, std::shared_ptr<IGeom> g);
    // ...a new contact: its geometry and physics are copied into the pool of their classes (an
    // object Python holds for the pair shows the record from then on);
    void makeContact(size_t k, const std::shared_ptr<IGeom>& g, const std::shared_ptr<IPhys>& p, long long iter);
    // ...a contact that is over: back to a potential pair (an object Python holds is reset, and the
    // geom and phys it showed keep their last values). Its record leaves the pool in sweep().
    void endContact(size_t k);
    // After the loop's parallel part: the ended contacts' records leave their pools.
    void sweep();
    // A contact read from a saved file joins the pool of its classes as it was (the header's ids and
    // step; k is the pair's entry, a potential pair until then). Throws std::invalid_argument if the
    // header does not name pair k or the pair is a contact already.
    void restoreContact(const ContactPool::Header& h, const IGeom& g, const IPhys& p);
    // An interaction read from a saved file whose geometry or physics were outside a pool (a geometry
    // before its physics, objects set from Python): pair k keeps the object, and they join a pool at
    // the next step, as after insert().
    void restoreUnpooled(size_t k, Ptr I);
    // Puts each pool's records in the order of the pairs in `lists` (the interaction loop's thread
    // lists, one after the other): the records a thread reads one after the other are then
    // neighbours, and no cache line holds records of two threads (appended in parallel, they
    // were interleaved). onlyNeeded: only the pools whose ContactPool::needsOrder() says so.
    void orderPools(const std::vector<std::vector<uint32_t>>& lists, bool onlyNeeded = false);
    // Before the loop's parallel part: objects Python changed (geom, phys set) or let go.
    void syncObjects();
    long long objectsWrites = -1; // externalWrites() at the last syncObjects()
    mutable std::atomic<size_t> objectsMade{0}; // objects made since the last syncObjects()
    // Drops the object of pair k if it is `which` and nobody else holds it or its geom and phys:
    // what iterating O.interactions made is dropped as the iteration moves on.
    void releaseObject(size_t k, const Interaction* which);

    // The objects of one body's interactions that are real or have one.
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

    // Columns kept contiguous for the hot loop (entry k): the two ids (the loop swaps them when
    // the Ig2 functor takes the shapes in the other order), and whether the interaction was real
    // after the last InteractionLoop pass (the loop keeps it up to date), so that distant
    // potential pairs are skipped without reading anything else.
    std::vector<id_t> pairIds; // 2 per interaction
    std::vector<char> wasReal;
    std::vector<long long> iterBorn; // the step each pair was added (Interaction.iterBorn)
    // In a periodic scene (periodic; empty otherwise): per pair, Interaction.cellDist, by how many
    // cells (along the edges of O.cell.hSize) body 2's image is shifted from body 2.
    std::vector<Vector3i> cellDist;
    bool periodic = false;
    void setPeriodic(bool p); // (every pair's cellDist zero)
    long long iterNow = 0;           // the step new pairs are born in (set by Scene::beginStep)
    // Where a contact's record is: pool index (high bits) and slot, or noContact.
    static constexpr uint32_t noContact = 0xffffffffu, slotBits = 26, maxPools = 64;
    std::vector<uint32_t> contactOf;
    static uint32_t slotOf(uint32_t c) { return c & ((1u << slotBits) - 1); }
    static uint32_t poolOf(uint32_t c) { return c >> slotBits; }
    ContactPool& pool(uint32_t c) const { return *pools[poolOf(c)]; }
    // The pools (null: not made yet); a NumPy view holds its pool.
    std::array<std::shared_ptr<ContactPool>, maxPools> pools;
    size_t poolCount() const { return nPools; }
    // The NumPy views of the contacts handed out (O.interactions.arrays()), told when the set of
    // contacts changes (through the pools, which share it) and when the pools are dropped.
    const std::shared_ptr<ViewRegistry> views = std::make_shared<ViewRegistry>();

    // A pair whose object Python holds, or that has geometry or physics outside a pool (a new
    // geometry before its physics, a contact set from Python or read from a file before the loop
    // takes it), has a record: those objects. Most pairs have none (4 bytes instead).
    struct Record {
        std::shared_ptr<IGeom> geom; // outside a pool, or the object's views of the pool record
        std::shared_ptr<IPhys> phys;
        Ptr object;
    };
    static constexpr uint32_t noRecord = 0xffffffffu;
    mutable std::vector<uint32_t> recordOf; // per pair: its record, or noRecord
    Record* record(size_t k) { return recordOf[k] == noRecord ? nullptr : &records[recordOf[k]]; }
    const Record* record(size_t k) const { return recordOf[k] == noRecord ? nullptr : &records[recordOf[k]]; }
    void prepareRecords(); // room for a record per pair, so that the loop makes them without moving any
    // Incremented by every insert, erase and clear (the order of the entries changed). A scene just
    // loaded from a file has 0 (InteractionLoop::threadSplit applies only then).
    long long changes = 0;

private:
    mutable std::vector<Record> records; // (free ones are listed in freeRecords)
    mutable std::vector<uint32_t> freeRecords;
    mutable std::mutex recordsMutex, poolsMutex;
    size_t nPools = 0;
    std::vector<std::vector<Partner>> partners; // per body
    static const Ptr none;
    Record& ensureRecord(size_t k) const; // thread-safe after prepareRecords()
    void freeRecord(size_t k);            // (its object is dropped)
    bool unpooledReal(size_t k) const {
        const Record& r = records[recordOf[k]];
        return r.geom && r.phys;
    }
    ContactPool& poolFor(const IGeom& g, const IPhys& p, uint32_t& index); // made if new (thread-safe)
    void removeContact(size_t k);   // its record leaves the pool now (not while the loop runs)
    void dropObjects(size_t k);     // a pair back to potential: an object Python holds is reset, else its record freed
    void moved(ContactPool& pool, uint32_t index, size_t slot); // a record moved to `slot`: relink
    // The views of a contact's record (the geom and phys of its object) are kept in its Record
    // (geom, phys), so that they can be pointed at the record when it moves and detached when it
    // leaves, also after Python gave the object other ones.
    void makeViews(size_t k);   // the object of pair k gets views of its pool record
    void pointViews(size_t k);  // the views follow the record to its (new) slot
    void detachViews(size_t k); // the views keep the record's values, and it no longer has any
    bool append(id_t a, id_t b, Ptr I);
    void unlinkPartner(id_t from, id_t other);
    void relinkPartner(id_t from, uint32_t oldK, uint32_t newK);
};

} // namespace yade
