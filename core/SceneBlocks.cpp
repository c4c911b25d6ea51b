#include <core/SceneBlocks.hpp>
#include <lib/serialization/Columns.hpp>
#include <lib/serialization/Validate.hpp>
#include <unordered_map>

namespace yade {

namespace {

// A block: a 4-byte type, the payload's length (8 bytes), its CRC-32 (4 bytes), the payload.
constexpr uint32_t blockType(const char (&s)[5]) {
    return uint32_t((unsigned char)s[0]) | uint32_t((unsigned char)s[1]) << 8 | uint32_t((unsigned char)s[2]) << 16 | uint32_t((unsigned char)s[3]) << 24;
}
constexpr uint32_t HEAD = blockType("HEAD"), TABL = blockType("TABL"), ROWS = blockType("ROWS"), LIST = blockType("LIST"),
                   PAIR = blockType("PAIR"), POOL = blockType("POOL"), CONT = blockType("CONT"), PERM = blockType("PERM"),
                   END = blockType("END ");
constexpr size_t headerBytes = 16;
constexpr size_t rowsPerBlock = 4096, refsPerBlock = 65536, pairsPerBlock = 65536;
constexpr uint64_t maxBlockBytes = uint64_t(1) << 30;

// The lists of objects a scene holds, in the order they are written.
enum Section : uint8_t { materials, bodies, engines, miscParams, unpooled, cell, nSections };

std::string typeName(uint32_t t) {
    std::string s(4, ' ');
    for (int i = 0; i < 4; ++i) s[i] = char((t >> (8 * i)) & 0xff);
    return s;
}

// ------------------------------------------------------------------ writing

class Writer final : public RefWriter {
public:
    Writer(Scene& scene, ByteSink& sink) : s(scene), out(sink) {}

    void all() {
        out.write(SceneBlocks::magic, SceneBlocks::magicSize);
        head();
        // (objects first, shared ones numbered once: a material is written with O.materials, and the
        // bodies refer to it)
        std::vector<std::shared_ptr<Serializable>> roots(s.materials.begin(), s.materials.end());
        section(materials, roots);
        roots.assign(s.bodies.begin(), s.bodies.end());
        section(bodies, roots);
        roots.assign(s.getEngines().begin(), s.getEngines().end());
        section(engines, roots);
        roots.assign(s.miscParams.begin(), s.miscParams.end());
        section(miscParams, roots);
        section(unpooled, unpooledInteractions());
        if (s.isPeriodic) section(cell, {s.cell});
        pairs();
        contacts();
        permanentForces();
        block(END);
        out.close();
    }

private:
    Scene& s;
    ByteSink& out;
    std::string buf;
    Encoder e{buf};
    struct Table {
        const ClassInfo* cls;
        std::vector<const AttrInfo*> attrs;
        uint32_t numbered = 0, written = 0; // rows given to objects met, rows written
        bool announced = false;
    };
    std::vector<Table> tables;
    std::unordered_map<const ClassInfo*, uint32_t> tableOf;
    std::unordered_map<const Serializable*, ObjectRef> shared; // objects that more than one pointer holds
    std::vector<std::vector<std::shared_ptr<Serializable>>> pending; // per table: met, not yet written
    std::vector<char> leftPool;                                      // per pair: written as an object, not from its pool

    void block(uint32_t type) {
        char h[headerBytes];
        const uint64_t n = buf.size();
        const uint32_t crc = checksum(0, buf.data(), buf.size());
        std::memcpy(h, &type, 4);
        std::memcpy(h + 4, &n, 8);
        std::memcpy(h + 12, &crc, 4);
        out.write(h, headerBytes);
        out.write(buf.data(), buf.size());
        buf.clear();
    }

    ObjectRef ref(const std::shared_ptr<Serializable>& p, long extraOwners) override {
        if (!p) return nullRef;
        const auto it = shared.find(p.get());
        if (it != shared.end()) return it->second;
        const ClassInfo& info = ClassRegistry::instance().get(typeid(*p));
        auto t = tableOf.find(&info);
        if (t == tableOf.end()) {
            t = tableOf.emplace(&info, (uint32_t)tables.size()).first;
            tables.push_back(Table{&info, Columns::saved(info)});
            pending.emplace_back();
        }
        const ObjectRef r = (ObjectRef(t->second) << 32) | tables[t->second].numbered++;
        // (an object only this pointer holds cannot be met again: no need to remember it)
        if (p.use_count() > 1 + extraOwners) shared.emplace(p.get(), r);
        pending[t->second].push_back(p);
        return r;
    }

    void head() {
        e.size(SceneBlocks::formatVersion);
        e.put<int64_t>(s.iter);
        e.put<int64_t>(s.stopAtIter);
        e.put<Real>(s.stopAtTime);
        e.put<Real>(s.time);
        e.put<Real>(s.dt);
        e.put<uint8_t>(s.trackEnergy);
        e.put<int64_t>(s.bodies.changes);
        e.size(s.interactions.size());
        e.size(s.tags.size());
        for (const auto& kv : s.tags) {
            e.string(kv.first);
            e.string(kv.second);
        }
        const auto names = s.energy.names();
        const auto values = s.energy.values();
        const auto cumulative = s.energy.cumulativeFlags();
        e.size(names.size());
        for (size_t i = 0; i < names.size(); ++i) {
            e.string(names[i]);
            e.put<uint8_t>(cumulative[i]);
            e.put<Real>(values[i]);
        }
        e.put<uint8_t>(s.isPeriodic);
        block(HEAD);
    }

    // The roots of one list (null: None), then every object they lead to, table by table.
    void section(Section which, const std::vector<std::shared_ptr<Serializable>>& roots) {
        for (size_t i = 0; i < roots.size() || i == 0; i += refsPerBlock) { // (an empty list: one empty block)
            const size_t n = std::min(refsPerBlock, roots.size() - std::min(i, roots.size()));
            e.put<uint8_t>(which);
            e.size(n);
            for (size_t j = i; j < i + n; ++j) e.put<ObjectRef>(ref(roots[j], 1)); // (roots holds a copy)
            block(LIST);
        }
        // Objects are written after what refers to them: a parent's rows number its children, whose
        // rows come next (the reader sets the pointers once all are read).
        for (bool more = true; more;) {
            more = false;
            for (size_t t = 0; t < pending.size(); ++t) {
                if (pending[t].empty()) continue;
                more = true;
                const auto objects = std::move(pending[t]);
                pending[t].clear();
                rows((uint32_t)t, objects);
            }
        }
    }

    void rows(uint32_t t, const std::vector<std::shared_ptr<Serializable>>& objects) {
        if (!tables[t].announced) {
            e.size(t);
            e.string(tables[t].cls->name);
            Columns::writeSchema(e, tables[t].attrs);
            block(TABL);
            tables[t].announced = true;
        }
        const auto attrs = tables[t].attrs; // (tables grows as children are met)
        std::vector<Serializable*> ptrs;
        for (size_t i = 0; i < objects.size(); i += rowsPerBlock) {
            const size_t n = std::min(rowsPerBlock, objects.size() - i);
            ptrs.clear();
            for (size_t j = i; j < i + n; ++j) ptrs.push_back(objects[j].get());
            for (Serializable* o : ptrs) o->preSave();
            e.size(t);
            e.size(tables[t].written);
            e.size(n);
            for (const AttrInfo* a : attrs) Columns::write(e, *a, ptrs.data(), n, this);
            for (Serializable* o : ptrs) o->postSave();
            tables[t].written += (uint32_t)n;
            block(ROWS);
        }
    }

    // Pairs whose geometry or physics are outside a pool (a geometry before its physics), or whose
    // object Python gave others that the next step takes: written as Interaction objects (and marked
    // in leftPool, so that contacts() leaves their records out).
    std::vector<std::shared_ptr<Serializable>> unpooledInteractions() {
        const InteractionContainer& I = s.interactions;
        std::vector<std::shared_ptr<Serializable>> r;
        leftPool.assign(I.size(), 0);
        for (size_t k = 0; k < I.size(); ++k) {
            const InteractionContainer::Record* rec = I.record(k);
            if (!rec) continue;
            const Interaction* obj = rec->object.get();
            const bool pooled = I.contactOf[k] != InteractionContainer::noContact;
            const bool replaced = pooled && obj && (obj->geom != rec->geom || obj->phys != rec->phys);
            const bool outside = !pooled && ((obj && (obj->geom || obj->phys)) || rec->geom || rec->phys);
            if (!replaced && !outside) continue;
            leftPool[k] = replaced;
            r.push_back(I.snapshot(k));
        }
        return r;
    }

    void pairs() {
        const InteractionContainer& I = s.interactions;
        for (size_t k = 0; k < I.size(); k += pairsPerBlock) {
            const size_t n = std::min(pairsPerBlock, I.size() - k);
            e.size(k);
            e.size(n);
            std::vector<int32_t> ids(n);
            for (int side = 0; side < 2; ++side) {
                for (size_t i = 0; i < n; ++i) ids[i] = I.pairIds[2 * (k + i) + side];
                Columns::writeRaw(e, ids.data(), sizeof(int32_t), n);
            }
            Columns::writeRaw(e, &I.iterBorn[k], sizeof(int64_t), n);
            if (I.periodic) Columns::writeRaw(e, I.cellDist[k].data(), sizeof(Vector3i), n);
            block(PAIR);
        }
    }

    // (contacts hold no objects: a pointer attribute of an IGeom or IPhys would need its own table)
    struct NoObjects final : RefWriter {
        ObjectRef ref(const std::shared_ptr<Serializable>&, long) override {
            throw std::logic_error("saving a contact whose geometry or physics has an object attribute is not supported");
        }
    };

    void contacts() {
        const InteractionContainer& I = s.interactions;
        NoObjects noObjects;
        for (size_t i = 0; i < I.poolCount(); ++i) {
            const ContactPool* P = I.pools[i].get();
            if (!P || !P->size()) continue;
            const auto geomAttrs = Columns::saved(P->geomClass), physAttrs = Columns::saved(P->physClass);
            e.size(i);
            e.string(P->geomClass.name);
            e.string(P->physClass.name);
            Columns::writeSchema(e, geomAttrs);
            Columns::writeSchema(e, physAttrs);
            block(POOL);
            std::vector<size_t> slots;
            for (size_t slot = 0; slot < P->size(); ++slot)
                if (!leftPool[P->header(slot).k]) slots.push_back(slot);
            std::vector<Serializable*> geoms, physs;
            std::vector<int32_t> id1, id2;
            std::vector<uint32_t> ks;
            std::vector<int64_t> made;
            for (size_t j = 0; j < slots.size(); j += rowsPerBlock) {
                const size_t n = std::min(rowsPerBlock, slots.size() - j);
                geoms.clear(), physs.clear(), id1.clear(), id2.clear(), ks.clear(), made.clear();
                for (size_t r = j; r < j + n; ++r) {
                    const ContactPool::Header& h = P->header(slots[r]);
                    geoms.push_back(P->geom(slots[r]));
                    physs.push_back(P->phys(slots[r]));
                    id1.push_back(h.id1), id2.push_back(h.id2), ks.push_back(h.k), made.push_back(h.iterMadeReal);
                }
                e.size(i);
                e.size(n);
                Columns::writeRaw(e, id1.data(), sizeof(int32_t), n);
                Columns::writeRaw(e, id2.data(), sizeof(int32_t), n);
                Columns::writeRaw(e, ks.data(), sizeof(uint32_t), n);
                Columns::writeRaw(e, made.data(), sizeof(int64_t), n);
                for (const AttrInfo* a : geomAttrs) Columns::write(e, *a, geoms.data(), n, &noObjects);
                for (const AttrInfo* a : physAttrs) Columns::write(e, *a, physs.data(), n, &noObjects);
                block(CONT);
            }
        }
    }

    void permanentForces() {
        std::vector<uint32_t> ids;
        for (size_t i = 0; s.forces.hasPermanent() && i < s.forces.size(); ++i)
            if (s.forces.getPermForce((int)i) != Vector3r::Zero() || s.forces.getPermTorque((int)i) != Vector3r::Zero()) ids.push_back((uint32_t)i);
        e.size(ids.size());
        for (uint32_t id : ids) {
            e.put<uint32_t>(id);
            e.bytes(s.forces.getPermForce((int)id).data(), 3 * sizeof(Real));
            e.bytes(s.forces.getPermTorque((int)id).data(), 3 * sizeof(Real));
        }
        block(PERM);
    }
};

// ------------------------------------------------------------------ reading

class Reader final : public RefReader {
public:
    explicit Reader(ByteSource& source) : in(source) {}

    std::shared_ptr<Scene> all() {
        if (!next() || type != HEAD) throw FormatError("corrupt file (the first block is not the scene's head)");
        head();
        while (next()) {
            Cursor c{buf.data(), buf.data() + buf.size(), what.c_str()};
            if (type == TABL || type == ROWS || type == LIST) {
                if (objectsDone) c.fail("objects after the contacts");
                if (type == TABL) table(c);
                else if (type == ROWS) rows(c);
                else list(c);
            } else {
                if (!objectsDone) finishObjects();
                if (type == PAIR) pairs(c);
                else if (type == POOL) pool(c);
                else if (type == CONT) contacts(c);
                else if (type == PERM) permanentForces(c);
                else c.fail("unknown block type '" + FormatError::printable(typeName(type)) + "'");
            }
            if (!c.atEnd()) c.fail("extra bytes at the end of the block");
        }
        if (!objectsDone) finishObjects();
        for (auto& I : unpooledObjects) {
            const long k = s->interactions.findIndex(I->id1, I->id2);
            if (k < 0) throw FormatError("an interaction refers to a pair that does not exist");
            s->interactions.restoreUnpooled((size_t)k, I);
        }
        char extra;
        if (in.read(&extra, 1)) throw FormatError("corrupt file (extra bytes after the scene)");
        s->interactions.changes = 0; // (a scene just loaded: see InteractionContainer::changes)
        return s;
    }

private:
    ByteSource& in;
    std::string buf, what;
    uint32_t type = 0;
    size_t blockCount = 0;
    uint64_t bytesRead = 0;
    std::shared_ptr<Scene> s = std::make_shared<Scene>();
    uint64_t declaredPairs = 0;

    struct Table {
        const ClassInfo* cls;
        std::vector<const AttrInfo*> attrs;
        std::vector<std::shared_ptr<Serializable>> objects;
    };
    std::vector<Table> tables;
    std::vector<Serializable*> created; // in the order read: postLoad runs in reverse (children first)
    size_t objectCount = 0;
    struct Fixup {
        void* member;
        const AttrInfo* attr;
        ObjectRef ref;
    };
    struct ListFixup {
        void* member;
        const AttrInfo* attr;
        std::vector<ObjectRef> refs;
    };
    std::vector<Fixup> fixups;
    std::vector<ListFixup> listFixups;
    std::vector<ObjectRef> lists[nSections];
    bool objectsDone = false;
    std::vector<std::shared_ptr<Interaction>> unpooledObjects;
    struct PoolSchema {
        const ClassInfo *geom, *phys;
        std::vector<const AttrInfo*> geomAttrs, physAttrs;
        std::shared_ptr<Serializable> geomDefault, physDefault;
        std::vector<std::shared_ptr<Serializable>> geoms, physs; // rowsPerBlock objects, reset per block
    };
    std::unordered_map<uint64_t, PoolSchema> poolSchemas;

    // The next block into buf (false at the end block); checks its length and checksum.
    bool next() {
        char h[headerBytes];
        what = "block " + std::to_string(blockCount);
        const size_t got = in.read(h, headerBytes);
        if (got != headerBytes) throw FormatError("truncated file (ends in " + what + ", after " + std::to_string(bytesRead) + " bytes)");
        bytesRead += got;
        uint64_t n;
        uint32_t crc;
        std::memcpy(&type, h, 4);
        std::memcpy(&n, h + 4, 8);
        std::memcpy(&crc, h + 12, 4);
        what += " (" + FormatError::printable(typeName(type)) + ")";
        if (n > maxBlockBytes) throw FormatError("corrupt file (" + what + " claims " + std::to_string(n) + " bytes)");
        buf.clear();
        // (read as it comes: a damaged length cannot make it allocate more than the file holds)
        constexpr size_t chunk = size_t(1) << 24;
        while (buf.size() < n) {
            const size_t want = (size_t)std::min<uint64_t>(chunk, n - buf.size()), at = buf.size();
            buf.resize(at + want);
            const size_t r = in.read(&buf[at], want);
            bytesRead += r;
            if (r != want) throw FormatError("truncated file (ends in " + what + ", after " + std::to_string(bytesRead) + " bytes)");
        }
        if (checksum(0, buf.data(), buf.size()) != crc) throw FormatError("corrupt file (" + what + ": wrong checksum)");
        ++blockCount;
        if (type == END) {
            if (n) throw FormatError("corrupt file (" + what + " is not empty)");
            return false;
        }
        return true;
    }

    void head() {
        Cursor c{buf.data(), buf.data() + buf.size(), what.c_str()};
        const uint64_t version = c.size();
        if (version > (uint64_t)SceneBlocks::formatVersion)
            throw FormatError("the file was written in format version " + std::to_string(version) + " by a newer build; this build reads up to version "
                    + std::to_string(SceneBlocks::formatVersion));
        if (version < 2) throw FormatError("invalid format version " + std::to_string(version));
        s->iter = c.get<int64_t>();
        s->stopAtIter = c.get<int64_t>();
        s->stopAtTime = c.get<Real>();
        s->time = c.get<Real>();
        s->setDt(c.get<Real>());
        s->trackEnergy = c.get<uint8_t>() != 0;
        s->bodies.changes = c.get<int64_t>();
        declaredPairs = c.size();
        s->tags.clear();
        for (uint64_t i = 0, n = c.count(2); i < n; ++i) {
            const std::string key = Validate::utf8(c.string(), "a tag");
            s->tags[key] = Validate::utf8(c.string(), "a tag");
        }
        for (uint64_t i = 0, n = c.count(10); i < n; ++i) {
            const std::string name = Validate::utf8(c.string(), "an energy term");
            const bool cumulative = c.get<uint8_t>() != 0;
            s->energy.set(name, c.get<Real>(), cumulative);
        }
        if (version >= 3) s->setPeriodic(c.get<uint8_t>() != 0);
        if (!c.atEnd()) c.fail("extra bytes at the end of the block");
    }

    void table(Cursor& c) {
        const uint64_t key = c.size();
        if (key != tables.size()) c.fail("tables out of order");
        const std::string name = c.string();
        const ClassInfo* cls = ClassRegistry::instance().find(name);
        if (!cls || !cls->factory) throw FormatError("unknown class '" + name + "'");
        tables.push_back(Table{cls, Columns::readSchema(c, *cls), {}});
    }

    void rows(Cursor& c) {
        const uint64_t key = c.size(), first = c.size(), n = c.size();
        if (key >= tables.size()) c.fail("rows of a table not announced");
        Table& T = tables[key];
        if (first != T.objects.size()) c.fail("rows out of order");
        if (n == 0 || n > rowsPerBlock) c.fail("a bad row count");
        // (a row of a table whose columns all hold one value takes no bytes: the count of objects
        // is bounded by the bytes read, so that a damaged file cannot make it allocate without end)
        objectCount += n;
        if (objectCount > 4 * bytesRead + (1u << 20)) c.fail("more objects than the file's size allows");
        std::vector<Serializable*> ptrs;
        for (uint64_t i = 0; i < n; ++i) {
            T.objects.push_back(T.cls->factory());
            ptrs.push_back(T.objects.back().get());
            created.push_back(ptrs.back());
        }
        for (const AttrInfo* a : T.attrs) Columns::read(c, *a, ptrs.data(), n, this, T.cls->name);
    }

    void list(Cursor& c) {
        const unsigned which = c.get<uint8_t>();
        if (which >= nSections) c.fail("an unknown list");
        const uint64_t n = c.count(sizeof(ObjectRef));
        for (uint64_t i = 0; i < n; ++i) lists[which].push_back(c.get<ObjectRef>());
    }

    Serializable* checkRef(ObjectRef r, const std::string& where) const {
        const uint64_t t = uint64_t(r) >> 32, row = uint64_t(r) & 0xffffffffu;
        if (r < 0 || t >= tables.size() || row >= tables[t].objects.size()) throw FormatError(where + ": a reference to an object the file does not hold");
        return tables[t].objects[row].get();
    }
    std::shared_ptr<Serializable> object(ObjectRef r, const std::string& where) const {
        if (r == nullRef) return nullptr;
        checkRef(r, where);
        return tables[uint64_t(r) >> 32].objects[uint64_t(r) & 0xffffffffu];
    }

    void bind(void* member, const AttrInfo& a, ObjectRef r, const std::string& where) override {
        if (objectsDone || r == nullRef) {
            if (!a.setPtr(member, object(r, where))) throw FormatError(where + ": object of the wrong class");
        } else fixups.push_back(Fixup{member, &a, r});
    }
    void bindList(void* member, const AttrInfo& a, std::vector<ObjectRef> refs, const std::string& where) override {
        if (objectsDone) setList(member, a, refs, where);
        else listFixups.push_back(ListFixup{member, &a, std::move(refs)});
    }
    void setList(void* member, const AttrInfo& a, const std::vector<ObjectRef>& refs, const std::string& where) const {
        std::vector<std::shared_ptr<Serializable>> xs;
        for (ObjectRef r : refs) xs.push_back(object(r, where));
        if (!a.setPtrVector(member, xs)) throw FormatError(where + ": object of the wrong class in the list");
    }

    template <class T> std::vector<std::shared_ptr<T>> listOf(Section which, const char* what, bool noneAllowed) const {
        std::vector<std::shared_ptr<T>> r;
        for (ObjectRef ref : lists[which]) {
            auto obj = object(ref, std::string("the list of ") + sectionName(which));
            auto t = std::dynamic_pointer_cast<T>(obj);
            if (obj && !t) throw FormatError(std::string("expected ") + what + ", found " + obj->getClassName());
            if (!t && !noneAllowed) throw FormatError(std::string("None in the list of ") + sectionName(which));
            r.push_back(t);
        }
        return r;
    }
    static const char* sectionName(Section which) {
        static const char* names[nSections] = {"materials", "bodies", "engines", "O.miscParams", "interactions", "O.cell"};
        return names[which];
    }

    // All objects are read: pointers set, postLoad (children before parents), the lists into the scene.
    void finishObjects() {
        for (const Fixup& f : fixups)
            if (!f.attr->setPtr(f.member, object(f.ref, f.attr->name))) throw FormatError(f.attr->name + ": object of the wrong class");
        for (const ListFixup& f : listFixups) setList(f.member, *f.attr, f.refs, f.attr->name);
        fixups = {};
        listFixups = {};
        for (auto it = created.rbegin(); it != created.rend(); ++it) (*it)->postLoad();
        created = {};
        s->materials = listOf<Material>(materials, "a Material", false);
        try {
            s->bodies.restore(listOf<Body>(bodies, "a Body", true), s->bodies.changes);
        } catch (std::invalid_argument& e) {
            throw FormatError(std::string("inconsistent bodies: ") + e.what());
        }
        s->interactions.resizeBodies(s->bodies.size());
        s->forces.resize(s->bodies.size());
        s->setEngines(listOf<Engine>(engines, "an Engine", false));
        s->miscParams = listOf<Serializable>(miscParams, "an object", false);
        unpooledObjects = listOf<Interaction>(unpooled, "an Interaction", false);
        const auto cells = listOf<Cell>(cell, "a Cell", false);
        if (cells.size() > 1) throw FormatError("more than one O.cell");
        if (!cells.empty()) {
            try {
                cells[0]->check();
            } catch (const std::invalid_argument& e) {
                throw FormatError(e.what());
            }
            s->cell = cells[0];
        }
        tables = {};
        for (auto& l : lists) l = {};
        objectsDone = true;
        s->interactions.reserve((size_t)std::min<uint64_t>(declaredPairs, uint64_t(1) << 26));
    }

    void pairs(Cursor& c) {
        InteractionContainer& I = s->interactions;
        const uint64_t first = c.size(), n = c.size();
        if (first != I.size()) c.fail("pairs out of order");
        if (n > pairsPerBlock) c.fail("a bad pair count");
        const auto id1 = Columns::readRaw(c, sizeof(int32_t), n), id2 = Columns::readRaw(c, sizeof(int32_t), n);
        const auto born = Columns::readRaw(c, sizeof(int64_t), n);
        const auto shifts = I.periodic ? Columns::readRaw(c, sizeof(Vector3i), n) : decltype(born){nullptr, 0};
        for (uint64_t i = 0; i < n; ++i) {
            int32_t a, b;
            int64_t iterBorn;
            std::memcpy(&a, id1.first + i * id1.second, 4);
            std::memcpy(&b, id2.first + i * id2.second, 4);
            std::memcpy(&iterBorn, born.first + i * born.second, 8);
            if (!s->bodies.exists(a) || !s->bodies.exists(b) || a == b) throw FormatError("an interaction refers to a body that does not exist");
            if (!I.insertPotential(a, b)) throw FormatError("the same interaction appears twice");
            I.iterBorn.back() = iterBorn;
            if (I.periodic) std::memcpy(I.cellDist.back().data(), shifts.first + i * shifts.second, sizeof(Vector3i));
        }
    }

    void pool(Cursor& c) {
        const uint64_t key = c.size();
        const std::string geomName = c.string(), physName = c.string();
        const ClassRegistry& reg = ClassRegistry::instance();
        const ClassInfo *g = reg.find(geomName), *p = reg.find(physName);
        if (!g || !g->factory) throw FormatError("unknown class '" + geomName + "'");
        if (!p || !p->factory) throw FormatError("unknown class '" + physName + "'");
        PoolSchema P{g, p, Columns::readSchema(c, *g), Columns::readSchema(c, *p), g->factory(), p->factory(), {}, {}};
        if (!dynamic_cast<IGeom*>(P.geomDefault.get())) throw FormatError("expected an IGeom, found " + geomName);
        if (!dynamic_cast<IPhys*>(P.physDefault.get())) throw FormatError("expected an IPhys, found " + physName);
        if (!poolSchemas.emplace(key, std::move(P)).second) c.fail("the same pool twice");
    }

    void contacts(Cursor& c) {
        const uint64_t key = c.size(), n = c.size();
        auto it = poolSchemas.find(key);
        if (it == poolSchemas.end()) c.fail("contacts of a pool not announced");
        if (n == 0 || n > rowsPerBlock) c.fail("a bad row count");
        PoolSchema& P = it->second;
        while (P.geoms.size() < n) P.geoms.push_back(P.geom->factory()), P.physs.push_back(P.phys->factory());
        std::vector<Serializable*> geoms(n), physs(n);
        for (uint64_t i = 0; i < n; ++i) { // (fresh values: those the flags accept as defaults)
            P.geom->assign(*P.geoms[i], *P.geomDefault);
            P.phys->assign(*P.physs[i], *P.physDefault);
            geoms[i] = P.geoms[i].get();
            physs[i] = P.physs[i].get();
        }
        const auto id1 = Columns::readRaw(c, sizeof(int32_t), n), id2 = Columns::readRaw(c, sizeof(int32_t), n);
        const auto ks = Columns::readRaw(c, sizeof(uint32_t), n), made = Columns::readRaw(c, sizeof(int64_t), n);
        for (const AttrInfo* a : P.geomAttrs) Columns::read(c, *a, geoms.data(), n, this, P.geom->name);
        for (const AttrInfo* a : P.physAttrs) Columns::read(c, *a, physs.data(), n, this, P.phys->name);
        for (uint64_t i = 0; i < n; ++i) {
            ContactPool::Header h{};
            uint32_t k;
            std::memcpy(&h.id1, id1.first + i * id1.second, 4);
            std::memcpy(&h.id2, id2.first + i * id2.second, 4);
            std::memcpy(&k, ks.first + i * ks.second, 4);
            std::memcpy(&h.iterMadeReal, made.first + i * made.second, 8);
            h.k = k;
            geoms[i]->postLoad();
            physs[i]->postLoad();
            try {
                s->interactions.restoreContact(h, static_cast<IGeom&>(*geoms[i]), static_cast<IPhys&>(*physs[i]));
            } catch (std::invalid_argument& e) {
                throw FormatError(std::string("inconsistent contacts: ") + e.what());
            }
        }
    }

    void permanentForces(Cursor& c) {
        for (uint64_t i = 0, n = c.count(4 + 6 * sizeof(Real)); i < n; ++i) {
            const uint32_t id = c.get<uint32_t>();
            if (id >= s->bodies.size()) throw FormatError("a permanent force refers to a body that does not exist");
            Vector3r f, t;
            std::memcpy(f.data(), c.bytes(3 * sizeof(Real)), 3 * sizeof(Real));
            std::memcpy(t.data(), c.bytes(3 * sizeof(Real)), 3 * sizeof(Real));
            s->forces.setPermForce((int)id, f);
            s->forces.setPermTorque((int)id, t);
        }
    }
};

} // namespace

void SceneBlocks::write(Scene& scene, ByteSink& out) { Writer(scene, out).all(); }

std::shared_ptr<Scene> SceneBlocks::read(ByteSource& in) { return Reader(in).all(); }

} // namespace yade
