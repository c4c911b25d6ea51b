#include <algorithm>
#include <exception>
#include <stdexcept>
#include <core/Scene.hpp>
#include <pkg/common/InsertionSortCollider.hpp>
#include <pkg/common/Sphere.hpp>

namespace yade {

// limit: how far a body may have moved (the sweep, less what the cell's deformation took of it).
bool InsertionSortCollider::needsRun(Real limit) {
    const BodyContainer& bodies = scene->bodies;
    if (bodies.changes != lastBodyChanges) return true;
    if (!(limit > 0)) return true;
    const Real limit2 = limit * limit;
    const long n = (long)bodies.size();
    int moved = 0;
    const MotionRecord& m = scene->motion; // (the skin protocol: core/MotionRecord.hpp)
    if (m.current() && boxes.size() == bodies.size()) { // contiguous: the integrator's positions, our boxes
        // no body moved farther than the sum of the fastest body's steps since the bounds were made
        // (each step with the rounding of pos + vel·dt): below the sweep, nothing to check
        if (m.step() == travelledTo + 1) travelled += m.maxStep() * (1 + 1e-12) + 1e-15 * (scale + sweep);
        else if (m.step() != travelledTo) travelled = Inf;
        travelledTo = m.step();
        if (travelled < limit * (1 - 1e-9)) return false;
        const Vector3r* pos = m.positions();
#pragma omp parallel for schedule(static) reduction(| : moved)
        for (long id = 0; id < n; ++id) moved |= boxes[id].collidable && (pos[id] - boxes[id].refPos).squaredNorm() > limit2; // (3.1.6)
        return moved != 0;
    }
    travelled = Inf; // (positions not the integrator's: checked every step until the next run)
    // split as in NewtonIntegrator, so that each thread reads the states it has just written
#pragma omp parallel for schedule(static) reduction(| : moved)
    for (long id = 0; id < n; ++id) {
        const Body* b = bodies[(Body::id_t)id].get();
        if (!b || !b->shape || !b->bound) continue; // bodies without a Bo1 functor take no part
        moved |= (b->state->pos() - b->bound->refPos).squaredNorm() > limit2; // (3.1.6)
    }
    return moved != 0;
}

void InsertionSortCollider::updateBounds() {
    const BodyContainer& bodies = scene->bodies;
    const long n = (long)bodies.size();
    Real minRadius = Inf, extent = 0;
#pragma omp parallel for schedule(static) reduction(min : minRadius) reduction(max : extent)
    for (long id = 0; id < n; ++id) {
        const Body* b = bodies[(Body::id_t)id].get();
        if (b) extent = std::max(extent, b->state->pos().cwiseAbs().maxCoeff()); // (NaN: ignored)
        if (b && b->shape)
            if (const auto* s = dynamic_cast<const Sphere*>(b->shape.get())) minRadius = std::min(minRadius, s->radius);
    }
    scale = extent;
    travelled = 0; // the bounds start from the positions now, those of the last step's integrator if current
    travelledTo = scene->motion.current() ? scene->motion.step() : scene->iter - 1;
    sweep = verletDist >= 0 ? verletDist : (std::isfinite(minRadius) ? -verletDist * minRadius : 0);
    // the first rebuild turns a relative verletDist into the distance it gave, as the reference does (-0.5 with
    // a smallest radius of 0.3 reads 0.15 after the first step); a relative value set later stays relative
    if (verletDist < 0 && numReinit == 0 && std::isfinite(minRadius)) verletDist = sweep;
    boundDispatcher->scene = scene;
    boundDispatcher->prepareTable(); // the loop below only reads the table
    for (const auto& f : boundDispatcher->functors)
        if (f) f->scene = scene;
    boxes.swap(previousBoxes);
    boxes.assign(bodies.size(), Box{Vector3r::Constant(NaN), Vector3r::Constant(NaN), Vector3r::Constant(NaN), 0, -1, false, false});
    // each body on its own (the Bo1 functors write only the bound they are given); a Bo1's error is rethrown after the loop
    std::exception_ptr error;
#pragma omp parallel for schedule(static)
    for (long id = 0; id < n; ++id) try {
        Body* b = bodies[(Body::id_t)id].get();
        if (!b || !b->shape) continue;
        if (!b->bounded) {
            b->bound.reset();
            continue;
        }
        BoundFunctor* f = boundDispatcher->getFunctor(*b->shape);
        if (!f) { // no Bo1 functor for this shape: the body takes no part in collisions
            b->bound.reset();
            continue;
        }
        f->go(*b->shape, b->bound, *b->state, *b);
        b->bound->min -= Vector3r::Constant(sweep);
        b->bound->max += Vector3r::Constant(sweep);
        b->bound->refPos = b->state->pos();
        b->bound->lastUpdateIter = scene->iter;
        boxes[id] = Box{b->bound->min, b->bound->max, b->bound->refPos, b->mask, b->clumpId, b->isDynamic(), true};
    } catch (...) {
#pragma omp critical(colliderBoundError)
        if (!error) error = std::current_exception();
    }
    if (error) std::rethrow_exception(error);
}

bool InsertionSortCollider::boundsOverlap(const Body& a, const Body& b) const {
    const Bound &A = *a.bound, &B = *b.bound;
    for (int i = 0; i < 3; ++i)
        if (!(A.max[i] >= B.min[i] && B.max[i] >= A.min[i])) return false; // written so that NaN never overlaps
    return true;
}

bool InsertionSortCollider::overlapNow(Body::id_t a, Body::id_t b) const {
    const Box &A = boxes[a], &B = boxes[b];
    const bool mayCollide = (A.mask & B.mask) != 0 && a != b && (A.dynamic || B.dynamic) && !avoidsItself(A.mask, B.mask)
            && !(A.clumpId >= 0 && A.clumpId == B.clumpId); // as mayCollide()
    return mayCollide && boxesOverlap(A, B);
}

bool InsertionSortCollider::overlappedBefore(Body::id_t a, Body::id_t b) const {
    return previousBoxes.size() != boxes.size() || boxesOverlap(previousBoxes[a], previousBoxes[b]); // (not known: assume they did)
}

void InsertionSortCollider::handleInversion(Body::id_t a, Body::id_t b) {
    const bool overlap = overlapNow(a, b);
    InteractionContainer& intrs = scene->interactions;
    const long k = intrs.findIndex(a, b);
    if (overlap && k < 0) intrs.insertPotential(std::min(a, b), std::max(a, b));
    else if (!overlap && k >= 0 && !intrs.isReal((size_t)k)) intrs.eraseAt((size_t)k);
}

// Insertion sort (3.1.3): each element moves left past the larger ones; passing a bound of the
// opposite kind means the overlap along this axis began or ended. The pairs whose interaction may
// have to be created or dropped are appended to `inversions` (handled afterwards, in this order):
// an overlap that begins along this axis but not along all needs nothing (there was no overlap
// before either).
void InsertionSortCollider::insertionSort(std::vector<Bound1D>& list, std::vector<std::pair<Body::id_t, Body::id_t>>& inversions) const {
    for (size_t i = 1; i < list.size(); ++i) {
        const Bound1D current = list[i];
        size_t j = i;
        while (j > 0 && current.coord < list[j - 1].coord) {
            const Bound1D& passed = list[j - 1];
            // a lower bound moving below an upper one: the overlap along this axis begins (an interaction
            // is due if the bounds now overlap along every axis); the converse: it ends (the pair can
            // have a potential interaction only if the bounds overlapped before this update)
            if (passed.isMin != current.isMin && passed.id != current.id
                    && (current.isMin ? overlapNow(current.id, passed.id) : overlappedBefore(current.id, passed.id)))
                inversions.emplace_back(current.id, passed.id);
            list[j] = list[j - 1];
            --j;
        }
        list[j] = current;
    }
}

void InsertionSortCollider::rebuild() {
    ++numReinit;
    const BodyContainer& bodies = scene->bodies;
    for (auto& axis : axes) axis.clear();
    for (const auto& b : bodies)
        if (collidable(b))
            for (int ax = 0; ax < 3; ++ax) {
                axes[ax].push_back({b->bound->min[ax], b->id, true});
                axes[ax].push_back({b->bound->max[ax], b->id, false});
            }
    for (auto& axis : axes)
        std::sort(axis.begin(), axis.end(), [](const Bound1D& x, const Bound1D& y) { return x.coord < y.coord; });
    InteractionContainer& intrs = scene->interactions;
    // Drop potential interactions whose bounds are apart (or whose bodies lost their bounds).
    std::vector<std::pair<Body::id_t, Body::id_t>> stale;
    for (size_t k = 0; k < intrs.size(); ++k) {
        if (intrs.isReal(k)) continue;
        const Body::id_t a = intrs.pairIds[2 * k], b = intrs.pairIds[2 * k + 1];
        const auto &A = bodies.exists(a) ? bodies[a] : nullptr, &B = bodies.exists(b) ? bodies[b] : nullptr;
        if (!collidable(A) || !collidable(B) || !mayCollide(*A, *B) || !boundsOverlap(*A, *B)) stale.emplace_back(a, b);
    }
    for (const auto& p : stale) intrs.erase(p.first, p.second);
    // Sweep along x: every body whose lower bound lies inside [min, max] of another may overlap it.
    // (the new pairs are collected first, so that the container's columns are sized once)
    std::vector<std::pair<Body::id_t, Body::id_t>> added;
    const auto& xs = axes[0];
    for (size_t i = 0; i < xs.size(); ++i) {
        if (!xs[i].isMin) continue;
        const Body::id_t a = xs[i].id;
        for (size_t j = i + 1; j < xs.size() && !(xs[j].id == a && !xs[j].isMin); ++j) {
            if (!xs[j].isMin) continue;
            const Body::id_t b = xs[j].id;
            if (mayCollide(*bodies[a], *bodies[b]) && boundsOverlap(*bodies[a], *bodies[b]) && intrs.findIndex(a, b) < 0)
                added.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    // in the order of the bodies' ids, which the interaction loop follows (its lists are sorted so):
    // the container's columns are then read in order too
    std::sort(added.begin(), added.end());
    intrs.reserve(intrs.size() + added.size());
    std::vector<uint32_t> perBody(bodies.size(), 0); // (each body's partner list grows once, to its size)
    for (const auto& p : added) {
        ++perBody[p.first];
        ++perBody[p.second];
    }
    intrs.reservePartners(perBody);
    for (const auto& p : added) intrs.insertPotential(p.first, p.second);
}

void InsertionSortCollider::preSave() {
    savedCoords.clear();
    savedIds.clear();
    for (const auto& axis : axes)
        for (const auto& e : axis) {
            savedCoords.push_back(e.coord);
            savedIds.push_back(2 * e.id + (e.isMin ? 1 : 0));
        }
}

void InsertionSortCollider::postLoad() {
    if (savedIds.empty()) return; // an attribute was set from Python, nothing to restore
    const size_t n = savedIds.size() / 3;
    if (savedIds.size() != savedCoords.size() || savedIds.size() % 3) {
        lastBodyChanges = -1; // inconsistent: rebuild at the next step
    } else {
        for (int ax = 0; ax < 3; ++ax) {
            axes[ax].clear();
            for (size_t i = ax * n; i < (ax + 1) * n; ++i) axes[ax].push_back({savedCoords[i], savedIds[i] / 2, (savedIds[i] & 1) != 0});
        }
        verifyLists = true;
    }
    savedCoords.clear();
    savedIds.clear();
}

void InsertionSortCollider::action() {
    if (!boundDispatcher) throw std::invalid_argument("InsertionSortCollider.boundDispatcher must not be None"); // (from Python or a file)
    if (scene->serial != lastScene) { // used in another scene before (engines kept across O.reset()): start afresh
        if (lastScene >= 0) lastBodyChanges = -1;
        lastScene = scene->serial;
    }
    if (verifyLists) { // lists loaded from a file must name existing bodies with bounds
        verifyLists = false;
        for (const auto& axis : axes)
            for (const auto& e : axis)
                if (e.id < 0 || !scene->bodies.exists(e.id) || !collidable(scene->bodies[e.id])) lastBodyChanges = -1;
    }
    if (scene->isPeriodic) {
        if (scene->cell->flipFlippable) scene->flipCell(Matrix3r::Zero()); // (nothing when no flip helps)
        periodicAction();
        return;
    }
    if (lastHSize.allFinite()) { // periodic until now: the lists are rebuilt
        lastHSize = Matrix3r::Constant(NaN);
        lastBodyChanges = -1;
    }
    if (!needsRun(sweep)) return;
    ++numAction;
    updateBounds();
    const BodyContainer& bodies = scene->bodies;
    size_t nCollidable = 0;
    for (const auto& b : bodies) nCollidable += collidable(b);
    if (bodies.changes != lastBodyChanges || 2 * nCollidable != axes[0].size()) {
        rebuild();
        lastBodyChanges = bodies.changes;
        return;
    }
    // the three axes sort in parallel (they only read the boxes); the interactions are then created
    // and dropped serially, axis by axis in sort order: the same sequence as one sort after the other
    std::vector<std::pair<Body::id_t, Body::id_t>> inversions[3];
#pragma omp parallel for schedule(dynamic, 1)
    for (int ax = 0; ax < 3; ++ax) {
        for (auto& e : axes[ax]) e.coord = e.isMin ? boxes[e.id].min[ax] : boxes[e.id].max[ax];
        insertionSort(axes[ax], inversions[ax]);
    }
    for (const auto& list : inversions)
        for (const auto& p : list) handleInversion(p.first, p.second);
}

} // namespace yade
