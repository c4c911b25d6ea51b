#include <core/InteractionContainer.hpp>
#include <algorithm>
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
    Record& rec = records[r];
    rec = Record();
    recordOf[k] = noRecord;
    std::lock_guard<std::mutex> lock(recordsMutex);
    freeRecords.push_back(r);
}

const InteractionContainer::Ptr& InteractionContainer::operator[](size_t k) const {
    Record& rec = ensureRecord(k);
    if (!rec.object) {
        rec.object = std::make_shared<Interaction>(pairIds[2 * k], pairIds[2 * k + 1]);
        rec.object->geom = rec.geom;
        rec.object->phys = rec.phys;
        rec.object->iterMadeReal = rec.iterMadeReal;
        ++objectsMade;
    }
    return rec.object;
}

InteractionContainer::Ptr InteractionContainer::snapshot(size_t k) const {
    const Record* rec = record(k);
    if (rec && rec->object) return rec->object;
    auto I = std::make_shared<Interaction>(pairIds[2 * k], pairIds[2 * k + 1]);
    if (rec) {
        I->geom = rec->geom;
        I->phys = rec->phys;
        I->iterMadeReal = rec->iterMadeReal;
    }
    return I;
}

void InteractionContainer::setGeom(size_t k, std::shared_ptr<IGeom> g) {
    Record& rec = ensureRecord(k);
    if (rec.object) rec.object->geom = g;
    rec.geom = std::move(g);
    rec.law = nullptr;
}

void InteractionContainer::setPhys(size_t k, std::shared_ptr<IPhys> p, long long iter) {
    Record& rec = ensureRecord(k);
    if (rec.object) {
        rec.object->phys = p;
        rec.object->iterMadeReal = iter;
    }
    rec.phys = std::move(p);
    rec.iterMadeReal = iter;
    rec.law = nullptr;
}

void InteractionContainer::clearLaws() {
    for (Record& rec : records) rec.law = nullptr;
}

InteractionContainer::~InteractionContainer() {
    for (const Record& rec : records)
        if (rec.object) rec.object->erased = true;
}

bool InteractionContainer::append(id_t a, id_t b, Ptr I) {
    if (a < 0 || b < 0 || a == b) throw std::invalid_argument("interaction needs two distinct non-negative ids");
    if (I && I->erased) throw std::invalid_argument("this interaction was erased; make a new one");
    if (size() >= std::numeric_limits<uint32_t>::max() - 1) throw std::length_error("too many interactions");
    resizeBodies((size_t)std::max(a, b) + 1);
    if (findIndex(a, b) >= 0) return false;
    const uint32_t k = (uint32_t)size();
    wasReal.push_back(I && I->isReal());
    recordOf.push_back(noRecord);
    pairIds.push_back(a);
    pairIds.push_back(b);
    partners[a].push_back(Partner{b, k});
    partners[b].push_back(Partner{a, k});
    if (I) {
        ++objectsMade;
        prepareRecords();
        Record& rec = ensureRecord(k);
        rec.geom = I->geom;
        rec.phys = I->phys;
        rec.iterMadeReal = I->iterMadeReal;
        rec.object = std::move(I);
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

void InteractionContainer::eraseAt(size_t idx) {
    const id_t a = pairIds[2 * idx], b = pairIds[2 * idx + 1];
    if (Interaction* I = object(idx)) I->erased = true;
    freeRecord(idx);
    unlinkPartner(a, b);
    unlinkPartner(b, a);
    const size_t last = size() - 1;
    if (idx != last) { // the last entry fills the hole, with all its columns
        recordOf[idx] = recordOf[last];
        pairIds[2 * idx] = pairIds[2 * last];
        pairIds[2 * idx + 1] = pairIds[2 * last + 1];
        wasReal[idx] = wasReal[last];
        relinkPartner(pairIds[2 * idx], (uint32_t)last, (uint32_t)idx);
        relinkPartner(pairIds[2 * idx + 1], (uint32_t)last, (uint32_t)idx);
    }
    recordOf.pop_back();
    pairIds.resize(2 * last);
    wasReal.pop_back();
    ++changes;
}

void InteractionContainer::reserve(size_t n) {
    if (n <= size()) return;
    recordOf.reserve(n);
    pairIds.reserve(2 * n);
    wasReal.reserve(n);
}

void InteractionContainer::clear() {
    for (const Record& rec : records)
        if (rec.object) rec.object->erased = true;
    records.clear();
    records.shrink_to_fit();
    freeRecords.clear();
    recordOf.clear();
    pairIds.clear();
    wasReal.clear();
    for (auto& p : partners) p.clear();
    ++changes;
}

void InteractionContainer::endContact(size_t k) {
    Record* rec = record(k);
    if (!rec) return;
    if (rec->object && rec->object.use_count() > 1) { // (Python holds it: it stays, reset)
        rec->object->reset();
        rec->geom.reset();
        rec->phys.reset();
        rec->law = nullptr;
        rec->iterMadeReal = -1;
    } else freeRecord(k); // (its ids are in the columns)
}

void InteractionContainer::syncObjects() {
    for (size_t k = 0; k < size(); ++k) {
        Record* rec = record(k);
        if (!rec || !rec->object) continue;
        const Interaction& I = *rec->object;
        if (rec->geom != I.geom || rec->phys != I.phys) {
            rec->geom = I.geom;
            rec->phys = I.phys;
            rec->law = nullptr;
        }
        rec->iterMadeReal = I.iterMadeReal;
        releaseObject(k, rec->object.get());
    }
    objectsMade = 0;
}

void InteractionContainer::releaseObject(size_t k, const Interaction* which) {
    Record* rec = record(k);
    if (!rec || rec->object.get() != which || rec->object.use_count() > 1) return;
    rec->geom = rec->object->geom; // (what Python may have set)
    rec->phys = rec->object->phys;
    rec->law = nullptr;
    rec->object.reset();
    if (!rec->geom && !rec->phys) freeRecord(k);
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
    if (owner) owner->setGeom((size_t)k, std::move(g));
    else I->geom = std::move(g);
}

} // namespace yade
