#include <core/InteractionContainer.hpp>
#include <algorithm>
#include <functional>
#include <limits>
#include <stdexcept>

namespace yade {

const InteractionContainer::Ptr InteractionContainer::none;

long InteractionContainer::findIndex(id_t a, id_t b) const {
    if (a < 0 || b < 0 || (size_t)a >= partners.size() || (size_t)b >= partners.size()) return -1;
    const auto& pa = partners[a];
    const auto& pb = partners[b];
    const auto& shorter = pa.size() <= pb.size() ? pa : pb;
    const id_t other = pa.size() <= pb.size() ? b : a;
    for (const Partner& p : shorter)
        if (p.other == other) return (long)p.k;
    return -1;
}

const InteractionContainer::Ptr& InteractionContainer::find(id_t a, id_t b) const {
    const long k = findIndex(a, b);
    return k < 0 ? none : (*this)[(size_t)k];
}

// ---- records (pairs with an object or with geometry/physics outside a pool)

InteractionContainer::Record& InteractionContainer::ensureRecord(size_t k) const {
    if (recordOf[k] != noRecord) return records[recordOf[k]];
    std::lock_guard<std::mutex> lock(recordsMutex);
    uint32_t r;
    if (!freeRecords.empty()) {
        r = freeRecords.back();
        freeRecords.pop_back();
    } else {
        // (no reallocation in the interaction loop: prepareRecords() made room for a record per
        // pair, and a pair without record means that fewer are in use)
        r = (uint32_t)records.size();
        records.emplace_back();
    }
    recordOf[k] = r;
    return records[r];
}

void InteractionContainer::prepareRecords() {
    if (records.capacity() < size()) records.reserve(std::max(size(), 2 * records.capacity()));
}

void InteractionContainer::freeRecord(size_t k) {
    const uint32_t r = recordOf[k];
    if (r == noRecord) return;
    records[r] = Record();
    recordOf[k] = noRecord;
    std::lock_guard<std::mutex> lock(recordsMutex);
    freeRecords.push_back(r);
}

// ---- pools

ContactPool& InteractionContainer::poolFor(const IGeom& g, const IPhys& p, uint32_t& index) {
    std::lock_guard<std::mutex> lock(poolsMutex);
    for (size_t i = 0; i < nPools; ++i)
        if (pools[i]->geomClass.classIndex == g.getClassIndex() && pools[i]->physClass.classIndex == p.getClassIndex()) {
            index = (uint32_t)i;
            return *pools[i];
        }
    if (nPools == maxPools) throw std::length_error("more than " + std::to_string(maxPools) + " kinds of contacts (IGeom+IPhys class pairs) in one scene");
    const ClassRegistry& reg = ClassRegistry::instance();
    pools[nPools] = std::make_shared<ContactPool>(reg.get(typeid(g)), reg.get(typeid(p)));
    pools[nPools]->views = views;
    index = (uint32_t)nPools;
    return *pools[nPools++];
}

void InteractionContainer::makeViews(size_t k) {
    Record* rec = record(k);
    const uint32_t c = contactOf[k];
    if (!rec || !rec->object || c == noContact) return;
    Interaction& I = *rec->object;
    ContactPool& P = pool(c);
    const size_t s = slotOf(c);
    // (the object's own geom and phys become the views, unless they are another record's views)
    const auto usable = [](const auto& x, int classIndex, const void* target) {
        return x && x->getClassIndex() == classIndex && (!x->viewTarget() || x->viewTarget() == target);
    };
    rec->geom = usable(I.geom, P.geomClass.classIndex, P.geom(s)) ? I.geom : std::static_pointer_cast<IGeom>(P.geomClass.factory());
    rec->phys = usable(I.phys, P.physClass.classIndex, P.phys(s)) ? I.phys : std::static_pointer_cast<IPhys>(P.physClass.factory());
    I.geom = rec->geom;
    I.phys = rec->phys;
    I.iterMadeReal = P.header(s).iterMadeReal;
    pointViews(k);
}

void InteractionContainer::pointViews(size_t k) {
    Record* rec = record(k);
    const uint32_t c = contactOf[k];
    if (!rec || c == noContact) return;
    if (rec->geom) rec->geom->setViewTarget(pool(c).geom(slotOf(c)));
    if (rec->phys) rec->phys->setViewTarget(pool(c).phys(slotOf(c)));
}

void InteractionContainer::detachViews(size_t k) {
    Record* rec = record(k);
    const uint32_t c = contactOf[k];
    if (!rec || c == noContact) return;
    ContactPool& P = pool(c);
    const size_t s = slotOf(c);
    if (rec->geom && rec->geom->viewTarget() == P.geom(s)) P.geomClass.assign(*rec->geom, *P.geom(s)); // (the values; no target)
    if (rec->phys && rec->phys->viewTarget() == P.phys(s)) P.physClass.assign(*rec->phys, *P.phys(s));
    rec->geom.reset();
    rec->phys.reset();
}

void InteractionContainer::moved(ContactPool& P, uint32_t index, size_t slot) {
    const uint32_t k = P.header(slot).k;
    contactOf[k] = (index << slotBits) | (uint32_t)slot;
    pointViews(k);
}

void InteractionContainer::removeContact(size_t k) {
    const uint32_t c = contactOf[k];
    if (c == noContact) return;
    detachViews(k); // (the object keeps them: geom and phys with the last values)
    contactOf[k] = noContact;
    ContactPool& P = pool(c);
    if (P.removeAt(slotOf(c))) moved(P, poolOf(c), slotOf(c));
}

void InteractionContainer::makeContact(size_t k, const std::shared_ptr<IGeom>& g, const std::shared_ptr<IPhys>& p, long long iter) {
    uint32_t index;
    ContactPool& P = poolFor(*g, *p, index);
    const size_t s = P.append(ContactPool::Header{pairIds[2 * k], pairIds[2 * k + 1], (uint32_t)k, 0, iter}, *g, *p);
    if (s >= (size_t(1) << slotBits)) throw std::length_error("more than 2^26 contacts of one kind");
    contactOf[k] = (index << slotBits) | (uint32_t)s;
    if (recordOf[k] == noRecord) return;
    Record& rec = records[recordOf[k]];
    rec.geom.reset();
    rec.phys.reset();
    if (!rec.object) {
        freeRecord(k);
        return;
    }
    rec.object->geom = g; // (they become views of the record: Python may hold them)
    rec.object->phys = p;
    makeViews(k);
}

void InteractionContainer::restoreContact(const ContactPool::Header& h, const IGeom& g, const IPhys& p) {
    const size_t k = h.k;
    if (k >= size() || !((pairIds[2 * k] == h.id1 && pairIds[2 * k + 1] == h.id2) || (pairIds[2 * k] == h.id2 && pairIds[2 * k + 1] == h.id1)))
        throw std::invalid_argument("a contact names a pair that does not exist");
    if (contactOf[k] != noContact || recordOf[k] != noRecord) throw std::invalid_argument("the same contact appears twice");
    uint32_t index;
    ContactPool& P = poolFor(g, p, index);
    const size_t s = P.append(ContactPool::Header{h.id1, h.id2, (uint32_t)k, 0, h.iterMadeReal}, g, p);
    if (s >= (size_t(1) << slotBits)) throw std::length_error("more than 2^26 contacts of one kind");
    contactOf[k] = (index << slotBits) | (uint32_t)s;
    wasReal[k] = 1;
}

void InteractionContainer::restoreUnpooled(size_t k, Ptr I) {
    if (k >= size() || !I) throw std::invalid_argument("an interaction names a pair that does not exist");
    if (contactOf[k] != noContact || recordOf[k] != noRecord) throw std::invalid_argument("the same interaction appears twice");
    wasReal[k] = I->isReal();
    prepareRecords();
    Record& rec = ensureRecord(k);
    rec.geom = I->geom;
    rec.phys = I->phys;
    rec.object = std::move(I);
    ++objectsMade;
}

void InteractionContainer::keepGeom(size_t k, std::shared_ptr<IGeom> g) {
    Record& rec = ensureRecord(k);
    if (rec.object) rec.object->geom = g;
    rec.geom = std::move(g);
}

void InteractionContainer::endContact(size_t k) {
    const uint32_t c = contactOf[k];
    if (c != noContact) {
        detachViews(k); // (Python may hold them: they keep the last values)
        contactOf[k] = noContact;
        pool(c).markEnded(slotOf(c));
    }
    dropObjects(k);
}

void InteractionContainer::dropObjects(size_t k) {
    Record* rec = record(k);
    if (!rec) return;
    if (rec->object && rec->object.use_count() > 1) { // (Python holds it: it stays, reset)
        rec->object->reset();
        rec->geom.reset();
        rec->phys.reset();
    } else freeRecord(k); // (its ids are in the columns)
}

void InteractionContainer::sweep() {
    for (uint32_t index = 0; index < nPools; ++index) {
        ContactPool& P = *pools[index];
        if (P.ended.empty()) continue;
        std::sort(P.ended.begin(), P.ended.end(), std::greater<uint32_t>()); // (the last record is then never an ended one)
        for (const uint32_t s : P.ended)
            if (P.removeAt(s)) moved(P, index, s);
        P.ended.clear();
    }
}

void InteractionContainer::orderPools(const std::vector<std::vector<uint32_t>>& lists, bool onlyNeeded) {
    for (uint32_t index = 0; index < nPools; ++index) {
        ContactPool& P = *pools[index];
        if (P.size() == 0 || (onlyNeeded && !P.needsOrder())) continue;
        std::vector<uint32_t> to(P.size(), noContact);
        uint32_t next = 0;
        for (const auto& list : lists)
            for (const uint32_t k : list)
                if (contactOf[k] != noContact && poolOf(contactOf[k]) == index) to[slotOf(contactOf[k])] = next++;
        for (auto& t : to)
            if (t == noContact) t = next++; // (a pair in no list: after the others)
        P.permute(to);
        for (size_t slot = 0; slot < P.size(); ++slot) moved(P, index, slot);
    }
}

long long InteractionContainer::iterMadeReal(size_t k) const {
    if (contactOf[k] != noContact) return pool(contactOf[k]).header(slotOf(contactOf[k])).iterMadeReal;
    const Interaction* I = object(k);
    return I ? I->iterMadeReal : -1;
}

// ---- objects

const InteractionContainer::Ptr& InteractionContainer::operator[](size_t k) const {
    Record& rec = ensureRecord(k);
    if (!rec.object) {
        rec.object = std::make_shared<Interaction>(pairIds[2 * k], pairIds[2 * k + 1]);
        rec.object->iterBorn = iterBorn[k];
        if (periodic) rec.object->cellDist = cellDist[k];
        if (contactOf[k] != noContact) const_cast<InteractionContainer*>(this)->makeViews(k);
        else {
            rec.object->geom = rec.geom;
            rec.object->phys = rec.phys;
        }
        ++objectsMade;
    }
    return rec.object;
}

InteractionContainer::Ptr InteractionContainer::snapshot(size_t k) const {
    if (object(k)) return records[recordOf[k]].object;
    auto I = std::make_shared<Interaction>(pairIds[2 * k], pairIds[2 * k + 1]);
    I->iterBorn = iterBorn[k];
    if (periodic) I->cellDist = cellDist[k];
    if (contactOf[k] != noContact) {
        const ContactPool& P = pool(contactOf[k]);
        const size_t s = slotOf(contactOf[k]);
        I->geom = std::static_pointer_cast<IGeom>(P.geomClass.factory());
        P.geomClass.assign(*I->geom, *P.geom(s));
        I->phys = std::static_pointer_cast<IPhys>(P.physClass.factory());
        P.physClass.assign(*I->phys, *P.phys(s));
        I->iterMadeReal = P.header(s).iterMadeReal;
    } else if (const Record* rec = record(k)) {
        I->geom = rec->geom;
        I->phys = rec->phys;
    }
    return I;
}

void InteractionContainer::syncObjects() {
    for (size_t k = 0; k < size(); ++k) {
        if (recordOf[k] == noRecord) continue;
        Interaction* I = records[recordOf[k]].object.get();
        if (I && contactOf[k] != noContact) {
            const Record& rec = records[recordOf[k]];
            if (I->geom != rec.geom || I->phys != rec.phys) {
                // Python set geom or phys: the contact leaves the pool with what the object has now
                // (the views it had keep the values of the record)
                removeContact(k);
                Record& r = records[recordOf[k]];
                r.geom = I->geom;
                r.phys = I->phys;
            }
        } else if (I) {
            Record& rec = records[recordOf[k]];
            rec.geom = I->geom;
            rec.phys = I->phys;
        }
        Record& rec = records[recordOf[k]];
        if (contactOf[k] == noContact && rec.geom && rec.phys) { // a contact set from Python or read from a file
            const auto g = rec.geom;
            const auto p = rec.phys;
            makeContact(k, g, p, I ? I->iterMadeReal : -1);
        }
        if (I) releaseObject(k, I);
    }
    objectsMade = 0;
}

void InteractionContainer::releaseObject(size_t k, const Interaction* which) {
    Record* rec = record(k);
    if (!rec || rec->object.get() != which || rec->object.use_count() > 1) return;
    const Interaction& I = *rec->object;
    if (contactOf[k] != noContact) { // (its geom and phys are views, held by the object and the record)
        if (I.geom != rec->geom || I.phys != rec->phys || rec->geom.use_count() > 2 || rec->phys.use_count() > 2) return; // (Python holds a view, or set others)
        freeRecord(k);
        return;
    }
    if ((I.geom && I.geom.use_count() > 1) || (I.phys && I.phys.use_count() > 1)) return; // (Python holds them)
    rec->geom = I.geom; // (what Python may have set)
    rec->phys = I.phys;
    rec->object.reset();
    if (!rec->geom && !rec->phys) freeRecord(k);
}

// ---- pairs

InteractionContainer::~InteractionContainer() {
    views->invalidate();
    for (size_t k = 0; k < size(); ++k)
        if (Interaction* I = object(k)) {
            detachViews(k);
            I->erased = true;
        }
}

bool InteractionContainer::append(id_t a, id_t b, Ptr I) {
    if (a < 0 || b < 0 || a == b) throw std::invalid_argument("interaction needs two distinct non-negative ids");
    if (I && I->erased) throw std::invalid_argument("this interaction was erased; make a new one");
    if (size() >= std::numeric_limits<uint32_t>::max() - 1) throw std::length_error("too many interactions");
    resizeBodies((size_t)std::max(a, b) + 1);
    if (findIndex(a, b) >= 0) return false;
    const uint32_t k = (uint32_t)size();
    wasReal.push_back(I && I->isReal());
    iterBorn.push_back(I && I->iterBorn >= 0 ? I->iterBorn : iterNow);
    recordOf.push_back(noRecord);
    contactOf.push_back(noContact);
    pairIds.push_back(a);
    pairIds.push_back(b);
    if (periodic) cellDist.push_back(I ? I->cellDist : Vector3i::Zero());
    partners[a].push_back(Partner{b, k});
    partners[b].push_back(Partner{a, k});
    if (I) { // (its geom and phys join a pool at the next syncObjects())
        prepareRecords();
        Record& rec = ensureRecord(k);
        rec.geom = I->geom;
        rec.phys = I->phys;
        rec.object = std::move(I);
        ++objectsMade;
    }
    ++changes;
    return true;
}

bool InteractionContainer::insert(const Ptr& I) {
    if (!I) throw std::invalid_argument("None is not an interaction");
    return append(I->id1, I->id2, I);
}

bool InteractionContainer::insertPotential(id_t a, id_t b) { return append(a, b, nullptr); }

void InteractionContainer::unlinkPartner(id_t from, id_t other) {
    auto& list = partners[from];
    for (size_t i = 0; i < list.size(); ++i)
        if (list[i].other == other) {
            list[i] = list.back();
            list.pop_back();
            return;
        }
}

void InteractionContainer::relinkPartner(id_t from, uint32_t oldK, uint32_t newK) {
    for (Partner& p : partners[from])
        if (p.k == oldK) {
            p.k = newK;
            return;
        }
}

bool InteractionContainer::erase(id_t a, id_t b) {
    const long k = findIndex(a, b);
    if (k < 0) return false;
    eraseAt((size_t)k);
    return true;
}

bool InteractionContainer::makePotential(id_t a, id_t b) {
    const long k = findIndex(a, b);
    if (k < 0) return false;
    if (!isReal((size_t)k)) return true;
    removeContact((size_t)k); // (an object Python holds keeps the last values in its geom and phys)
    dropObjects((size_t)k);
    wasReal[k] = 0;
    ++changes;
    return true;
}

void InteractionContainer::eraseAt(size_t idx) {
    const id_t a = pairIds[2 * idx], b = pairIds[2 * idx + 1];
    removeContact(idx);
    if (Interaction* I = object(idx)) I->erased = true;
    freeRecord(idx);
    unlinkPartner(a, b);
    unlinkPartner(b, a);
    const size_t last = size() - 1;
    if (idx != last) { // the last entry fills the hole, with all its columns
        recordOf[idx] = recordOf[last];
        contactOf[idx] = contactOf[last];
        if (contactOf[idx] != noContact) pool(contactOf[idx]).header(slotOf(contactOf[idx])).k = (uint32_t)idx;
        pairIds[2 * idx] = pairIds[2 * last];
        pairIds[2 * idx + 1] = pairIds[2 * last + 1];
        wasReal[idx] = wasReal[last];
        iterBorn[idx] = iterBorn[last];
        if (periodic) cellDist[idx] = cellDist[last];
        relinkPartner(pairIds[2 * idx], (uint32_t)last, (uint32_t)idx);
        relinkPartner(pairIds[2 * idx + 1], (uint32_t)last, (uint32_t)idx);
    }
    recordOf.pop_back();
    contactOf.pop_back();
    pairIds.resize(2 * last);
    wasReal.pop_back();
    iterBorn.pop_back();
    if (periodic) cellDist.pop_back();
    ++changes;
}

void InteractionContainer::setPeriodic(bool p) {
    periodic = p;
    cellDist.assign(p ? size() : 0, Vector3i::Zero());
}

void InteractionContainer::reserve(size_t n) {
    if (n <= size()) return;
    recordOf.reserve(n);
    contactOf.reserve(n);
    pairIds.reserve(2 * n);
    wasReal.reserve(n);
    iterBorn.reserve(n);
    if (periodic) cellDist.reserve(n);
}

void InteractionContainer::reservePartners(const std::vector<uint32_t>& more) {
    resizeBodies(more.size());
    for (size_t id = 0; id < more.size(); ++id)
        if (more[id]) partners[id].reserve(partners[id].size() + more[id]);
}

void InteractionContainer::clear() {
    for (size_t k = 0; k < size(); ++k)
        if (Interaction* I = object(k)) {
            detachViews(k);
            I->erased = true;
        }
    views->invalidate();
    for (auto& P : pools) P.reset(); // (a NumPy view may keep one)
    nPools = 0;
    records.clear();
    records.shrink_to_fit();
    freeRecords.clear();
    recordOf.clear();
    contactOf.clear();
    pairIds.clear();
    wasReal.clear();
    iterBorn.clear();
    cellDist.clear();
    for (auto& p : partners) p.clear();
    ++changes;
}

size_t InteractionContainer::countReal() const {
    size_t n = 0;
    for (size_t k = 0; k < size(); ++k) n += isReal(k);
    return n;
}

std::vector<InteractionContainer::Ptr> InteractionContainer::withBody(id_t id) const {
    std::vector<Ptr> r;
    if (id < 0 || (size_t)id >= partners.size()) return r;
    for (const Partner& p : partners[id])
        if (isReal(p.k) || object(p.k)) r.push_back((*this)[p.k]);
    return r;
}

void InteractionContainer::eraseBody(id_t id) {
    if (id < 0 || (size_t)id >= partners.size()) return;
    while (!partners[id].empty()) eraseAt(partners[id].back().k);
}

Interaction& Contact::interaction() const { return I ? *I : *(*owner)[(size_t)k]; }

void Contact::setGeom(std::shared_ptr<IGeom> g) {
    geom = g.get();
    if (made) *made = std::move(g);
    else if (owner) owner->keepGeom((size_t)k, std::move(g));
    else I->geom = std::move(g);
}

} // namespace yade
