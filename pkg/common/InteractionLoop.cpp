#include <core/Scene.hpp>
#include <lib/base/ExternalWrites.hpp>
#include <lib/base/ThreadRange.hpp>
#include <lib/base/Logging.hpp>
#include <pkg/common/InteractionLoop.hpp>
#include <pkg/common/Facet.hpp>
#include <pkg/common/Sphere.hpp>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

void InteractionLoop::checkFunctorChain() const {
    auto& reg = ClassRegistry::instance();
    auto accepts = [&](const std::string& geom, const std::string& phys) {
        for (const auto& law : lawDispatcher->functors) {
            const auto t = law->argTypes();
            if (reg.isSubclass(geom, t.at(0)) && (phys.empty() || reg.isSubclass(phys, t.at(1)))) return true;
        }
        return false;
    };
    std::string laws;
    for (const auto& law : lawDispatcher->functors) laws += (laws.empty() ? "" : ", ") + law->getClassName();
    if (laws.empty()) return; // (no Law2 functor at all: contacts without forces, geometry and physics only, as the reference allows)
    for (const auto& ig2 : geomDispatcher->functors) {
        const std::string g = ig2->producedType();
        if (!accepts(g, ""))
            throw std::invalid_argument(ig2->getClassName() + " produces " + g + ", but no Law2 functor accepts " + g
                    + " (Law2 functors given: " + laws + "); add e.g. a Law2_" + g + "_..._... functor");
        for (const auto& ip2 : physDispatcher->functors) {
            const std::string p = ip2->producedType();
            if (!accepts(g, p))
                throw std::invalid_argument(ig2->getClassName() + " produces " + g + " and " + ip2->getClassName() + " produces "
                        + p + ", but no Law2 functor accepts the pair (" + g + ", " + p + ") (Law2 functors given: " + laws + ")");
        }
    }
}

void InteractionLoop::warnMissingIg2(const Shape& a, const Shape& b) {
    // (std::minmax of two temporaries returns references to them: the indices are copied first)
    const int ia = a.getClassIndex(), ib = b.getClassIndex();
    const std::pair<int, int> key(std::min(ia, ib), std::max(ia, ib));
    if (!warnedShapePairs.insert(key).second) return;
    logWarning("InteractionLoop: no Ig2 functor for " + a.getClassName() + "+" + b.getClassName()
            + " (an Ig2_" + a.getClassName() + "_" + b.getClassName() + "_* functor would handle them); such pairs are skipped");
}

void InteractionLoop::prepareShapes() {
    const BodyContainer& bodies = scene->bodies;
    const long n = (long)bodies.size();
    ShapeCache& cache = shapeCache;
    if (cache.changes == bodies.changes && cache.writes == externalWrites() && cache.scene == scene->serial && cache.radius.size() == (size_t)n)
        return;
    cache.writes = externalWrites();
    cache.changes = bodies.changes;
    cache.scene = scene->serial;
    cache.radius.assign(n, NaN);
    cache.shape.assign(n, nullptr);
    cache.shapeIndex.assign(n, -1);
    cache.material.assign(n, nullptr);
    cache.facetIds.clear();
    const int sphereIndex = Sphere::classIndexStatic(), facetIndex = Facet::classIndexStatic();
    for (long id = 0; id < n; ++id) {
        const Body* b = bodies[(Body::id_t)id].get();
        if (b) cache.material[id] = b->material;
        if (!b || !b->shape) continue;
        const int c = b->shape->getClassIndex();
        cache.shape[id] = b->shape.get();
        cache.shapeIndex[id] = c;
        if (const Sphere* sphere = c == sphereIndex ? static_cast<const Sphere*>(b->shape.get()) : dynamic_cast<const Sphere*>(b->shape.get()))
            cache.radius[id] = sphere->radius;
        else if (c == facetIndex) { // few facets: in id order
            cache.radius[id] = -1 - (Real)cache.facetIds.size();
            cache.facetIds.push_back((Body::id_t)id);
        }
    }
    cacheBuilt = true;
}

bool InteractionLoop::prepareQuickReject() {
    Sphere sphereProbe;
    Facet facetProbe;
    const IGeomFunctor* ss = geomDispatcher->getFunctor(sphereProbe, sphereProbe).functor;
    const IGeomFunctor* fs = geomDispatcher->getFunctor(facetProbe, sphereProbe).functor;
    sphereSphereReach = ss ? ss->quickRejectFactor() : -1;
    facetSphereReach = fs ? fs->quickRejectFactor() : -1;
    if (sphereSphereReach <= 0 && facetSphereReach <= 0) return false;
    const BodyContainer& bodies = scene->bodies;
    const long n = (long)bodies.size();
    quickFromIntegrator = !cacheBuilt && scene->motion.current();
    if (quickFromIntegrator) { // shapes unchanged: the integrator's positions
        shapePos = scene->motion.positions();
        if (!quickPos.empty()) std::vector<Vector3r>().swap(quickPos); // (the usual case: not kept)
    } else { // from the bodies' records
        quickPos.resize(n);
        const BodyStore& hot = bodies.hot();
        for (long id = 0; id < n; ++id) quickPos[id] = hot.exists[id] ? hot.pos[id] : Vector3r::Constant(NaN);
        shapePos = quickPos.data();
    }
    shapeRadius = shapeCache.radius.data();
    facetPlanes.clear(); // facets may move or turn: their planes are computed every step
    facetOri.clear();
    facetReach.clear();
    for (Body::id_t id : shapeCache.facetIds) {
        const Body& b = *bodies[id];
        const Facet& f = static_cast<const Facet&>(*b.shape);
        const Quaternionr& ori = b.state->ori();
        facetPlanes.push_back(FacetPlane{b.state->pos(), ori * f.normal, {ori * f.ne[0], ori * f.ne[1], ori * f.ne[2]}, f.icr});
        facetOri.push_back(ori);
        facetReach.push_back(std::max({f.vertices[0].norm(), f.vertices[1].norm(), f.vertices[2].norm()}));
    }
    return true;
}

// Any point of a facet moved at most |Δposition| + θ·reach since the epoch began, θ the angle it
// turned by (|R(θ) - I| = 2 sin(θ/2) <= θ): with this in D the gaps stay lower bounds, as for spheres.
Real InteractionLoop::facetDisplacement2() const {
    Real worst = 0;
    for (size_t f = 0; f < facetPlanes.size(); ++f) {
        const Real moved = (facetPlanes[f].point - skin.facetPlanes[f].point).norm();
        const Real dot = std::min(Real(1), std::abs(facetOri[f].coeffs().dot(skin.facetOri[f].coeffs())));
        const Real angle = 2 * std::acos(dot);
        worst = std::max(worst, moved + angle * facetReach[f]);
    }
    return worst * worst;
}

void InteractionLoop::prepareSkin(bool quick) {
    skin.active = skin.fresh = false;
    if (!quick) {
        skin.pairsBuild = -1;
        return;
    }
    const size_t n = shapeCache.radius.size();
    // (facets that moved or turned keep the epoch: their motion is added to D, facetDisplacement2)
    const bool keep = quickFromIntegrator && skin.pairsBuild == threadPairsBuild && skin.refPos->size() == n
            && skin.facetPlanes.size() == facetPlanes.size() && skin.sphereSphereReach == sphereSphereReach && skin.facetSphereReach == facetSphereReach;
    skin.active = true;
    if (keep) return;
    // a new epoch: positions now are the reference; every pair is tested in this step
    skin.fresh = true;
    // (of the spheres only: the pairs it skips are of two spheres, or of a facet and a sphere, whose
    // facet's motion is facetDisplacement2; other bodies are NaN, which the largest displacement ignores)
    auto ref = std::make_shared<std::vector<Vector3r>>(shapePos, shapePos + n);
    for (size_t id = 0; id < n; ++id)
        if (!(shapeCache.radius[id] > 0)) (*ref)[id] = Vector3r::Constant(NaN);
    skin.refPos = ref;
    // the integrator measures D from them too (a tag unique to this epoch of this loop)
    static std::atomic<long long> epochs{0};
    skin.tag = ++epochs;
    scene->motion.setReference(skin.refPos, skin.tag);
    Real scale = 0;
    for (size_t id = 0; id < n; ++id) {
        const Real extent = (*skin.refPos)[id].cwiseAbs().maxCoeff() + std::abs(shapeCache.radius[id]);
        if (extent > scale) scale = extent; // (NaN: ignored)
    }
    skin.tolerance = 1e-11 * scale;
    skin.gap.resize(threadPairs.size());
    skin.todo.resize(threadPairs.size());
    skin.near.resize(threadPairs.size());
    skin.nearLimit.assign(threadPairs.size(), {-Inf, -Inf});
    skin.withFacet.resize(threadPairs.size());
    for (size_t list = 0; list < threadPairs.size(); ++list) {
        skin.gap[list].assign(threadPairs[list].size(), -Inf);
        skin.withFacet[list].assign(threadPairs[list].size(), 0);
    }
    skin.facetPlanes = facetPlanes;
    skin.facetOri = facetOri;
    skin.sphereSphereReach = sphereSphereReach;
    skin.facetSphereReach = facetSphereReach;
    skin.pairsBuild = threadPairsBuild;
}

// A sphere whose center is out of reach of a facet's plane. The functor computes the distance in
// the facet's frame, this in global coordinates: a relative margin of 1e-12 for the rounding
// leaves the borderline cases to the functor.
// x as a float not above it: the skin's gaps are kept in floats (half the memory), and a gap
// rounded down only makes a pair tested a step earlier, never skipped when it should not be.
// (Lowered by more than a float's rounding error before rounding, relative 2^-24 plus 2^-149
// below the normal range: no branch and no library call, it runs for every pair left out.)
static inline float floatBelow(Real x) { return (float)(x - (std::abs(x) * 0x1p-22 + 0x1p-140)); }

bool InteractionLoop::facetSphereReject(Body::id_t sphere, Real facetCode, Real& gap) const {
    const Real radius = shapeRadius[sphere];
    if (facetSphereReach <= 0 || !(radius > 0) || !(facetCode < 0)) return false;
    const FacetPlane& plane = facetPlanes[(size_t)(-1 - facetCode)];
    const Vector3r d = shapePos[sphere] - plane.point;
    const Real reach = facetSphereReach * radius;
    // The distance from the triangle is at least that from the half-plane (of the facet's plane)
    // inside the edge the centre is farthest beyond: out of the plane by |n·d|, beyond that edge's
    // line by its ne·d - icr (0 inside the triangle). The functor finds the contact point on the
    // triangle (face, edge or vertex; shrinkFactor only makes it smaller), so it finds no contact
    // either. Each of these half-plane distances moves at most as much as the sphere: the skin's
    // bound holds for this gap as for the plane's. (The margin covers the functor's rounding in
    // the facet's frame.)
    const Real height = plane.normal.dot(d);
    const Real beyond = std::max(Real(0), std::max({plane.edge[0].dot(d), plane.edge[1].dot(d), plane.edge[2].dot(d)}) - plane.icr);
    const Real distance = std::sqrt(height * height + beyond * beyond), limit = reach + 1e-12 * (d.cwiseAbs().sum() + plane.point.cwiseAbs().sum() + reach);
    gap = distance - limit;
    return distance > limit; // false for NaN
}

// (threadOwning() gives the thread that integrates a body: only locality depends on the split, never results.)
void InteractionLoop::assignPairsToThreads(int threads) {
    const InteractionContainer& intrs = scene->interactions;
    const long nBodies = (long)scene->bodies.size(), n = (long)intrs.size();
    threadPairs.resize(threads); // (the lists and scratch arrays keep their memory from call to call: fresh pages cost more than the work)
    for (auto& list : threadPairs) list.clear();
    // A contact (real at the last pass) costs the functors' work, a potential pair about one test.
    constexpr long realWeight = 30;
    // first the weight of the pairs with one possible thread, then, in container order (each list
    // stays in it), the pairs across two ranges to the one of their two threads with less work.
    // Without branches: which case a pair is in is unpredictable, and a mispredicted branch per
    // pair cost more than the rest of the work.
    std::vector<int>& owner = assignScratch.owner; // per body (contiguous: the loops below read them at random)
    std::vector<int>& partners = assignScratch.partners;
    std::vector<int>& fixed = assignScratch.fixed; // per pair: the thread, or -1: either of the two bodies' threads
    owner.resize(nBodies);
    partners.resize(nBodies);
    fixed.resize(n);
    for (long id = 0; id < nBodies; ++id) {
        owner[id] = threadOwning(id, nBodies, threads);
        partners[id] = (int)intrs.partnersOf((Body::id_t)id).size();
    }
    std::vector<long> loads(threads + 1, 0); // [0]: the pairs not fixed yet; [1 + t]: thread t
    long* load = loads.data() + 1;
    const bool saved = useSavedSplit(threads, n); // (a scene just loaded: split as it was saved)
    for (long k = 0; k < n && !saved; ++k) {
        const Body::id_t a = intrs.pairIds[2 * k], b = intrs.pairIds[2 * k + 1];
        const int ta = owner[a], tb = owner[b], na = partners[a], nb = partners[b];
        const bool followA = ta == tb || nb > 4 * na + 16; // (b is a boundary, e.g. a facet touching many bodies: follow a)
        const int t = followA ? ta : (na > 4 * nb + 16 ? tb : -1);
        fixed[k] = t;
        load[t] += intrs.wasReal[k] ? realWeight : 1;
    }
    for (long k = 0; k < n && !saved; ++k) {
        const int ta = owner[intrs.pairIds[2 * k]], tb = owner[intrs.pairIds[2 * k + 1]], f = fixed[k];
        const int t = f >= 0 ? f : (load[tb] < load[ta] ? tb : ta);
        load[t] += (f < 0) * (intrs.wasReal[k] ? realWeight : 1);
        threadPairs[t].push_back((uint32_t)k);
    }
    // Each list in the order of its pairs' smaller body id (a counting sort: container order among
    // equal ids). Consecutive contacts then read neighbouring entries of the body columns; in the
    // container's order (the collider's sweep along x) they read bodies anywhere in the scene, and
    // at 50 000 spheres most of those reads missed the caches. (Bodies read from a file are in no
    // spatial order, so the larger id of each pair is anywhere: processBatch and the fused passes
    // load those ahead, processBatch only where a list's pairs are so (threadPairsScattered: in a
    // lattice built in order those loads cost more than they saved). A spatial order of the pairs
    // (Morton code of the bodies) was tried on the DEM8 drum: about 10 % slower than this, as the
    // smaller ids no longer come in order.)
    std::vector<uint32_t>& start = assignScratch.start;
    std::vector<uint32_t>& sorted = assignScratch.sorted;
    threadPairsScattered.assign(threads, false);
    for (int t = 0; t < threads; ++t) {
        std::vector<uint32_t>& list = threadPairs[t];
        start.assign(nBodies + 1, 0);
        unsigned long long spread = 0; // sum of |id2 - id1|
        for (uint32_t k : list) {
            ++start[std::min(intrs.pairIds[2 * k], intrs.pairIds[2 * k + 1]) + 1];
            spread += (unsigned long long)std::abs((long long)intrs.pairIds[2 * k + 1] - intrs.pairIds[2 * k]);
        }
        threadPairsScattered[t] = spread > scatteredSpread * list.size();
        for (long id = 0; id < nBodies; ++id) start[id + 1] += start[id];
        sorted.resize(list.size());
        for (uint32_t k : list) sorted[start[std::min(intrs.pairIds[2 * k], intrs.pairIds[2 * k + 1])]++] = k;
        list.swap(sorted);
        // in a periodic scene the pairs through the cell's faces (cellDist not zero) last: the others
        // fill whole batches, which the fast passes and the kept entries take (a batch with one such
        // pair is gathered in full every step)
        if (intrs.periodic)
            std::stable_partition(list.begin(), list.end(), [&](uint32_t k) { return intrs.cellDist[k] == Vector3i::Zero(); });
    }
    // (the per-pair scratch is not kept when large: in a dense packing it was 8 bytes per pair, 5 MB
    // at 50 000 spheres; small ones are, since the lists are rebuilt whenever the pairs change)
    if (sorted.capacity() > (size_t(1) << 16)) std::vector<uint32_t>().swap(sorted);
    if (fixed.capacity() > (size_t(1) << 16)) std::vector<int>().swap(fixed);
    threadPairsFor = intrs.changes;
    threadPairsScene = scene->serial;
    threadPairsBodies = (size_t)nBodies;
    threadPairsCount = (size_t)n; // the lists cover exactly 0 .. n-1
    ++threadPairsBuild;
}

bool InteractionLoop::useSavedSplit(int threads, long pairs) {
    std::vector<int> saved;
    saved.swap(threadSplit); // (used once: the next splits follow the pairs as they change)
    // (only if the pairs did not change since the load, which left the count at 0: a change would
    // have made the original split them anew too)
    if (scene->interactions.changes != 0) return false;
    long total = 0;
    for (size_t i = 0; i + 1 < saved.size(); i += 2) {
        if (saved[i] < 0 || saved[i] >= threads || saved[i + 1] < 0) return false;
        total += saved[i + 1];
    }
    if (saved.empty() || saved.size() % 2 || total != pairs) return false;
    uint32_t k = 0;
    for (size_t i = 0; i < saved.size(); i += 2)
        for (int j = 0; j < saved[i + 1]; ++j) threadPairs[saved[i]].push_back(k++);
    return true;
}

void InteractionLoop::preSave() {
    threadSplit.clear();
    size_t total = 0;
    for (const auto& list : threadPairs) total += list.size();
    if (threadPairs.size() < 2 || total != threadPairsCount) return;
    std::vector<int> threadOf(total, 0);
    for (size_t t = 0; t < threadPairs.size(); ++t)
        for (uint32_t k : threadPairs[t])
            if (k < total) threadOf[k] = (int)t;
    for (size_t k = 0; k < total; ++k) {
        if (k == 0 || threadOf[k] != threadOf[k - 1]) threadSplit.insert(threadSplit.end(), {threadOf[k], 0});
        ++threadSplit.back();
    }
}

void InteractionLoop::postSave() { std::vector<int>().swap(threadSplit); }

// Starts loading the first three cache lines of an object (none: null).
static inline void prefetchObject(const void* p) {
    if (!p) return;
    const char* c = static_cast<const char*>(p);
    for (int l = 0; l < 3; ++l) __builtin_prefetch(c + 64 * l);
}

// (written only when it changes: the flags of both threads' interactions share cache lines, and
// reading a line both threads only read costs nothing; writing it moves it between cores)
static inline void setWasReal(char* wasReal, long k, bool real) {
    if (wasReal[k] != (char)real) wasReal[k] = real;
}

// A pair whose Ig2 functor takes the shapes in the other order: its ids swapped wherever they are kept.
void InteractionLoop::swapPair(long k) {
    InteractionContainer& intrs = scene->interactions;
    if (Interaction* I = intrs.object((size_t)k)) I->swapOrder();
    std::swap(intrs.pairIds[2 * k], intrs.pairIds[2 * k + 1]);
    if (intrs.periodic) intrs.cellDist[k] = -intrs.cellDist[k];
    if (intrs.contactOf[k] != InteractionContainer::noContact) {
        ContactPool::Header& h = intrs.pool(intrs.contactOf[k]).header(InteractionContainer::slotOf(intrs.contactOf[k]));
        std::swap(h.id1, h.id2);
    }
}

// The objects and Law2 functor of pair k: a contact's from its pool record, or a geometry kept from
// an earlier step without physics (where: contactOf[k]).
void InteractionLoop::PoolCursor::find(const InteractionContainer& intrs, uint32_t where, long k, IGeom*& geom, IPhys*& phys, LawFunctor*& law) {
    if (where != InteractionContainer::noContact) { // a contact: its record in a pool
        if (InteractionContainer::poolOf(where) != index) { // (mostly all of one kind)
            index = InteractionContainer::poolOf(where);
            pool = intrs.pools[index].get();
        }
        geom = pool->geom(InteractionContainer::slotOf(where));
        phys = pool->phys(InteractionContainer::slotOf(where));
        law = pool->law; // (refreshed before the parallel part; null for a pool made since)
    } else if (const InteractionContainer::Record* rec = intrs.record((size_t)k)) {
        geom = rec->geom.get();
        phys = rec->phys.get();
    }
}

// The Ig2 functor if it and the Law2 functor have a fast pass (KernelPasses, cached for the last pair asked), else null.
IGeomFunctor* InteractionLoop::fastPass(Scratch& sc, IGeomFunctor* geom, LawFunctor* law) {
    if (sc.passGeom != geom || sc.passLaw != law) {
        sc.passGeom = geom;
        sc.passLaw = law;
        sc.pass = KernelPasses::find(*geom, *law);
    }
    return sc.pass ? geom : nullptr;
}

// A potential pair (ids: its two) that quickReject finds still apart; its gap beyond reach, less the
// margin, then kept for the skin at entry i of the list (gaps null: no skin).
inline bool InteractionLoop::stillApart(const Body::id_t* ids, size_t i, float* gaps, unsigned char* withFacet, const Real* twiceD) const {
    Real gap;
    if (!quickReject(ids[0], ids[1], gap)) return false;
    if (gaps) {
        const bool facet = (shapeRadius[ids[0]] < 0) | (shapeRadius[ids[1]] < 0); // (a facet's radius is its code)
        gaps[i] = floatBelow(gap - twiceD[facet]);
        withFacet[i] = facet;
    }
    return true;
}

// A potential pair of two spheres whose body 2 is the image at + shift2 (a periodic scene) farther
// apart than Ig2_Sphere_Sphere_ScGeom's reach (its test, in the same arithmetic).
inline bool InteractionLoop::imageApart(const Body::id_t* ids, const Vector3r& shift2) const {
    const Real ra = shapeRadius[ids[0]], rb = shapeRadius[ids[1]];
    if (!(ra > 0 && rb > 0 && sphereSphereReach > 0)) return false;
    const Real r = sphereSphereReach * (ra + rb);
    return ((shapePos[ids[1]] + shift2) - shapePos[ids[0]]).squaredNorm() > r * r;
}

// Step 1 of processBatch: the entries j0 .. j1-1 of thread list `list` that the quick rejects
// leave, with their Ig2 functor and, for existing contacts, their objects and Law2 functor (into
// sc's entries and contacts); returns how many.
size_t InteractionLoop::gatherBatch(Scratch& sc, int list, size_t j0, size_t j1, bool quick, const Real* twiceD,
        std::vector<std::pair<const Shape*, const Shape*>>& missingIg2) {
    InteractionContainer& intrs = scene->interactions;
    const std::vector<uint32_t>& pairs = threadPairs[list];
    float* gaps = skin.active ? skin.gap[list].data() : nullptr;
    unsigned char* withFacet = skin.active ? skin.withFacet[list].data() : nullptr;
    const unsigned* todo = work[list]->todo;
    const bool fuse = fusedPasses;
    // a periodic scene: each pair's body 2 is the image of its cellDist (Contact::shift)
    const Vector3i* cellDist = intrs.periodic ? intrs.cellDist.data() : nullptr;
    const Matrix3r hSize = scene->cell->hSize, prevHSize = scene->cell->prevHSize, prevVelGrad = scene->cell->prevVelGrad;
    const int* shapeIndex = shapeCache.shapeIndex.data();
    const Shape* const* shapes = shapeCache.shape.data();
    Body::id_t* ids = intrs.pairIds.data();
    // (written by index into arrays of batchEntries: a push_back per entry cost more than the rest of the gathering)
    if (sc.entries.size() < batchEntries) {
        sc.entries.resize(batchEntries);
        sc.contacts.resize(batchEntries);
        sc.shifts.resize(batchEntries);
        sc.made.resize(batchEntries);
        sc.flags.resize(batchEntries);
        sc.apart.resize(batchEntries);
    }
    // (raw pointers: through the containers each access would reload them; none of these arrays
    // is resized below)
    Scratch::Entry* const entries = sc.entries.data();
    Contact* const contacts = sc.contacts.data();
    char* const wasReal = intrs.wasReal.data();
    char* const apart = sc.apart.data();
    size_t n = 0;
    sc.oneGeomFunctor = true;
    // (raw pointers: through the containers each access would reload them)
    const uint32_t* contactOf = intrs.contactOf.data();
    std::shared_ptr<IGeom>* made = sc.made.data();
    PoolCursor pools;
    // the dispatch entry of the last shape-class pair (consecutive pairs are mostly of one kind)
    int lastC1 = -1, lastC2 = -1;
    const DispatchTable2D<IGeomFunctor>::Entry* lastEntry = nullptr;
    const bool ahead = threadPairsScattered[list]; // (else the hardware's own prefetching does better)
    // 1. the pairs to compute, and their Ig2 functor
    for (size_t j = j0; j < j1; ++j) {
        // (what the pairs a few places ahead read, loaded in advance: in a scene whose body ids are
        // in no spatial order, e.g. spheres read from a file, these reads are all over memory)
        if (ahead && j + 2 * pairLookahead < j1) {
            const long far = pairs[todo ? todo[j + 2 * pairLookahead] : j + 2 * pairLookahead];
            __builtin_prefetch(&ids[2 * far]);
            __builtin_prefetch(&wasReal[far]);
            __builtin_prefetch(&contactOf[far]);
        }
        if (ahead && j + pairLookahead < j1) {
            const long near = pairs[todo ? todo[j + pairLookahead] : j + pairLookahead];
            for (const Body::id_t id : {ids[2 * near], ids[2 * near + 1]}) {
                __builtin_prefetch(&shapeIndex[id]);
                if (quick) {
                    __builtin_prefetch(&shapePos[id]);
                    __builtin_prefetch(&shapeRadius[id]);
                }
            }
        }
        const size_t i = todo ? todo[j] : j;
        const long k = pairs[i];
        const bool shifted = cellDist && cellDist[k] != Vector3i::Zero(); // (body 2's image elsewhere: a periodic scene)
        Vector3r shift2;
        if (!shifted)
            apart[j - j0] = quick && !wasReal[k] && stillApart(ids + 2 * k, i, gaps, withFacet, twiceD);
        else { // (the image moves with the cell: tested every step, no gap kept; 2: not to be kept as apart)
            shift2 = hSize * cellDist[k].cast<Real>();
            apart[j - j0] = quick && !wasReal[k] && imageApart(ids + 2 * k, shift2) ? 2 : 0;
            if (gaps) gaps[i] = -Inf;
        }
        if (apart[j - j0]) continue;
        if (gaps) gaps[i] = -Inf; // tested again at the next step
        const int c1 = shapeIndex[ids[2 * k]], c2 = shapeIndex[ids[2 * k + 1]];
        if (c1 < 0 || c2 < 0) continue; // a body without shape
        if (c1 != lastC1 || c2 != lastC2) {
            lastEntry = &geomDispatcher->getFunctor(c1, c2);
            lastC1 = c1;
            lastC2 = c2;
        }
        const auto& geomEntry = *lastEntry;
        if (!geomEntry.functor) {
#pragma omp critical(yadeMissing)
            missingIg2.emplace_back(shapes[ids[2 * k]], shapes[ids[2 * k + 1]]);
            continue;
        }
        if (geomEntry.swap) swapPair(k); // the functor takes the shapes in the other order
        IGeom* geom = nullptr;
        IPhys* phys = nullptr;
        LawFunctor* law = nullptr;
        pools.find(intrs, contactOf[k], k, geom, phys, law);
        // the functors read the contact's objects once the whole batch is gathered: their loads
        // start now, all at once, instead of one contact after the other
        prefetchObject(geom);
        prefetchObject(phys);
        // an existing contact whose Ig2 and Law2 functors have a fast pass: both run in step 4
        IGeomFunctor* fused = fuse && law && geom && phys ? fastPass(sc, geomEntry.functor, law) : nullptr;
        sc.oneGeomFunctor &= !fused && (n == 0 || entries[0].geom == geomEntry.functor);
        entries[n] = fused ? Scratch::Entry{k, nullptr, law, fused, sc.pass, 1, (unsigned)i} : Scratch::Entry{k, geomEntry.functor, nullptr, nullptr, nullptr, 0, (unsigned)i};
        contacts[n] = Contact(&intrs, k, geom, phys, ids[2 * k], ids[2 * k + 1]);
        if (shifted) {
            sc.shifts[n] = ContactShift{shift2, prevVelGrad * (prevHSize * cellDist[k].cast<Real>())};
            contacts[n].shift = &sc.shifts[n];
        }
        if (!fused) { // (may get a new geometry)
            contacts[n].made = made + n;
            if (made[n]) made[n].reset(); // (left by a step that threw)
        }
        ++n;
    }
    return n;
}

// An Ig2 functor over n contacts; false (and error set, naming it and the bodies) if it threw: the
// exception stays inside the parallel region and is reported after it, as the Ip2 and Law2 ones.
bool InteractionLoop::geometryOf(IGeomFunctor& f, const BodyColumns& columns, Contact* c, size_t n, char* flags, std::string& error) {
    try {
        f.goBatch(columns, c, n, flags);
        return true;
    } catch (const std::exception& e) {
        std::string bodies = "bodies #" + std::to_string(c[0].id1) + " and #" + std::to_string(c[0].id2);
        if (n > 1) bodies = "one of " + std::to_string(n) + " pairs, the first " + bodies;
#pragma omp critical(yadeError)
        error = f.getClassName() + " (" + bodies + "): " + e.what();
        return false;
    }
}

// Step 2 of processBatch: the geometry of the entries, one batch per Ig2 functor (usually one or
// two in a batch of entries); entries[e].real is the functor's answer.
void InteractionLoop::computeGeometry(Scratch& sc, size_t n, const BodyColumns& columns, std::string& error) {
    Scratch::Entry* const entries = sc.entries.data();
    Contact* const contacts = sc.contacts.data();
    char* const flags = sc.flags.data();
    if (sc.oneGeomFunctor) { // (the common case: all of one shape pair)
        if (!geometryOf(*entries[0].geom, columns, contacts, n, flags, error)) std::fill(flags, flags + n, geomFailed);
        for (size_t e = 0; e < n; ++e) entries[e].real = flags[e];
    } else {
        for (size_t first = 0; first < n; ++first) {
            IGeomFunctor* f = entries[first].geom;
            if (!f) continue; // done (or fused)
            sc.batch.clear();
            sc.where.clear();
            for (size_t e = first; e < n; ++e)
                if (entries[e].geom == f) {
                    sc.batch.push_back(contacts[e]);
                    sc.where.push_back(e);
                }
            if (!geometryOf(*f, columns, sc.batch.data(), sc.batch.size(), flags, error)) std::fill(flags, flags + sc.batch.size(), geomFailed);
            for (size_t m = 0; m < sc.where.size(); ++m) {
                entries[sc.where[m]].geom = nullptr;
                entries[sc.where[m]].real = flags[m];
                contacts[sc.where[m]].geom = sc.batch[m].geom; // (a new one, or the same)
            }
        }
    }
}

// A new contact (step 3): its geometry (made in this step, or kept from an earlier one) and its
// physics from the Ip2 functor join a pool; false (and error set where it is one) if it cannot.
bool InteractionLoop::makeNewContact(Scratch& sc, Contact& c, long k, std::string& error) {
    Scene& s = *scene;
    InteractionContainer& intrs = s.interactions;
        std::shared_ptr<IGeom> geom = std::move(*c.made);
        if (!geom)
            if (const InteractionContainer::Record* rec = intrs.record((size_t)k)) geom = rec->geom;
        if (!geom) {
#pragma omp critical(yadeError)
            error = "an Ig2 functor found bodies #" + std::to_string(c.id1) + " and #" + std::to_string(c.id2) + " in contact but made no geometry";
            return false;
        }
        // (the materials from the shape cache, refreshed when bodies or anything from Python changed: no visit to the Bodies)
        const std::shared_ptr<Material>& m1 = shapeCache.material[(size_t)c.id1];
        const std::shared_ptr<Material>& m2 = shapeCache.material[(size_t)c.id2];
        const auto* physEntry = m1 && m2 ? &physDispatcher->getFunctor(*m1, *m2) : nullptr;
        if (!physEntry || !physEntry->functor) {
            const InteractionContainer::Record* rec = intrs.record((size_t)k);
            if (!rec || rec->geom != geom) intrs.keepGeom((size_t)k, geom); // (for the next step)
            if (physEntry) {
#pragma omp critical(yadeError)
                error = "no Ip2 functor for " + m1->getClassName() + "+" + m2->getClassName()
                        + " (bodies #" + std::to_string(c.id1) + " and #" + std::to_string(c.id2) + ")";
            }
            return false;
        }
        // (the Ip2 functors take an Interaction: this thread's stand-in, so that no object is
        // made per contact)
        Interaction& I = sc.standIn;
        I.id1 = c.id1;
        I.id2 = c.id2;
        I.geom = geom;
        I.phys.reset();
        bool failed = false;
        try {
            physEntry->functor->go(m1, m2, I);
        } catch (const std::exception& e) { // (not out of the parallel region: reported after it)
            I.phys.reset();
            failed = true;
#pragma omp critical(yadeError)
            error = physEntry->functor->getClassName() + " (bodies #" + std::to_string(c.id1) + " and #" + std::to_string(c.id2) + "): " + e.what();
        }
        std::shared_ptr<IPhys> phys = std::move(I.phys);
        I.geom.reset();
        if (!phys) {
            if (failed) return false;
#pragma omp critical(yadeError)
            error = physEntry->functor->getClassName() + " made no physics for bodies #" + std::to_string(c.id1) + " and #" + std::to_string(c.id2);
            return false;
        }
        intrs.makeContact((size_t)k, geom, phys, s.iter);
        c.geom = intrs.geom((size_t)k);
        c.phys = intrs.phys((size_t)k);
#pragma omp critical(yadeNewContact)
        s.newContacts.push_back((size_t)k);
    return true;
}

// Step 3 of processBatch, in list order: contacts that ended, physics of new ones, and each one's
// Law2 functor; the entries left for step 4 are compacted to the front, their count returned.
size_t InteractionLoop::settleContacts(Scratch& sc, size_t n, std::string& error) {
    InteractionContainer& intrs = scene->interactions;
    Scratch::Entry* const entries = sc.entries.data();
    Contact* const contacts = sc.contacts.data();
    char* const wasReal = intrs.wasReal.data();
    size_t live = 0;
    for (size_t e = 0; e < n; ++e) {
        Scratch::Entry& x = entries[e];
        Contact& c = contacts[e];
        if (x.fused) { // (a contact with its functors: nothing to do before step 4)
            if (live != e) {
                entries[live] = x;
                contacts[live] = c;
            }
            ++live;
            continue;
        }
        if (x.real == geomFailed) continue; // (its Ig2 functor threw: the pair is left as it was)
        if (!x.real) {
            if (c.isReal()) intrs.endContact((size_t)x.k); // the geometry says the contact is over
            else if (*c.made) intrs.keepGeom((size_t)x.k, std::move(*c.made)); // (made, yet not a contact)
            setWasReal(wasReal, x.k, false);
            continue;
        }
        if (!c.phys && !makeNewContact(sc, c, x.k, error)) continue; // a new contact
        const ContactPool& pool = intrs.pool(intrs.contactOf[x.k]);
        // (the pool's, chosen before the parallel part; for a pool made since, chosen here)
        x.law = pool.lawTable == lawDispatcher->tableGeneration() ? pool.law : lawDispatcher->getFunctor(*c.geom, *c.phys).functor;
        if (!x.law) {
            setWasReal(wasReal, x.k, true); // (no Law2 functor at all: the contact stays, without forces)
            if (lawDispatcher->functors.empty()) continue;
#pragma omp critical(yadeError)
            error = "no Law2 functor for " + c.geom->getClassName() + "+" + c.phys->getClassName();
            continue;
        }
        if (live != e) { // (compacted over the entries left out)
            entries[live] = x;
            contacts[live] = c;
        }
        ++live;
    }
    return live;
}

// Step 4 of processBatch: the forces, over runs of one Law2 functor (with its Ig2 functor in a
// fast pass or not), in list order.
void InteractionLoop::applyLaws(Scratch& sc, size_t live, const BodyColumns& columns, std::string& error) {
    Scratch::Entry* const entries = sc.entries.data();
    for (size_t first = 0; first < live;) {
        LawFunctor* f = entries[first].law;
        IGeomFunctor* fused = entries[first].fused;
        size_t last = first;
        while (last < live && entries[last].law == f && entries[last].fused == fused) ++last;
        applyRun(f, fused, entries[first].pass, sc.contacts.data() + first, last - first, sc.flags.data(), columns, error);
        first = last;
    }
}

// One run of step 4; the contacts the law ends become potential.
void InteractionLoop::applyRun(LawFunctor* f, IGeomFunctor* fused, KernelPasses::Pass pass, Contact* c, size_t n, char* flags,
        const BodyColumns& columns, std::string& error) {
    InteractionContainer& intrs = scene->interactions;
    char* const wasReal = intrs.wasReal.data();
    try {
        if (fused) pass(*fused, *f, columns, c, n, flags);
        else f->goBatch(c, n, flags);
    } catch (const std::exception& e) { // (not out of the parallel region: reported after it; the contacts stay)
        std::fill(flags, flags + n, 1);
#pragma omp critical(yadeError)
        error = f->getClassName() + ": " + e.what();
    }
    for (size_t e = 0; e < n; ++e) {
        const bool keep = flags[e];
        if (!keep) intrs.endContact((size_t)c[e].k); // back to a potential interaction
        setWasReal(wasReal, c[e].k, keep);
    }
}

// The index of a kind of kept contact in keptKinds, added if new (any thread).
unsigned char InteractionLoop::keptKindOf(LawFunctor* law, IGeomFunctor* fused, KernelPasses::Pass pass) {
    auto find = [&](int from, int to) {
        for (int c = from; c < to; ++c)
            if (keptKinds[c].law == law && keptKinds[c].fused == fused && keptKinds[c].pass == pass) return c;
        return -1;
    };
    const int known = keptKindCount.load(std::memory_order_acquire);
    int c = find(0, known);
    if (c >= 0) return (unsigned char)c;
#pragma omp critical(yadeKeptKinds)
    {
        const int now = keptKindCount.load(std::memory_order_relaxed);
        c = find(known, now);
        if (c < 0 && now < (int)keptKinds.size()) {
            keptKinds[now] = KeptKind{law, fused, pass};
            keptKindCount.store(now + 1, std::memory_order_release);
            c = now;
        }
    }
    return c >= 0 ? (unsigned char)c : keptUnknown;
}

// After a batch computed in full: what each of its entries was, for the next steps (live: the
// entries left for step 4, all computed). In a periodic scene only pairs of cellDist zero are kept (the
// collider counts a change of a pair's cellDist in InteractionContainer::changes: every kept entry is
// then stale).
void InteractionLoop::keepBatch(const Scratch& sc, int list, size_t j0, size_t j1, size_t live) {
    KeptEntries& ke = kept[list];
    const unsigned* todo = work[list]->todo;
    for (size_t j = j0; j < j1; ++j) ke.kind[todo ? todo[j] : j] = sc.apart[j - j0] == 1 ? keptApart : keptUnknown;
    const InteractionContainer& intrs = scene->interactions;
    const Scratch::Entry* entries = sc.entries.data();
    unsigned char kind = keptUnknown; // (of the last kind looked up)
    const Scratch::Entry* kindOf = nullptr;
    for (size_t e = 0; e < live; ++e) {
        const Scratch::Entry& x = entries[e];
        const uint32_t where = intrs.contactOf[x.k];
        if (!x.fused || where == InteractionContainer::noContact) continue; // (a new contact, or one the law ended)
        if (sc.contacts[e].shift) continue; // (a pair through a periodic cell's face: its image is not kept)
        if (!kindOf || x.law != kindOf->law || x.fused != kindOf->fused) {
            kind = keptKindOf(x.law, x.fused, x.pass);
            kindOf = &x;
        }
        ke.kind[x.i] = kind;
        ke.where[x.i] = where;
    }
}

// A batch computed again from its kept entries (false, with nothing done but gaps of pairs still
// apart recorded, which the gathering records the same, if one of them cannot be taken).
bool InteractionLoop::replayBatch(int list, size_t j0, size_t j1, bool quick, const Real* twiceD, const BodyColumns& columns, std::string& error) {
    const KeptEntries& ke = kept[list];
    InteractionContainer& intrs = scene->interactions;
    Scratch& sc = *scratch[threadNumber()];
    if (sc.contacts.size() < batchEntries) return false; // (sized by gatherBatch)
    const unsigned* todo = work[list]->todo;
    const uint32_t* pairs = threadPairs[list].data();
    const uint32_t* contactOf = intrs.contactOf.data();
    const char* wasReal = intrs.wasReal.data();
    const Body::id_t* ids = intrs.pairIds.data();
    float* gaps = skin.active ? skin.gap[list].data() : nullptr;
    unsigned char* withFacet = skin.active ? skin.withFacet[list].data() : nullptr;
    Contact* const contacts = sc.contacts.data();
    char* const kinds = sc.apart.data(); // (the contacts' kinds, in this step's scratch)
    const ContactPool* pool = nullptr;
    uint32_t poolIndex = InteractionContainer::noContact;
    size_t n = 0;
    for (size_t j = j0; j < j1; ++j) {
        const unsigned i = todo ? todo[j] : (unsigned)j;
        const unsigned char kind = ke.kind[i];
        if (kind == keptUnknown) return false;
        const long k = pairs[i];
        if (kind == keptApart) { // a pair still apart then: still apart now?
            if (!(quick && !wasReal[k] && stillApart(ids + 2 * k, i, gaps, withFacet, twiceD))) return false;
            continue;
        }
        const uint32_t where = contactOf[k];
        if (where != ke.where[i] || !wasReal[k]) return false;
        if (InteractionContainer::poolOf(where) != poolIndex) {
            poolIndex = InteractionContainer::poolOf(where);
            pool = intrs.pools[poolIndex].get();
        }
        const uint32_t slot = InteractionContainer::slotOf(where);
        contacts[n] = Contact(&intrs, k, pool->geom(slot), pool->phys(slot), ids[2 * k], ids[2 * k + 1]);
        kinds[n++] = (char)kind;
    }
    for (size_t first = 0; first < n;) { // runs of one kind, in order
        size_t last = first + 1;
        while (last < n && kinds[last] == kinds[first]) ++last;
        const KeptKind& r = keptKinds[(unsigned char)kinds[first]];
        applyRun(r.law, r.fused, r.pass, contacts + first, last - first, sc.flags.data(), columns, error);
        first = last;
    }
    ++sc.replayed;
    return true;
}

// Entries j0 .. j1-1 of thread list `list` (at most batchEntries), in four steps: gatherBatch,
// computeGeometry, settleContacts, applyLaws (or a kept batch again). Forces are added in the order
// of the list. Existing contacts are reached through the container's columns, never through their
// Interaction.
void InteractionLoop::processBatch(int list, size_t j0, size_t j1, bool quick, const Real* twiceD,
        std::vector<std::pair<const Shape*, const Shape*>>& missingIg2, std::string& error) {
    const BodyColumns columns{scene->bodies.hot().columns(), shapeCache.shape.data(), shapeCache.radius.data()};
    if (fusedPasses && replayBatch(list, j0, j1, quick, twiceD, columns, error)) return;
    Scratch& sc = *scratch[threadNumber()];
    const size_t n = gatherBatch(sc, list, j0, j1, quick, twiceD, missingIg2);
    if (n > 0) computeGeometry(sc, n, columns, error);
    const size_t live = n > 0 ? settleContacts(sc, n, error) : 0;
    applyLaws(sc, live, columns, error);
    if (fusedPasses) keepBatch(sc, list, j0, j1, live);
}

void InteractionLoop::action() {
    for (const auto& cb : callbacks)
        if (!cb) throw std::invalid_argument("InteractionLoop.callbacks: None in the list");
    for (const auto& cb : callbacks) cb->stepInit(*scene);
    runLoop();
    if (callbacks.empty()) return;
    const InteractionContainer& intrs = scene->interactions;
    for (size_t k = 0; k < intrs.size(); ++k) {
        if (!intrs.isReal(k)) continue;
        for (const auto& cb : callbacks) cb->go(intrs.pairIds[2 * k], intrs.pairIds[2 * k + 1], *intrs.phys(k));
    }
}

// The dispatch tables resolved (and the functor chain checked when they changed), every functor
// told its scene.
bool InteractionLoop::prepareFunctors() {
    Scene& s = *scene;
    const bool changed = geomDispatcher->prepareTable() | physDispatcher->prepareTable() | lawDispatcher->prepareTable();
    if (changed) checkFunctorChain();
    for (auto* d : std::initializer_list<Dispatcher*>{geomDispatcher.get(), physDispatcher.get(), lawDispatcher.get()})
        for (const auto& f : d->functorsBase()) {
            f->scene = &s;
            f->prepare();
        }
    return changed;
}

// Each pool's Law2 functor, for the current law table (before the parallel part reads them).
void InteractionLoop::refreshPoolLaws() {
    InteractionContainer& intrs = scene->interactions;
    for (size_t p = 0; p < intrs.poolCount(); ++p) { // each kind of contact's Law2 functor, for this table
        ContactPool& pool = *intrs.pools[p];
        if (pool.lawTable == lawDispatcher->tableGeneration()) continue;
        pool.law = pool.size() > 0 ? lawDispatcher->getFunctor(*pool.geom(0), *pool.phys(0)).functor : nullptr;
        pool.lawTable = pool.size() > 0 ? lawDispatcher->tableGeneration() : -1;
    }
}

// The entries of thread list `list` to test in this step (work[list]'s count and todo): all, or with
// the skin those not certainly beyond reach since their last test (gathered without branches: which
// ones are skipped is unpredictable). skipAbove: the margins 2D' of sphere pairs and facet pairs.
void InteractionLoop::gatherTodo(int list, const Real* skipAbove) {
    const std::vector<uint32_t>& pairs = threadPairs[list];
    const float* gaps = skin.active ? skin.gap[list].data() : nullptr;
    ListWork& w = *work[list];
    w.count = pairs.size();
    w.todo = nullptr;
    if (gaps) {
        std::vector<unsigned>& entries = skin.todo[list];
        std::vector<unsigned>& near = skin.near[list];
        const unsigned char* withFacet = skin.withFacet[list].data();
        std::array<Real, 2>& nearLimit = skin.nearLimit[list];
        size_t count = 0;
        if (skipAbove[0] <= nearLimit[0] && skipAbove[1] <= nearLimit[1]) { // the entries left out of near are still beyond reach
            entries.resize(near.size());
            for (const unsigned i : near) {
                entries[count] = i;
                count += !(gaps[i] > skipAbove[withFacet[i]]);
            }
        } else { // all, keeping those within twice this step's margin as near
            nearLimit = {2 * skipAbove[0], 2 * skipAbove[1]};
            entries.resize(pairs.size());
            near.resize(pairs.size());
            size_t nearCount = 0;
            for (size_t i = 0; i < pairs.size(); ++i) {
                entries[count] = (unsigned)i;
                count += !(gaps[i] > skipAbove[withFacet[i]]);
                near[nearCount] = (unsigned)i;
                nearCount += !(gaps[i] > nearLimit[withFacet[i]]);
            }
            near.resize(nearCount);
        }
        w.count = count;
        w.todo = entries.data();
    }
    KeptEntries& ke = kept[list]; // (all unknown in a new generation)
    if (ke.generation != keptGeneration || ke.kind.size() != pairs.size()) {
        ke.kind.assign(pairs.size(), keptUnknown);
        ke.where.resize(pairs.size());
        ke.generation = keptGeneration;
    }
}

// With several threads: this thread's own chunks from the front, then the others' last chunks (their
// forces and energies captured), then the forces of its own chunks that others did, in chunk order:
// every force is added in the order the list's thread alone would have added it.
template <class Process> void InteractionLoop::runChunks(int first, int step, int threads, Process& process) {
    Scene& s = *scene;
    unsigned c;
    for (int list = first; list < threads; list += step) // own chunks, from the front
        while (work[list]->queue.takeFront(c)) process(list, (size_t)c * chunkEntries, std::min(work[list]->count, ((size_t)c + 1) * chunkEntries));
    for (int other = 0; other < threads; ++other) { // then the others' last chunks
        if ((other - first) % step == 0 && other >= first) continue;
        ListWork& w = *work[other];
        while (!w.queue.published()) std::this_thread::yield(); // (its thread is gathering the entries)
        while (w.queue.takeBack(c)) {
            w.captured[c].clear();
            w.capturedEnergy[c].clear();
            s.forces.capture(&w.captured[c]);
            s.energy.capture(&w.capturedEnergy[c]);
            process(other, (size_t)c * chunkEntries, std::min(w.count, ((size_t)c + 1) * chunkEntries));
            s.forces.capture(nullptr);
            s.energy.capture(nullptr);
            w.queue.markDone(c);
        }
    }
    for (int list = first; list < threads; list += step) { // the forces of own chunks done by others, in order
        ListWork& w = *work[list];
        for (c = w.queue.stolenFrom(); c < w.queue.count(); ++c) {
            w.queue.waitDone(c);
            s.forces.applyCaptured(w.captured[c]);
            s.energy.applyCaptured(w.capturedEnergy[c]);
        }
    }
}

void InteractionLoop::runLoop() {
    Scene& s = *scene;
    if (!geomDispatcher || !physDispatcher || !lawDispatcher) // (None assigned from Python or read from a file)
        throw std::invalid_argument("InteractionLoop: geomDispatcher, physDispatcher and lawDispatcher must not be None");
    const bool functorsChanged = prepareFunctors();
    const BodyContainer& bodies = s.bodies;
    InteractionContainer& intrs = s.interactions;
    const int threads = s.threads(); // (the scene's count, which its force and energy buffers are made for; Omega sets OpenMP's to it)
    cacheBuilt = false;
    prepareShapes();
    if (intrs.objectsWrites != externalWrites() || intrs.objectsMade) { // (Python may have set geom or phys)
        intrs.objectsWrites = externalWrites();
        intrs.syncObjects();
    }
    refreshPoolLaws();
    intrs.prepareRecords(); // (the parallel part makes records without moving any)
    // the records of the contacts that end leave their pools when the parallel part is over (also
    // when it throws)
    struct Sweep {
        InteractionContainer& intrs;
        ~Sweep() { intrs.sweep(); }
    } sweepAfter{intrs};
    const bool quick = fastPath && prepareQuickReject();
    if ((int)scratch.size() < threads) {
        scratch.clear();
        for (int t = 0; t < threads; ++t) scratch.emplace_back(new Scratch);
    }
    std::vector<std::pair<const Shape*, const Shape*>> missingIg2;
    std::string error;
    if (threadPairsFor != intrs.changes || threadPairsScene != s.serial || threadPairsBodies != bodies.size()
            || threadPairsCount != intrs.size() || (int)threadPairs.size() != threads)
        assignPairsToThreads(threads);
    // the pools whose records drifted out of the order of the thread lists: in that order again
    for (size_t p = 0; p < intrs.poolCount(); ++p)
        if (intrs.pools[p]->needsOrder()) {
            intrs.orderPools(threadPairs, true);
            break;
        }
    prepareSkin(quick);
    const KeptKey key{intrs.changes, s.serial, threadPairsBuild, lawDispatcher->tableGeneration(), externalWrites()};
    if (!(key == keptKey) || functorsChanged || cacheBuilt || !fusedPasses) { // (every kept entry is stale)
        keptKey = key;
        ++keptGeneration;
        keptKindCount.store(0);
    }
    if (kept.size() != (size_t)threads) kept.resize(threads);
    const Vector3r* skinRef = skin.active && !skin.fresh ? skin.refPos->data() : nullptr; // (D = 0 in a fresh epoch)
    // D² of the spheres, and of the facets
    Real displacement2 = 0;
    const Real facetDisplacement = skinRef ? facetDisplacement2() : 0;
    const Real movedByIntegrator = skinRef && quickFromIntegrator ? s.motion.maxMovedSince(skin.tag) : NaN;
    if (!std::isnan(movedByIntegrator)) { // found by the integrator with these positions
        displacement2 = std::max(displacement2, movedByIntegrator);
        skinRef = nullptr;
    }
    // Each thread's list is cut into chunks of the entries it tests. A thread does the chunks of
    // its own list from the front, then helps with what is left of the others' from their back;
    // the forces of a chunk done for another list are kept (O.forces' capture) and added by the
    // list's thread after its own chunks, in chunk order: every force is added in the order the
    // list's thread alone would have added it, whoever computed it and however fast each thread
    // ran (on shared machines one core is often slower than the other for seconds). The same for
    // the functors' energy terms (O.energy's capture).
    const bool steal = threads > 1;
    if (work.size() != (size_t)threads) {
        work.clear();
        for (int t = 0; t < threads; ++t) work.emplace_back(new ListWork);
    }
    for (auto& w : work) w->queue.unpublish();
#pragma omp parallel num_threads(threads)
    {
    int first = 0, step = 1;
#ifdef _OPENMP
    first = omp_get_thread_num();
    step = omp_get_num_threads();
#endif
    if (skinRef) { // D: each thread over the bodies it integrates, then the largest (exact: any order)
        const auto range = myThreadRange((long)shapeCache.radius.size());
        Real mine = 0;
        for (long id = range.first; id < range.second; ++id) mine = std::max(mine, (shapePos[id] - skinRef[id]).squaredNorm()); // (holes and bodies other than spheres: NaN, ignored)
#pragma omp critical(yadeSkin)
        displacement2 = std::max(displacement2, mine);
#pragma omp barrier
    }
    // 2D of a pair of spheres, and of a facet and a sphere (each moved at most the larger D); their margins
    const Real twiceD[2] = {2 * std::sqrt(displacement2), 2 * std::sqrt(std::max(displacement2, facetDisplacement))};
    const Real skipAbove[2] = {twiceD[0] + skin.tolerance, twiceD[1] + skin.tolerance};
    // entries j0 .. j1-1 of list `list` (positions in its todo, or in the list without the skin),
    // batch by batch
    auto process = [&](int list, size_t j0, size_t j1) {
        for (size_t b0 = j0; b0 < j1; b0 += batchEntries) processBatch(list, b0, std::min(j1, b0 + batchEntries), quick, twiceD, missingIg2, error);
    };
    for (int list = first; list < threads; list += step) { // (one list each unless fewer threads came)
        ListWork& w = *work[list];
        gatherTodo(list, skipAbove);
        const unsigned chunks = steal ? (unsigned)((w.count + chunkEntries - 1) / chunkEntries) : 0;
        if (w.captured.size() < chunks) w.captured.resize(chunks);
        if (w.capturedEnergy.size() < chunks) w.capturedEnergy.resize(chunks);
        w.queue.reset(chunks);
        if (!steal) process(list, 0, w.count);
    }
    if (steal) runChunks(first, step, threads, process);
    }
    pairsTested = 0;
    for (const auto& w : work) pairsTested += (long long)w->count;
    keptBatches = 0;
    for (const auto& sc : scratch) {
        keptBatches += sc->replayed;
        sc->replayed = 0;
    }
    for (const auto& p : missingIg2) warnMissingIg2(*p.first, *p.second);
    if (!error.empty()) throw std::runtime_error("InteractionLoop: " + error);
}

} // namespace yade
