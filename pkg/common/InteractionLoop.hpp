// Runs the three dispatchers over every interaction (1.2.1): Ig2 (geometry), Ip2 (physics of a
// new contact) and Law2 (forces). The Ig2 → Law2 and Ip2 → Law2 type chains are checked.
#pragma once
#include <core/ContactKernel.hpp>
#include <core/IGeomDispatcher.hpp>
#include <core/IPhysDispatcher.hpp>
#include <core/EnergyTracker.hpp>
#include <core/ForceContainer.hpp>
#include <core/LawDispatcher.hpp>
#include <lib/base/ChunkQueue.hpp>
#include <pkg/common/IntrCallback.hpp>
#include <array>
#include <atomic>
#include <memory>
#include <set>
#include <string>
#ifdef _OPENMP
#include <omp.h>
#endif
#include <vector>

namespace yade {

class InteractionLoop : public GlobalEngine {
public:
    static constexpr const char* classDoc = "Engine that runs the three dispatchers over every interaction (1.2.1): Ig2 (geometry), Ip2 (physics of a new contact) and Law2 (forces).";
    std::shared_ptr<IGeomDispatcher> geomDispatcher = std::make_shared<IGeomDispatcher>();
    std::shared_ptr<IPhysDispatcher> physDispatcher = std::make_shared<IPhysDispatcher>();
    std::shared_ptr<LawDispatcher> lawDispatcher = std::make_shared<LawDispatcher>();
    std::vector<std::shared_ptr<IntrCallback>> callbacks;
    bool fastPath = true;
    bool fusedPasses = true;
    long long pairsTested = 0;
    long long keptBatches = 0;
    // How the pairs were split between the threads when the scene was saved, run-length encoded
    // (thread, count of consecutive pairs, thread, count...): the first split after a load is that
    // one, so that a loaded scene continues bit for bit with as many threads (the sums of the
    // threads' forces round the same way). Empty except while saving and until that first split.
    std::vector<int> threadSplit;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("geomDispatcher", geomDispatcher, "Ig2 functors: contact geometry from two shapes");
        v.attr("physDispatcher", physDispatcher, "Ip2 functors: contact physics from two materials");
        v.attr("lawDispatcher", lawDispatcher, "Law2 functors: forces from geometry and physics");
        v.attr("callbacks", callbacks, "Interaction callbacks (IntrCallback): each is told when the loop starts a step, then called for every real interaction once the loop has processed them (SumIntrForcesCb)");
        v.attr("fusedPasses", fusedPasses, "Run the geometry and the law of existing contacts in one pass, two contacts at a time, where both functors are kernels (Ig2_Sphere_Sphere_ScGeom or Ig2_Facet_Sphere_ScGeom with any Law2 functor on ScGeom written as a kernel: doc/contact-laws.md): the same results, less bookkeeping");
        v.attr("fastPath", fastPath, "Reject distant potential sphere-sphere and facet-sphere pairs from contiguous positions, without calling their Ig2 functor (same results as the general path)");
        v.attr("pairsTested", pairsTested, "Interactions (contacts and potential ones) the last step looked at; with fastPath, the potential pairs certain to stay apart since their last test are left out (for profiling)", Attr::readonly | Attr::noSave);
        v.attr("keptBatches", keptBatches, "Batches the last step computed from what their entries were when last gathered (lasting contacts of fused passes, pairs still apart), without gathering them again (fusedPasses; the same results; for profiling)", Attr::readonly | Attr::noSave);
        v.attr("threadSplit", threadSplit, "How the pairs were split between threads when saved (thread, count, ...): a loaded scene splits them the same way", Attr::hidden);
    }
    void action() override;
    void preSave() override;  // threadSplit from the current split (with more than one thread)
    void postSave() override; // threadSplit emptied
    // Throws std::invalid_argument explaining a broken chain (an Ig2 or Ip2 product no Law2 accepts).
    void checkFunctorChain() const;

private:
    void runLoop(); // the step's work, without the callbacks
    bool prepareFunctors(); // true if a dispatch table was filled anew
    void refreshPoolLaws();
    void gatherTodo(int list, const Real* skipAbove);
    template <class Process> void runChunks(int first, int step, int threads, Process& process);
    std::set<std::pair<int, int>> warnedShapePairs;
    // Per step, contiguous, indexed by body id: sphere centers (shapePos) and radii (shapeRadius:
    // sphere > 0; facet: -1 - (index into facetPlanes); anything else NaN), and facet planes, so
    // that distant potential sphere-sphere and facet-sphere pairs are rejected without touching
    // bodies or interactions (the Ig2 functors' quickRejectFactor promise). The centers are the
    // integrator's positions (Scene::motion) while they are current, else copied from the
    // bodies into quickPos; the radii are shapeCache's.
    struct FacetPlane {
        Vector3r point, normal; // the facet's centre (its inscribed circle's), unit normal (global)
        Vector3r edge[3];       // the in-plane outward normals of its edges (global)
        Real icr;               // the radius of its inscribed circle
    };
    std::vector<Vector3r> quickPos;
    const Vector3r* shapePos = nullptr;
    const Real* shapeRadius = nullptr;
    bool quickFromIntegrator = false; // this step's centers are the integrator's positions (the radii cached)
    bool cacheBuilt = false;      // prepareShapes() rebuilt shapeCache in this step
    // Radii of spheres (NaN for other shapes, the facet marker for facets) and facet ids, valid
    // while no body was added or removed and nothing was written from Python.
    // Also each body's shape (null: none or a hole) and its class index (-1: none), read by
    // the batched dispatch instead of the bodies.
    struct ShapeCache {
        std::vector<Real> radius;
        std::vector<Body::id_t> facetIds;
        std::vector<const Shape*> shape;
        std::vector<int> shapeIndex;
        // each body's material (a new contact's Ip2 functor takes them: read here, not through the Body)
        std::vector<std::shared_ptr<Material>> material;
        long long changes = -1, writes = -1, scene = -1; // bodies.changes, externalWrites(), Scene::serial
    } shapeCache;
    std::vector<FacetPlane> facetPlanes;
    // Per facet (as facetPlanes): its orientation and the largest distance of its vertices from its
    // position, to bound how far any point of it moved since the skin's epoch began.
    std::vector<Quaternionr> facetOri;
    std::vector<Real> facetReach;
    Real facetDisplacement2() const; // the square of that bound, the largest over the facets
    Real sphereSphereReach = -1, facetSphereReach = -1; // the functors' factors (negative: unused)
    void prepareShapes();      // refreshes shapeCache when bodies or anything from Python changed
    bool prepareQuickReject(); // sets shapePos and shapeRadius; false if no functor makes the promise
    // True when the Ig2 functor would certainly return false for this potential pair; gap is
    // then how far the pair is beyond the functor's reach (distance of the centres, or a lower
    // bound of the distance of the sphere's centre from the facet's triangle, minus the reach).
    static constexpr size_t pairLookahead = 8; // pairs ahead whose reads processBatch starts early
    bool quickReject(Body::id_t id1, Body::id_t id2, Real& gap) const {
        const Real ra = shapeRadius[id1], rb = shapeRadius[id2];
        if (ra > 0 && rb > 0) { // the very test of Ig2_Sphere_Sphere_ScGeom, in the same arithmetic
            const Real r = sphereSphereReach * (ra + rb);
            const Real d2 = (shapePos[id1] - shapePos[id2]).squaredNorm();
            if (!(sphereSphereReach > 0 && d2 > r * r)) return false;
            gap = std::sqrt(d2) - r;
            return true;
        }
        return (ra < 0 || rb < 0) && facetSphereReject(ra < 0 ? id2 : id1, ra < 0 ? ra : rb, gap);
    }
    bool facetSphereReject(Body::id_t sphere, Real facetCode, Real& gap) const;
    bool imageApart(const Body::id_t* ids, const Vector3r& shift2) const;
    // The skin of the fast path (Verlet lists): a potential pair found a gap g beyond reach while
    // every body was within D of its position at the start of the epoch cannot come within reach
    // as long as every body stays within D' with 2D + 2D' < g (each body moved at most D + D'
    // since). Each entry of a thread's list keeps g - 2D from its last test, and is skipped while
    // that exceeds 2D' (plus a rounding margin): one contiguous read instead of the two bodies'
    // positions. D is kept apart for the pairs of two spheres (the spheres' motion) and for those
    // of a facet and a sphere (with the facets' motion, facetDisplacement2): a turning drum does not
    // make the pairs of spheres tested again. An epoch ends when the interactions, the bodies,
    // anything written from Python, the set of facets or the functors' reach change.
    struct Skin {
        // each body's position at the start of the epoch (the reference of Scene::motion: MotionRecord::setReference)
        std::shared_ptr<const std::vector<Vector3r>> refPos = std::make_shared<std::vector<Vector3r>>();
        std::vector<std::vector<float>> gap; // per thread list, per entry: g - 2D (-Inf: test the pair), rounded down
        std::vector<std::vector<unsigned>> todo; // per thread list: the entries tested in this step
        // Per thread list, the entries whose value was at most nearLimit at the last full pass over
        // the list (the others were not tested since, so their values did not change): while the
        // margin 2D' stays below nearLimit only these are looked at (a full pass when D doubled).
        std::vector<std::vector<unsigned>> near;
        std::vector<std::array<Real, 2>> nearLimit; // of the pairs of spheres, and with a facet (-Inf: none yet in this epoch)
        // per thread list, per entry: 1 if the pair is of a facet and a sphere (its g - 2D is of their D)
        std::vector<std::vector<unsigned char>> withFacet;
        std::vector<FacetPlane> facetPlanes; // facet planes at the start of the epoch
        std::vector<Quaternionr> facetOri;    // and their orientations
        Real sphereSphereReach = NaN, facetSphereReach = NaN;
        Real tolerance = 0;                  // rounding margin, relative to the scene's coordinates
        long long pairsBuild = -1;           // threadPairsBuild when the epoch began
        long long tag = -1;                  // this epoch's tag of the motion record's reference (MotionRecord::setReference)
        bool active = false;                 // used in this step
        bool fresh = false;                  // the epoch begins in this step (D = 0, every pair tested)
    } skin;
    void prepareSkin(bool quick);
    void warnMissingIg2(const Shape& a, const Shape& b);
    // Interactions (positions in O.interactions) per thread: each goes to a thread that integrates
    // one of its bodies (NewtonIntegrator splits the body ids in equal consecutive ranges), so that
    // the states it reads were written on the same core; pairs across two ranges go to the one of
    // their two threads with less work (contacts weigh more than potential pairs), except pairs with
    // a boundary (a body with many partners, e.g. a facet), which follow the other body (else the
    // thread owning the boundaries would get most of them). Each list is in the order of the pairs'
    // smaller body id, then container order (locality of the body columns); one thread gives the
    // serial order; the split and the order depend only on the interactions, never on timing.
    std::vector<std::vector<uint32_t>> threadPairs; // (positions in O.interactions: fewer than 2^32, see InteractionContainer::append)
    long long threadPairsFor = -1, threadPairsScene = -1; // O.interactions' change counter, Scene::serial when built
    long long threadPairsBuild = 0;                         // incremented by every rebuild
    size_t threadPairsBodies = 0, threadPairsCount = 0;     // O.bodies' and O.interactions' sizes then
    // per list: whether its pairs' two ids are far apart (a mean |id2 - id1| above scatteredSpread,
    // as for bodies read from a file in no spatial order); then processBatch loads their entries ahead
    std::vector<char> threadPairsScattered;
    static constexpr unsigned long long scatteredSpread = 2048;
    void assignPairsToThreads(int threads);
    bool useSavedSplit(int threads, long pairs); // the split of threadSplit, if it fits (once)
    // Work stealing within a step (action()): per thread list, its entries to test and their chunks.
    static constexpr size_t chunkEntries = 256;
    struct ListWork {
        ChunkQueue queue;
        size_t count = 0;                 // entries to test
        const unsigned* todo = nullptr;   // their positions in the list (nullptr: all, in order)
        std::vector<std::vector<ForceContainer::Captured>> captured; // per chunk done by another thread
        std::vector<std::vector<EnergyTracker::Captured>> capturedEnergy;
    };
    std::vector<std::unique_ptr<ListWork>> work;
    // Batched dispatch (processBatch): per thread, the entries of the batch being computed.
    static constexpr size_t batchEntries = 256;
    struct Scratch {
        struct Entry {
            long k;             // position in O.interactions
            IGeomFunctor* geom; // its Ig2 functor (null once computed)
            LawFunctor* law;    // its Law2 functor
            IGeomFunctor* fused; // an existing contact whose Ig2 and Law2 functors have a fast pass (else null)
            KernelPasses::Pass pass; // (then that pass)
            char real;          // the Ig2 functor's answer
            unsigned i;         // its position in the thread list
        };
        std::vector<Entry> entries;
        std::vector<Contact> contacts; // (entry e: contacts[e])
        std::vector<ContactShift> shifts; // (entry e, a periodic pair through a face: where its body 2 is)
        std::vector<std::shared_ptr<IGeom>> made; // (entry e: a new geometry, until it joins a pool)
        std::vector<Contact> batch;
        std::vector<size_t> where;
        std::vector<char> flags;
        bool oneGeomFunctor = true; // every entry has the same Ig2 functor (and none is fused)
        // the fast pass of an Ig2 functor with a Law2 functor (KernelPasses::find), for the last pair asked
        const IGeomFunctor* passGeom = nullptr;
        const LawFunctor* passLaw = nullptr;
        KernelPasses::Pass pass = nullptr;
        Interaction standIn; // what the Ip2 functors get for a pair without object
        long long replayed = 0; // kept batches computed again in this step
        std::vector<char> apart; // (entry j - j0 of the batch: a potential pair still apart)
    };
    std::vector<std::unique_ptr<Scratch>> scratch; // [thread]
    void processBatch(int list, size_t j0, size_t j1, bool quick, const Real* twiceD,
            std::vector<std::pair<const Shape*, const Shape*>>& missingIg2, std::string& error);
    // its four steps, and what they share
    size_t gatherBatch(Scratch& sc, int list, size_t j0, size_t j1, bool quick, const Real* twiceD,
            std::vector<std::pair<const Shape*, const Shape*>>& missingIg2);
    void computeGeometry(Scratch& sc, size_t n, const BodyColumns& columns, std::string& error);
    static constexpr char geomFailed = 2; // (an entry's `real` when its Ig2 functor threw)
    bool geometryOf(IGeomFunctor& f, const BodyColumns& columns, Contact* c, size_t n, char* flags, std::string& error);
    size_t settleContacts(Scratch& sc, size_t n, std::string& error);
    bool makeNewContact(Scratch& sc, Contact& c, long k, std::string& error);
    void applyLaws(Scratch& sc, size_t live, const BodyColumns& columns, std::string& error);
    // one run of step 4: contacts c[0] .. c[n-1] of one Law2 functor (with the Ig2 functor of its fast pass, or not)
    void applyRun(LawFunctor* law, IGeomFunctor* fused, KernelPasses::Pass pass, Contact* c, size_t n, char* flags, const BodyColumns& columns,
            std::string& error);
    // Kept entries (doc/storage.md, "Kept batches"): what each entry of a thread list was when it
    // was last gathered, if that can be taken again without gathering: a potential pair still apart,
    // or an existing contact of a fast pass that lasted (where its record was, and which pass). A
    // batch whose entries are all kept is computed from these (replayBatch) while each contact's
    // record did not move, each pair apart is still apart (tested again), and nothing the gathering
    // reads changed (keptKey): what gatherBatch would have found, in the same order, so the same bits.
    // Kept by entry of the list, not by batch: an entry that starts or stops being tested (the skin)
    // shifts the batches after it, not what their entries were. In a packing whose contacts last (most
    // steps of most runs) most batches are taken this way.
    static constexpr unsigned char keptUnknown = 255, keptApart = 254; // (else: an index into keptKinds)
    struct KeptEntries {
        long long generation = -1;       // keptGeneration when filled (else all unknown)
        std::vector<unsigned char> kind; // per entry of the list: keptUnknown, keptApart or a contact's kind
        std::vector<uint32_t> where;     // per entry: a contact's InteractionContainer::contactOf then
    };
    std::vector<KeptEntries> kept; // [list]
    // the (Law2 functor, fused Ig2 functor, pass) of the kept contacts, each kind once (made during the
    // parallel part: published by keptKindCount; emptied with every new keptGeneration)
    struct KeptKind {
        LawFunctor* law;
        IGeomFunctor* fused;
        KernelPasses::Pass pass;
    };
    std::array<KeptKind, keptApart> keptKinds;
    std::atomic<int> keptKindCount{0};
    unsigned char keptKindOf(LawFunctor* law, IGeomFunctor* fused, KernelPasses::Pass pass); // keptUnknown if the table is full
    // What the entries' functors, objects and order depend on besides their positions and records:
    // a change of any makes every kept entry stale (a new keptGeneration).
    struct KeptKey {
        long long changes = -1, serial = -1, pairsBuild = -1, lawTable = -1, writes = -1;
        bool operator==(const KeptKey& o) const {
            return changes == o.changes && serial == o.serial && pairsBuild == o.pairsBuild && lawTable == o.lawTable && writes == o.writes;
        }
    } keptKey;
    long long keptGeneration = 0;
    void keepBatch(const Scratch& sc, int list, size_t j0, size_t j1, size_t live);
    bool replayBatch(int list, size_t j0, size_t j1, bool quick, const Real* twiceD, const BodyColumns& columns, std::string& error);
    bool stillApart(const Body::id_t* ids, size_t i, float* gaps, unsigned char* withFacet, const Real* twiceD) const;
    void swapPair(long k);
    IGeomFunctor* fastPass(Scratch& sc, IGeomFunctor* geom, LawFunctor* law);
    struct PoolCursor { // the pool of the last contact looked up (consecutive ones are mostly of one kind)
        uint32_t index = InteractionContainer::noContact;
        const ContactPool* pool = nullptr;
        void find(const InteractionContainer& intrs, uint32_t where, long k, IGeom*& geom, IPhys*& phys, LawFunctor*& law);
    };
    static int threadNumber() {
#ifdef _OPENMP
        return omp_get_thread_num();
#else
        return 0;
#endif
    }
    struct {
        std::vector<int> owner, partners, fixed;
        std::vector<uint32_t> start, sorted;
    } assignScratch;
};

} // namespace yade
