// Sweep and prune with insertion sort on three axes (3.1.3). Bounds are enlarged by the
// Verlet distance and the collider reruns only when a body has moved farther than that.
#pragma once
#include <pkg/common/Collider.hpp>

namespace yade {

class InsertionSortCollider : public Collider {
public:
    static constexpr const char* classDoc = "Collider using sweep and prune with insertion sort on three axes (3.1.3); bounds are enlarged by the Verlet distance so that it reruns only when bodies moved farther than that.";
    Real verletDist = -0.5;
    bool allowBiggerThanPeriod = false;
    long long numAction = 0, numReinit = 0;
    template <class V> void visit(V& v) {
        Collider::visit(v);
        v.attr("verletDist", verletDist,
                "Enlargement of the bounds (the Verlet distance ΔL of 3.1.3); negative: that fraction of the smallest sphere radius (replaced by that distance at the first run, as in the reference)",
                Attr::finite);
        v.attr("allowBiggerThanPeriod", allowBiggerThanPeriod,
                "In a periodic scene, accept bodies whose bound spans half the cell or more along an axis (each then meets the nearest image of every body along that axis); otherwise such a body stops the run with an error");
        v.attr("numAction", numAction, "How many times the collider has run (not counting skipped steps)", Attr::readonly | Attr::noSave);
        v.attr("numReinit", numReinit, "How many times the sorted lists were rebuilt from scratch", Attr::readonly | Attr::noSave);
        // run-time state, saved so that a loaded scene continues exactly
        v.attr("savedCoords", savedCoords, "Sorted bound coordinates (x, y, z lists), written on save", Attr::hidden);
        v.attr("savedIds", savedIds, "Body ids ×2 (+1 for lower bounds) of savedCoords", Attr::hidden);
        v.attr("lastBodyChanges", lastBodyChanges, "Value of the body container's change counter at the last rebuild", Attr::hidden);
        v.attr("sweep", sweep, "Current enlargement of the bounds", Attr::hidden);
        v.attr("lastHSize", lastHSize, "O.cell.hSize at the last run in a periodic scene (NaN: the last run was not periodic)", Attr::hidden);
    }
    void action() override;
    void preSave() override;
    void postSave() override {
        savedCoords.clear();
        savedIds.clear();
    }
    void postLoad() override;
    Real sweepLength() const { return sweep; }

private:
    struct Bound1D {
        Real coord;
        Body::id_t id;
        bool isMin;
    };
    std::vector<Bound1D> axes[3];
    // What the sort needs of each body, contiguous by id (filled by updateBounds): the sort then
    // reads this array instead of following Body -> Bound and Body -> State pointers.
    struct Box {
        Vector3r min, max;
        Vector3r refPos; // position when the bound was computed
        int mask;
        int clumpId; // members of one clump do not collide with each other
        bool dynamic;
        bool collidable;
    };
    std::vector<Box> boxes;
    // The boxes of the run before (potential interactions exist where those overlapped): the sort
    // looks up only the pairs whose bounds stopped overlapping and had overlapped, not every crossing.
    std::vector<Box> previousBoxes;
    long long lastBodyChanges = -1;
    long long lastScene = -1; // Scene::serial of the scene of the last run (not saved)
    Real sweep = 0;
    std::vector<Real> savedCoords;
    std::vector<int> savedIds;
    bool verifyLists = false; // lists came from a file: check them against the bodies first
    // A bound on how far any body has moved since updateBounds() (Inf: unknown), from the
    // integrator's steps up to the position mirror of step travelledTo; scale: the largest coordinate then.
    Real travelled = Inf, scale = 0;
    long long travelledTo = -2;
    bool needsRun(Real limit);
    void updateBounds();
    void rebuild();
    void insertionSort(std::vector<Bound1D>& list, std::vector<std::pair<Body::id_t, Body::id_t>>& inversions) const;
    bool overlapNow(Body::id_t a, Body::id_t b) const; // bounds overlap and the bodies may collide
    bool overlappedBefore(Body::id_t a, Body::id_t b) const; // their previous boxes overlapped (true if unknown)
    // The overlap of the bounds of a and b may have changed: create or drop their potential interaction.
    void handleInversion(Body::id_t a, Body::id_t b);
    bool boundsOverlap(const Body& a, const Body& b) const;
    static bool boxesOverlap(const Box& a, const Box& b) {
        for (int i = 0; i < 3; ++i)
            if (!(a.max[i] >= b.min[i] && b.max[i] >= a.min[i])) return false; // written so that NaN never overlaps
        return true;
    }
    bool collidable(const std::shared_ptr<Body>& b) const { return b && b->shape && b->bound; }

    // The periodic scene (3.6.2, InsertionSortColliderPeriodic.cpp): every run finds the overlapping
    // bounds in the cell's own coordinates (fractions of its edges), each pair with the shift of body
    // 2's image (cellDist).
    Matrix3r lastHSize = Matrix3r::Constant(NaN); // the cell at the last periodic run (NaN: none, or aperiodic since)
    Real cellDrift() const;                       // how far any image may have moved with the cell since then
    void periodicAction();
    struct PeriodicBox {
        Vector3r lo, hi; // in cell coordinates, not wrapped
        Body::id_t id;
    };
    std::vector<PeriodicBox> periodicBoxes(); // of the collidable bodies (throws for one too big)
    void periodicPairs(const std::vector<PeriodicBox>& boxes, std::vector<std::pair<std::pair<Body::id_t, Body::id_t>, Vector3i>>& found) const;
};

} // namespace yade
