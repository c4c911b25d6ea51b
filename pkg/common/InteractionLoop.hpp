// Runs the three dispatchers over every interaction (1.2.1): Ig2 (geometry), Ip2 (physics of a
// new contact) and Law2 (forces). The Ig2 → Law2 and Ip2 → Law2 type chains are checked.
#pragma once
#include <core/IGeomDispatcher.hpp>
#include <core/IPhysDispatcher.hpp>
#include <core/LawDispatcher.hpp>
#include <set>
#include <vector>

namespace yade {

class InteractionLoop : public GlobalEngine {
public:
    std::shared_ptr<IGeomDispatcher> geomDispatcher = std::make_shared<IGeomDispatcher>();
    std::shared_ptr<IPhysDispatcher> physDispatcher = std::make_shared<IPhysDispatcher>();
    std::shared_ptr<LawDispatcher> lawDispatcher = std::make_shared<LawDispatcher>();
    bool fastPath = true;
    template <class V> void visit(V& v) {
        GlobalEngine::visit(v);
        v.attr("geomDispatcher", geomDispatcher, "Ig2 functors: contact geometry from two shapes");
        v.attr("physDispatcher", physDispatcher, "Ip2 functors: contact physics from two materials");
        v.attr("lawDispatcher", lawDispatcher, "Law2 functors: forces from geometry and physics");
        v.attr("fastPath", fastPath, "Reject distant potential sphere pairs from contiguous positions (same results as the general path)");
    }
    void action() override;
    // Throws std::invalid_argument explaining a broken chain (an Ig2 or Ip2 product no Law2 accepts).
    void checkFunctorChain() const;

private:
    std::set<std::pair<int, int>> warnedShapePairs;
    // Per step, contiguous: sphere centers and radii (radius NaN for other bodies), so that
    // distant potential sphere pairs are rejected without touching bodies or interactions.
    struct SphereAt {
        Vector3r pos;
        Real radius;
    };
    std::vector<SphereAt> spheres;
    Real prepareQuickReject(); // fills `spheres`; the reach factor, or a negative value if unused
    void warnMissingIg2(const Shape& a, const Shape& b);
};

} // namespace yade
