"""The cohesive-frictional law with moments (CohFrictMat, CohFrictPhys, ScGeom6D, Ig2_Sphere_Sphere_ScGeom6D,
Ip2_CohFrictMat_CohFrictMat_CohFrictPhys, Law2_ScGeom6D_CohFrictPhys_CohesionMoment).

Checked against beam theory (a cantilever chain), analytic bond strengths, and the reference's numbers on the same scenes:
tests/reference/cohesive.py is a plain Yade script, tests/reference/data/cohesive.json what the reference (Yade 2023.02a)
printed running it. The rules found by running the reference are in doc/cohesive.md."""
import os
import subprocess
import sys

import pytest
from reference_data import flat, scenes_and_data

from yade import (O, CohFrictMat, CohFrictPhys, ScGeom6D, Ig2_Sphere_Sphere_ScGeom6D, Ig2_Facet_Sphere_ScGeom6D, Ip2_CohFrictMat_CohFrictMat_CohFrictPhys,
                  Law2_ScGeom6D_CohFrictPhys_CohesionMoment, MatchMaker, Quaternion, Vector3)
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
scenes, REFERENCE = scenes_and_data('cohesive.py', 'cohesive.json')  # (tests/reference_data.py)
REFERENCE_CHAIN = '/usr/lib/x86_64-linux-gnu/yade-double/py/yade/tests/cohesive-chain.py'


def assert_close(here, ref, rel, abs_=0.0):
    """every number of `here` within rel (relative) or abs_ of the reference's; None (no contact) where it has one"""
    a, b = flat(here), flat(ref)
    assert len(a) == len(b), (len(a), len(b))
    for k, (x, y) in enumerate(zip(a, b)):
        if y is None:
            assert x is None, (k, x, y)
        elif isinstance(y, bool):
            assert x is y, (k, x, y)
        else:
            assert x == pytest.approx(y, rel=rel, abs=abs_), (k, x, y)


# ---------------------------------------------------------------- the classes

def test_attributes_and_defaults_as_in_reference():
    assert CohFrictMat().dict() == dict(isCohesive=True, alphaKr=2.0, alphaKtw=2.0, etaRoll=-1.0, etaTwist=-1.0, normalCohesion=-1.0,
                                        shearCohesion=-1.0, fragile=True, momentRotationLaw=False, frictionAngle=0.5, young=1e9,
                                        poisson=0.25, id=-1, label='', density=1000.0)
    p = CohFrictPhys().dict()
    assert {k: p[k] for k in ('cohesionDisablesFriction', 'cohesionBroken', 'fragile', 'maxRollPl', 'maxTwistPl', 'normalAdhesion',
                              'shearAdhesion', 'unp', 'unpMax', 'momentRotationLaw', 'initCohesion', 'creep_viscosity', 'kr', 'ktw')} == dict(
        cohesionDisablesFriction=False, cohesionBroken=True, fragile=True, maxRollPl=0.0, maxTwistPl=0.0, normalAdhesion=0.0,
        shearAdhesion=0.0, unp=0.0, unpMax=0.0, momentRotationLaw=False, initCohesion=False, creep_viscosity=-1.0, kr=0.0, ktw=0.0)
    g = ScGeom6D()
    assert (g.twist, tuple(g.bending), g.initialOrientation1, g.twistCreep) == (0, (0, 0, 0), Quaternion.Identity, Quaternion.Identity)
    ig2 = Ig2_Sphere_Sphere_ScGeom6D()
    assert (ig2.updateRotations, ig2.creep, ig2.interactionDetectionFactor) == (True, False, 1.0)
    assert Ip2_CohFrictMat_CohFrictMat_CohFrictPhys().dict() == dict(setCohesionNow=False, setCohesionOnNewContacts=False, normalCohesion=None,
                                                                     shearCohesion=None, frictAngle=None, label='')
    assert Law2_ScGeom6D_CohFrictPhys_CohesionMoment().dict() == dict(neverErase=False, always_use_moment_law=False, shear_creep=False,
                                                                      twist_creep=False, traceEnergy=False, useIncrementalForm=False,
                                                                      creep_viscosity=1.0, label='')


# ---------------------------------------------------------------- against the reference's numbers

def test_contact_constants_equal_the_reference():
    """kn, ks (as FrictPhys), kr = ks·αr·R1·R2 and ktw (α: harmonic means), adhesions Cn·min(R)², maxRollPl = min(etaRoll·R), fragile
    if either material is, moments if both say so, cohesion only if both are cohesive, MatchMakers"""
    here = scenes.constants()
    assert sorted(here) == sorted(REFERENCE['constants'])
    for name in here:
        assert_close(here[name], REFERENCE['constants'][name], rel=1e-14, abs_=1e-9)


@pytest.fixture(scope='module')
def motions():
    from yade import setNumThreads
    setNumThreads(1)
    return scenes.motions()


@pytest.mark.parametrize('name', sorted(REFERENCE['motions']))
def test_pair_motions_equal_the_reference(motions, name):
    """a fixed sphere and one moved kinematically (pulled, sheared, twisted, bent, tumbling), every step: the contact's forces,
    moments, twist and bending, flags, and the forces and torques on both bodies; None where the contact ended"""
    assert len(motions[name]) == len(REFERENCE['motions'][name])
    for step, (here, ref) in enumerate(zip(motions[name], REFERENCE['motions'][name])):
        assert (here is None) == (ref is None), step
        if ref is not None:
            assert_close(here, ref, rel=1e-9, abs_=1e-6)


def test_set_cohesion_now_and_init_cohesion_equal_the_reference():
    """setCohesionNow makes the existing contact cohesive at the next step (adhesions, rotations counted from then on, the shear force
    kept), the flag turns false one step later; initCohesion does the same for one contact"""
    assert_close(scenes.cohesionNow(), REFERENCE['cohesionNow'], rel=1e-9, abs_=1e-6)


def test_distant_bonds_equal_the_reference():
    """interactionDetectionFactor 1.1 (and aabbEnlargeFactor): spheres 5 % apart are bonded, in tension from the start"""
    here = scenes.distant()
    assert here[0][0] is not None and here[0][0]['geom'][0] < 0  # (a contact in tension)
    assert_close(here, REFERENCE['distant'], rel=1e-9, abs_=1e-9)


def test_facet_contact_equals_the_reference():
    """Ig2_Facet_Sphere_ScGeom6D: a sphere rolled, twisted and slid on a facet (the incremental moments, capped), then pulled off:
    every step's forces, moments, rotations and the torques on the facet (lever arm from its centre to the contact point)"""
    here = scenes.facetContact()
    ref = REFERENCE['facet']
    assert [r[0] is None for r in here[1:]] == [r[0] is None for r in ref[1:]]
    assert_close(here, ref, rel=1e-9, abs_=1e-6)


def test_periodic_bond_across_the_cell_equals_the_reference():
    """a bonded pair moving in a periodic cell, inside it and through its face: the reference's numbers, and the same forces
    both ways (to the rounding of the positions)"""
    here = scenes.periodic()
    assert_close(here, REFERENCE['periodic'], rel=1e-9, abs_=1e-7)
    assert_close(here[1], here[0], rel=1e-11, abs_=1e-7)


def test_energies_equal_the_reference():
    """with O.trackEnergy, O.energy's shearDissip ((Fs_trial - Fs)·Fs/ks when sliding), bendingDissip and twistDissip (the same with
    the capped moments and kr, ktw); plasticDissipation() sums the shear part with traceEnergy or O.trackEnergy; elasticEnergy() is
    Σ Fn²/2kn + |Fs|²/2ks + |Mb|²/2kr + |Mt|²/2ktw, each part also alone"""
    here = scenes.energy()
    assert sorted(here) == sorted(REFERENCE['energy'])
    for mode in here:
        assert_close(here[mode], REFERENCE['energy'][mode], rel=1e-9, abs_=1e-9)


# ---------------------------------------------------------------- analytic

def cantilever_theory(n, r, force, ks, kr):
    """tip deflection and rotation of a chain of n spheres (centres 2r apart, sphere 0 clamped) under a transverse tip force: at
    contact j the bending moment is F·r·(2(n-1-j) - 1) (lever from the contact point to the last centre), the rotation jumps by
    M/kr, and the shear spring, loaded by F, adds F/ks to the relative displacement of the contact points:
    w[j+1] = w[j] + r·(θ[j] + θ[j+1]) + F/ks."""
    w, th = 0.0, 0.0
    for j in range(n - 1):
        th1 = th + force * r * (2 * (n - 1 - j) - 1) / kr
        w, th = w + r * (th + th1) + force / ks, th1
    return w, th


def test_cantilever_deflection_equals_beam_theory_and_the_reference():
    here = scenes.cantilever()
    ref = REFERENCE['cantilever']
    w, th = cantilever_theory(6, 0.01, 1e-2, here['ks'], here['kr'])
    tip = here['rows'][-1][-1]
    assert tip[1] == pytest.approx(w, rel=1e-6)  # (seen: 8e-8, the damped run's last oscillation)
    assert tip[5] == pytest.approx(th, rel=1e-6)
    assert (here['kr'], here['ks']) == (6.0, 3e4)  # ks·alphaKr·r², ks = E·ν·r
    assert [here[k] for k in ('dt', 'kn', 'ks', 'kr', 'ktw', 'contacts')] == [ref[k] for k in ('dt', 'kn', 'ks', 'kr', 'ktw', 'contacts')]
    # the damped run: NewtonIntegrator's damping, -0.8·sign(v·F)·|F|, turns where a velocity crosses zero, and an ulp there moves
    # the trajectory by up to 3e-9 m for a while (seen); the static state is the reference's to 1.6e-14 m
    assert_close(here['rows'], ref['rows'], rel=0, abs_=1e-8)
    assert_close(here['rows'][-1], ref['rows'][-1], rel=0, abs_=1e-13)


def test_fragile_bond_breaks_when_tension_exceeds_normal_cohesion_times_area():
    """the normal force follows kn·u in tension down to -normalAdhesion = -normalCohesion·min(R1,R2)², and the contact ends at the
    first step beyond it"""
    rows = scenes.pair([(30, (1., 0, 0), (0, 0, 0))])
    alive = [r for r in rows if r is not None]
    adhesion = 1e5 * 1.0 ** 2
    assert alive[0]['phys'][5] == adhesion
    last = alive[-1]['forces'][0]  # normalForce.x of the last step with a contact
    kn = alive[0]['phys'][0]
    assert -adhesion <= last < -adhesion + kn * 1e-3 * 1.0000001  # (the step's displacement is 1e-3)
    assert rows[len(alive)] is None  # ended at the next step
    assert -kn * (alive[-1]['geom'][0] - 1e-3) > adhesion


def test_plastic_bond_yields_at_normal_adhesion():
    """not fragile (unpMax < 0): the tension stays at normalAdhesion while unp = u + normalAdhesion/kn grows; unloading is elastic
    from there"""
    rows = scenes.pair([(26, (1., 0, 0), (0, 0, 0)), (5, (-1., 0, 0), (0, 0, 0))], fragile=False, unpMax=-1)
    kn, adhesion = rows[0]['phys'][0], rows[0]['phys'][5]
    plastic = [r for r in rows if r['phys'][9] < 0]
    assert len(plastic) >= 5
    for r in plastic[:4]:
        u, unp = r['geom'][0], r['phys'][9]
        if r['forces'][0] == pytest.approx(-adhesion):
            assert unp == pytest.approx(u + adhesion / kn, abs=1e-15)
    last = rows[-1]
    assert last['forces'][0] == pytest.approx(kn * (last['geom'][0] - last['phys'][9]), rel=1e-12)
    assert last['forces'][0] > -adhesion


def test_twist_and_bending_are_the_relative_rotation():
    """a rotation of sphere 2 by angle a about the normal gives twist -a (sphere 1's rotation minus sphere 2's) and a moment
    -ktw·twist on sphere 2; about an axis in the contact plane, bending; the contact is new at the first step: both zero"""
    heavy = O.materials.append(CohFrictMat(young=1e7, poisson=0.3, momentRotationLaw=True, normalCohesion=1e6, shearCohesion=1e6, density=1e20))
    O.bodies.append([sphere((0, 0, 0), 1.0, material=heavy), sphere((1.99, 0, 0), 1.0, material=heavy, fixed=True)])
    scenes.engines()
    O.dt = 1e-3
    O.step()
    g, p = O.interactions[0, 1].geom, O.interactions[0, 1].phys
    assert (g.twist, tuple(g.bending)) == (0, (0, 0, 0))
    O.bodies[1].state.ori = Quaternion(Vector3(1, 0, 0), 0.01) * Quaternion(Vector3(0, 0, 1), 0.02)
    O.step()
    assert g.twist == pytest.approx(-0.01, rel=1e-3)
    assert g.bending[2] == pytest.approx(-0.02, rel=1e-3)
    assert p.moment_twist[0] == pytest.approx(p.ktw * g.twist, rel=1e-12)
    assert O.forces.t(1)[0] == pytest.approx(p.ktw * g.twist, rel=1e-12)  # restoring: opposite to the rotation


def bonded_packing():
    """a small cubic packing of bonded spheres, bent and twisted by a turning top layer"""
    from yade import setNumThreads
    O.materials.append(CohFrictMat(young=1e7, poisson=0.3, density=2600, normalCohesion=1e6, shearCohesion=1e6, momentRotationLaw=True,
                                   etaRoll=0.1, etaTwist=0.1))
    for i in range(4):
        for j in range(4):
            for k in range(4):
                O.bodies.append(sphere((0.02 * i, 0.02 * j, 0.02 * k), 0.0101, fixed=(k == 0)))
    scenes.engines(law=Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=True), damping=0.1)
    O.dt = 2e-6
    O.step()
    for b in O.bodies:
        if b.state.pos[2] > 0.05:
            b.state.vel = (0.05, 0, 0)
            b.state.angVel = (0, 0, 20)


def snapshot():
    return [tuple(b.state.pos) + tuple(b.state.angVel) for b in O.bodies]


def test_a_saved_bonded_packing_continues_as_if_not_saved(tmp_path):
    """ScGeom6D (orientations, twist, bending) and CohFrictPhys (bond, moments) are saved and loaded: the run goes on to the same bits"""
    bonded_packing()
    O.run(200, True)
    path = str(tmp_path / 'bonded.yade')
    O.save(path)
    O.run(200, True)
    here = snapshot()
    assert len([i for i in O.interactions if i.isReal]) == 120  # (3·48 neighbours, less the 24 among the fixed bottom layer)
    O.load(path)
    O.run(200, True)
    assert snapshot() == here


def test_two_threads_give_the_one_thread_run():
    """the law runs in the parallel interaction loop (forces through the ForceContainer): the same motion with 2 threads"""
    from yade import setNumThreads
    bonded_packing()
    O.run(300, True)
    one = snapshot()
    O.reset()
    setNumThreads(2)
    bonded_packing()
    O.run(300, True)
    for a, b in zip(snapshot(), one):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-15)


# ---------------------------------------------------------------- errors

def test_bad_input_gives_clear_errors():
    O.materials.append(CohFrictMat(momentRotationLaw=True))
    O.bodies.append([sphere((0, 0, 0), 1.0), sphere((1.99, 0, 0), 1.0)])
    scenes.engines(law=Law2_ScGeom6D_CohFrictPhys_CohesionMoment(twist_creep=True))
    O.dt = 1e-5
    with pytest.raises(RuntimeError, match='twist_creep'):
        O.step()
    O.engines[2].lawDispatcher.functors[0].twist_creep = False
    O.engines[2].lawDispatcher.functors[0].shear_creep = True
    O.engines[2].lawDispatcher.functors[0].creep_viscosity = 0
    with pytest.raises(Exception, match='creep_viscosity'):
        O.step()
    O.reset()
    O.materials.append(CohFrictMat())
    O.bodies.append([sphere((0, 0, 0), 1.0), sphere((1.99, 0, 0), 1.0)])
    scenes.engines(ip2=Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionOnNewContacts=True, normalCohesion=MatchMaker(algo='avg')))
    O.dt = 1e-5
    with pytest.raises(Exception, match='MatchMaker|algo'):
        O.step()


# ---------------------------------------------------------------- the reference's own test

@pytest.mark.skipif(not os.path.exists(REFERENCE_CHAIN), reason='the reference Yade is not installed')
def test_the_references_own_cohesive_chain_test():
    """The reference's regression module yade.tests.cohesive-chain, run here as it is."""
    script = ('import importlib.util, unittest\n'
              'spec = importlib.util.spec_from_file_location("cohesivechain", %r)\n'
              'm = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n'
              'r = unittest.TextTestRunner(verbosity=2).run(unittest.defaultTestLoader.loadTestsFromModule(m))\n'
              'print("RESULT", r.testsRun, len(r.failures), len(r.errors))\n') % REFERENCE_CHAIN
    out = subprocess.run([sys.executable, '-c', script], env=dict(os.environ), capture_output=True, text=True, timeout=300)
    # it builds its chain of ChainedCylinder bodies (Bo1_ChainedCylinder_Aabb, Ig2_ChainedCylinder_ChainedCylinder_ScGeom6D,
    # yade.gridpfacet.chainedCylinder), not in this engine yet: until they are, it stops at exactly that name and nothing else
    if 'RESULT 1 0 0' not in out.stdout:
        assert "name 'Bo1_ChainedCylinder_Aabb' is not defined" in out.stdout + out.stderr, out.stdout + out.stderr


def test_cantilever_example(tmp_path):
    """examples/cohesive-cantilever.py with the launcher prints the tip's deflection and rotation next to the beam of the contact
    springs (the reference prints the same lines)"""
    import pathlib
    import re
    repo = pathlib.Path(__file__).resolve().parent.parent
    env = dict(os.environ)
    env.setdefault('YADE_BUILD_DIR', str(repo / 'build'))
    r = subprocess.run(['/usr/bin/python3', str(repo / 'yade'), '-n', '-x', str(repo / 'examples' / 'cohesive-cantilever.py')],
                       capture_output=True, text=True, timeout=300, env=env, cwd=str(tmp_path))
    assert r.returncode == 0, r.stderr
    for what in ('deflection', 'rotation'):
        found = re.search(r'tip %s\s+([-\d.e]+) \S+ \(beam of the contact springs: ([-\d.e]+)' % what, r.stdout)
        assert found, r.stdout
        assert float(found.group(1)) == pytest.approx(float(found.group(2)), rel=1e-6)
