// The collider in a periodic scene (3.6.2). Positions are never wrapped: each run takes the bounds in
// the cell's coordinates s = hSize⁻¹·x (the cell is [0,1)³ there, whatever its shear), wraps their
// lower ends into the cell to sort them along the first edge, and tests each candidate pair along the
// three edges for the one whole shift k of body 2's image (at most one, since no bound spans half a
// cell) that makes the bounds overlap: k is the pair's cellDist. A run sorts from scratch (O(n log n));
// the bounds' Verlet enlargement makes runs rare, as in the aperiodic sort.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <core/Scene.hpp>
#include <pkg/common/InsertionSortCollider.hpp>
#include <pkg/common/Sphere.hpp>

namespace yade {

// The images of body 2 are at x₂ + hSize·c: since the last run they moved with the cell by at most
// the change of hSize's columns for |c| <= 1 along each edge.
Real InsertionSortCollider::cellDrift() const {
    const Matrix3r& h = scene->cell->hSize;
    if (!lastHSize.allFinite()) return Inf;
    return (h - lastHSize).colwise().norm().sum();
}

std::vector<InsertionSortCollider::PeriodicBox> InsertionSortCollider::periodicBoxes() {
    const Matrix3r inv = scene->cell->hSize.inverse();
    const Vector3r rowNorm(inv.row(0).norm(), inv.row(1).norm(), inv.row(2).norm());
    std::vector<PeriodicBox> out;
    for (const auto& b : scene->bodies) {
        if (!collidable(b)) continue;
        const Bound& B = *b->bound;
        if (!B.min.allFinite() || !B.max.allFinite())
            throw std::runtime_error("InsertionSortCollider: body #" + std::to_string(b->id)
                    + " has an infinite or undefined bound (e.g. a Wall), which a periodic cell cannot wrap");
        const Vector3r center = inv * (0.5 * (B.min + B.max));
        Vector3r half;
        if (const auto* s = dynamic_cast<const Sphere*>(b->shape.get()))
            half = (s->radius + sweep) * rowNorm; // (the exact extent of a ball in the cell's coordinates)
        else
            half = inv.cwiseAbs() * (0.5 * (B.max - B.min)); // (of the box's corners: a box around them)
        for (int i = 0; i < 3; ++i)
            if (2 * half[i] >= 0.5 && !allowBiggerThanPeriod) {
                std::ostringstream os;
                os << "InsertionSortCollider: body #" << b->id << " is too big for the periodic cell: its bound spans "
                   << 2 * half[i] << " of the cell along edge " << i << " (hSize column " << i
                   << "), more than the half allowed (a body would touch two images of another); enlarge the cell, or set allowBiggerThanPeriod=True";
                throw std::runtime_error(os.str());
            }
        out.push_back({center - half, center + half, b->id});
    }
    return out;
}

// The shift k (body 2's image at +k cells) for which [a0, a1] and [b0 + k, b1 + k] overlap, if any
// (both shorter than half a cell: at most one). A span of half a cell or more (allowBiggerThanPeriod)
// overlaps everything, through the nearest image of the centers.
static bool overlapShift(Real a0, Real a1, Real b0, Real b1, int& k) {
    if (a1 - a0 >= 0.5 || b1 - b0 >= 0.5) {
        k = (int)std::lround(0.5 * (a0 + a1) - 0.5 * (b0 + b1));
        return true;
    }
    const Real f = std::ceil(a0 - b1);
    k = (int)f;
    return f <= a1 - b0;
}

void InsertionSortCollider::periodicPairs(const std::vector<PeriodicBox>& boxes,
        std::vector<std::pair<std::pair<Body::id_t, Body::id_t>, Vector3i>>& found) const {
    const size_t n = boxes.size();
    // the lower ends along the first edge, wrapped into [0, 1), in order
    std::vector<std::pair<Real, uint32_t>> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = {boxes[i].lo[0] - std::floor(boxes[i].lo[0]), (uint32_t)i};
    std::sort(order.begin(), order.end());
    const BodyContainer& bodies = scene->bodies;
    for (size_t p = 0; p < n; ++p) {
        const PeriodicBox& A = boxes[order[p].second];
        const Real start = order[p].first, end = start + (A.hi[0] - A.lo[0]);
        // every box whose (wrapped) lower end lies in [start, end], going round the cell once
        for (size_t q = 1; q < n; ++q) {
            const size_t r = (p + q) % n;
            const Real lower = order[r].first + (p + q >= n ? 1 : 0);
            if (lower > end) break;
            const PeriodicBox& B = boxes[order[r].second];
            Vector3i k;
            bool overlap = true;
            for (int i = 0; i < 3 && overlap; ++i) overlap = overlapShift(A.lo[i], A.hi[i], B.lo[i], B.hi[i], k[i]);
            if (!overlap || !mayCollide(*bodies[A.id], *bodies[B.id])) continue;
            if (A.id < B.id) found.push_back({{A.id, B.id}, k});
            else found.push_back({{B.id, A.id}, -k});
        }
    }
    // (a pair whose lower ends coincide is found from both sides)
    std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    found.erase(std::unique(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first == y.first; }), found.end());
}

void InsertionSortCollider::periodicAction() {
    if (!needsRun(sweep - 0.5 * cellDrift())) return;
    ++numAction;
    updateBounds();
    for (auto& axis : axes) axis.clear(); // (the aperiodic lists: rebuilt if the scene stops being periodic)
    std::vector<std::pair<std::pair<Body::id_t, Body::id_t>, Vector3i>> found;
    periodicPairs(periodicBoxes(), found); // (throws for a body too big: then the next step tries again)
    lastBodyChanges = scene->bodies.changes;
    lastHSize = scene->cell->hSize;
    InteractionContainer& intrs = scene->interactions;
    std::vector<char> seen(intrs.size(), 0);
    std::vector<std::pair<Body::id_t, Body::id_t>> added;
    std::vector<Vector3i> addedShift;
    for (const auto& f : found) {
        const Body::id_t a = f.first.first, b = f.first.second;
        const long k = intrs.findIndex(a, b);
        if (k < 0) {
            added.push_back(f.first);
            addedShift.push_back(f.second);
            continue;
        }
        seen[k] = 1;
        // a potential pair takes the shift of the overlap now; a contact keeps the image it touches
        if (!intrs.isReal((size_t)k)) {
            const Vector3i c = intrs.pairIds[2 * k] == a ? f.second : Vector3i(-f.second);
            if (c != intrs.cellDist[k]) { // (another image: what the interaction loop kept of the pair is stale)
                intrs.cellDist[k] = c;
                ++intrs.changes;
            }
        }
    }
    std::vector<std::pair<Body::id_t, Body::id_t>> stale;
    for (size_t k = 0; k < seen.size(); ++k)
        if (!seen[k] && !intrs.isReal(k)) stale.emplace_back(intrs.pairIds[2 * k], intrs.pairIds[2 * k + 1]);
    for (const auto& p : stale) intrs.erase(p.first, p.second);
    intrs.reserve(intrs.size() + added.size());
    for (size_t i = 0; i < added.size(); ++i) {
        intrs.insertPotential(added[i].first, added[i].second);
        intrs.cellDist.back() = addedShift[i];
    }
}

} // namespace yade
