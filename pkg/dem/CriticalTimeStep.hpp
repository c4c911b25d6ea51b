// Stiffness-based critical time step (3.5.5): per dynamic body, the diagonal of the translational
// and rotational stiffness matrices summed over its contacts (3.5.20), and
// Δt = min over bodies and degrees of freedom of sqrt(2)·sqrt(m/K) (3.5.18).
#pragma once
#include <core/Scene.hpp>

namespace yade {

struct CriticalStep {
    Real dt = Inf;         // Inf when no dynamic body has a contact
    Body::id_t body = -1;  // the body that sets it
    int dof = -1;          // 0-2 translation x,y,z; 3-5 rotation
    // The smaller step; of equal ones the smaller body id and dof (the same answer whatever the
    // order in which bodies are visited, e.g. by several threads).
    bool before(const CriticalStep& o) const {
        return dt < o.dt || (dt == o.dt && o.body >= 0 && (body < o.body || (body == o.body && dof < o.dof)));
    }
};

// asLastLoopSawThem: only the interactions InteractionLoop found real in its last pass (its
// contiguous flags; the contacts whose forces it computes), instead of asking each interaction.
CriticalStep criticalTimeStep(const Scene& scene, bool asLastLoopSawThem = false);
// The same, keeping each body's stiffness diagonals (translations, rotations) in kTrans and kRot.
CriticalStep criticalTimeStep(const Scene& scene, bool asLastLoopSawThem, std::vector<Vector3r>& kTrans, std::vector<Vector3r>& kRot);
// The bodies of the contacts made in this step (entries of O.interactions), cheaply: each new
// contact's stiffness is added to its bodies' sums in kTrans and kRot (those of the last full check,
// and of the new contacts since); only a body whose sums give a critical step below O.dt is then
// computed again from all its contacts (its sums replaced by those). A body's contacts that grew
// stiffer since the last full check are thus seen at the next one.
CriticalStep criticalStepOfNewContacts(const Scene& scene, const std::vector<size_t>& contacts, std::vector<Vector3r>& kTrans,
        std::vector<Vector3r>& kRot);
// The same for a few bodies only (those that just got a new contact): cost ∝ their contacts.
CriticalStep criticalTimeStep(const Scene& scene, const std::vector<Body::id_t>& bodies);
// One body's part of the above, kept in best if lower (asLastLoopSawThem: as for the whole scene).
void criticalStepOfBody(const Scene& scene, Body::id_t id, CriticalStep& best, bool asLastLoopSawThem = false);

} // namespace yade
