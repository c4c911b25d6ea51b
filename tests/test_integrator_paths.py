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


def runPeriodic(general, homoDeform):
    """A periodic packing compressed and sheared by the cell (its homogeneous field in every mode), with
    damping and gravity; velGrad changes halfway."""
    O.reset()
    O.periodic = True
    O.cell.hSize = Matrix3(.1, 0, .01, 0, .1, 0, 0, 0, .12)
    O.cell.homoDeform = homoDeform
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (.1, .1, .12), rMean=.006, rRelFuzz=.3, num=250, periodic=True, seed=7)
    sp.toSimulation()
    O.cell.hSize = Matrix3(.1, 0, .01, 0, .1, 0, 0, 0, .12)
    for b in O.bodies:
        b.state.angVel = (b.id % 7 - 3, b.id % 5 - 2, 0)
        if b.id % 11 == 0:
            b.state.blockedDOFs = 'xZ'
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -30), damping=0.3)]
    O.dt = .5 * PWaveTimeStep()
    if general == 'energy':
        O.trackEnergy = True
    elif general == 'mask':
        O.engines[-1].mask = 1
    O.cell.velGrad = Matrix3(-25, 0, .3, 0, -25, 0, 0, .1, -25)
    O.run(400, True)
    O.cell.velGrad = Matrix3(-2, .1, 0, 0, -3, 0, .2, 0, -1)
    O.run(400, True)
    assert O.interactions.countReal() > 100 and any(tuple(i.cellDist) != (0, 0, 0) for i in O.interactions if i.isReal)
    a = O.bodies.arrays()
    return {k: np.array(getattr(a, k)).tobytes() for k in ('pos', 'vel', 'angVel', 'ori')}


@pytest.mark.parametrize('general', ['energy', 'mask'])
@pytest.mark.parametrize('homoDeform', [0, 1, 2])
def test_free_spheres_step_in_a_periodic_cell_gives_the_bits_of_the_general_step(general, homoDeform):
    free = runPeriodic(None, homoDeform)
    other = runPeriodic(general, homoDeform)
    for k in free:
        assert free[k] == other[k], "%s differs" % k


@pytest.mark.parametrize('general', ['energy', 'mask'])
@pytest.mark.parametrize('threads', [1, 2])
def test_free_spheres_step_gives_the_bits_of_the_general_step(general, threads):
    free = run(None, threads)
    other = run(general, threads)
    for k in free:
        assert free[k] == other[k], "%s differs" % k


def spinning(alone):
    """Free spheres far apart, each spinning at its own rate (none, slow, fast enough for the library's
    sine, an orientation set off unit length). The integrator takes consecutive free spheres two at a
    time; `alone`: a fixed body after each sphere, so that it takes each sphere by itself."""
    O.reset()
    spheres = []
    for i in range(41):
        b = sphere((i, 0, 0), .01)
        b.state.angVel = [(0, 0, 0), (.3, -.2, .1), (400, 100, -300), (1e-9, 0, 0), (-50, 20, 7)][i % 5]
        if i % 7 == 3:
            b.state.ori = Quaternion(1.01, .1, 0, 0)  # (off unit length: the exact normalization)
        spheres.append(O.bodies.append(b))
        if alone:
            O.bodies.append(sphere((i, 0, -1), .01, fixed=True))
    O.engines = [ForceResetter(), NewtonIntegrator(damping=0.2)]
    O.dt = 1e-4
    O.run(300, True)
    return [(tuple(O.bodies[i].state.ori), tuple(O.bodies[i].state.angVel)) for i in spheres]


def test_spheres_turned_two_at_a_time_or_one_by_one_get_the_same_bits():
    paired = spinning(False)
    assert paired == spinning(True)
    assert len({o for o, w in paired}) >= 9  # (they did turn: each rate and start its own way)
