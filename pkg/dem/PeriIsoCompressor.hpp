// Compresses a periodic packing isotropically through the stresses listed in `stresses`, one after
// the other, by setting the diagonal of O.cell.velGrad each step; runs doneHook after the last one.
// Formulas: doc/periodic.md.
#pragma once
#include <pkg/dem/BoundaryController.hpp>

namespace yade {

class PeriIsoCompressor : public BoundaryController {
public:
    static constexpr const char* classDoc =
            "Engine compressing a periodic packing (O.cell) to each stress of stresses in turn (negative: compression): each step the cell shrinks or grows by a step estimated from the mean contact stiffness (at most charLen/100 along its longest edge); a stress counts as reached when the mean normal stress (every normal stress without keepProportions) is within 0.5 % of it (and, at the steps checked every globalUpdateInt, the unbalanced force is below maxUnbalanced). doneHook runs after the last one.";
    std::vector<Real> stresses;
    Real charLen = -1;
    Real maxSpan = -1;
    Real maxUnbalanced = 1e-4;
    int globalUpdateInt = 20;
    int state = 0;
    std::string doneHook;
    bool keepProportions = true;
    Vector3r sigma = Vector3r::Zero();
    Real currUnbalanced = -1;

    template <class V> void visit(V& v) {
        BoundaryController::visit(v);
        v.attr("stresses", stresses, "Stresses to reach, one after the other (negative: compression) [Pa]");
        v.attr("charLen", charLen, "Characteristic length: the cell's longest edge moves at most charLen/100 per step (-1: the extent of the first body's bound, found at the first step) [m]");
        v.attr("maxSpan", maxSpan, "Largest extent of a body's bound (-1: found at the first step); the cell must stay at least 2.1 times as large [m]");
        v.attr("maxUnbalanced", maxUnbalanced, "A stress is reached only while the unbalanced force, checked every globalUpdateInt steps, is below this");
        v.attr("globalUpdateInt", globalUpdateInt, "The unbalanced force is checked at the steps that are multiples of this", Attr::positive);
        v.attr("state", state, "Index of the stress of stresses being reached now (len(stresses): all done)");
        v.attr("doneHook", doneHook, "Python command run (in the script's namespace) once the last stress is reached");
        v.attr("keepProportions", keepProportions, "Keep the cell's proportions (one strain rate for the three axes, from the mean stress); else each axis follows its own stress");
        v.attr("sigma", sigma, "Normal stresses of the packing, -Σ|f_i| / (area of face i) over the contacts, predicted to the end of the step [Pa]", Attr::readonly | Attr::hidden | Attr::noSave);
        v.attr("currUnbalanced", currUnbalanced, "Unbalanced force at the last check (-1: none yet)", Attr::readonly | Attr::hidden | Attr::noSave);
    }
    void action() override;
};

} // namespace yade
