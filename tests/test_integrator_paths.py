"""NewtonIntegrator's step for free spheres (no blocked DOF, equal principal moments; taken without
energy tracking and without a mask) must give the bits of its general step, which the same scene
takes with O.trackEnergy or with a mask that every body matches: positions, velocities, spins and
orientations, with damping, gravity, contacts, spinning, still and blocked bodies in the mix."""
import numpy as np
import pytest

from yade import *  # noqa: F401,F403
from yade import O, pack, geom
from yade.utils import *  # noqa: F401,F403


def run(general, threads=1):
    O.reset()
    setNumThreads(threads)
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    O.bodies.append(geom.facetBox((.05, .05, .1), (.05, .05, .1), wallMask=31))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (.1, .1, .2), rMean=.006, rRelFuzz=.3, num=300, seed=5)
    sp.toSimulation()
    for b in O.bodies:
        if isinstance(b.shape, Sphere):
            b.state.angVel = (b.id % 7 - 3, b.id % 5 - 2, 0)
            if b.id % 11 == 0:
                b.state.blockedDOFs = 'xZ'  # the general step, beside the free ones
            if b.id % 13 == 0:
                b.state.vel = (0, 0, 0)
                b.state.angVel = (0, 0, 0)  # still until its first contact
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -300), damping=0.3)]
    O.dt = .5 * PWaveTimeStep()
    if general == 'energy':
        O.trackEnergy = True
    elif general == 'mask':
        O.engines[-1].mask = 1  # every body's mask is 1: all are moved, by the general step
    O.run(1500, True)
    setNumThreads(1)
    a = O.bodies.arrays()
    return {k: np.array(getattr(a, k)).tobytes() for k in ('pos', 'vel', 'angVel', 'ori')}


@pytest.mark.parametrize('general', ['energy', 'mask'])
@pytest.mark.parametrize('threads', [1, 2])
def test_free_spheres_step_gives_the_bits_of_the_general_step(general, threads):
    free = run(None, threads)
    other = run(general, threads)
    for k in free:
        assert free[k] == other[k], "%s differs" % k
