"""InteractionLoop.fastPath's facet-sphere quick reject (InteractionLoop::facetSphereReject): a
pair is skipped when a lower bound of the sphere centre's distance from the facet's triangle is
beyond reach, which must never skip a pair Ig2_Facet_Sphere_ScGeom would have made a contact:
the trajectories with and without the fast path are the same bits."""
import numpy as np
import pytest

from yade import *  # noqa: F401,F403
from yade import O, geom
from yade.utils import *  # noqa: F401,F403


def slide_over_a_wall(fast):
    """Spheres rolling over a two-triangle facet wall: across its diagonal, past its outer edges
    and corners, and at a gap from it (contacts with one or both triangles, starting and ending)."""
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.3, density=2600))
    wall = O.bodies.append(geom.facetBox((0, 0, 0), (.05, .05, .05), wallMask=16))  # only the bottom wall (-z): two facets
    r = .005
    z = -.05 + r * .999
    starts = [((-.04, -.03, z), (.5, .4, 0)),            # across the diagonal, off the far edge
              ((.03, -.04, z), (.1, .6, 0)),             # along the wall, off an edge
              ((-.045, .045, z), (-.2, .2, 0)),          # off a corner
              ((.001, -.001, -.05 + r * 1.3), (0, 0, -.3))]  # falling onto the diagonal
    for pos, vel in starts:
        s = sphere(pos, r)
        s.state.vel = vel
        O.bodies.append(s)
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                           [Law2_ScGeom_FrictPhys_CundallStrack()])
    loop.fastPath = fast
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]), loop,
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=0)]
    O.dt = .5 * PWaveTimeStep()
    facetContacts = set()
    for chunk in range(300):
        O.run(10, True)
        facetContacts |= {(i.id1, i.id2) for i in O.interactions if i.isReal and (i.id1 in wall or i.id2 in wall)}
    a = O.bodies.arrays()
    return {k: np.array(getattr(a, k)).tobytes() for k in ('pos', 'vel', 'angVel', 'ori')}, facetContacts


def test_facet_triangle_quick_reject_changes_nothing():
    # fastPath rejects facet-sphere pairs from a bound of the distance to the triangle
    # (InteractionLoop::facetSphereReject); without it every pair goes to Ig2_Facet_Sphere_ScGeom
    fast, contactsFast = slide_over_a_wall(True)
    general, contactsGeneral = slide_over_a_wall(False)
    assert contactsFast == contactsGeneral
    assert len({min(p) for p in contactsFast}) == 2, "the spheres touched both triangles of the wall"
    assert len({max(p) for p in contactsFast}) == 4, "every sphere touched the wall"
    for k in fast:
        assert fast[k] == general[k], k


def turning_drum(fast, mindlin):
    """A drum of facets turned by a RotationEngine, half filled with spheres: the facets move and turn
    at every step, which the skin of the fast path bounds instead of testing every pair again."""
    import math
    from yade import (O, FrictMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb, InteractionLoop,
                      Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                      Law2_ScGeom_FrictPhys_CundallStrack, Ip2_FrictMat_FrictMat_MindlinPhys, Law2_ScGeom_MindlinPhys_Mindlin,
                      RotationEngine, NewtonIntegrator, Quaternion, PWaveTimeStep, geom, pack, utils)
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    R, L = 0.1, 0.04
    drum = O.bodies.append(geom.facetCylinder((0, 0, 0), R, L, orientation=Quaternion((1, 0, 0), math.pi / 2),
                                              segmentsNumber=24, wallMask=7, fixed=True))
    sp = pack.SpherePack()
    sp.makeCloud((-0.6 * R, -0.4 * L, -0.7 * R), (0.6 * R, 0.4 * L, 0.2 * R), rMean=0.006, rRelFuzz=0.2, seed=1)
    O.bodies.append([utils.sphere(c, r) for c, r in sp])
    ip2, law = ((Ip2_FrictMat_FrictMat_MindlinPhys(en=.5), Law2_ScGeom_MindlinPhys_Mindlin()) if mindlin
                else (Ip2_FrictMat_FrictMat_FrictPhys(), Law2_ScGeom_FrictPhys_CundallStrack()))
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(hertzian=mindlin)], [ip2], [law])
    loop.fastPath = fast
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]), loop,
                 RotationEngine(ids=drum, rotationAxis=(0, 1, 0), rotateAroundZero=True, zeroPoint=(0, 0, 0), angularVelocity=30),
                 NewtonIntegrator(gravity=(0, 0, -300), damping=0.2)]  # (a strong gravity: a short run)
    O.dt = 0.5 * PWaveTimeStep()
    O.run(3000, True)
    a = O.bodies.arrays()
    return np.array(a.pos).tobytes(), np.array(a.vel).tobytes(), O.interactions.countReal()


@pytest.mark.parametrize('mindlin', [False, True], ids=['linear', 'hertz-mindlin'])
def test_turning_facets_keep_the_skin_and_change_nothing(mindlin):
    fast, general = turning_drum(True, mindlin), turning_drum(False, mindlin)
    assert fast[2] > 20  # contacts with the drum and between spheres
    assert fast == general


def test_turning_facets_do_not_make_sphere_pairs_tested_again():
    """The skin bounds the motion of the spheres and of the facets apart: a pair of two spheres is
    tested again only once the spheres moved, whatever the facets did (a facet-sphere pair, once the
    facet or the sphere moved). Spheres at rest in a turning drum: the potential pairs of two
    spheres are left out at every step, while the drum's facets go on turning."""
    import math
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    R, L, r = 0.1, 0.04, 0.005
    drum = O.bodies.append(geom.facetCylinder((0, 0, 0), R, L, orientation=Quaternion((1, 0, 0), math.pi / 2),
                                              segmentsNumber=24, wallMask=7, fixed=True))
    # a cubic lattice of spheres 0.2 r apart (potential pairs: within the collider's verletDist), at rest
    spheres = O.bodies.append([sphere((x * 2.2 * r, y * 2.2 * r, z * 2.2 * r), r)
                               for x in range(-4, 5) for y in range(-1, 2) for z in range(-4, 5)])
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                           [Law2_ScGeom_FrictPhys_CundallStrack()])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()], verletDist=0.5 * r), loop,
                 RotationEngine(ids=drum, rotationAxis=(0, 1, 0), rotateAroundZero=True, zeroPoint=(0, 0, 0), angularVelocity=2.5),
                 NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 0.5 * PWaveTimeStep()
    first = set(drum)
    O.run(1, True)
    pairs = list(O.interactions.all(False))
    spherePairs = [i for i in pairs if i.id1 not in first and i.id2 not in first]
    facetPairs = [i for i in pairs if i.id1 in first or i.id2 in first]
    assert len(spherePairs) > 500 and O.interactions.countReal() == 0  # 0.2 r apart: none touches
    assert loop.pairsTested == len(pairs)  # a new skin: every pair tested
    rim = tuple(O.bodies[drum[0]].state.pos)
    for _ in range(40):
        O.run(5, True)
        assert O.interactions.countReal() == 0
        assert loop.pairsTested <= len(facetPairs), "pairs of two spheres at rest were tested again"
    assert all(b.state.vel.norm() == 0 for b in (O.bodies[i] for i in spheres))
    # a facet moved by more than the spheres' gaps (0.2 r): a bound D of the motion of every body,
    # facets included, would have had every pair of spheres tested again once D reached 0.1 r
    assert (O.bodies[drum[0]].state.pos - Vector3(*rim)).norm() > 0.2 * r
