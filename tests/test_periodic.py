"""Periodic boundary conditions (3.6): the cell, periodic contacts, the homogeneous field, the stress
utilities and save/load. Reference numbers: tests/reference/periodic.py run by the reference Yade
(tests/reference/data/periodic.json); the rest analytic."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import yade
from yade import (O, Bo1_Sphere_Aabb, ForceResetter, Ig2_Sphere_Sphere_ScGeom, InsertionSortCollider, InteractionLoop,
                  Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, Matrix3, NewtonIntegrator, Vector3,
                  utils)
from yade.utils import sphere

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, 'reference')


@pytest.fixture(autouse=True)
def fresh():
    O.reset()
    yield
    O.reset()


def engines(damping=0.2):
    return [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
            NewtonIntegrator(damping=damping)]


def M(m):
    return np.asarray(m, dtype=float)


# ---------------------------------------------------------------- agreement with the reference

@pytest.fixture(scope='module')
def runs():
    """The reference script run here, next to what the reference printed."""
    sys.path.insert(0, REFERENCE)
    try:
        import periodic as script
    finally:
        sys.path.remove(REFERENCE)
    here = {'homogeneousField': script.homogeneousField(), 'packing': script.packing(), 'cell': script.cell()}
    with open(os.path.join(REFERENCE, 'data', 'periodic.json')) as f:
        return here, json.load(f)


def relDev(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    assert a.shape == b.shape
    return (np.abs(a - b) / np.maximum(1.0, np.abs(b))).max() if a.size else 0.0


def test_homogeneous_field_is_the_references_to_the_last_bit(runs):
    """One free sphere in a deforming cell, every homoDeform mode, with gravity and damping: position,
    velocity, spin, hSize and trsf after each of 6 steps (velGrad changed at the 4th) are the same
    numbers as the reference's (the same arithmetic in the same order)."""
    here, ref = runs
    assert sorted(here['homogeneousField']) == sorted(ref['homogeneousField']) and len(ref['homogeneousField']) == 8
    for key, rows in ref['homogeneousField'].items():
        assert relDev(here['homogeneousField'][key], rows) <= 1e-15, key


def test_sheared_packing_follows_the_reference(runs):
    """48 spheres in a skewed, sheared cell: contacts across faces, edges and corners (their cellDist)
    are the reference's, and positions, velocities and spins agree to rounding after 20 steps."""
    here, ref = runs
    for a, b in zip(here['packing']['steps'], ref['packing']['steps']):
        assert a['iter'] == b['iter']
        assert a['contacts'] == b['contacts']  # (pairs and cellDist, exactly)
        assert relDev(a['state'], b['state']) < 1e-11
        assert relDev(a['hSize'], b['hSize']) < 1e-15
    crossing = [c for c in ref['packing']['steps'][-1]['contacts'] if c[2:] != [0, 0, 0]]
    assert len(crossing) >= 10 and any(sum(map(abs, c[2:])) >= 2 for c in crossing)  # (across edges too)


@pytest.mark.parametrize('name', ['getStress', 'stressTensorOfPeriodicCell', 'normalShear', 'normalShearSplit', 'fabric', 'fabricSplit',
                                  'bodyStress', 'porosity', 'voxelPorosity', 'dynamicStress'])
def test_periodic_utilities_equal_the_references(runs, name):
    here, ref = runs
    assert relDev(here['packing'][name], ref['packing'][name]) < 1e-9


def test_cell_accessors_equal_the_references(runs):
    here, ref = runs
    assert sorted(here['cell']) == sorted(ref['cell'])
    for key in ref['cell']:
        assert relDev(here['cell'][key], ref['cell'][key]) < 1e-13, key


# ---------------------------------------------------------------- the cell

def test_cell_is_none_until_periodic_and_refuses_bad_cells():
    assert O.cell is None and not O.periodic
    O.periodic = True
    c = O.cell
    assert c.hSize == Matrix3.Identity and c.homoDeform == 2 and c.volume == 1
    c.setBox(2, 3, 4)
    before = c.hSize
    for bad, what, error in [(Matrix3(1, 0, 0, 0, 0, 0, 0, 0, 1), 'degenerate', RuntimeError), (Matrix3(-1, 0, 0, 0, 1, 0, 0, 0, 1), 'inverted', RuntimeError),
                             (Matrix3(1, 0, 0, 0, float('nan'), 0, 0, 0, 1), 'finite', ValueError)]:
        with pytest.raises(error, match=what):  # (RuntimeError for a degenerate cell, as the reference)
            c.hSize = bad
        assert c.hSize == before  # (left as it was)
    with pytest.raises(ValueError, match='positive'):
        c.setBox(1, 0, 1)
    with pytest.raises(ValueError, match='finite'):
        c.velGrad = Matrix3(float('inf'), 0, 0, 0, 0, 0, 0, 0, 0)
    assert c.hSize == before and not c.velGradChanged
    O.periodic = False
    assert O.cell is None


def test_velgrad_takes_effect_at_the_next_step_and_deforms_the_cell():
    """(3.6.1): F ← (I + ∇v·Δt)·F and H likewise, each step, from the step after the one where the
    integrator takes the assigned velGrad."""
    O.periodic = True
    O.cell.setBox(2, 3, 4)
    O.engines = [ForceResetter(), NewtonIntegrator()]
    O.dt = 0.01
    L = Matrix3(0.1, 0.2, 0, 0, -0.3, 0, 0.05, 0, 0.2)
    O.cell.velGrad = L
    assert O.cell.velGrad == Matrix3.Zero and O.cell.nextVelGrad == L and O.cell.velGradChanged
    O.step()
    assert O.cell.velGrad == L and O.cell.hSize == Matrix3(2, 0, 0, 0, 3, 0, 0, 0, 4)
    for n in range(1, 5):
        O.step()
        F = np.linalg.matrix_power(np.eye(3) + 0.01 * M(L), n)
        assert np.allclose(M(O.cell.trsf), F, rtol=0, atol=1e-15)
        assert np.allclose(M(O.cell.hSize), F.dot(np.diag([2, 3, 4])), rtol=0, atol=1e-14)
        assert O.cell.prevVelGrad == L


def test_homothetic_compression_moves_bodies_with_the_cell():
    """A free body in a cell compressed homothetically (homoDeform 2): from the first step on, its
    velocity is velGrad·x (x before the step) and its coordinates in the cell stay constant."""
    O.periodic = True
    O.cell.setBox(1, 1, 1)
    O.bodies.append([sphere((0.3, 0.6, 0.8), 0.05), sphere((0.9, 0.1, 0.5), 0.05)])
    O.engines = [ForceResetter(), NewtonIntegrator(damping=0)]
    O.dt = 1e-3
    L = M(Matrix3(-0.5, 0, 0, 0, -0.2, 0, 0, 0, 0.3))
    O.cell.velGrad = Matrix3(*L.reshape(9))
    O.step()
    s0 = [np.linalg.solve(M(O.cell.hSize), M(b.state.pos)) for b in O.bodies]
    for _ in range(200):
        x = [M(b.state.pos) for b in O.bodies]
        O.step()
        for b, xb, s in zip(O.bodies, x, s0):
            assert np.allclose(M(b.state.vel), L.dot(xb), rtol=1e-12, atol=1e-15)
    for b, s in zip(O.bodies, s0):
        assert np.allclose(np.linalg.solve(M(O.cell.hSize), M(b.state.pos)), s, rtol=0, atol=1e-12)
    assert abs(O.cell.hSize[0, 0] - (1 - 0.5e-3) ** 200) < 1e-12


def test_wrap_in_a_sheared_cell():
    O.periodic = True
    O.cell.hSize = Matrix3(1, 0, 0.5, 0, 1, 0, 0, 0, 1)  # (the third edge leans over x)
    H = M(O.cell.hSize)
    for p in [(5.1, -1.2, 9.3), (-0.2, 0.5, 0.1), (0.7, 0.3, 0.2)]:
        w = M(O.cell.wrap(p))
        s = np.linalg.solve(H, w)
        assert (s >= 0).all() and (s < 1).all()  # inside the cell
        assert np.allclose(np.round(np.linalg.solve(H, M(p) - w)), np.linalg.solve(H, M(p) - w), atol=1e-12)  # by whole cells
    assert np.allclose(M(O.cell.wrapPt((2.3, -0.4, 2.3))), [0.3, 0.6, 2.3 - 2 * math.sqrt(1.25)], atol=1e-12)  # (by the edge lengths)


# ---------------------------------------------------------------- contacts through the boundary

def test_contact_through_a_sheared_boundary_by_hand():
    """Two spheres whose nearest images touch across the leaning face of a sheared cell: the contact
    has the cellDist that brings body 2's image next to body 1, and its overlap is r1 + r2 less the
    distance to that image."""
    O.periodic = True
    O.cell.hSize = Matrix3(1, 0, 0.5, 0, 1, 0, 0, 0, 1)
    O.bodies.append([sphere((0.5, 0.5, 0.05), 0.1), sphere((1.02, 0.48, 0.93), 0.1)])
    O.engines = engines()
    O.dt = 1e-8
    O.step()
    assert O.interactions.countReal() == 1
    i = [i for i in O.interactions if i.isReal][0]
    x1, x2 = M(O.bodies[i.id1].state.pos), M(O.bodies[i.id2].state.pos)
    image = x2 + M(O.cell.hSize).dot(np.array(tuple(i.cellDist), dtype=float))
    assert tuple(i.cellDist) in ((0, 0, -1), (0, 0, 1)) and i.id1 in (0, 1)
    assert abs(i.geom.penetrationDepth - (0.2 - np.linalg.norm(image - x1))) < 1e-10  # (the step moved them by ~1e-12)
    assert np.allclose(M(i.geom.normal), (image - x1) / np.linalg.norm(image - x1), atol=1e-10)


def test_stress_of_a_two_sphere_cell_by_hand():
    """Two spheres overlapping by u across the x face of a cubic cell: σ = -1/V f ⊗ l (l = 0.25 the
    branch to the image, f = kn·u), normal part of Thornton's decomposition kn·u·(r1 + r2)/V."""
    O.periodic = True
    O.cell.setBox(1, 1.2, 1.3)
    O.bodies.append([sphere((0.1, 0.6, 0.65), 0.15), sphere((0.85, 0.6, 0.65), 0.15)])
    O.engines = engines(damping=0)
    O.dt = 1e-9
    O.step()
    i = [i for i in O.interactions if i.isReal][0]
    assert tuple(i.cellDist) == ((-1, 0, 0) if i.id1 == 0 else (1, 0, 0))
    u = i.geom.penetrationDepth
    assert abs(u - 0.05) < 1e-9
    V = 1 * 1.2 * 1.3
    fn = i.phys.kn * u
    s = M(utils.getStress())
    expected = np.zeros((3, 3))
    expected[0, 0] = -fn * 0.25 / V
    assert np.allclose(s, expected, rtol=1e-6, atol=1e-9 * abs(expected[0, 0]))
    normal, shear = utils.normalShearStressTensors()
    assert abs(normal[0, 0] - fn * 0.3 / V) < 1e-6 * fn and abs(M(shear)).max() < 1e-9 * fn
    assert abs(utils.porosity() - (1 - 2 * 4 / 3 * math.pi * 0.15 ** 3 / V)) < 1e-14


def test_a_body_bigger_than_half_the_cell_is_refused_by_name():
    O.periodic = True
    O.cell.setBox(1, 1, 1)
    O.bodies.append([sphere((0.5, 0.5, 0.5), 0.24), sphere((0.78, 0.5, 0.5), 0.05)])
    O.engines = engines()
    O.dt = 1e-6
    with pytest.raises(RuntimeError, match=r'body #0 is too big for the periodic cell.*allowBiggerThanPeriod'):
        O.step()
    O.engines[1].allowBiggerThanPeriod = True
    O.step()  # (accepted: it meets the nearest image of each body)
    assert O.interactions.countReal() == 1


def test_flip_keeps_every_contact_where_it_is():
    """A cell sheared past one cell length flipped back (utils.flipCell): the edges are less skewed,
    the contacts' cellDist follow, and the run goes on with the same forces."""
    def build():
        O.reset()
        O.periodic = True
        O.cell.hSize = Matrix3(1, 0, 1.3, 0, 1, 0, 0, 0, 1)
        for k, p in enumerate([(0.1, 0.2, 0.05), (0.3, 0.25, 0.95), (0.5, 0.5, 0.5), (0.62, 0.55, 0.58), (0.95, 0.9, 0.1), (0.1, 0.95, 0.1)]):
            O.bodies.append(sphere(p, 0.09))
        O.engines = engines()
        O.dt = 1e-5
        O.bodies[2].state.vel = (1, 0, 0)
        O.run(20, True)

    build()
    O.run(30, True)
    straight = [M(b.state.pos) for b in O.bodies]
    build()
    contactsBefore = {(i.id1, i.id2): M(O.cell.hSize).dot(tuple(i.cellDist)) for i in O.interactions if i.isReal}
    assert any(np.any(v != 0) for v in contactsBefore.values())
    flip = utils.flipCell()
    assert flip == Matrix3(0, 0, -1, 0, 0, 0, 0, 0, 0)
    assert np.allclose(M(O.cell.hSize), [[1, 0, 0.3], [0, 1, 0], [0, 0, 1]], atol=1e-15)
    for i in O.interactions:
        if i.isReal:  # (the same image: the shift vector is unchanged)
            assert np.allclose(M(O.cell.hSize).dot(tuple(i.cellDist)), contactsBefore[(i.id1, i.id2)], atol=1e-14)
    O.run(30, True)
    assert max(np.abs(M(b.state.pos) - p).max() for b, p in zip(O.bodies, straight)) < 1e-12
    assert utils.flipCell() == Matrix3.Zero  # (nothing left to flip)
    with pytest.raises(ValueError, match='determinant 1'):
        utils.flipCell(Matrix3(1, 0, 0, 0, 0, 0, 0, 0, 0))


# ---------------------------------------------------------------- save, load, threads

def packingScene():
    O.periodic = True
    O.cell.hSize = Matrix3(1.2, 0.1, 0, 0, 1.0, 0, 0, 0.05, 0.9)
    rng = np.random.RandomState(3)
    for i in range(4):
        for j in range(4):
            for k in range(3):
                O.bodies.append(sphere((0.3 * i + 0.02 * rng.rand(), 0.25 * j + 0.02 * rng.rand(), 0.3 * k + 0.02 * rng.rand()), 0.14))
    O.engines = engines(damping=0.3)
    O.dt = 1e-5
    O.cell.velGrad = Matrix3(-0.1, 0, 0.2, 0, -0.1, 0, 0, 0, -0.1)


def snapshot():
    return (np.array([list(b.state.pos) + list(b.state.vel) + list(b.state.angVel) for b in O.bodies]), M(O.cell.hSize), M(O.cell.trsf),
            sorted((i.id1, i.id2, tuple(i.cellDist), tuple(i.phys.shearForce)) for i in O.interactions if i.isReal))


@pytest.mark.parametrize('suffix', ['.xml', '.yade'])
def test_saved_periodic_scene_resumes_bit_for_bit(tmp_path, suffix):
    packingScene()
    O.run(30, True)
    path = str(tmp_path / ('peri' + suffix))
    O.save(path)
    O.run(40, True)
    straight = snapshot()
    O.load(path)
    assert O.periodic and O.iter == 30
    O.run(40, True)
    resumed = snapshot()
    assert np.array_equal(straight[0], resumed[0]) and np.array_equal(straight[1], resumed[1])
    assert np.array_equal(straight[2], resumed[2]) and straight[3] == resumed[3]
    assert any(c[2] != (0, 0, 0) for c in resumed[3])


def test_periodic_results_do_not_depend_on_the_thread_count():
    script = ('import sys; sys.path.insert(0, %r)\n'
              'from test_periodic import packingScene, snapshot\n'
              'from yade import O\n'
              'packingScene(); O.run(200, True)\n'
              'import hashlib; s = snapshot(); print(hashlib.md5(s[0].tobytes()).hexdigest(), len(s[3]))\n') % HERE
    outs = []
    for threads in ('1', '2'):
        env = dict(os.environ, OMP_NUM_THREADS=threads)
        outs.append(subprocess.run([sys.executable, '-c', script], env=env, check=True, capture_output=True, text=True, timeout=300).stdout)
    assert outs[0] == outs[1] and outs[0].split()[-1] != '0'


def test_incident_velocity_and_kinetic_energy_see_the_homogeneous_field():
    """Two spheres ten cells apart along z in a cell compressed along z (velGrad zz = -1), O.dt = 0:
    the integrator gives each the field's velocity velGrad·x; an interaction made by createInteraction
    takes body 2's nearest image (cellDist), whose velocity includes the field's difference between the
    images, so the incident velocity is what body 2 had of its own (0, 0, 5); kinetic energy counts only
    that fluctuation, and the stress utilities see the image."""
    O.periodic = True
    O.cell.setBox(2.5, 2.5, 3)
    O.bodies.append(sphere((1, 1, 1), .5))
    O.bodies.append(sphere((1, 1 + 1, 1 + 10 * 3), .5))  # (touching its neighbour's image)
    O.bodies[1].state.vel = (0, 0, 5)
    O.engines = [NewtonIntegrator(warnNoForceReset=False)]
    O.cell.velGrad = Matrix3(0, 0, 0, 0, 0, 0, 0, 0, -1)
    O.dt = 0
    O.run(2, True)
    assert O.bodies[0].state.vel == Vector3(0, 0, -1) and O.bodies[1].state.vel == Vector3(0, 0, 5 - 31)
    assert abs(utils.kineticEnergy() - .5 * O.bodies[1].state.mass * 25) < 1e-9
    O.engines = [InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [])]  # (no law: allowed)
    i = utils.createInteraction(0, 1)
    assert tuple(i.cellDist) == (0, 0, -10)
    for ratchet in (True, False):
        assert i.geom.incidentVel(i, avoidGranularRatcheting=ratchet) == Vector3(0, 0, 5)
    assert abs(i.geom.penetrationDepth) < 1e-12
    assert i.geom.relAngVel(i) == Vector3.Zero


REFERENCE_PBC = '/usr/lib/x86_64-linux-gnu/yade-double/py/yade/tests/pbc.py'


@pytest.mark.skipif(not os.path.exists(REFERENCE_PBC), reason='the reference Yade is not installed')
def test_the_references_own_pbc_tests():
    """The reference's regression module yade.tests.pbc, run here as it is: all 8 pass (testL3GeomIncidentVelocity
    since the L3Geom family, pkg/dem/localframe)."""
    script = ('import importlib.util, unittest\n'
              'spec = importlib.util.spec_from_file_location("pbc", %r)\n'
              'm = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n'
              'r = unittest.TextTestRunner(verbosity=2).run(unittest.defaultTestLoader.loadTestsFromModule(m))\n'
              'print("RESULT", r.testsRun, len(r.failures), [t.id().split(".")[-1] for t, _ in r.errors])\n') % REFERENCE_PBC
    out = subprocess.run([sys.executable, '-c', script], env=dict(os.environ), capture_output=True, text=True, timeout=300).stdout
    assert "RESULT 8 0 []" in out, out


def test_fast_passes_give_the_bits_of_the_one_contact_path():
    """The fused passes (two contacts at a time, images of pairs through the cell's faces included) and
    the kept batches give the same bits as the one-contact path (InteractionLoop.fusedPasses=False)."""
    runs = []
    for fused in (True, False):
        O.reset()
        packingScene()
        O.engines[2].fusedPasses = fused
        O.run(300, True)
        runs.append(snapshot())
    assert np.array_equal(runs[0][0], runs[1][0]) and runs[0][3] == runs[1][3]
    assert sum(1 for c in runs[0][3] if c[2] != (0, 0, 0)) >= 10
