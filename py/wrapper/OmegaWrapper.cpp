// Python's O object and its containers. Proxies always act on the current scene.
#include <chrono>
#include <core/Functor.hpp>
#include <core/SceneIO.hpp>
#include <lib/base/ExternalWrites.hpp>
#include <pkg/common/Clump.hpp>
#include <pkg/common/InteractionLoop.hpp>
#include <core/TimeStepper.hpp>
#include <lib/base/Logging.hpp>
#include <py/wrapper/Attributes.hpp>
#include <py/wrapper/OmegaWrapper.hpp>
#include <pybind11/stl.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>

namespace py = pybind11;

namespace yade {

Omega& omega() {
    static Omega* o = new Omega(); // never destroyed: the loop thread may outlive static destructors
    return *o;
}

static Scene& scene() { return omega().scene(); }

py::list bodyInteractions(const Body& b) {
    py::list r;
    Scene& s = scene();
    if (b.id < 0 || !s.bodies.exists(b.id) || s.bodies[b.id].get() != &b) return r;
    auto intrs = s.interactions.withBody(b.id);
    std::sort(intrs.begin(), intrs.end(), [&](const auto& x, const auto& y) { // by partner id, as in Yade
        return (x->id1 == b.id ? x->id2 : x->id1) < (y->id1 == b.id ? y->id2 : y->id1);
    });
    for (const auto& I : intrs)
        if (I->isReal()) r.append(py::cast(I));
    return r;
}

// (a label given twice names the first object with it, as in the reference)
static void collectLabels(const std::shared_ptr<Serializable>& obj, std::set<Serializable*>& seen, std::set<std::string>& named, py::module_& builtins) {
    if (!obj || !seen.insert(obj.get()).second) return;
    std::string label;
    if (auto* e = dynamic_cast<Engine*>(obj.get())) label = e->label;
    else if (auto* f = dynamic_cast<Functor*>(obj.get())) label = f->label;
    else return; // only engines and functors (and what they hold) carry labels
    if (!label.empty() && named.insert(label).second) builtins.attr(label.c_str()) = py::cast(obj);
    for (const AttrInfo& a : classInfoOf(*obj).attrs) {
        void* p = a.address(*obj);
        if (a.kind == AttrKind::Ptr) collectLabels(a.getPtr(p), seen, named, builtins);
        else if (a.kind == AttrKind::PtrVector)
            for (const auto& child : a.getPtrVector(p)) collectLabels(child, seen, named, builtins);
    }
}

// The engine or functor of O.engines (or held by one) with that label; null if none.
static std::shared_ptr<Serializable> findLabeled(const std::shared_ptr<Serializable>& obj, const std::string& label, std::set<Serializable*>& seen) {
    if (!obj || !seen.insert(obj.get()).second) return nullptr;
    std::string own;
    if (auto* e = dynamic_cast<Engine*>(obj.get())) own = e->label;
    else if (auto* f = dynamic_cast<Functor*>(obj.get())) own = f->label;
    else return nullptr;
    if (own == label) return obj;
    for (const AttrInfo& a : classInfoOf(*obj).attrs) {
        void* p = a.address(*obj);
        if (a.kind == AttrKind::Ptr) {
            if (auto r = findLabeled(a.getPtr(p), label, seen)) return r;
        } else if (a.kind == AttrKind::PtrVector) {
            for (const auto& child : a.getPtrVector(p))
                if (auto r = findLabeled(child, label, seen)) return r;
        }
    }
    return nullptr;
}

void injectLabels(const std::vector<std::shared_ptr<Engine>>& engines) {
    py::module_ builtins = py::module_::import("builtins");
    std::set<Serializable*> seen;
    std::set<std::string> named;
    for (const auto& e : engines) collectLabels(e, seen, named, builtins);
}

namespace {
// Python index → id, with negative indices from the end.
long normIndex(long i, size_t n) { return i < 0 ? i + (long)n : i; }

struct BodyContainerProxy {
    py::object append(py::object arg) {
        BetweenSteps between;
        Scene& s = scene();
        if (py::isinstance<Body>(arg)) return py::cast(s.appendBody(py::cast<std::shared_ptr<Body>>(arg)));
        if (!py::isinstance<py::sequence>(arg) || py::isinstance<py::str>(arg))
            throw py::type_error("O.bodies.append: expected a Body or a list of bodies, got " + std::string(py::str(py::type::of(arg).attr("__name__"))));
        std::vector<std::shared_ptr<Body>> bodies;
        for (py::handle h : arg) {
            if (!py::isinstance<Body>(h)) throw py::type_error("O.bodies.append: every item must be a Body, got " + std::string(py::str(py::type::of(h).attr("__name__"))));
            bodies.push_back(py::cast<std::shared_ptr<Body>>(h));
        }
        std::set<Body*> unique;
        for (const auto& b : bodies) // checked before any is appended, so a failure appends nothing
            if (b->id >= 0 || !unique.insert(b.get()).second)
                throw py::index_error("Body already has id " + std::to_string(b->id) + " set; appending such body (for the second time) is not allowed.");
        py::list ids;
        for (const auto& b : bodies) ids.append(s.appendBody(b));
        return std::move(ids);
    }
    // Bodies of a Python list, checked as append does (each a Body, none in a scene, none twice).
    static std::vector<std::shared_ptr<Body>> newBodies(py::handle arg, const char* what) {
        if (!py::isinstance<py::sequence>(arg) || py::isinstance<py::str>(arg))
            throw py::type_error(std::string(what) + ": expected a list of bodies, got " + std::string(py::str(py::type::of(arg).attr("__name__"))));
        std::vector<std::shared_ptr<Body>> bodies;
        std::set<Body*> unique;
        for (py::handle h : arg) {
            if (!py::isinstance<Body>(h)) throw py::type_error(std::string(what) + ": every item must be a Body, got " + std::string(py::str(py::type::of(h).attr("__name__"))));
            bodies.push_back(py::cast<std::shared_ptr<Body>>(h));
            if (bodies.back()->id >= 0 || !unique.insert(bodies.back().get()).second)
                throw py::index_error("Body already has id " + std::to_string(bodies.back()->id) + " set; appending such body (for the second time) is not allowed.");
        }
        return bodies;
    }
    py::list replace(py::object arg) { // (checked before anything is removed)
        const std::vector<std::shared_ptr<Body>> bodies = newBodies(arg, "O.bodies.replace");
        BetweenSteps between;
        clearBodies();
        py::list ids;
        for (const auto& b : bodies) ids.append(scene().appendBody(b));
        return ids;
    }
    long insertAtId(const std::shared_ptr<Body>& b, long id) {
        BetweenSteps between;
        Scene& s = scene();
        if (!b) throw py::type_error("O.bodies.insertAtId: the body is None");
        if (id < 0 || id > std::numeric_limits<Body::id_t>::max()) throw py::index_error("O.bodies.insertAtId: invalid id " + std::to_string(id));
        s.bodies.insertAtId(b, (Body::id_t)id);
        b->iterBorn = s.iter;
        b->timeBorn = s.time;
        s.forces.resize(s.bodies.size());
        s.interactions.resizeBodies(s.bodies.size());
        return id;
    }
    py::object get(long i) {
        Scene& s = scene();
        const long id = normIndex(i, s.bodies.size());
        if (id < 0 || id >= (long)s.bodies.size()) throw py::index_error("Body id " + std::to_string(i) + " out of range.");
        return s.bodies[id] ? py::cast(s.bodies[id]) : py::none();
    }
    size_t len() { return scene().bodies.size(); }
    py::iterator iter() {
        py::list l;
        for (const auto& b : scene().bodies)
            if (b) l.append(py::cast(b));
        return py::iter(l);
    }
    bool erase(long id, bool eraseClumpMembers) {
        BetweenSteps between;
        Scene& s = scene();
        if (id < 0 || id >= (long)s.bodies.size()) throw py::index_error("Body id " + std::to_string(id) + " out of range.");
        if (!s.bodies.exists((Body::id_t)id)) return false; // already erased
        const Body& b = *s.bodies[(Body::id_t)id];
        if (b.isClumpMember())
            throw py::value_error("O.bodies.erase: body #" + std::to_string(id) + " is a member of clump #" + std::to_string(b.clumpId)
                    + "; release it first (O.bodies.releaseFromClump), or erase the clump (eraseClumpMembers=True erases its members too)");
        if (b.isClump()) Clump::erase(s, (Body::id_t)id, eraseClumpMembers);
        else s.eraseBody((Body::id_t)id);
        return true;
    }
    // --- clumps (pkg/common/Clump.hpp) ---
    static std::vector<Body::id_t> idList(py::handle arg, const char* what) {
        if (!py::isinstance<py::sequence>(arg) || py::isinstance<py::str>(arg))
            throw py::type_error(std::string(what) + ": expected a list of body ids, got " + std::string(py::str(py::type::of(arg).attr("__name__"))));
        std::vector<Body::id_t> ids;
        for (py::handle h : arg) {
            if (!py::isinstance<py::int_>(h) || py::isinstance<py::bool_>(h))
                throw py::type_error(std::string(what) + ": every item must be a body id (int), got " + std::string(py::str(py::type::of(h).attr("__name__"))));
            const long id = py::cast<long>(h);
            if (id < 0 || id > std::numeric_limits<Body::id_t>::max()) throw py::value_error(std::string(what) + ": invalid body id " + std::to_string(id));
            ids.push_back((Body::id_t)id);
        }
        return ids;
    }
    py::tuple appendClumped(py::object arg, int discretization) {
        const std::vector<std::shared_ptr<Body>> bodies = newBodies(arg, "O.bodies.appendClumped");
        std::vector<const Body*> members;
        for (const auto& b : bodies) members.push_back(b.get());
        Clump::checkNewMembers(members, discretization); // (before anything is appended)
        BetweenSteps between;
        Scene& s = scene();
        std::vector<Body::id_t> ids;
        for (const auto& b : bodies) ids.push_back(s.appendBody(b));
        const Body::id_t cid = Clump::make(s, ids, discretization);
        return py::make_tuple(cid, ids);
    }
    long clump(py::object arg, int discretization) {
        const std::vector<Body::id_t> ids = idList(arg, "O.bodies.clump");
        BetweenSteps between;
        return Clump::make(scene(), ids, discretization);
    }
    void addToClump(py::object arg, long clumpId, int discretization) {
        const std::vector<Body::id_t> ids = idList(arg, "O.bodies.addToClump");
        BetweenSteps between;
        Clump::add(scene(), ids, (Body::id_t)clumpId, discretization);
    }
    Real getRoundness(py::object excludeList) {
        const std::vector<Body::id_t> ids = idList(excludeList, "O.bodies.getRoundness");
        BetweenSteps between;
        return Clump::roundness(scene(), ids);
    }
    void releaseFromClump(long id, long clumpId, int discretization) {
        BetweenSteps between;
        if (!Clump::release(scene(), (Body::id_t)id, (Body::id_t)clumpId, discretization))
            PyErr_WarnEx(PyExc_UserWarning, ("Body " + std::to_string(id) + " not released from clump " + std::to_string(clumpId)
                    + ", because number of clump members would get < 2!").c_str(), 1);
    }
    void clear() {
        BetweenSteps between;
        clearBodies();
    }
    static void clearBodies() {
        Scene& s = scene();
        s.interactions.clear();
        for (const auto& b : s.bodies)
            if (b) b->id = -1;
        s.bodies.clear();
    }
};

// Iteration over O.interactions: the pairs that were real when the iteration began and still
// exist, one object at a time; an object made for the iteration is dropped when the iteration
// moves on and Python no longer holds it (objects of all contacts cost as much memory as the
// contacts themselves).
struct RealInteractionIterator {
    std::vector<std::pair<int, int>> pairs;
    size_t next = 0;
    long long serial = -1; // the scene's
    // The objects made for the last two steps (a loop variable still holds the last one when the
    // next is asked for: `for i in O.interactions` rebinds i after __next__ returns).
    std::shared_ptr<Interaction> made[2];
    py::object step() {
        BetweenSteps between; // (see InteractionContainerProxy)
        Scene& s = scene();
        InteractionContainer& intrs = s.interactions;
        if (made[0]) {
            const Interaction* old = made[0].get();
            made[0].reset();
            const long k = s.serial == serial ? intrs.findIndex(old->id1, old->id2) : -1;
            if (k >= 0) intrs.releaseObject((size_t)k, old);
        }
        made[0] = std::move(made[1]);
        while (s.serial == serial && next < pairs.size()) {
            const long k = intrs.findIndex(pairs[next].first, pairs[next].second);
            ++next;
            if (k < 0 || !intrs.isReal((size_t)k)) continue; // (erased, or made potential, since the iteration began)
            const bool had = intrs.object((size_t)k) != nullptr;
            std::shared_ptr<Interaction> I = intrs[(size_t)k];
            if (!had) made[1] = I;
            return py::cast(I);
        }
        throw py::stop_iteration();
    }
};

// O.interactions from Python. While O.run() runs in the background, each call waits for the end of
// the current step and lets the run go on afterwards (BetweenSteps): the loop adds and removes
// pairs (its columns may move in memory) and a read from Python may make a pair's object.
struct InteractionContainerProxy {
    py::object get(py::tuple ids) {
        if (ids.size() != 2) throw py::type_error("O.interactions[id1,id2] takes two body ids");
        for (py::handle id : ids) // (py::cast<int> of anything else raised "RuntimeError: Unable to cast Python instance")
            if (!py::isinstance<py::int_>(id)) throw py::type_error("O.interactions[id1,id2]: a body id must be an int, got " + std::string(py::repr(id)));
        int id1, id2;
        try {
            id1 = py::cast<int>(ids[0]);
            id2 = py::cast<int>(ids[1]);
        } catch (py::cast_error&) { // beyond the range of an int: no body has that id
            throw py::index_error("No such interaction: ##" + std::string(py::str(ids[0])) + "+" + std::string(py::str(ids[1])));
        }
        BetweenSteps between;
        const auto& I = scene().interactions.find(id1, id2);
        if (!I) throw py::index_error("No such interaction: ##" + std::string(py::str(ids[0])) + "+" + std::string(py::str(ids[1])));
        return py::cast(I);
    }
    bool has(int a, int b, bool onlyReal) {
        BetweenSteps between;
        const InteractionContainer& intrs = scene().interactions;
        const long k = intrs.findIndex(a, b);
        return k >= 0 && (!onlyReal || intrs.isReal((size_t)k));
    }
    size_t len() {
        BetweenSteps between;
        return scene().interactions.size();
    }
    py::list all(bool onlyReal) {
        BetweenSteps between;
        py::list l;
        const InteractionContainer& intrs = scene().interactions;
        for (size_t k = 0; k < intrs.size(); ++k)
            if (!onlyReal || intrs.isReal(k)) l.append(py::cast(intrs[k]));
        return l;
    }
    py::list withBody(int id) {
        BetweenSteps between;
        py::list l;
        for (const auto& I : scene().interactions.withBody(id))
            if (I->isReal()) l.append(py::cast(I));
        return l;
    }
    py::list withBodyAll(int id) { // (potential pairs too)
        BetweenSteps between;
        py::list l;
        InteractionContainer& intrs = scene().interactions;
        for (const auto& p : intrs.partnersOf(id)) l.append(py::cast(intrs[p.k]));
        return l;
    }
    py::object nth(long n) {
        BetweenSteps between;
        InteractionContainer& intrs = scene().interactions;
        if (n < 0) n += (long)intrs.size();
        if (n < 0 || n >= (long)intrs.size()) throw py::index_error("O.interactions.nth(" + std::to_string(n) + "): there are " + std::to_string(intrs.size()) + " interactions");
        return py::cast(intrs[(size_t)n]);
    }
    // As the reference: a real interaction becomes potential (the next step computes it again, and it is
    // real again if the bodies still touch); a potential one stays; no such pair: nothing happens.
    void erase(int a, int b) {
        BetweenSteps between;
        scene().interactions.makePotential(a, b);
    }
};

// utils.createInteraction: the pair (id1, id2) added by hand. Unless virtualI, its geometry is made
// by the Ig2 functor of O.engines' InteractionLoop with force (so bodies apart get one too: a
// negative penetration for spheres) and its physics by the Ip2 functor: a real contact from this
// step on, which the loop then treats as any other (and may end at its next step if the bodies
// are apart).
static InteractionContainer::Ptr createInteraction(long id1, long id2, bool virtualI) {
    Scene& s = scene();
    const auto body = [&s](long id) -> const Body& {
        if (id < 0 || id >= (long)s.bodies.size() || !s.bodies[(Body::id_t)id]) throw std::runtime_error("No body #" + std::to_string(id));
        return *s.bodies[(Body::id_t)id];
    };
    const Body &b1 = body(id1), &b2 = body(id2);
    if (id1 == id2) throw std::runtime_error("createInteraction: #" + std::to_string(id1) + " and #" + std::to_string(id2) + " are the same body");
    BetweenSteps between;
    const long existing = s.interactions.findIndex((Body::id_t)id1, (Body::id_t)id2);
    if (existing >= 0 && s.interactions.isReal((size_t)existing)) // (a potential pair is replaced)
        throw std::runtime_error("Interaction #" + std::to_string(id1) + "+#" + std::to_string(id2) + " already exists.");
    InteractionLoop* loop = nullptr;
    for (const auto& e : s.getEngines())
        if ((loop = dynamic_cast<InteractionLoop*>(e.get()))) break;
    if (!loop) throw std::runtime_error("No IGeomDispatcher in engines or inside InteractionLoop.");
    if (!loop->geomDispatcher || !loop->physDispatcher)
        throw std::runtime_error("createInteraction: the InteractionLoop's geomDispatcher and physDispatcher must not be None");
    for (auto* d : std::initializer_list<Dispatcher*>{loop->geomDispatcher.get(), loop->physDispatcher.get()})
        for (const auto& f : d->functorsBase()) { // (as the loop does before its pass)
            f->scene = &s;
            f->prepare();
        }
    auto I = std::make_shared<Interaction>((Body::id_t)id1, (Body::id_t)id2);
    I->iterBorn = s.iter;
    if (!virtualI) {
        if (!b1.shape || !b2.shape) throw std::runtime_error("createInteraction: bodies #" + std::to_string(id1) + " and #" + std::to_string(id2) + " need shapes");
        if (!b1.material || !b2.material) throw std::runtime_error("createInteraction: bodies #" + std::to_string(id1) + " and #" + std::to_string(id2) + " need materials");
        const auto& geomEntry = loop->geomDispatcher->getFunctor(*b1.shape, *b2.shape);
        if (!geomEntry.functor)
            throw std::runtime_error("createInteraction: no Ig2 functor in the InteractionLoop for " + b1.shape->getClassName() + "+" + b2.shape->getClassName());
        const Body &f1 = geomEntry.swap ? b2 : b1, &f2 = geomEntry.swap ? b1 : b2; // (in the functor's order)
        if (geomEntry.swap) I->swapOrder();
        // in a periodic scene, with the image of body 2 nearest to body 1, moving with the homogeneous
        // field (as the interaction loop takes it)
        State image;
        if (s.isPeriodic) {
            const Cell& c = *s.cell;
            I->cellDist = (c.hSize.inverse() * (f1.state->pos() - f2.state->pos())).array().round().cast<int>().matrix();
            image.pos() = f2.state->pos() + c.hSize * I->cellDist.cast<Real>();
            image.vel() = f2.state->vel() + c.prevVelGrad * (c.prevHSize * I->cellDist.cast<Real>());
            image.angVel() = f2.state->angVel();
            image.ori() = f2.state->ori();
        }
        if (!geomEntry.functor->go(*f1.shape, *f2.shape, *f1.state, s.isPeriodic ? image : *f2.state, Vector3r::Zero(), true, *I) || !I->geom)
            throw std::runtime_error("createInteraction: " + geomEntry.functor->getClassName() + " made no geometry for #" + std::to_string(id1) + "+#" + std::to_string(id2));
        const auto& physEntry = loop->physDispatcher->getFunctor(*b1.material, *b2.material);
        if (!physEntry.functor)
            throw std::runtime_error("createInteraction: no Ip2 functor in the InteractionLoop for " + b1.material->getClassName() + "+" + b2.material->getClassName());
        physEntry.functor->go(f1.material, f2.material, *I); // (as the loop calls it)
        if (!I->phys) throw std::runtime_error("createInteraction: " + physEntry.functor->getClassName() + " made no physics for #" + std::to_string(id1) + "+#" + std::to_string(id2));
        I->iterMadeReal = s.iter;
    }
    if (existing >= 0) s.interactions.eraseAt((size_t)existing);
    s.interactions.insert(I);
    return s.interactions.find((Body::id_t)id1, (Body::id_t)id2);
}

// The items of a Python list that must all be of class T (O.engines, O.miscParams); TypeError for
// anything else, naming the first item that is not a T.
template <class T> std::vector<std::shared_ptr<T>> listOf(py::object list, const std::string& name, const std::string& aList, const std::string& aT) {
    if (!py::isinstance<py::sequence>(list) || py::isinstance<py::str>(list)) throw py::type_error(name + " must be " + aList);
    std::vector<std::shared_ptr<T>> items;
    for (py::handle h : list) {
        if (!py::isinstance<T>(h)) throw py::type_error(name + ": " + std::string(py::str(py::repr(h))) + " is not " + aT);
        items.push_back(py::cast<std::shared_ptr<T>>(h));
    }
    return items;
}

void checkBodyId(long id) {
    if (id < 0 || id >= (long)scene().bodies.size()) throw py::index_error("Body id " + std::to_string(id) + " out of range.");
    scene().forces.resize(scene().bodies.size());
}

// O.forces from Python. While O.run() runs in the background, each call waits for the end of the
// current step and lets the run go on afterwards (BetweenSteps): reading a total syncs the per-thread
// lists and adding writes to them, which the loop's threads do at the same time (a data race). From a
// PyRunner (inside the loop, between two engines) the calls act at once.
struct ForceContainerProxy {
    Vector3r f(long id, bool) { BetweenSteps between; checkBodyId(id); return scene().forces.getForce((int)id); }
    Vector3r t(long id, bool) { BetweenSteps between; checkBodyId(id); return scene().forces.getTorque((int)id); }
    void addF(long id, const Vector3r& v, bool permanent) {
        if (permanent) { // (the reference's deprecated form: it sets the permanent force, as setPermF)
            logWarning("O.forces.addF(...,permanent=True) is deprecated, use O.forces.setPermF(...) instead");
            return setPermF(id, v);
        }
        if (!isFinite(v)) throw py::value_error("O.forces.addF: force must be finite");
        BetweenSteps between;
        checkBodyId(id);
        scene().forces.addForce((int)id, v);
    }
    void addT(long id, const Vector3r& v, bool permanent) {
        if (permanent) {
            logWarning("O.forces.addT(...,permanent=True) is deprecated, use O.forces.setPermT(...) instead");
            return setPermT(id, v);
        }
        if (!isFinite(v)) throw py::value_error("O.forces.addT: torque must be finite");
        BetweenSteps between;
        checkBodyId(id);
        scene().forces.addTorque((int)id, v);
    }
    void setPermF(long id, const Vector3r& v) {
        if (!isFinite(v)) throw py::value_error("O.forces.setPermF: force must be finite");
        BetweenSteps between;
        checkBodyId(id);
        scene().forces.setPermForce((int)id, v);
    }
    void setPermT(long id, const Vector3r& v) {
        if (!isFinite(v)) throw py::value_error("O.forces.setPermT: torque must be finite");
        BetweenSteps between;
        checkBodyId(id);
        scene().forces.setPermTorque((int)id, v);
    }
    Vector3r permF(long id) { BetweenSteps between; checkBodyId(id); return scene().forces.getPermForce((int)id); }
    Vector3r permT(long id) { BetweenSteps between; checkBodyId(id); return scene().forces.getPermTorque((int)id); }
    void reset(bool resetAll) {
        BetweenSteps between;
        ForceContainer& fc = scene().forces;
        fc.resize(scene().bodies.size());
        if (resetAll) fc.clearPermanent();
        fc.reset();
        fc.sync(); // (the totals then hold the permanent forces kept, as after a step's reset)
    }
};

struct MaterialContainerProxy {
    py::object append(py::object arg) {
        Scene& s = scene();
        if (py::isinstance<Material>(arg)) return py::cast(s.appendMaterial(py::cast<std::shared_ptr<Material>>(arg)));
        if (!py::isinstance<py::sequence>(arg) || py::isinstance<py::str>(arg))
            throw py::type_error("O.materials.append: expected a Material or a list of materials");
        py::list ids;
        for (py::handle h : arg) {
            if (!py::isinstance<Material>(h)) throw py::type_error("O.materials.append: every item must be a Material");
            ids.append(s.appendMaterial(py::cast<std::shared_ptr<Material>>(h)));
        }
        return std::move(ids);
    }
    std::shared_ptr<Material> get(py::object key) {
        auto& mats = scene().materials;
        if (py::isinstance<py::str>(key)) {
            const std::string label = py::cast<std::string>(key);
            for (const auto& m : mats)
                if (m->label == label) return m;
            throw py::key_error("No material labeled '" + label + "'.");
        }
        if (!py::isinstance<py::int_>(key)) // (py::cast<long> of anything else raised "RuntimeError: Unable to cast Python instance")
            throw py::type_error("O.materials[...]: expected an int id or a str label, got " + std::string(py::repr(key)));
        long i = -1;
        try {
            i = normIndex(py::cast<long>(key), mats.size());
        } catch (py::cast_error&) { // beyond the range of a long: out of range
        }
        if (i < 0 || i >= (long)mats.size()) throw py::index_error("Material id " + std::string(py::str(key)) + " out of range.");
        return mats[i];
    }
    long index(const std::string& label) { return get(py::str(label))->id; }
    size_t len() { return scene().materials.size(); }
    py::iterator iter() { return py::iter(py::cast(scene().materials)); }
};

struct TagsProxy {
    std::string get(const std::string& k) {
        auto& t = scene().tags;
        auto it = t.find(k);
        if (it == t.end()) throw py::key_error("No such tag: " + k);
        return it->second;
    }
    void set(const std::string& k, const std::string& v) { scene().tags[k] = v; }
    bool has(const std::string& k) { return scene().tags.count(k) > 0; }
    std::vector<std::string> keys() {
        std::vector<std::string> r;
        for (const auto& kv : scene().tags) r.push_back(kv.first);
        return r;
    }
    py::list items() {
        py::list r;
        for (const auto& kv : scene().tags) r.append(py::make_tuple(kv.first, kv.second));
        return r;
    }
};

struct EnergyProxy {
    py::list keys() { return py::cast(scene().energy.names()); }
    Real get(const std::string& k) {
        auto& e = scene().energy;
        const auto n = e.names();
        const auto v = e.values();
        for (size_t i = 0; i < n.size(); ++i)
            if (n[i] == k) return v[i];
        throw py::key_error("No energy term '" + k + "' (O.energy.keys() lists them; is O.trackEnergy on?)");
    }
    py::list items() {
        auto& e = scene().energy;
        const auto n = e.names();
        const auto v = e.values();
        py::list r;
        for (size_t i = 0; i < v.size(); ++i) r.append(py::make_tuple(n[i], v[i]));
        return r;
    }
    py::list values() { return py::cast(scene().energy.values()); }
    bool has(const std::string& k) {
        for (const auto& n : scene().energy.names())
            if (n == k) return true;
        return false;
    }
};

struct OmegaProxy {};

// The time stepper of O.engines (the first one; null if none).
static TimeStepper* timeStepper() {
    for (const auto& e : scene().getEngines())
        if (auto* t = dynamic_cast<TimeStepper*>(e.get())) return t;
    return nullptr;
}

// Runs save(scene) between two steps: directly from inside the loop (a PyRunner making a checkpoint),
// otherwise by stopping a running loop and starting it again afterwards.
template <class Save> void betweenSteps(Save save) {
    Omega& o = omega();
    if (o.inLoopThread()) return save(o.scene());
    const bool resume = o.interrupt();
    try {
        save(o.scene());
    } catch (...) {
        if (resume) o.run(-1);
        throw;
    }
    if (resume) o.run(-1); // stopAtIter is kept: a run of n steps still ends where it would have
}
std::string saveCurrentScene(bool xml) {
    std::string data;
    betweenSteps([&](Scene& s) { data = SceneIO::save(s, xml); });
    return data;
}
// Replaces the current scene by one loaded (labels bound again), or raises leaving it as it was.
void loadScene(const std::function<std::shared_ptr<Scene>()>& load) {
    std::shared_ptr<Scene> loaded;
    {
        py::gil_scoped_release nogil;
        loaded = load(); // throws before anything changes
        omega().setScene(loaded);
    }
    injectLabels(loaded->getEngines());
}
// Raises the error that stopped the loop as Python sees it (C++ exceptions translated as usual),
// with a note naming where it arose (the engine with its label, the iteration).
[[noreturn]] void raiseNamingSource(std::exception_ptr failure, const std::string& source) {
    py::cpp_function rethrow([failure]() { std::rethrow_exception(failure); });
    try {
        rethrow();
    } catch (py::error_already_set& e) {
        if (!source.empty() && py::hasattr(e.value(), "add_note")) // (Python 3.11)
            e.value().attr("add_note")("The simulation stopped on this error " + source + ".");
        throw;
    }
    throw std::logic_error("raiseNamingSource: no exception"); // (not reached)
}
// The GUI's turn while the main thread waits for a run: yade.qt._whileWaiting (draws the open views and
// saves the snapshots SnapshotEngine asks for), or None when yade.qt is not imported or has no view.
static py::object guiWhileWaiting() {
    py::dict modules = py::module_::import("sys").attr("modules");
    if (!modules.contains("yade.qt")) return py::none();
    return py::getattr(modules["yade.qt"], "_whileWaiting", py::none());
}

// Blocks until the background run stops, with the GIL released, waking every 50 ms (20 ms while the GUI
// has views, to draw them) to let Python handle signals: on Ctrl-C (KeyboardInterrupt, or whatever a
// signal handler raised) the run stops at the end of its current step and the exception propagates.
void waitInterruptibly() {
    Omega& o = omega();
    py::object gui = guiWhileWaiting();
    for (;;) {
        bool stopped;
        {
            py::gil_scoped_release nogil;
            stopped = o.waitFor(std::chrono::milliseconds(gui.is_none() ? 50 : 20));
        }
        if (stopped) {
            if (!gui.is_none()) gui(); // (the views show the last step; snapshots asked for are saved)
            break;
        }
        if (!gui.is_none() && !py::cast<bool>(gui())) gui = py::none(); // (False: no view any more)
        if (PyErr_CheckSignals() != 0) {
            py::error_already_set e; // (takes the pending exception)
            {
                py::gil_scoped_release nogil;
                o.pause();
            }
            throw e;
        }
    }
    std::exception_ptr failure;
    {
        py::gil_scoped_release nogil;
        try {
            o.wait(); // rethrows what stopped the run
        } catch (...) {
            failure = std::current_exception();
        }
    }
    if (failure) raiseNamingSource(failure, o.lastErrorSource());
}
} // namespace

void bindOmega(py::module_& m) {
    m.def("createInteraction", &createInteraction, py::arg("id1"), py::arg("id2"), py::arg("virtualI") = false,
            "Create the interaction of bodies id1 and id2 by hand: its geometry from the Ig2 functor of O.engines' InteractionLoop, "
            "made even if the bodies do not touch, and its physics from the Ip2 functor (virtualI=True: a potential pair only). "
            "RuntimeError if a body is missing, the pair exists, or the loop has no functor for it.");
    py::class_<BodyContainerProxy>(m, "BodyContainer", "O.bodies: bodies indexed by id")
            .def("append", &BodyContainerProxy::append, py::arg("body"), "Append a Body (returns its id) or a list of bodies (returns their ids)")
            .def("__getitem__", &BodyContainerProxy::get)
            .def("__len__", &BodyContainerProxy::len)
            .def("__iter__", &BodyContainerProxy::iter)
            .def("erase", &BodyContainerProxy::erase, py::arg("id"), py::arg("eraseClumpMembers") = false,
                    "Remove a body and its interactions; True if it existed. A clump's members become standalone, or are erased with it "
                    "(eraseClumpMembers=True); a clump member cannot be erased alone (ValueError: release it first)")
            .def("appendClumped", &BodyContainerProxy::appendClumped, py::arg("bodies"), py::arg("discretization") = 0,
                    "Append the bodies of the list and make a clump of them (3.5.3); returns (clumpId, [memberIds]). Mass, centroid and "
                    "inertia are the members' summed (discretization=0: overlaps counted twice, as the reference) or integrated over "
                    "the union of the member spheres on a grid of discretization cells along the shortest side of their box")
            .def("clump", &BodyContainerProxy::clump, py::arg("ids"), py::arg("discretization") = 0,
                    "Make a clump of the standalone bodies with these ids; returns the clump's id")
            .def("addToClump", &BodyContainerProxy::addToClump, py::arg("bids"), py::arg("cid"), py::arg("discretization") = 0,
                    "Add standalone bodies (or all members of other clumps, which end) to clump cid; its properties are computed again")
            .def("getRoundness", &BodyContainerProxy::getRoundness, py::arg("excludeList") = py::list(),
                    "Mean roundness R1/R2 of the standalone spheres (1) and clumps: R1 the radius of a sphere of the members' volume, R2 "
                    "the radius of the sphere about the centroid that holds every member; bodies in excludeList are left out (0: none left)")
            .def("releaseFromClump", &BodyContainerProxy::releaseFromClump, py::arg("bid"), py::arg("cid"), py::arg("discretization") = 0,
                    "Make member bid of clump cid standalone (it keeps its velocity); a clump keeps 2 members at least (warning)")
            .def("replace", &BodyContainerProxy::replace, py::arg("bodies"),
                    "Remove all bodies and interactions, then append the bodies of the list (ids from 0); returns their ids")
            .def("insertAtId", &BodyContainerProxy::insertAtId, py::arg("body"), py::arg("insertatid"),
                    "Put a body (not yet in a scene) at a free id: a hole left by erase, or past the end (the ids between become holes); returns the id")
            .def("clear", &BodyContainerProxy::clear, "Remove all bodies and interactions");
    py::class_<RealInteractionIterator>(m, "InteractionIterator", "Iterator over the real interactions of O.interactions")
            .def("__iter__", [](RealInteractionIterator& it) -> RealInteractionIterator& { return it; }, py::return_value_policy::reference_internal)
            .def("__next__", &RealInteractionIterator::step);
    py::class_<InteractionContainerProxy>(m, "InteractionContainer", "O.interactions: interactions indexed by a pair of ids")
            .def("__getitem__", &InteractionContainerProxy::get)
            .def("__len__", &InteractionContainerProxy::len)
            .def("__iter__",
                    [](InteractionContainerProxy&) {
                        BetweenSteps between;
                        const InteractionContainer& intrs = scene().interactions;
                        RealInteractionIterator it;
                        it.serial = scene().serial;
                        for (size_t k = 0; k < intrs.size(); ++k)
                            if (intrs.isReal(k)) it.pairs.emplace_back(intrs.pairIds[2 * k], intrs.pairIds[2 * k + 1]);
                        return it;
                    },
                    "Iterate over real interactions")
            .def("has", &InteractionContainerProxy::has, py::arg("id1"), py::arg("id2"), py::arg("onlyReal") = false)
            .def("all", &InteractionContainerProxy::all, py::arg("onlyReal") = false)
            .def("withBody", &InteractionContainerProxy::withBody, py::arg("id"), "Real interactions of body #id")
            .def("withBodyAll", &InteractionContainerProxy::withBodyAll, py::arg("id"), "All interactions of body #id, potential ones (bounds overlapping, no contact) too")
            .def("nth", &InteractionContainerProxy::nth, py::arg("n"), "The n-th interaction of the container (in its own order, real or potential)")
            .def("countReal", [](InteractionContainerProxy&) {
                BetweenSteps between;
                return scene().interactions.countReal();
            })
            .def("erase", &InteractionContainerProxy::erase, py::arg("id1"), py::arg("id2"), "Make the real interaction of id1 and id2 a potential one (its geom and phys dropped; the next step computes it again, real again if the bodies still touch), as the reference does; a potential pair, or no pair, is left as it is")
            .def("clear", [](InteractionContainerProxy&) {
                BetweenSteps between;
                scene().interactions.clear();
            });
    py::class_<ForceContainerProxy>(m, "ForceContainer", "O.forces: forces and torques of the current step")
            .def("f", &ForceContainerProxy::f, py::arg("id"), py::arg("sync") = false, "Force on body #id")
            .def("t", &ForceContainerProxy::t, py::arg("id"), py::arg("sync") = false, "Torque on body #id")
            .def("addF", &ForceContainerProxy::addF, py::arg("id"), py::arg("f"), py::arg("permanent") = false)
            .def("addT", &ForceContainerProxy::addT, py::arg("id"), py::arg("t"), py::arg("permanent") = false)
            .def("permF", &ForceContainerProxy::permF, py::arg("id"), "Permanent force on body #id (setPermF)")
            .def("permT", &ForceContainerProxy::permT, py::arg("id"), "Permanent torque on body #id (setPermT)")
            .def("setPermF", &ForceContainerProxy::setPermF, py::arg("id"), py::arg("f"), "Set the permanent force on body #id: it acts at every step until changed (replaces the previous one)")
            .def("setPermT", &ForceContainerProxy::setPermT, py::arg("id"), py::arg("t"), "Set the permanent torque on body #id: it acts at every step until changed (replaces the previous one)")
            .def("m", &ForceContainerProxy::t, py::arg("id"), py::arg("sync") = false, "Deprecated alias of t (torque)")
            .def("reset", &ForceContainerProxy::reset, py::arg("resetAll") = true,
                    "Zero the forces and torques of the current step and, with resetAll (the default), the permanent ones; resetAll=False keeps the permanent ones")
            .def("getPermForceUsed", [](ForceContainerProxy&) { BetweenSteps between; return scene().forces.hasPermanent(); },
                    "Whether permanent forces or torques were set (since the last reset(resetAll=True))")
            .def_property("syncCount", [](ForceContainerProxy&) { return scene().forces.syncCount; },
                    [](ForceContainerProxy&, long long n) { scene().forces.syncCount = n; }, "Syncs of the per-thread contributions that had something to add (as O.forceSyncCount)");
    py::class_<MaterialContainerProxy>(m, "MaterialContainer", "O.materials: shared materials")
            .def("append", &MaterialContainerProxy::append)
            .def("__getitem__", &MaterialContainerProxy::get)
            .def("__len__", &MaterialContainerProxy::len)
            .def("__iter__", &MaterialContainerProxy::iter)
            .def("index", &MaterialContainerProxy::index, py::arg("label"));
    py::class_<TagsProxy>(m, "TagsWrapper", "O.tags: string tags of the simulation")
            .def("__getitem__", &TagsProxy::get)
            .def("__setitem__", &TagsProxy::set)
            .def("__contains__", &TagsProxy::has)
            .def("has_key", &TagsProxy::has)
            .def("keys", &TagsProxy::keys)
            .def("items", &TagsProxy::items);

    py::class_<EnergyProxy>(m, "EnergyTracker", "O.energy: energy terms (filled while O.trackEnergy is True)")
            .def("keys", &EnergyProxy::keys)
            .def("items", &EnergyProxy::items)
            .def("values", &EnergyProxy::values)
            .def("__getitem__", &EnergyProxy::get)
            .def("__contains__", &EnergyProxy::has)
            .def("__len__", [](EnergyProxy&) { return scene().energy.names().size(); })
            .def("__iter__", [](EnergyProxy& e) { return py::iter(e.keys()); })
            .def("total", [](EnergyProxy&) { return scene().energy.total(); }, "Sum of all terms (constant when the budget is complete)")
            .def("clear", [](EnergyProxy&) { scene().energy.clear(); }, "Remove all terms");

    using release = py::call_guard<py::gil_scoped_release>;
    static auto startTime = std::chrono::steady_clock::now(); // (O.resetTime() moves it)
    py::class_<OmegaProxy>(m, "Omega", "The simulation controller; the instance is O (Omega() gives another handle on the same one, as in Yade's O = Omega())")
            .def(py::init<>())
            .def_property_readonly("bodies", [](OmegaProxy&) { return BodyContainerProxy(); })
            .def_property_readonly("interactions", [](OmegaProxy&) { return InteractionContainerProxy(); })
            .def_property_readonly("forces", [](OmegaProxy&) { return ForceContainerProxy(); })
            .def_property_readonly("materials", [](OmegaProxy&) { return MaterialContainerProxy(); })
            .def_property_readonly("tags", [](OmegaProxy&) { return TagsProxy(); })
            .def_property_readonly("energy", [](OmegaProxy&) { return EnergyProxy(); })
            .def_property("trackEnergy", [](OmegaProxy&) { return scene().trackEnergy; },
                    [](OmegaProxy&, bool v) { scene().trackEnergy = v; }, "Whether engines add to O.energy (off: no cost)")
            .def_property("timingEnabled", [](OmegaProxy&) { return Scene::timingEnabled; },
                    [](OmegaProxy&, bool v) { Scene::timingEnabled = v; },
                    "Whether engines accumulate execTime/execCount (yade.timing.stats() prints them)")
            .def_property("miscParams", [](OmegaProxy&) { return scene().miscParams; },
                    [](OmegaProxy&, py::object list) {
                        scene().miscParams = listOf<Serializable>(list, "O.miscParams", "a list of Yade objects", "a Yade object (Serializable)");
                    }, "Objects of any Yade class saved and loaded with the simulation (e.g. parameters a script reads back)")
            .def_property("engines", [](OmegaProxy&) { return scene().getEngines(); },
                    [](OmegaProxy&, py::object list) {
                        const auto engines = listOf<Engine>(list, "O.engines", "a list of engines", "an Engine");
                        scene().setEngines(engines);
                        injectLabels(engines);
                    }, "The simulation loop: engines run in this order every step")
            .def("resetTime", [](OmegaProxy&) {
                if (omega().isRunning()) throw std::runtime_error("O.resetTime() while the simulation runs: O.pause() first");
                scene().iter = 0;
                scene().time = 0;
                startTime = std::chrono::steady_clock::now();
            }, "Set O.iter, O.time and O.realtime back to zero (nothing else changes)")
            // (read while a background run may advance them: relaxed atomic loads, as the stores in Scene.cpp)
            .def_property_readonly("iter", [](OmegaProxy&) { return __atomic_load_n(&scene().iter, __ATOMIC_RELAXED); }, "Current iteration (step) number")
            .def_property_readonly("time", [](OmegaProxy&) {
                Real t;
                __atomic_load(&scene().time, &t, __ATOMIC_RELAXED);
                return t;
            }, "Simulated time [s]")
            .def_property_readonly("realtime", [](OmegaProxy&) {
                return std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime).count();
            }, "Wall-clock seconds since start-up")
            .def_property("dt", [](OmegaProxy&) { return scene().dt; }, [](OmegaProxy&, Real v) {
                // (a negative value hands the step to the time stepper in O.engines, as the manual says)
                if (std::isfinite(v) && v < 0) {
                    TimeStepper* stepper = timeStepper();
                    if (!stepper) throw std::runtime_error("No TimeStepper found in O.engines: O.dt < 0 hands the step to one (add e.g. GlobalStiffnessTimeStepper())");
                    stepper->active = true;
                    return;
                }
                scene().setDt(v);
            }, "Time step [s]; a negative value activates the time stepper of O.engines (GlobalStiffnessTimeStepper), which then sets it")
            .def_property("dynDt", [](OmegaProxy&) {
                const TimeStepper* stepper = timeStepper();
                return stepper && stepper->active;
            }, [](OmegaProxy&, bool v) {
                TimeStepper* stepper = timeStepper();
                if (stepper) stepper->active = v;
                else if (v) throw std::runtime_error("No TimeStepper found in O.engines.");
            }, "Whether a time stepper in O.engines sets O.dt (dynamic time step); True activates it (RuntimeError without one), False deactivates it")
            .def_property("stopAtIter", [](OmegaProxy&) { return scene().stopAtIter; },
                    [](OmegaProxy&, long long v) { scene().stopAtIter = v; }, "The loop stops when O.iter reaches this value")
            .def_property_readonly("running", [](OmegaProxy&) { return omega().isRunning(); })
            .def_property_readonly("_lastErrorSource", [](OmegaProxy&) { return omega().lastErrorSource(); },
                    "Where the error that stopped the last run arose: \"in Class labeled 'label' at iteration N\" (empty if none)")
            .def_property("periodic", [](OmegaProxy&) { return scene().isPeriodic; },
                    [](OmegaProxy&, bool v) {
                        if (v != scene().isPeriodic && omega().isRunning()) throw std::runtime_error("O.periodic cannot change while the simulation runs (O.pause() first)");
                        scene().setPeriodic(v);
                        noteExternalWrite();
                    }, "Whether space is periodic, repeating the cell O.cell (3.6)")
            .def("_flipCell", [](OmegaProxy&, const Matrix3r& flip) { return scene().flipCell(flip); }, py::arg("flip"), "utils.flipCell")
            .def_property_readonly("cell", [](OmegaProxy&) -> py::object {
                if (!scene().isPeriodic) return py::none();
                return py::cast(scene().cell);
            }, "The periodic cell (None unless O.periodic)")
            .def_property_readonly("numThreads", [](OmegaProxy&) { return scene().threads(); })
            .def("step", [](OmegaProxy&) { omega().step(); }, release(), "Run one step and return")
            .def("run", [](OmegaProxy&, long long nSteps, bool wait) {
                {
                    py::gil_scoped_release nogil;
                    omega().run(nSteps, wait);
                }
                if (wait) waitInterruptibly();
            }, py::arg("nSteps") = -1, py::arg("wait") = false,
                    "Run in the background (returns at once); nSteps>0 stops after that many steps; wait=True blocks until it stops "
                    "(Ctrl-C stops the run at the end of the current step and raises KeyboardInterrupt)")
            .def("pause", [](OmegaProxy&) { omega().pause(); }, release(), "Stop the loop after the current step")
            .def("wait", [](OmegaProxy&) {
                if (omega().inLoopThread()) throw std::runtime_error("O.wait() cannot be called from inside the simulation loop");
                waitInterruptibly();
            }, "Block until the loop stops; raise what stopped it (Ctrl-C stops the run at the end of the current step and raises KeyboardInterrupt)")
            .def_property("stopAtTime", [](OmegaProxy&) { return scene().stopAtTime; },
                    [](OmegaProxy&, Real v) {
                        if (std::isnan(v)) throw py::value_error("O.stopAtTime must be a number (got NaN)");
                        scene().stopAtTime = v;
                    }, "When positive, the loop stops at the end of the step where O.time reaches it (and sets it to -1)")
            .def_property_readonly("speed", [](OmegaProxy&) { return omega().speed(); },
                    "Steps per second: the mean of the rates (1 / time between the ends of two consecutive steps) over the last 10 steps")
            .def_property("subStepping", [](OmegaProxy&) { return scene().subStepping; },
                    [](OmegaProxy&, bool v) { scene().subStepping = v; },
                    "When True, O.step() runs one part of a step: its start, one engine, or its end (see O.subStep)")
            .def_property_readonly("subStep", [](OmegaProxy&) { return scene().subStep; },
                    "The part of the step O.step() runs next when O.subStepping: -1 the step's start (outside a step), "
                    "k the k-th engine of O.engines, len(O.engines) the step's end (iter and time advance)")
            .def_property("forceSyncCount", [](OmegaProxy&) { return scene().forces.syncCount; },
                    [](OmegaProxy&, long long v) { scene().forces.syncCount = v; },
                    "How many times O.forces gathered the contributions of the threads into the totals (for profiling; may be set)")
            .def("exitNoBacktrace", [](OmegaProxy&, int status) {
                // the run stops at the end of its step (from inside the loop: no wait), the output is flushed, no atexit handler runs
                {
                    py::gil_scoped_release nogil;
                    omega().pause();
                }
                for (const char* stream : {"stdout", "stderr"}) {
                    try {
                        py::module_::import("sys").attr(stream).attr("flush")();
                    } catch (py::error_already_set&) {
                    }
                }
                std::fflush(nullptr);
                std::_Exit(status);
            }, py::arg("status") = 0, "Exit the process at once with the given status (output flushed; no exit handlers run)")
            .def("reset", [](OmegaProxy&) { omega().reset(); }, release(), "Replace the scene with an empty one")
            .def("switchWorld", [](OmegaProxy&) { omega().switchWorld(); }, release(), "Toggle between the primary and the secondary scene")
            .def("_toBytes", [](OmegaProxy&, bool xml) {
                std::string data;
                {
                    py::gil_scoped_release nogil;
                    data = saveCurrentScene(xml);
                }
                return py::bytes(data);
            }, py::arg("xml") = false, "The scene as a saved file's content (binary or XML)")
            .def("_fromBytes", [](OmegaProxy&, py::bytes data) {
                const std::string s = data;
                loadScene([&] { return SceneIO::load(s); });
            }, "Replace the scene by one read from a saved file's content (compressed or not)")
            .def("_saveToFd", [](OmegaProxy&, int fd, bool xml, const std::string& fileName) {
                py::gil_scoped_release nogil;
                betweenSteps([&](Scene& s) { SceneIO::save(s, *fdSink(fd, codecForName(fileName)), xml); });
            }, py::arg("fd"), py::arg("xml"), py::arg("fileName"),
                    "Write the scene to an open file (binary or XML), compressed as the name says (.gz, .bz2, .zst)")
            .def("_loadFromFd", [](OmegaProxy&, int fd) {
                loadScene([&] { return SceneIO::load(*fdSource(fd)); });
            }, py::arg("fd"), "Replace the scene by one read from an open file (any format and compression)")
            .def_property_readonly_static("_codecs", [](py::object) {
                std::vector<std::string> r;
                for (Codec c : {Codec::gzip, Codec::bzip2, Codec::zstd})
                    if (codecAvailable(c)) r.push_back(codecName(c));
                return r;
            }, "The compressions this build writes and reads")
            .def("saveTmp", [](OmegaProxy&, const std::string& slot, bool) {
                py::gil_scoped_release nogil;
                omega().tmpSlots[slot] = saveCurrentScene(false);
            }, py::arg("mark") = "", py::arg("quiet") = false, "Save the scene in memory under a slot name (quiet: accepted, nothing is printed anyway)")
            .def("loadTmp", [](OmegaProxy&, const std::string& slot, bool) {
                auto it = omega().tmpSlots.find(slot);
                if (it == omega().tmpSlots.end())
                    throw std::runtime_error("Cannot load nonexistent memory-saved simulation :memory:" + slot + " (O.saveTmp first)");
                const std::string& data = it->second;
                loadScene([&] { return SceneIO::load(data); });
            }, py::arg("mark") = "", py::arg("quiet") = false, "Load the scene saved by O.saveTmp under that slot name")
            .def("labeledEngine", [](OmegaProxy&, const std::string& label) {
                std::set<Serializable*> seen;
                for (const auto& e : scene().getEngines())
                    if (auto r = findLabeled(e, label, seen)) return py::cast(r);
                throw py::value_error("No engine labeled `" + label + "'");
            }, py::arg("label"), "The engine or functor of O.engines with that label (a label also names it in the script's namespace)")
            .def("runEngine", [](OmegaProxy&, const std::shared_ptr<Engine>& e) {
                if (!e) throw py::type_error("O.runEngine: the engine is None");
                if (omega().isRunning()) throw std::runtime_error("O.runEngine() while the simulation runs: O.pause() first");
                py::gil_scoped_release nogil;
                Scene& s = scene();
                s.forces.resize(s.bodies.size());
                s.interactions.resizeBodies(s.bodies.size());
                e->scene = &s;
                e->action();
            }, py::arg("engine"), "Run one engine once in the current scene; O.iter and O.time do not change")
            .def_property_readonly("_currEngines", [](OmegaProxy&) { return scene().currentEngines(); },
                    "The engines the current step runs (O.engines assigned during a step takes effect at its end)")
            .def_property_readonly("_nextEngines", [](OmegaProxy&) { return scene().pendingEngines(); },
                    "The engines assigned during the current step, run from the next one (empty if none)")
            .def_property_readonly("dynDtAvailable", [](OmegaProxy&) { return timeStepper() != nullptr; },
                    "Whether O.engines holds a time stepper, active or not")
            .def("resetThisScene", [](OmegaProxy&) { omega().reset(); }, release(), "Replace the current scene with an empty one (as O.reset())")
            .def("resetCurrentScene", [](OmegaProxy&) { omega().reset(); }, release(), "Replace the current scene with an empty one (as O.reset())")
            .def("resetAllScenes", [](OmegaProxy&) { omega().resetAll(); }, release(), "Replace both scenes (see O.switchScene) with empty ones")
            .def("switchScene", [](OmegaProxy&) { omega().switchWorld(); }, release(), "Toggle between the primary and the secondary scene (as O.switchWorld())")
            .def_property_readonly("thisScene", [](OmegaProxy&) { return omega().sceneIndex(); }, "The current scene: 0 the primary, 1 the secondary")
            .def("disableGdb", [](OmegaProxy&) {}, "Does nothing (no debugger handlers are installed)")
            .def("tmpToString", [](OmegaProxy&, const std::string& slot) {
                auto it = omega().tmpSlots.find(slot);
                if (it == omega().tmpSlots.end()) throw std::runtime_error("No memory-saved simulation :memory:" + slot + " (O.saveTmp first)");
                std::string xml;
                {
                    py::gil_scoped_release nogil;
                    xml = SceneIO::save(*SceneIO::load(it->second), true);
                }
                return xml;
            }, py::arg("mark") = "", "The simulation saved by O.saveTmp under that slot name, as XML text")
            .def("lsTmp", [](OmegaProxy&) {
                std::vector<std::string> r;
                for (const auto& kv : omega().tmpSlots) r.push_back(kv.first);
                return r;
            }, "Names of the memory slots");
    m.attr("O") = OmegaProxy();
}

} // namespace yade
