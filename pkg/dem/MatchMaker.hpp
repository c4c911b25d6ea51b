// A value per pair of materials (e.g. a friction angle or a restitution coefficient): looked up
// in `matches` by the two materials' ids, else computed from the materials' own values by `algo`.
#pragma once
#include <lib/factory/ClassRegistry.hpp>
#include <string>
#include <vector>

namespace yade {

class MatchMaker : public Serializable {
public:
    static constexpr const char* classDoc =
            "A value per pair of materials: `matches` lists (id1, id2, value) for material ids in either order; other pairs get "
            "`algo` applied to the two materials' own values: 'avg', 'min', 'max', 'harmAvg' (2ab/(a+b)) or 'val' (always `val`). "
            "A number given where a MatchMaker is expected becomes MatchMaker(algo='val', val=number).";
    std::vector<Vector3r> matches;
    std::string algo = "avg";
    Real val = NaN;
    template <class V> void visit(V& v) {
        Serializable::visit(v);
        v.attr("matches", matches, "Values for given pairs of material ids: (id1, id2, value), either order");
        v.attr("algo", algo, "How to combine the materials' values for pairs not in matches: val, avg, min, max, harmAvg");
        v.attr("val", val, "The constant value given by algo='val'");
    }
    void postLoad() override; // checks algo (std::invalid_argument)
    // The value for materials id1, id2 whose own values are v1, v2 (NaN: they have none).
    // std::invalid_argument when the pair is not matched and algo needs values that are missing.
    Real operator()(int id1, int id2, Real v1 = NaN, Real v2 = NaN) const;
    // algo applied to v1, v2.
    Real computeFallback(Real v1, Real v2) const;
    // A MatchMaker that always gives v.
    static std::shared_ptr<MatchMaker> constant(Real v);
};

} // namespace yade
