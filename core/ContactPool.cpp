#include <core/ContactPool.hpp>
#include <algorithm>
#include <stdexcept>

namespace yade {

static size_t roundUp(size_t n, size_t to) { return (n + to - 1) / to * to; }

// Address space for 4 GiB of records per pool (about 16 million contacts of sphere-sphere size),
// made memory as it is used; halved where the address space is limited (StableArray).
static constexpr size_t poolBlocks = size_t(1) << 28;

ContactPool::ContactPool(const ClassInfo& geom, const ClassInfo& phys) : geomClass(geom), physClass(phys), memory(poolBlocks) {
    if (!geom.copyAt || !geom.assign || !phys.copyAt || !phys.assign)
        throw std::logic_error("ContactPool: " + geom.name + " and " + phys.name + " must be copyable");
    if (geom.align > 16 || phys.align > 16) throw std::logic_error("ContactPool: alignment above 16 bytes");
    geomOffset = roundUp(sizeof(Header), geom.align);
    physOffset = roundUp(geomOffset + geom.size, phys.align);
    stride = roundUp(physOffset + phys.size, std::max<size_t>({alignof(Header), geom.align, phys.align}));
    base = reinterpret_cast<char*>(memory.data());
}

ContactPool::~ContactPool() {
    for (size_t s = 0; s < count; ++s) destroy(s);
}

void ContactPool::construct(size_t slot, const IGeom& g, const IPhys& p) {
    const IGeom& gv = g.viewTarget() ? static_cast<const IGeom&>(*g.viewTarget()) : g;
    const IPhys& pv = p.viewTarget() ? static_cast<const IPhys&>(*p.viewTarget()) : p;
    Serializable* go = geomClass.copyAt(record(slot) + geomOffset, gv);
    Serializable* po = physClass.copyAt(record(slot) + physOffset, pv);
    // (the records are reached by address: the bases must be where the objects start)
    if (static_cast<IGeom*>(go) != geom(slot) || static_cast<IPhys*>(po) != phys(slot))
        throw std::logic_error("ContactPool: " + geomClass.name + " or " + physClass.name + " does not start with its base class");
    geom(slot)->setViewTarget(nullptr);
    phys(slot)->setViewTarget(nullptr);
}

void ContactPool::destroy(size_t slot) {
    geom(slot)->~IGeom();
    phys(slot)->~IPhys();
}

size_t ContactPool::append(const Header& h, const IGeom& g, const IPhys& p) {
    if (g.getClassIndex() != geomClass.classIndex || p.getClassIndex() != physClass.classIndex)
        throw std::logic_error("ContactPool of " + geomClass.name + "+" + physClass.name + " given " + g.getClassName() + "+" + p.getClassName());
    if (views) views->invalidate();
    size_t slot;
    {
        std::lock_guard<std::mutex> lock(mutex);
        slot = count;
        memory.resize(((slot + 1) * stride + sizeof(Block) - 1) / sizeof(Block));
        ++count; // (the record is built below, outside the lock: nobody else reads it yet)
        ++appendsSinceOrder;
    }
    header(slot) = h;
    construct(slot, g, p);
    return slot;
}

void ContactPool::markEnded(size_t slot) {
    header(slot).ended = 1;
    std::lock_guard<std::mutex> lock(mutex);
    ended.push_back((uint32_t)slot);
}

void ContactPool::relocate(char* to, char* from) {
    *reinterpret_cast<Header*>(to) = *reinterpret_cast<Header*>(from);
    IGeom* g = reinterpret_cast<IGeom*>(from + geomOffset);
    IPhys* p = reinterpret_cast<IPhys*>(from + physOffset);
    geomClass.copyAt(to + geomOffset, *g);
    physClass.copyAt(to + physOffset, *p);
    g->~IGeom();
    p->~IPhys();
}

void ContactPool::permute(const std::vector<uint32_t>& to) {
    if (to.size() != count) throw std::logic_error("ContactPool::permute: wrong size");
    if (views) views->invalidate();
    std::vector<uint32_t> from(count);
    for (size_t s = 0; s < count; ++s) from[to[s]] = (uint32_t)s;
    std::vector<Block> spare(stride / sizeof(Block) + 1); // (one record, while a cycle moves)
    char* tmp = reinterpret_cast<char*>(spare.data());
    std::vector<char> done(count, 0);
    for (size_t s = 0; s < count; ++s) { // each cycle of the permutation, through one spare record
        if (done[s] || from[s] == s) continue;
        relocate(tmp, record(s));
        size_t j = s;
        for (;;) {
            done[j] = 1;
            const size_t i = from[j]; // the record that goes to slot j
            if (i == s) {
                relocate(record(j), tmp);
                break;
            }
            relocate(record(j), record(i));
            j = i;
        }
    }
    appendsSinceOrder = movesSinceOrder = 0;
}

bool ContactPool::removeAt(size_t slot) {
    if (views) views->invalidate();
    const size_t last = count - 1;
    destroy(slot);
    if (slot != last) {
        header(slot) = header(last);
        construct(slot, *geom(last), *phys(last));
        destroy(last);
        ++movesSinceOrder;
    }
    --count;
    return slot != last;
}

} // namespace yade
