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
// The same for a few bodies only (those that just got a new contact): cost ∝ their contacts.
CriticalStep criticalTimeStep(const Scene& scene, const std::vector<Body::id_t>& bodies);
// One body's part of the above, kept in best if lower.
void criticalStepOfBody(const Scene& scene, Body::id_t id, CriticalStep& best);

} // namespace yade
