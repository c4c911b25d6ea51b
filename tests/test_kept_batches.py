"""Kept batches of InteractionLoop (doc/storage.md, "Kept batches"): a batch of existing contacts of
fast passes is computed again at the next step from what was kept, without gathering it, while its
entries, functors and records are unchanged. It must give the bits of the general path
(fusedPasses=False, which keeps nothing) in the steady state and across everything that makes the
kept batches stale: contacts ending and starting, writes from Python, a contact erased, the functors
replaced, two threads."""
import numpy as np
import pytest

from yade import *  # noqa: F401,F403
from yade import O, geom, pack
from yade.utils import *  # noqa: F401,F403


def engines(fused):
    """Spheres and facets, Cundall-Strack, gravity and damping; the interaction loop returned."""
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                           [Law2_ScGeom_FrictPhys_CundallStrack()])
    loop.fusedPasses = fused
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]), loop,
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=.4)]
    O.dt = .5 * PWaveTimeStep()
    return loop


def lattice(fused, threads=1):
    """A compressed simple cubic lattice in a facet box (every contact lasts), spheres spinning."""
    O.reset()
    setNumThreads(threads)
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    r, n = .01, 9
    a = 2 * r * .995
    half = ((n - 1) * a + 2 * r - .01 * r) / 2
    c = (n - 1) * a / 2
    O.bodies.append(geom.facetBox((c, c, c), (half, half, half), wallMask=63))
    for k in range(n):
        for j in range(n):
            for i in range(n):
                b = sphere((i * a, j * a, k * a), r)
                b.state.angVel = ((i + j) % 3 - 1, (j + k) % 5 - 2, (i * k) % 3 - 1)
                O.bodies.append(b)
    return engines(fused)


def state():
    a = O.bodies.arrays()
    s = {k: np.array(getattr(a, k)).tobytes() for k in ('pos', 'vel', 'angVel', 'ori', 'force', 'torque')}
    s['contacts'] = sorted((i.id1, i.id2, tuple(i.phys.normalForce), tuple(i.phys.shearForce), tuple(i.geom.shearInc))
                           for i in O.interactions if i.isReal)
    return s


def run(fused, script, threads=1):
    """script(step): called every 50 steps; returns the states then and the kept batches seen."""
    loop = lattice(fused, threads)
    states, kept = [], []
    for chunk in range(8):
        script(chunk)
        O.run(50, True)
        kept.append(loop.keptBatches)
        states.append(state())
    setNumThreads(1)
    return states, kept


def same_bits(script, threads=1):
    fast, kept = run(True, script, threads)
    general, none = run(False, script, threads)
    assert set(none) == {0}, "fusedPasses=False keeps no batch"
    for m, (a, b) in enumerate(zip(fast, general)):
        for k in a:
            assert a[k] == b[k], "%s differs after %d steps" % (k, 50 * (m + 1))
    return kept


@pytest.mark.parametrize('threads', [1, 2])
def test_a_lasting_packing_is_computed_from_kept_batches_with_the_same_bits(threads):
    kept = same_bits(lambda step: None, threads)
    # 729 spheres, about 2 000 contacts: every batch of the last step was a kept one
    assert min(kept) >= 2000 // 256, kept


def deposition(fused):
    """Spheres falling into a box: contacts start and end in most steps, and most batches mix
    contacts with potential pairs still apart."""
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    N, r = 1000, .01
    side = (N * (4. / 3.) * 3.14159 * r ** 3 / .3) ** (1. / 3.)
    O.bodies.append(geom.facetBox((side / 2, side / 2, side), (side / 2, side / 2, side), wallMask=31))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (side, side, 1.5 * side), rMean=r, rRelFuzz=.2, num=N, seed=1)
    sp.toSimulation()
    loop = engines(fused)
    kept, states = 0, []
    for step in range(1500):
        O.run(1, True)
        kept += loop.keptBatches
        if step % 250 == 249:
            states.append(b''.join(np.array(b.state.pos).tobytes() + np.array(b.state.vel).tobytes() for b in O.bodies))
    return states, kept


def test_batches_with_pairs_still_apart_and_contacts_that_end_keep_the_bits():
    fast, kept = deposition(True)
    general, none = deposition(False)
    assert none == 0
    assert kept > 100, kept
    for m, (a, b) in enumerate(zip(fast, general)):
        assert a == b, "the states differ after %d steps" % (250 * (m + 1))


def test_writes_from_python_make_them_stale():
    def script(step):
        if step == 3:  # a write from Python: the batches are gathered again
            O.bodies[100].state.vel = (0, 0, .05)
            O.bodies[200].state.angVel = (3, 0, 0)
    kept = same_bits(script)
    assert kept[-1] > 0


def test_an_erased_contact_and_contacts_that_end_make_them_stale():
    def script(step):
        if step == 2:  # a contact back to a potential pair, through Python (recomputed at the next step)
            i = next(i for i in O.interactions if i.isReal and i.id1 > 50)
            O.interactions.erase(i.id1, i.id2)
        if step == 4:  # the top wall lifted: contacts end and others start while others last
            for b in O.bodies:
                if isinstance(b.shape, Sphere) and b.state.pos[2] > .12:
                    b.state.vel = (0, 0, .3)
    kept = same_bits(script)
    assert kept[-1] > 0


def test_replaced_functors_make_them_stale():
    def script(step, replace=True):
        if step == 3 and replace:  # new functor objects (the kept runs named the old ones), which compute otherwise
            O.engines[2].geomDispatcher.functors = [Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(hertzian=True)]
        if step == 4 and replace:
            O.engines[2].lawDispatcher.functors = [Law2_ScGeom_FrictPhys_CundallStrack(neverErase=True)]
        if step == 5:  # the top layer thrown off the top wall: its contacts kept by the new law, ended by the old one
            for b in O.bodies:
                if isinstance(b.shape, Sphere) and b.state.pos[2] > .15:
                    b.state.vel = (0, 0, -5)
    fast, kept = run(True, script)
    general, _ = run(False, script)
    for m, (a, b) in enumerate(zip(fast, general)):
        for k in a:
            assert a[k] == b[k], "%s differs after %d steps" % (k, 50 * (m + 1))
    assert kept[-1] > 0


def test_replaced_functors_or_shapes_make_every_kept_batch_stale():
    loop = lattice(True)
    O.run(20, True)
    assert loop.keptBatches > 2000 // 256
    changes = {
        'Law2 functors': lambda: setattr(loop.lawDispatcher, 'functors', [Law2_ScGeom_FrictPhys_CundallStrack(neverErase=True)]),
        'Ig2 functors': lambda: setattr(loop.geomDispatcher, 'functors', [Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(hertzian=True)]),
        'a shape': lambda: setattr(O.bodies[300].shape, 'radius', .0101),
        'fusedPasses': lambda: setattr(loop, 'fusedPasses', False),
    }
    for what, change in changes.items():
        change()
        O.run(1, True)
        assert loop.keptBatches == 0, what
        loop.fusedPasses = True
        O.run(3, True)  # (a new skin epoch tests every pair once: the batches are kept from the step after it)
        assert loop.keptBatches > 2000 // 256, what
