// The contacts of one (IGeom class, IPhys class) pair, in one contiguous array of records: each
// record is a header (the pair's ids and entry in O.interactions, the step it became real) and the
// geometry and physics objects themselves, constructed in place (no allocation per contact).
// The array is compact: rows 0 .. size()-1 are the live contacts (what NumPy views show); a
// contact that ends is replaced by the last record. Records never move while no record is
// removed, so appends may run in parallel with work on other records (the interaction loop
// appends new contacts as they are found and removes ended ones after its parallel part).
// The layout and who keeps what in step: doc/storage.md.
#pragma once
#include <core/Body.hpp>
#include <core/IGeom.hpp>
#include <core/IPhys.hpp>
#include <lib/base/StableArray.hpp>
#include <lib/base/ViewRegistry.hpp>
#include <lib/factory/ClassRegistry.hpp>
#include <cstdint>
#include <mutex>
#include <vector>

namespace yade {

class LawFunctor;

class ContactPool {
public:
    struct Header {
        Body::id_t id1, id2;     // the pair's ids, in the order of O.interactions' columns when it was added
        uint32_t k;              // the pair's entry in O.interactions
        uint32_t ended;          // 1: the contact ended in this step (removed when the step's loop is over)
        long long iterMadeReal;  // the step it became real
    };
    ContactPool(const ClassInfo& geom, const ClassInfo& phys);
    ~ContactPool();
    ContactPool(const ContactPool&) = delete;
    ContactPool& operator=(const ContactPool&) = delete;

    const ClassInfo& geomClass;
    const ClassInfo& physClass;
    size_t size() const { return count; }
    char* record(size_t slot) const { return base + slot * stride; }
    Header& header(size_t slot) const { return *reinterpret_cast<Header*>(record(slot)); }
    // (the base class is at the start of each object: checked in the constructor)
    IGeom* geom(size_t slot) const { return reinterpret_cast<IGeom*>(record(slot) + geomOffset); }
    IPhys* phys(size_t slot) const { return reinterpret_cast<IPhys*>(record(slot) + physOffset); }
    // A new record holding copies of g and p (of this pool's classes; a view is copied from what
    // it shows). Safe while other threads append or work on other records.
    size_t append(const Header& h, const IGeom& g, const IPhys& p);
    // Removes record `slot`: the last one moves into it; true if one moved. Not thread-safe.
    bool removeAt(size_t slot);
    // Moves record s to slot to[s] for every s (a permutation of 0 .. size()-1). Not thread-safe.
    void permute(const std::vector<uint32_t>& to);
    // Records put out of the loop's order since the last permute(): appended at the end, and moved from
    // the end into the slot of a record removed (removeAt).
    size_t appendsSinceOrder = 0, movesSinceOrder = 0;
    // Whether the records should be put back in the interaction loop's order (InteractionContainer::orderPools):
    // - many were appended since they last were (the first step of a dense packing): made in parallel,
    //   the records of two threads were interleaved, and a cache line written by both went back and
    //   forth between the cores;
    // - or, in a pool larger than the caches, one record in 16 is out of that order: the loop then read
    //   those records at random instead of one after the other (in the DEM8 drum, where contacts end as
    //   the bed loosens, a step took about 15 % longer after 1 000 steps; reordering its 80 000 records
    //   takes about a step's time, every 60-300 steps there).
    bool needsOrder() const {
        constexpr size_t cacheBytes = size_t(8) << 20; // (beyond it, a random read costs about 10x one within 4 MB here)
        return (count >= 1024 && 4 * appendsSinceOrder > count) || (count * stride > cacheBytes && 16 * (appendsSinceOrder + movesSinceOrder) > count);
    }
    // Slots of the contacts that ended while the loop ran (removed afterwards, InteractionContainer::sweep).
    std::vector<uint32_t> ended;
    void markEnded(size_t slot);
    // The Law2 functor for this pair of classes, valid while lawTable is the law dispatcher's
    // table generation (refreshed by the interaction loop before its parallel part).
    LawFunctor* law = nullptr;
    long long lawTable = -1;
    // Where the fields are in a record, for NumPy views: stride in bytes, offsets of the objects.
    size_t stride = 0, geomOffset = 0, physOffset = 0;
    // The NumPy views of the contacts (its InteractionContainer's): told when a record is appended,
    // removed or moved (null: nobody to tell).
    std::shared_ptr<ViewRegistry> views;

private:
    struct alignas(16) Block {
        char bytes[16];
    };
    StableArray<Block> memory;
    char* base = nullptr;
    size_t count = 0;
    std::mutex mutex; // appends and markEnded
    void construct(size_t slot, const IGeom& g, const IPhys& p);
    void destroy(size_t slot);
    void relocate(char* to, char* from); // a record's objects and header from one place to another
};

} // namespace yade
