"""The fused pass of InteractionLoop (fusedPasses, on by default): existing sphere-sphere contacts
with Law2_ScGeom_FrictPhys_CundallStrack run Ig2_Sphere_Sphere_ScGeom and the law in one hand-written
pass (pkg/dem/Ig2_Sphere_Sphere_ScGeom_CundallStrack.cpp). It must give the very bits of the two
functors run one after the other (fusedPasses=False): positions, velocities, spins, orientations,
contact forces and geometry, with contacts sliding, rolling, ending and starting again."""
import numpy as np
import pytest

from yade import *  # noqa: F401,F403
from yade import O, pack, geom
from yade.utils import *  # noqa: F401,F403


def run(fused, steps, neverErase=False, energy=False, frictionAngle=.5, mindlin=False):
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=frictionAngle, density=2600))
    O.bodies.append(geom.facetBox((.05, .05, .1), (.05, .05, .1), wallMask=31))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (.1, .1, .2), rMean=.006, rRelFuzz=.3, num=400, seed=3)
    sp.toSimulation()
    for b in O.bodies:
        if isinstance(b.shape, Sphere):
            b.state.angVel = (b.id % 7 - 3, b.id % 5 - 2, b.id % 3 - 1)  # spins: rolling and twisting contacts
    if mindlin:
        ip2, law = Ip2_FrictMat_FrictMat_MindlinPhys(en=.5), Law2_ScGeom_MindlinPhys_Mindlin(neverErase=neverErase)
    else:
        ip2, law = Ip2_FrictMat_FrictMat_FrictPhys(), Law2_ScGeom_FrictPhys_CundallStrack(neverErase=neverErase)
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [ip2], [law])
    assert loop.fusedPasses is True
    loop.fusedPasses = fused
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]), loop,
                 NewtonIntegrator(gravity=(0, 0, -300), damping=0.2)]
    O.trackEnergy = energy
    O.dt = .5 * PWaveTimeStep()
    ended = 0
    real = set()
    for chunk in range(10):
        O.run(steps // 10, True)
        now = {(i.id1, i.id2) for i in O.interactions if i.isReal}
        ended += len(real - now)
        real = now
    a = O.bodies.arrays()
    state = {k: np.array(getattr(a, k)).tobytes() for k in ('pos', 'vel', 'angVel', 'ori', 'force', 'torque')}
    contacts = sorted((i.id1, i.id2, tuple(i.phys.normalForce), tuple(i.phys.shearForce), tuple(i.geom.normal),
                       tuple(i.geom.shearInc), i.geom.penetrationDepth, tuple(i.geom.contactPoint), i.phys.kn, i.phys.ks)
                      + ((tuple(i.phys.normalViscous), tuple(i.phys.shearViscous), tuple(i.phys.shearElastic),
                          tuple(i.phys.usElastic), tuple(i.phys.usTotal), i.phys.isSliding) if mindlin else ())
                      for i in O.interactions if i.isReal)
    sliding = sum(1 for i in O.interactions if i.isReal
                  and i.phys.shearForce.norm() >= .999 * i.phys.normalForce.norm() * i.phys.tangensOfFrictionAngle > 0)
    return state, contacts, ended, sliding, dict(O.energy.items()) if energy else None


@pytest.mark.parametrize("neverErase,energy", [(False, False), (True, False), (False, True)],
                         ids=["plain", "neverErase", "trackEnergy"])
def test_fused_pass_gives_the_same_bits_as_the_two_functors(neverErase, energy):
    fused = run(True, 1500, neverErase, energy)
    general = run(False, 1500, neverErase, energy)
    state, contacts, ended, sliding, en = fused
    # the scene exercised what the pass does (settled under a strong gravity: short runs)
    assert len(contacts) > 300, len(contacts)
    if neverErase:  # separated contacts are kept, with zero forces
        assert sum(1 for c in contacts if c[6] < 0 and c[2] == (0, 0, 0)) > 20
    else:
        assert ended > 20, "too few contacts ended: %d" % ended
    assert sliding > 0, "no sliding contact"
    for k in state:
        assert state[k] == general[0][k], "%s differs" % k
    assert contacts == general[1]
    assert en == general[4]


def test_fused_pass_is_used_for_frictionless_contacts_too():
    assert run(True, 500, frictionAngle=0)[0] == run(False, 500, frictionAngle=0)[0]



@pytest.mark.parametrize("neverErase", [False, True], ids=["plain", "neverErase"])
def test_fused_hertz_mindlin_pass_gives_the_same_bits_as_the_two_functors(neverErase):
    """Ig2_Sphere_Sphere_ScGeom with Law2_ScGeom_MindlinPhys_Mindlin: the two-lane pass
    (pkg/dem/Ig2_Sphere_Sphere_ScGeom_Mindlin.cpp) gives the bits of the two functors, every
    attribute of the contacts included (viscous and elastic parts, displacements, isSliding)."""
    fused = run(True, 1500, neverErase, mindlin=True)
    general = run(False, 1500, neverErase, mindlin=True)
    state, contacts, ended, sliding, _ = fused
    assert len(contacts) > 300, len(contacts)
    assert neverErase or ended > 20, "too few contacts ended: %d" % ended
    assert sliding > 0, "no sliding contact"
    assert sum(1 for c in contacts if c[-1]) > 0 and sum(1 for c in contacts if c[-5] != (0, 0, 0)) > 100  # sliding; shear damping
    assert fused[0] == general[0]
    assert fused[1] == general[1]
