#include <core/SceneBlocks.hpp>
#include <core/SceneIO.hpp>
#include <lib/serialization/Validate.hpp>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
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

// Whitespace-separated numbers of a text field, exactly n of them (n < 0: any count).
std::vector<Real> numbers(const std::string& text, long n, const std::string& what) {
    std::vector<Real> r;
    std::istringstream in(text);
    std::string tok;
    while (in >> tok) r.push_back(parseReal(tok));  // each token must be a whole number
    if (n >= 0 && (long)r.size() != n)
        throw FormatError(what + ": expected " + std::to_string(n) + " numbers, found " + std::to_string(r.size()));
    return r;
}

std::string joined(const Real* x, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += (i ? " " : "") + fmt(x[i]);
    return s;
}

class Writer {
public:
    Node write(const std::shared_ptr<Serializable>& obj) {
        if (!obj) return Node("null");
        auto it = ids.find(obj.get());
        if (it != ids.end()) {
            Node r("ref");
            r.attrs["id"] = std::to_string(it->second);
            return r;
        }
        const int id = (int)ids.size();
        ids[obj.get()] = id;
        obj->preSave();
        const ClassInfo& info = ClassRegistry::instance().get(typeid(*obj));
        Node n("obj");
        n.attrs["class"] = info.name;
        n.attrs["id"] = std::to_string(id);
        for (const AttrInfo& a : info.attrs) {
            if (a.has(Attr::noSave)) continue;
            Node& v = n.add("a");
            v.attrs["name"] = a.name;
            writeValue(v, a, a.address(*obj));
        }
        obj->postSave();
        return n;
    }

private:
    std::unordered_map<const Serializable*, int> ids;
    void writeValue(Node& v, const AttrInfo& a, void* p) {
        switch (a.kind) {
            case AttrKind::Bool: v.text = *static_cast<bool*>(p) ? "1" : "0"; break;
            case AttrKind::Int: v.text = std::to_string(*static_cast<int*>(p)); break;
            case AttrKind::Long: v.text = std::to_string(*static_cast<long long*>(p)); break;
            case AttrKind::Real: v.text = fmt(*static_cast<Real*>(p)); break;
            case AttrKind::String: v.text = *static_cast<std::string*>(p); break;
            case AttrKind::Vector2r: v.text = joined(static_cast<Vector2r*>(p)->data(), 2); break;
            case AttrKind::Vector3r: v.text = joined(static_cast<Vector3r*>(p)->data(), 3); break;
            case AttrKind::Vector6r: v.text = joined(static_cast<Vector6r*>(p)->data(), 6); break;
            case AttrKind::Matrix3r: v.text = joined(static_cast<Matrix3r*>(p)->data(), 9); break; // column-major
            case AttrKind::Quaternionr: v.text = joined(static_cast<Quaternionr*>(p)->coeffs().data(), 4); break; // x y z w
            case AttrKind::Vector2i: {
                const auto& x = *static_cast<Vector2i*>(p);
                v.text = std::to_string(x[0]) + " " + std::to_string(x[1]);
                break;
            }
            case AttrKind::Vector3i: {
                const auto& x = *static_cast<Vector3i*>(p);
                v.text = std::to_string(x[0]) + " " + std::to_string(x[1]) + " " + std::to_string(x[2]);
                break;
            }
            case AttrKind::IntVector:
                for (int x : *static_cast<std::vector<int>*>(p)) v.text += std::to_string(x) + " ";
                break;
            case AttrKind::RealVector:
                for (Real x : *static_cast<std::vector<Real>*>(p)) v.text += fmt(x) + " ";
                break;
            case AttrKind::Vector3rVector:
                for (const auto& x : *static_cast<std::vector<Vector3r>*>(p)) v.text += joined(x.data(), 3) + " ";
                break;
            case AttrKind::StringVector:
                for (const auto& x : *static_cast<std::vector<std::string>*>(p)) v.add("s").text = x;
                break;
            case AttrKind::Ptr: v.children.push_back(write(a.getPtr(p))); break;
            case AttrKind::PtrVector:
                for (const auto& x : a.getPtrVector(p)) v.children.push_back(write(x));
                break;
        }
    }
};

class Reader {
public:
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
        objects[n.attr("id")] = obj;
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

} // namespace

Node SceneIO::toNode(Scene& s) {
    Node root("yade");
    root.attrs["formatVersion"] = std::to_string(NodeIO::formatVersion);
    Node& sc = root.add("scene");
    sc.attrs["iter"] = std::to_string(s.iter);
    sc.attrs["stopAtIter"] = std::to_string(s.stopAtIter);
    sc.attrs["stopAtTime"] = fmt(s.stopAtTime);
    sc.attrs["time"] = fmt(s.time);
    sc.attrs["dt"] = fmt(s.dt);
    sc.attrs["trackEnergy"] = s.trackEnergy ? "1" : "0";
    sc.attrs["bodyChanges"] = std::to_string(s.bodies.changes);
    Node& tags = sc.add("tags");
    for (const auto& kv : s.tags) {
        Node& t = tags.add("tag");
        t.attrs["name"] = kv.first;
        t.text = kv.second;
    }
    Node& energy = sc.add("energy");
    const auto names = s.energy.names();
    const auto values = s.energy.values();
    const auto cumulative = s.energy.cumulativeFlags();
    for (size_t i = 0; i < names.size(); ++i) {
        Node& t = energy.add("term");
        t.attrs["name"] = names[i];
        t.attrs["cumulative"] = cumulative[i] ? "1" : "0";
        t.text = fmt(values[i]);
    }
    Writer w;
    Node& mats = sc.add("materials");
    for (const auto& m : s.materials) mats.children.push_back(w.write(m));
    Node& bodies = sc.add("bodies");
    for (const auto& b : s.bodies) bodies.children.push_back(w.write(b));
    Node& intrs = sc.add("interactions");
    std::vector<std::shared_ptr<Interaction>> made; // objects of pairs that had none (alive until written: the writer knows objects by address)
    for (size_t k = 0; k < s.interactions.size(); ++k) {
        made.push_back(s.interactions.snapshot(k));
        intrs.children.push_back(w.write(made.back()));
    }
    Node& engines = sc.add("engines");
    for (const auto& e : s.getEngines()) engines.children.push_back(w.write(e));
    Node& misc = sc.add("miscParams");
    for (const auto& m : s.miscParams) misc.children.push_back(w.write(m));
    Node& perm = sc.add("permanentForces");
    for (size_t i = 0; s.forces.hasPermanent() && i < s.forces.size(); ++i) {
        const Vector3r &f = s.forces.getPermForce((int)i), &t = s.forces.getPermTorque((int)i);
        if (f == Vector3r::Zero() && t == Vector3r::Zero()) continue;
        Node& n = perm.add("f");
        n.attrs["id"] = std::to_string(i);
        n.text = joined(f.data(), 3) + " " + joined(t.data(), 3);
    }
    return root;
}

std::shared_ptr<Scene> SceneIO::fromNode(const Node& root) {
    if (root.tag != "yade") throw FormatError("not a saved scene (root element <" + root.tag + ">)");
    const int version = std::stoi(root.attr("formatVersion"));
    if (version < 1) throw FormatError("invalid format version " + std::to_string(version));
    if (version > NodeIO::formatVersion)
        throw FormatError("the file was written in format version " + std::to_string(version) + " by a newer build; this build reads up to version "
                + std::to_string(NodeIO::formatVersion));
    const Node& sc = root.child("scene");
    auto s = std::make_shared<Scene>();
    s->iter = std::stoll(sc.attr("iter"));
    s->stopAtIter = std::stoll(sc.attr("stopAtIter"));
    if (sc.attrs.count("stopAtTime")) s->stopAtTime = parseReal(sc.attr("stopAtTime")); // (files written before it was saved lack it)
    s->time = parseReal(sc.attr("time"));
    s->setDt(parseReal(sc.attr("dt")));
    s->trackEnergy = sc.attr("trackEnergy") == "1";
    s->tags.clear();
    for (const Node& t : sc.child("tags").children) s->tags[utf8(t.attr("name"), "a tag")] = utf8(t.text, "a tag");
    for (const Node& t : sc.child("energy").children)
        s->energy.set(utf8(t.attr("name"), "an energy term"), parseReal(t.text), t.attr("cumulative") == "1");
    Reader r;
    for (const Node& n : sc.child("materials").children) {
        auto m = readAs<Material>(r, n, "a Material");
        if (!m) throw FormatError("None in the list of materials");
        s->materials.push_back(m);
    }
    std::vector<std::shared_ptr<Body>> bodies;
    for (const Node& n : sc.child("bodies").children) bodies.push_back(readAs<Body>(r, n, "a Body"));
    try {
        s->bodies.restore(std::move(bodies), std::stoll(sc.attr("bodyChanges")));
    } catch (std::invalid_argument& e) {
        throw FormatError(std::string("inconsistent bodies: ") + e.what());
    }
    s->interactions.resizeBodies(s->bodies.size());
    s->forces.resize(s->bodies.size());
    for (const Node& n : sc.child("interactions").children) {
        auto I = readAs<Interaction>(r, n, "an Interaction");
        if (!I || !s->bodies.exists(I->id1) || !s->bodies.exists(I->id2))
            throw FormatError("an interaction refers to a body that does not exist");
        if (!s->interactions.insert(I)) throw FormatError("the same interaction appears twice");
    }
    std::vector<std::shared_ptr<Engine>> engines;
    for (const Node& n : sc.child("engines").children) {
        auto e = readAs<Engine>(r, n, "an Engine");
        if (!e) throw FormatError("None in the list of engines");
        engines.push_back(e);
    }
    s->setEngines(engines);
    if (const Node* misc = sc.find("miscParams")) // (files written before it was saved lack it)
        for (const Node& n : misc->children) {
            auto m = readAs<Serializable>(r, n, "an object");
            if (!m) throw FormatError("None in O.miscParams");
            s->miscParams.push_back(m);
        }
    for (const Node& n : sc.child("permanentForces").children) {
        const long id = std::stol(n.attr("id"));
        if (id < 0 || id >= (long)s->bodies.size()) throw FormatError("a permanent force refers to a body that does not exist");
        const auto x = numbers(n.text, 6, "permanent force");
        s->forces.setPermForce((int)id, Vector3r(x[0], x[1], x[2]));
        s->forces.setPermTorque((int)id, Vector3r(x[3], x[4], x[5]));
    }
    return s;
}

void SceneIO::save(Scene& scene, ByteSink& out, bool xml) {
    if (!xml) return SceneBlocks::write(scene, out);
    const std::string text = NodeIO::toXml(toNode(scene));
    out.write(text.data(), text.size());
    out.close();
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
        // the tree (XML, or binary files of format version 1): read whole, then parsed
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
