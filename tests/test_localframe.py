"""The local-frame geometries and their laws (L3Geom, L6Geom, Ig2_Sphere_Sphere_L3Geom, Ig2_Wall_Sphere_L3Geom,
Ig2_Facet_Sphere_L3Geom, Ig2_Sphere_Sphere_L6Geom, Law2_L3Geom_FrictPhys_ElPerfPl, Law2_L6Geom_FrictPhys_Linear).

The scenes are tests/reference/localframe.py, a plain Yade script; tests/reference/data/localframe.json is what the reference
(Yade 2023.02a) printed running it. The rules the reference follows, found by running it, are in doc/localframe.md."""
import importlib.util
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from yade import (O, L3Geom, L6Geom, Ig2_Sphere_Sphere_L3Geom, Ig2_Wall_Sphere_L3Geom, Ig2_Facet_Sphere_L3Geom, Ig2_Sphere_Sphere_L6Geom,
                  Law2_L3Geom_FrictPhys_ElPerfPl, Law2_L6Geom_FrictPhys_Linear)

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('localframe_scenes', os.path.join(HERE, 'reference', 'localframe.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'localframe.json')) as _f:
    REFERENCE = json.load(_f)


def fields(row):
    """a contact's record (tests/reference/localframe.py: record) by name"""
    if row is None:
        return None
    r = np.array(row, float)
    out = dict(u=r[0:3], u0=r[3:6], trsf=r[6:15], F=r[15:18], normal=r[18:21], contactPoint=r[21:24], refR=r[24:26])
    k = 26
    if len(r) == 41:  # an L6Geom
        out.update(phi=r[26:29], phi0=r[29:32])
        k = 32
    out.update(constants=r[k:k + 3], forces=r[k + 3:k + 9])  # kn, ks, tan φ; normalForce, shearForce
    return out


def assert_record(here, ref, rel):
    """each field within rel of the reference, relative to the field's largest number (the forces on the bodies too)"""
    assert (here['i'] is None) == (ref['i'] is None)
    pairs = [('bodies', np.array(here['f']), np.array(ref['f']))]
    if ref['i'] is not None:
        a, b = fields(here['i']), fields(ref['i'])
        assert sorted(a) == sorted(b)
        pairs += [(k, a[k], b[k]) for k in b]
    for name, x, y in pairs:
        scale = max(np.abs(y).max(), 1e-300)
        assert np.abs(x - y).max() <= rel * scale, (name, x, y)


# ---------------------------------------------------------------- the classes

def test_attributes_and_defaults_as_in_reference():
    g = L3Geom().dict()
    assert set(g) == {'u', 'u0', 'trsf', 'F', 'normal', 'contactPoint', 'refR1', 'refR2'}
    assert tuple(g['u']) == tuple(g['u0']) == tuple(g['F']) == (0, 0, 0)
    assert [g['trsf'][i, j] for i in range(3) for j in range(3)] == [1, 0, 0, 0, 1, 0, 0, 0, 1]
    assert set(L6Geom().dict()) == set(g) | {'phi', 'phi0'}
    for ig2 in (Ig2_Sphere_Sphere_L3Geom, Ig2_Wall_Sphere_L3Geom, Ig2_Facet_Sphere_L3Geom, Ig2_Sphere_Sphere_L6Geom):
        assert ig2().dict() == dict(noRatch=True, distFactor=1.0, trsfRenorm=100, approxMask=0, label='')
        assert isinstance(ig2(), Ig2_Sphere_Sphere_L3Geom)
    assert Law2_L3Geom_FrictPhys_ElPerfPl().dict() == dict(noBreak=False, noSlip=False, label='')
    assert Law2_L6Geom_FrictPhys_Linear().dict() == dict(charLen=1.0, noBreak=False, noSlip=False, label='')
    assert isinstance(Law2_L6Geom_FrictPhys_Linear(), Law2_L3Geom_FrictPhys_ElPerfPl)
    assert isinstance(L6Geom(), L3Geom)


def test_bad_input_is_an_error():
    with pytest.raises(ValueError, match='approxMask'):
        Ig2_Sphere_Sphere_L3Geom(approxMask=-1)
    with pytest.raises(TypeError):
        Law2_L6Geom_FrictPhys_Linear(charLen='long')


# ---------------------------------------------------------------- against the reference

# every scene step by step: the contact's u, u0, trsf, F, normal, contact point, (phi, phi0), constants and forces, and the
# forces and torques on both bodies
SCENES = [k for k in REFERENCE if k not in ('pile', 'energy')]


@pytest.mark.parametrize('name', SCENES)
def test_scene_equals_the_reference(name):
    here = scenes.scenes()[name]()
    ref = REFERENCE[name]
    assert len(here) == len(ref)
    for h, r in zip(here, ref):
        assert_record(h, r, 1e-12)


def test_pile_falling_on_a_wall_equals_the_reference():
    """six free spheres falling on a wall (L3 law): positions, velocities, spins after 300, 1000 and 3000 steps"""
    here, ref = np.array(scenes.pile()), np.array(REFERENCE['pile'])
    for h, r in zip(here, ref):
        assert np.abs(h - r).max() <= 1e-12 * np.abs(r).max()


def test_energy_terms_equal_the_reference():
    """O.trackEnergy: elastPotential, Σ (F_x²/kn + F_s²/ks)/2 over the contacts, and plastDissip, the work of the slips"""
    assert scenes.energy() == pytest.approx(REFERENCE['energy'], rel=1e-14)


# ---------------------------------------------------------------- analytic

def contact():
    return O.interactions[0, 1]


def test_elastic_normal_force_is_kn_times_the_overlap():
    r1, r2, gap = 0.01, 0.015, -1e-4
    scenes.two_spheres(Ig2_Sphere_Sphere_L3Geom(), Law2_L3Geom_FrictPhys_ElPerfPl(), vel2=(-0.1, -0.03, 0.02), gap=gap, steps=10)
    i = contact()
    young = 1e7
    kn = 2 * young * r1 * young * r2 / (young * r1 + young * r2)
    assert i.phys.kn == pytest.approx(kn, rel=1e-15)
    d = O.bodies[1].state.pos - O.bodies[0].state.pos
    overlap = d.norm() - (r1 + r2)  # u_x (negative in compression), from the positions the step started with
    overlap -= (O.bodies[1].state.vel - O.bodies[0].state.vel).dot(d.normalized()) * O.dt
    assert i.geom.u[0] == pytest.approx(overlap, rel=1e-9)
    assert i.geom.F[0] == pytest.approx(kn * i.geom.u[0], rel=1e-15)
    assert i.phys.normalForce.norm() == pytest.approx(kn * abs(i.geom.u[0]), rel=1e-14)
    # the force pushes the spheres apart: body 1 gets -F·n, body 2 +F·n; no torque from a central force
    n = i.geom.normal
    assert O.forces.f(1).dot(n) == pytest.approx(kn * abs(i.geom.u[0]), rel=1e-14)
    assert O.forces.f(0) == -O.forces.f(1)
    assert O.forces.t(0).norm() < 1e-12 * O.forces.f(0).norm()


def test_elastic_shear_force_is_ks_times_the_shear_displacement():
    """a sphere moved sideways (noSlip): the shear force is ks·|u_s|, u_s = the sideways travel, in the local frame"""
    steps, v = 20, 0.2
    scenes.two_spheres(Ig2_Sphere_Sphere_L3Geom(), Law2_L3Geom_FrictPhys_ElPerfPl(noSlip=True), vel2=(0, v, 0), direction=(1, 0, 0),
                       steps=steps)
    i = contact()
    travel = v * O.dt * (steps - 1)  # (the first step makes the contact)
    us = math.hypot(i.geom.u[1], i.geom.u[2])
    assert us == pytest.approx(travel, rel=2e-3)  # (the normal turns by travel/(r1+r2))
    assert math.hypot(i.geom.F[1], i.geom.F[2]) == pytest.approx(i.phys.ks * us, rel=1e-15)
    # in global coordinates: trsf's rows are orthonormal again only every trsfRenorm steps (1e-7 off in between)
    assert i.phys.shearForce.norm() == pytest.approx(i.phys.ks * us, rel=1e-6)
    assert i.phys.shearForce.dot(i.geom.normal) == pytest.approx(0, abs=1e-12 * i.phys.shearForce.norm())


def test_sliding_is_perfectly_plastic_at_tan_phi_times_fn():
    scenes.two_spheres(Ig2_Sphere_Sphere_L3Geom(), Law2_L3Geom_FrictPhys_ElPerfPl(), vel2=(0, 0.5, 0.3), frict=0.2, steps=60)
    i = contact()
    fn, fs = -i.geom.F[0], math.hypot(i.geom.F[1], i.geom.F[2])  # (local: exact)
    assert fs == pytest.approx(math.tan(0.2) * fn, rel=1e-15)
    assert i.phys.shearForce.norm() == pytest.approx(math.tan(0.2) * i.phys.normalForce.norm(), rel=1e-5)  # (global: trsfRenorm)
    # the slip went into u0: the elastic shear displacement is what the force says
    assert math.hypot(i.geom.u[1] - i.geom.u0[1], i.geom.u[2] - i.geom.u0[2]) == pytest.approx(fs / i.phys.ks, rel=1e-12)
    assert math.hypot(i.geom.u0[1], i.geom.u0[2]) > 0


def test_separated_spheres_lose_their_contact_unless_noBreak():
    scenes.two_spheres(Ig2_Sphere_Sphere_L3Geom(), Law2_L3Geom_FrictPhys_ElPerfPl(), vel2=(0.3, 0.1, 0.), gap=-2e-5, steps=20)
    assert not O.interactions.has(0, 1) or not contact().isReal
    scenes.two_spheres(Ig2_Sphere_Sphere_L3Geom(), Law2_L3Geom_FrictPhys_ElPerfPl(noBreak=True), vel2=(0.3, 0.1, 0.), gap=-2e-5, steps=20)
    i = contact()
    assert i.geom.u[0] > 0 and i.geom.F[0] == pytest.approx(i.phys.kn * i.geom.u[0], rel=1e-15)  # it pulls
    assert i.geom.F[1] == i.geom.F[2] == 0  # no friction in tension


def test_L6_twist_moment_is_kn_charLen_phi():
    """two spheres spun in opposite senses about their normal: phi_x = (ω2-ω1)·n·t, torque kn·charLen·phi_x about n"""
    steps, w, charLen = 30, 5.0, 0.3
    n = np.array((1., .3, -.2)) / np.linalg.norm((1., .3, -.2))
    scenes.two_spheres(Ig2_Sphere_Sphere_L6Geom(), Law2_L6Geom_FrictPhys_Linear(charLen=charLen), ang1=tuple(-w * n), ang2=tuple(w * n),
                       steps=steps)
    i = contact()
    phi = 2 * w * O.dt * (steps - 1)
    assert i.geom.phi[0] == pytest.approx(phi, rel=1e-12)
    assert abs(i.geom.phi[1]) < 1e-12 * phi and abs(i.geom.phi[2]) < 1e-12 * phi
    torque = np.array(O.forces.t(0))
    assert torque == pytest.approx(i.phys.kn * charLen * phi * n, rel=1e-12)
    assert np.array(O.forces.t(1)) == pytest.approx(-torque, rel=1e-12)


def test_L6_bending_moment_is_ks_charLen_phi():
    """two spheres spun about the same axis normal to the contact: phi_bending = |ω2-ω1|·t, moment ks·charLen·phi"""
    steps, w, charLen = 30, 3.0, 2.0
    scenes.two_spheres(Ig2_Sphere_Sphere_L6Geom(), Law2_L6Geom_FrictPhys_Linear(charLen=charLen, noSlip=True), ang1=(0, 0, -w), ang2=(0, 0, w),
                       direction=(1, 0, 0), steps=steps)
    i = contact()
    phi = 2 * w * O.dt * (steps - 1)
    assert math.hypot(i.geom.phi[1], i.geom.phi[2]) == pytest.approx(phi, rel=1e-12)
    assert abs(i.geom.phi[0]) < 1e-12 * phi
    # the moment about z: ks·charLen·phi, plus the shear force's arm (the spheres' surfaces slide past each other)
    arm = np.cross(np.array(i.geom.contactPoint) - np.array(O.bodies[0].state.pos), np.array(O.forces.f(0)))
    bending = np.array(O.forces.t(0)) - arm
    assert bending == pytest.approx([0, 0, i.phys.ks * charLen * phi], rel=1e-9, abs=1e-12 * i.phys.ks * charLen * phi)


def test_contact_forces_are_equal_and_opposite_in_a_pile():
    """the forces of all contacts, the wall's included, sum to zero (Newton's third law); not their moments: as in the reference,
    the torque on a wall is taken at the branch (u/2)·n from its position, not at the contact point"""
    scenes.pile(1000)
    while len([i for i in O.interactions if i.isReal]) < 1 and O.iter < 20000:
        O.step()
    assert len([i for i in O.interactions if i.isReal]) >= 1
    zero = O.forces.f(0) * 0
    f = sum((O.forces.f(b.id) for b in O.bodies), zero)
    scale = max(O.forces.f(b.id).norm() for b in O.bodies)
    assert scale > 0 and f.norm() < 1e-12 * scale


# (the reference's own core module, which uses these classes among others, runs in tests/test_reference_core.py)


def test_spheres_with_the_same_centre_give_finite_numbers():
    """no normal: a new contact takes x, an existing one keeps its last normal (never NaN)"""
    from yade import ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys, NewtonIntegrator
    from yade.utils import sphere
    O.bodies.append([sphere((0, 0, 0), 1), sphere((0, 0, 0), 1)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_L3Geom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_L3Geom_FrictPhys_ElPerfPl()]),
                 NewtonIntegrator()]
    O.dt = 1e-5
    O.step()
    g = O.interactions[0, 1].geom
    assert tuple(g.normal) == (1, 0, 0) and g.u[0] == -2
    O.bodies[1].state.pos = (0, 0, 1e-3)
    O.run(3, True)
    O.bodies[0].state.pos = O.bodies[1].state.pos
    O.step()
    g = O.interactions[0, 1].geom
    assert all(math.isfinite(x) for x in list(g.normal) + list(g.u)) and g.normal[2] > 0.99


def test_pile_with_two_threads_equals_the_reference(tmp_path):
    """the parallel interaction loop (2 threads, the launcher's -j2) gives the reference's pile"""
    script = tmp_path / 'pile2.py'
    script.write_text('import importlib.util, json\n'
                      'spec = importlib.util.spec_from_file_location("s", %r)\n'
                      'm = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)\n'
                      'print("PILE " + json.dumps(m.pile()))\n' % os.path.join(HERE, 'reference', 'localframe.py'))
    launcher = os.path.join(os.path.dirname(HERE), 'yade')
    out = subprocess.run([sys.executable, launcher, '-n', '-x', '-j', '2', str(script)], capture_output=True, text=True, timeout=120,
                         env=dict(os.environ))
    line = [x for x in out.stdout.splitlines() if x.startswith('PILE ')]
    assert line, out.stdout + out.stderr
    here, ref = np.array(json.loads(line[0][5:])), np.array(REFERENCE['pile'])
    for h, r in zip(here, ref):
        assert np.abs(h - r).max() <= 1e-12 * np.abs(r).max()
