#include <core/SceneBlocks.hpp>
#include <core/SceneIO.hpp>
#include <lib/serialization/Validate.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <charconv>
#include <limits>
#include <set>
#include <sstream>
#include <system_error>
#include <unordered_map>

namespace yade {

namespace {

using Validate::checkFlags;
using Validate::fmt;
using Validate::utf8;

Real parseReal(const std::string& s) {
    char* end = nullptr;
    const Real x = std::strtod(s.c_str(), &end);
    while (end && std::isspace(static_cast<unsigned char>(*end))) ++end;
    if (end == s.c_str() || *end != '\0') throw FormatError("expected a number, found '" + s.substr(0, 40) + "'");
    return x;
}

long long parseInt(const std::string& s) {
    const Real x = parseReal(s);
    if (x != std::floor(x) || std::abs(x) > 9e15) throw FormatError("expected an integer, found '" + s.substr(0, 40) + "'");
    return (long long)x;
}

// A number read for an int attribute (or a component of one): integral and in the range of an int,
// as the Python setters require (a cast of anything else would be undefined).
int toInt(Real x, const std::string& where) {
    if (!(x == std::floor(x) && x >= std::numeric_limits<int>::min() && x <= std::numeric_limits<int>::max()))
        throw FormatError(where + ": expected a 32-bit integer, found " + fmt(x));
    return (int)x;
}

// Whitespace-separated numbers of a text field, exactly n of them (n < 0: any count); each token must
// be a whole number ("0.05xyz" is refused).
std::vector<Real> numbers(const std::string& text, long n, const std::string& what) {
    std::vector<Real> r;
    if (n > 0) r.reserve(n);
    const char* p = text.c_str();
    for (;;) {
        while (std::isspace(static_cast<unsigned char>(*p))) ++p;
        if (!*p) break;
        char* end = nullptr;
        const Real x = std::strtod(p, &end);
        if (end == p || (*end && !std::isspace(static_cast<unsigned char>(*end)))) {
            const char* stop = p;
            while (*stop && !std::isspace(static_cast<unsigned char>(*stop))) ++stop;
            throw FormatError("expected a number, found '" + std::string(p, stop).substr(0, 40) + "'");
        }
        r.push_back(x);
        p = end;
    }
    if (n >= 0 && (long)r.size() != n)
        throw FormatError(what + ": expected " + std::to_string(n) + " numbers, found " + std::to_string(r.size()));
    return r;
}

// Writes the objects of a scene as XML text (doc/file-format.md, "XML encoding"), straight into a
// buffer that goes to the sink every megabyte: no tree of the whole scene. Objects more than one
// pointer holds are numbered, marked shared="1" and written once (then <ref id="N"/>); the others
// cannot be met twice and are not remembered.
class XmlWriter {
public:
    explicit XmlWriter(ByteSink& sink) : out(sink) {}
    std::string buf;

    void flushIfFull() {
        if (buf.size() < (size_t(1) << 20)) return;
        out.write(buf.data(), buf.size());
        buf.clear();
    }
    void finish() {
        out.write(buf.data(), buf.size());
        buf.clear();
        out.close();
    }
    void indent(int depth) { buf.append(depth, ' '); }
    void text(const std::string& s) {
        for (char c : s) switch (c) {
                case '<': buf += "&lt;"; break;
                case '>': buf += "&gt;"; break;
                case '&': buf += "&amp;"; break;
                case '"': buf += "&quot;"; break;
                default: buf += c;
            }
    }
    // The shortest text that reads back to the same bits (nan, inf, -inf as such).
    void number(Real x) {
        char b[32];
        buf.append(b, std::to_chars(b, b + sizeof b, x).ptr);
    }
    void numbers(const Real* x, int n) {
        for (int i = 0; i < n; ++i) {
            if (i) buf += ' ';
            number(x[i]);
        }
    }
    template <class I> void integer(I x) {
        char b[24];
        buf.append(b, std::to_chars(b, b + sizeof b, x).ptr);
    }
    void open(const char* tag, int depth) {
        indent(depth);
        buf += '<';
        buf += tag;
        buf += ">\n";
    }
    void close(const char* tag, int depth) {
        indent(depth);
        buf += "</";
        buf += tag;
        buf += ">\n";
    }

    // extraOwners: pointers to obj the caller holds as copies (they do not make it shared).
    void object(const std::shared_ptr<Serializable>& obj, long extraOwners, int depth) {
        indent(depth);
        if (!obj) {
            buf += "<null/>\n";
            return;
        }
        const auto it = shared.find(obj.get());
        if (it != shared.end()) {
            buf += "<ref id=\"";
            integer(it->second);
            buf += "\"/>\n";
            return;
        }
        const long id = nextId++;
        const bool isShared = obj.use_count() > 1 + extraOwners;
        if (isShared) shared.emplace(obj.get(), id);
        obj->preSave();
        const ClassInfo& info = ClassRegistry::instance().get(typeid(*obj));
        buf += "<obj class=\"";
        buf += info.name;
        buf += "\" id=\"";
        integer(id);
        buf += isShared ? "\" shared=\"1\">\n" : "\">\n";
        for (const AttrInfo& a : info.attrs) {
            if (a.has(Attr::noSave)) continue;
            indent(depth + 1);
            buf += "<a name=\"";
            buf += a.name;
            buf += '"';
            value(a, const_cast<void*>(a.peek(*obj)), depth + 1);
        }
        obj->postSave();
        close("obj", depth);
    }

private:
    ByteSink& out;
    std::unordered_map<const Serializable*, long> shared;
    long nextId = 0;

    // The rest of <a name="..." : ">text</a>", "/>" when empty, or children.
    void value(const AttrInfo& a, void* p, int depth) {
        if ((a.kind == AttrKind::StringVector && static_cast<std::vector<std::string>*>(p)->empty())
                || (a.kind == AttrKind::PtrVector && a.getPtrVector(p).empty())) {
            buf += "/>\n";
            return;
        }
        const size_t start = buf.size();
        buf += '>';
        const size_t content = buf.size();
        switch (a.kind) {
            case AttrKind::Bool: buf += *static_cast<bool*>(p) ? '1' : '0'; break;
            case AttrKind::Int: integer(*static_cast<int*>(p)); break;
            case AttrKind::Long: integer(*static_cast<long long*>(p)); break;
            case AttrKind::Real: number(*static_cast<Real*>(p)); break;
            case AttrKind::String: text(*static_cast<std::string*>(p)); break;
            case AttrKind::Vector2r: numbers(static_cast<Vector2r*>(p)->data(), 2); break;
            case AttrKind::Vector3r: numbers(static_cast<Vector3r*>(p)->data(), 3); break;
            case AttrKind::Vector6r: numbers(static_cast<Vector6r*>(p)->data(), 6); break;
            case AttrKind::Matrix3r: numbers(static_cast<Matrix3r*>(p)->data(), 9); break; // column-major
            case AttrKind::Quaternionr: numbers(static_cast<Quaternionr*>(p)->coeffs().data(), 4); break; // x y z w
            case AttrKind::Vector2i: {
                const auto& x = *static_cast<Vector2i*>(p);
                integer(x[0]), buf += ' ', integer(x[1]);
                break;
            }
            case AttrKind::Vector3i: {
                const auto& x = *static_cast<Vector3i*>(p);
                integer(x[0]), buf += ' ', integer(x[1]), buf += ' ', integer(x[2]);
                break;
            }
            case AttrKind::Vector6i: {
                const auto& x = *static_cast<Vector6i*>(p);
                for (int i = 0; i < 6; ++i) {
                    if (i) buf += ' ';
                    integer(x[i]);
                }
                break;
            }
            case AttrKind::IntVector:
                for (int x : *static_cast<std::vector<int>*>(p)) integer(x), buf += ' ';
                break;
            case AttrKind::RealVector:
                for (Real x : *static_cast<std::vector<Real>*>(p)) number(x), buf += ' ';
                break;
            case AttrKind::Vector3rVector:
                for (const auto& x : *static_cast<std::vector<Vector3r>*>(p)) numbers(x.data(), 3), buf += ' ';
                break;
            case AttrKind::Vector2rVector:
                for (const auto& x : *static_cast<std::vector<Vector2r>*>(p)) numbers(x.data(), 2), buf += ' ';
                break;
            case AttrKind::QuaternionrVector: // (x y z w, as Quaternionr)
                for (const auto& x : *static_cast<std::vector<Quaternionr>*>(p)) numbers(x.coeffs().data(), 4), buf += ' ';
                break;
            case AttrKind::StringVector:
                buf += '\n';
                for (const auto& x : *static_cast<std::vector<std::string>*>(p)) {
                    indent(depth + 1);
                    buf += "<s>";
                    text(x);
                    buf += "</s>\n";
                }
                indent(depth);
                break;
            case AttrKind::Ptr:
                buf += '\n';
                object(a.getPtr(p), 1, depth + 1);
                indent(depth);
                break;
            case AttrKind::PtrVector:
                buf += '\n';
                for (const auto& x : a.getPtrVector(p)) object(x, 1, depth + 1);
                indent(depth);
                break;
        }
        if (buf.size() == content) { // (no text: <a name="x"/>)
            buf.resize(start);
            buf += "/>\n";
        } else buf += "</a>\n";
    }
};

class Reader {
public:
    // keepAll: every object may be referenced later (format version 1); else only those marked shared="1"
    bool keepAll = true;
    std::shared_ptr<Serializable> read(const Node& n) {
        if (n.tag == "null") return nullptr;
        if (n.tag == "ref") {
            auto it = objects.find(n.attr("id"));
            if (it == objects.end()) throw FormatError("reference to object #" + n.attr("id") + " before its definition");
            return it->second;
        }
        if (n.tag != "obj") throw FormatError("expected an object, found <" + n.tag + ">");
        const std::string& className = n.attr("class");
        const ClassInfo* info = ClassRegistry::instance().find(className);
        if (!info) throw FormatError("unknown class '" + className + "'");
        std::shared_ptr<Serializable> obj = info->factory();
        if (keepAll || n.attrs.count("shared")) objects[n.attr("id")] = obj;
        for (const Node& v : n.children) {
            const AttrInfo* a = info->findAttr(v.attr("name"));
            if (!a) throw FormatError(className + " has no attribute '" + v.attr("name") + "'");
            readValue(v, *a, a->address(*obj), className);
        }
        obj->postLoad();
        return obj;
    }

private:
    std::unordered_map<std::string, std::shared_ptr<Serializable>> objects;
    void readValue(const Node& v, const AttrInfo& a, void* p, const std::string& className) {
        const std::string where = className + "." + a.name;
        auto fill = [&](Real* dst, int n) {
            const auto x = numbers(v.text, n, where);
            checkFlags(a, x.data(), dst, n, where);
            std::copy(x.begin(), x.end(), dst);
        };
        switch (a.kind) {
            case AttrKind::Bool: *static_cast<bool*>(p) = parseInt(v.text) != 0; break;
            case AttrKind::Int: {
                const Real x = toInt((Real)parseInt(v.text), where), dflt = *static_cast<int*>(p);
                checkFlags(a, &x, &dflt, 1, where);
                *static_cast<int*>(p) = (int)x;
                break;
            }
            case AttrKind::Long: {
                size_t used = 0;
                long long x = 0;
                try {
                    x = std::stoll(v.text, &used);
                } catch (std::exception&) {
                    throw FormatError(where + ": expected an integer, found '" + v.text.substr(0, 40) + "'");
                }
                if (v.text.find_first_not_of(" \t\n", used) != std::string::npos)
                    throw FormatError(where + ": expected an integer, found '" + v.text.substr(0, 40) + "'");
                *static_cast<long long*>(p) = x;
                break;
            }
            case AttrKind::Real: fill(static_cast<Real*>(p), 1); break;
            case AttrKind::String: *static_cast<std::string*>(p) = utf8(v.text, where); break;
            case AttrKind::Vector2r: fill(static_cast<Vector2r*>(p)->data(), 2); break;
            case AttrKind::Vector3r: fill(static_cast<Vector3r*>(p)->data(), 3); break;
            case AttrKind::Vector6r: fill(static_cast<Vector6r*>(p)->data(), 6); break;
            case AttrKind::Matrix3r: fill(static_cast<Matrix3r*>(p)->data(), 9); break;
            case AttrKind::Quaternionr: {
                Quaternionr q = *static_cast<Quaternionr*>(p);
                fill(q.coeffs().data(), 4);
                Validate::checkQuaternion(q.coeffs().data(), where);
                *static_cast<Quaternionr*>(p) = q;
                break;
            }
            case AttrKind::Vector2i: {
                const auto x = numbers(v.text, 2, where);
                *static_cast<Vector2i*>(p) = Vector2i(toInt(x[0], where), toInt(x[1], where));
                break;
            }
            case AttrKind::Vector3i: {
                const auto x = numbers(v.text, 3, where);
                *static_cast<Vector3i*>(p) = Vector3i(toInt(x[0], where), toInt(x[1], where), toInt(x[2], where));
                break;
            }
            case AttrKind::Vector6i: {
                const auto x = numbers(v.text, 6, where);
                auto& dst = *static_cast<Vector6i*>(p);
                for (int i = 0; i < 6; ++i) dst[i] = toInt(x[i], where);
                break;
            }
            case AttrKind::IntVector: {
                auto& dst = *static_cast<std::vector<int>*>(p);
                dst.clear();
                for (Real x : numbers(v.text, -1, where)) dst.push_back(toInt(x, where));
                break;
            }
            case AttrKind::RealVector: {
                const auto x = numbers(v.text, -1, where);
                auto& dst = *static_cast<std::vector<Real>*>(p);
                // (a list as long as the default one, e.g. the unset NaN vertices of Facet(), has its items as defaults)
                checkFlags(a, x.data(), dst.size() == x.size() ? dst.data() : nullptr, (int)x.size(), where);
                dst = x;
                break;
            }
            case AttrKind::Vector3rVector: {
                const auto x = numbers(v.text, -1, where);
                if (x.size() % 3) throw FormatError(where + ": expected triplets of numbers");
                auto& dst = *static_cast<std::vector<Vector3r>*>(p);
                checkFlags(a, x.data(), 3 * dst.size() == x.size() && !dst.empty() ? dst[0].data() : nullptr, (int)x.size(), where);
                dst.clear();
                for (size_t i = 0; i < x.size(); i += 3) dst.emplace_back(x[i], x[i + 1], x[i + 2]);
                break;
            }
            case AttrKind::Vector2rVector: {
                const auto x = numbers(v.text, -1, where);
                if (x.size() % 2) throw FormatError(where + ": expected pairs of numbers");
                auto& dst = *static_cast<std::vector<Vector2r>*>(p);
                checkFlags(a, x.data(), 2 * dst.size() == x.size() && !dst.empty() ? dst[0].data() : nullptr, (int)x.size(), where);
                dst.clear();
                for (size_t i = 0; i < x.size(); i += 2) dst.emplace_back(x[i], x[i + 1]);
                break;
            }
            case AttrKind::QuaternionrVector: {
                const auto x = numbers(v.text, -1, where);
                if (x.size() % 4) throw FormatError(where + ": expected quadruplets of numbers (x y z w)");
                std::vector<Quaternionr> q;
                for (size_t i = 0; i < x.size(); i += 4) {
                    q.emplace_back(x[i + 3], x[i], x[i + 1], x[i + 2]);
                    if (!q.back().coeffs().allFinite() || q.back().coeffs().squaredNorm() == 0) throw FormatError(where + ": a quaternion is not finite or zero");
                }
                *static_cast<std::vector<Quaternionr>*>(p) = std::move(q);
                break;
            }
            case AttrKind::StringVector: {
                auto& dst = *static_cast<std::vector<std::string>*>(p);
                dst.clear();
                for (const Node& c : v.children) dst.push_back(utf8(c.text, where));
                break;
            }
            case AttrKind::Ptr: {
                if (v.children.size() != 1) throw FormatError(where + ": expected one object");
                if (!a.setPtr(p, read(v.children[0]))) throw FormatError(where + ": object of the wrong class");
                break;
            }
            case AttrKind::PtrVector: {
                std::vector<std::shared_ptr<Serializable>> xs;
                for (const Node& c : v.children) xs.push_back(read(c));
                if (!a.setPtrVector(p, xs)) throw FormatError(where + ": object of the wrong class in the list");
                break;
            }
        }
    }
};

template <class T> std::shared_ptr<T> readAs(Reader& r, const Node& n, const char* what) {
    auto obj = r.read(n);
    auto t = std::dynamic_pointer_cast<T>(obj);
    if (obj && !t) throw FormatError(std::string("expected ") + what + ", found " + obj->getClassName());
    return t;
}

// Builds a scene from the sections of the tree, in the order they are written (doc/file-format.md,
// "The tree"): from a whole tree (binary files of format version 1), or element by element as an
// XML file streams. The current scene is never touched.
class SceneBuilder {
public:
    std::shared_ptr<Scene> s = std::make_shared<Scene>();

    void root(const Node& yade) {
        if (yade.tag != "yade") throw FormatError("not a saved scene (root element <" + yade.tag + ">)");
        const int version = std::stoi(yade.attr("formatVersion"));
        if (version < 1) throw FormatError("invalid format version " + std::to_string(version));
        if (version > NodeIO::formatVersion)
            throw FormatError("the file was written in format version " + std::to_string(version) + " by a newer build; this build reads up to version "
                    + std::to_string(NodeIO::formatVersion));
        r.keepAll = version < 2;
    }
    void scene(const Node& sc) {
        s->iter = std::stoll(sc.attr("iter"));
        s->stopAtIter = std::stoll(sc.attr("stopAtIter"));
        if (sc.attrs.count("stopAtTime")) s->stopAtTime = parseReal(sc.attr("stopAtTime")); // (files written before it was saved lack it)
        s->time = parseReal(sc.attr("time"));
        s->setDt(parseReal(sc.attr("dt")));
        s->trackEnergy = sc.attr("trackEnergy") == "1";
        if (sc.attrs.count("periodic")) s->setPeriodic(sc.attr("periodic") == "1"); // (before the interactions: their cellDist)
        bodyChanges = std::stoll(sc.attr("bodyChanges"));
    }
    // A whole section of small size (tags, energy, permanent forces).
    void section(const Node& n) {
        if (isList(n.tag)) {
            beginList(n.tag);
            for (const Node& c : n.children) item(n.tag, c);
            return;
        }
        seen(n.tag);
        if (n.tag == "tags") {
            s->tags.clear();
            for (const Node& t : n.children) s->tags[utf8(t.attr("name"), "a tag")] = utf8(t.text, "a tag");
        } else if (n.tag == "energy") {
            for (const Node& t : n.children) s->energy.set(utf8(t.attr("name"), "an energy term"), parseReal(t.text), t.attr("cumulative") == "1");
        } else if (n.tag == "cell") {
            if (n.children.size() != 1) throw FormatError("<cell> must hold one Cell");
            auto c = readAs<Cell>(r, n.children[0], "a Cell");
            if (!c) throw FormatError("<cell> holds None");
            try {
                c->check();
            } catch (const std::invalid_argument& e) {
                throw FormatError(e.what());
            }
            s->cell = c;
        } else if (n.tag == "permanentForces") {
            needBodies("permanent forces");
            for (const Node& f : n.children) {
                const long id = std::stol(f.attr("id"));
                if (id < 0 || id >= (long)s->bodies.size()) throw FormatError("a permanent force refers to a body that does not exist");
                const auto x = numbers(f.text, 6, "permanent force");
                s->forces.setPermForce((int)id, Vector3r(x[0], x[1], x[2]));
                s->forces.setPermTorque((int)id, Vector3r(x[3], x[4], x[5]));
            }
        } else throw FormatError("<scene> has an unknown element <" + n.tag + ">");
    }
    // Sections of one object per child (materials, bodies, interactions, engines, miscParams).
    static bool isList(const std::string& tag) {
        return tag == "materials" || tag == "bodies" || tag == "interactions" || tag == "engines" || tag == "miscParams";
    }
    void beginList(const std::string& tag) {
        seen(tag);
        if (tag == "interactions") needBodies("interactions");
    }
    void item(const std::string& list, const Node& n) {
        if (list == "materials") {
            auto m = readAs<Material>(r, n, "a Material");
            if (!m) throw FormatError("None in the list of materials");
            s->materials.push_back(m);
        } else if (list == "bodies") {
            bodies.push_back(readAs<Body>(r, n, "a Body"));
        } else if (list == "interactions") {
            interaction(readAs<Interaction>(r, n, "an Interaction"));
        } else if (list == "engines") {
            auto e = readAs<Engine>(r, n, "an Engine");
            if (!e) throw FormatError("None in the list of engines");
            engines.push_back(e);
        } else {
            auto m = readAs<Serializable>(r, n, "an object");
            if (!m) throw FormatError("None in O.miscParams");
            s->miscParams.push_back(m);
        }
    }
    void endList(const std::string& tag) {
        if (tag == "bodies") restoreBodies();
    }
    std::shared_ptr<Scene> finish() {
        for (const char* required : {"tags", "energy", "materials", "bodies", "interactions", "engines", "permanentForces"})
            if (!sections.count(required)) throw FormatError(std::string("<scene> lacks the element <") + required + ">");
        s->setEngines(engines);
        s->interactions.changes = 0; // (a scene just loaded: see InteractionContainer::changes)
        return s;
    }

private:
    Reader r;
    std::set<std::string> sections;
    std::vector<std::shared_ptr<Body>> bodies;
    std::vector<std::shared_ptr<Engine>> engines;
    long long bodyChanges = 0;
    bool bodiesRestored = false;

    void seen(const std::string& tag) {
        if (!sections.insert(tag).second) throw FormatError("<scene> has two elements <" + tag + ">");
    }
    void needBodies(const char* what) {
        if (!bodiesRestored) throw FormatError(std::string(what) + " before the bodies");
    }
    void restoreBodies() {
        try {
            s->bodies.restore(std::move(bodies), bodyChanges);
        } catch (std::invalid_argument& e) {
            throw FormatError(std::string("inconsistent bodies: ") + e.what());
        }
        bodies = {};
        s->interactions.resizeBodies(s->bodies.size());
        s->forces.resize(s->bodies.size());
        bodiesRestored = true;
    }
    // A pair is an entry of the container; its contact joins the pool of its classes at once (no
    // object is kept: a potential pair is only its ids), other geometry or physics wait for the next step.
    void interaction(const std::shared_ptr<Interaction>& I) {
        InteractionContainer& C = s->interactions;
        if (!I || !s->bodies.exists(I->id1) || !s->bodies.exists(I->id2) || I->id1 == I->id2)
            throw FormatError("an interaction refers to a body that does not exist");
        if (!C.insertPotential(I->id1, I->id2)) throw FormatError("the same interaction appears twice");
        const size_t k = C.size() - 1;
        if (I->iterBorn >= 0) C.iterBorn[k] = I->iterBorn;
        if (C.periodic) C.cellDist[k] = I->cellDist;
        if (I->geom && I->phys) C.restoreContact(ContactPool::Header{I->id1, I->id2, (uint32_t)k, 0, I->iterMadeReal}, *I->geom, *I->phys);
        else if (I->geom || I->phys) C.restoreUnpooled(k, I);
    }
};

} // namespace

std::shared_ptr<Scene> SceneIO::fromNode(const Node& root) {
    SceneBuilder b;
    b.root(root);
    const Node& sc = root.child("scene");
    b.scene(sc);
    for (const Node& n : sc.children) {
        b.section(n);
        b.endList(n.tag);
    }
    return b.finish();
}

namespace {

// An XML file as it streams: the sections of one object per child are read one object at a time.
std::shared_ptr<Scene> loadXml(ByteSource& in, std::string prefix) {
    XmlReader x(in, std::move(prefix));
    x.declaration();
    SceneBuilder b;
    Node yade, sc, n;
    bool empty = false;
    if (!x.child(yade, empty, "")) x.fail("expected the root element");
    b.root(yade);
    if (empty || !x.child(sc, empty, "yade") || sc.tag != "scene") throw FormatError("<yade> lacks the element <scene>");
    b.scene(sc);
    bool sectionEmpty = false, itemEmpty = false;
    while (!empty && x.child(n, sectionEmpty, "scene")) {
        if (!SceneBuilder::isList(n.tag)) {
            b.section(x.rest(n, sectionEmpty, 2));
            continue;
        }
        b.beginList(n.tag);
        Node item;
        while (!sectionEmpty && x.child(item, itemEmpty, n.tag)) b.item(n.tag, x.rest(item, itemEmpty, 3));
        b.endList(n.tag);
    }
    if (!x.child(n, empty, "yade")) { // (</yade>)
        x.finish();
        return b.finish();
    }
    x.fail("more than one element in <yade>");
}

void saveXml(Scene& s, ByteSink& out) {
    XmlWriter w(out);
    std::string& b = w.buf;
    b = NodeIO::xmlDeclaration;
    b += "<yade formatVersion=\"" + std::to_string(NodeIO::formatVersion) + "\">\n";
    Node sc("scene"); // (its attributes in the order of their names, as the reader does not mind)
    sc.attrs["bodyChanges"] = std::to_string(s.bodies.changes);
    sc.attrs["dt"] = fmt(s.dt);
    sc.attrs["iter"] = std::to_string(s.iter);
    sc.attrs["stopAtIter"] = std::to_string(s.stopAtIter);
    sc.attrs["stopAtTime"] = fmt(s.stopAtTime);
    sc.attrs["time"] = fmt(s.time);
    sc.attrs["trackEnergy"] = s.trackEnergy ? "1" : "0";
    if (s.isPeriodic) sc.attrs["periodic"] = "1";
    b += " <scene";
    for (const auto& kv : sc.attrs) b += " " + kv.first + "=\"" + kv.second + "\"";
    b += ">\n";
    w.open("tags", 2);
    for (const auto& kv : s.tags) {
        b += "   <tag name=\"";
        w.text(kv.first);
        b += "\">";
        w.text(kv.second);
        b += "</tag>\n";
    }
    w.close("tags", 2);
    w.open("energy", 2);
    const auto names = s.energy.names();
    const auto values = s.energy.values();
    const auto cumulative = s.energy.cumulativeFlags();
    for (size_t i = 0; i < names.size(); ++i) {
        b += std::string("   <term cumulative=\"") + (cumulative[i] ? "1" : "0") + "\" name=\"";
        w.text(names[i]);
        b += "\">";
        w.number(values[i]);
        b += "</term>\n";
    }
    w.close("energy", 2);
    if (s.isPeriodic) {
        w.open("cell", 2);
        w.object(s.cell, 0, 3);
        w.close("cell", 2);
    }
    w.open("materials", 2);
    for (const auto& m : s.materials) w.object(m, 0, 3);
    w.close("materials", 2);
    w.open("bodies", 2);
    for (const auto& body : s.bodies) {
        w.object(body, 0, 3);
        w.flushIfFull();
    }
    w.close("bodies", 2);
    w.open("interactions", 2);
    for (size_t k = 0; k < s.interactions.size(); ++k) {
        w.object(s.interactions.snapshot(k), 1, 3);
        w.flushIfFull();
    }
    w.close("interactions", 2);
    w.open("engines", 2);
    for (const auto& e : s.getEngines()) w.object(e, 0, 3);
    w.close("engines", 2);
    w.open("miscParams", 2);
    for (const auto& m : s.miscParams) w.object(m, 0, 3);
    w.close("miscParams", 2);
    w.open("permanentForces", 2);
    for (size_t i = 0; s.forces.hasPermanent() && i < s.forces.size(); ++i) {
        const Vector3r &f = s.forces.getPermForce((int)i), &t = s.forces.getPermTorque((int)i);
        if (f == Vector3r::Zero() && t == Vector3r::Zero()) continue;
        b += "   <f id=\"" + std::to_string(i) + "\">";
        w.numbers(f.data(), 3);
        b += ' ';
        w.numbers(t.data(), 3);
        b += "</f>\n";
    }
    w.close("permanentForces", 2);
    w.close("scene", 1);
    w.close("yade", 0);
    w.finish();
}

} // namespace

void SceneIO::save(Scene& scene, ByteSink& out, bool xml) {
    if (xml) saveXml(scene, out);
    else SceneBlocks::write(scene, out);
}

std::string SceneIO::save(Scene& scene, bool xml) {
    std::string data;
    save(scene, *stringSink(data, Codec::none), xml);
    return data;
}

std::shared_ptr<Scene> SceneIO::load(ByteSource& in) {
    try {
        std::string data(SceneBlocks::magicSize, '\0');
        data.resize(in.read(&data[0], data.size()));
        if (data == SceneBlocks::magic) return SceneBlocks::read(in);
        if (data.compare(0, 5, "<?xml") == 0) return loadXml(in, std::move(data));
        // binary files of format version 1 (or not a scene): read whole, then parsed
        char chunk[1 << 16];
        for (size_t n; (n = in.read(chunk, sizeof chunk)) > 0;) data.append(chunk, n);
        return fromNode(NodeIO::parse(data));
    } catch (FormatError&) {
        throw;
    } catch (std::bad_alloc&) { // out of memory (MemoryError in Python): not a corrupt file
        throw;
    } catch (std::system_error&) { // reading failed (OSError in Python)
        throw;
    } catch (std::exception& e) { // stoll on garbage, bad dt, a value postLoad refuses...
        throw FormatError(std::string("corrupt file: ") + e.what());
    }
}

std::shared_ptr<Scene> SceneIO::load(const std::string& data) { return load(*stringSource(data)); }

} // namespace yade
