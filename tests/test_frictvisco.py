"""The Cundall-Strack law with normal viscous damping (FrictViscoMat, FrictViscoPhys, Ip2_FrictMat_FrictViscoMat_FrictViscoPhys,
Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys, Law2_ScGeom_FrictViscoPhys_CundallStrackVisco).

The scenes are tests/reference/frictvisco.py, a plain Yade script; tests/reference/data/frictvisco.json is what the reference
(Yade 2023.02a) printed running it (tests/reference/regenerate.sh). The rules the reference follows, found by running it, are
in doc/contact-laws.md."""
import importlib.util
import json
import math
import os

import pytest

from yade import (O, FrictMat, FrictViscoMat, FrictViscoPhys, Ip2_FrictMat_FrictViscoMat_FrictViscoPhys,
                  Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys, Law2_ScGeom_FrictViscoPhys_CundallStrackVisco, MatchMaker)
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('frictvisco_scenes', os.path.join(HERE, 'reference', 'frictvisco.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'frictvisco.json')) as _f:
    REFERENCE = json.load(_f)


def flat(x):
    if isinstance(x, dict):
        return [v for k in sorted(x) for v in flat(x[k])]
    if isinstance(x, list):
        return [v for y in x for v in flat(y)]
    return [x]


def assert_close(here, ref, rel, abs_=0.0):
    """every number of `here` within rel (relative) or abs_ of the reference's; None (no contact) and NaN where it has them"""
    if isinstance(ref, dict):
        assert sorted(here) == sorted(ref)
    a, b = flat(here), flat(ref)
    assert len(a) == len(b)
    for x, y in zip(a, b):
        if y is None or (isinstance(y, float) and math.isnan(y)):
            assert x is None or (isinstance(x, float) and math.isnan(x)), (x, y)
        else:
            assert x == pytest.approx(y, rel=rel, abs=abs_)


# ---------------------------------------------------------------- the classes

def test_attributes_and_defaults_as_in_reference():
    assert FrictViscoMat().dict() == dict(betan=0.0, frictionAngle=0.5, young=1e9, poisson=0.25, id=-1, label='', density=1000.0)
    p = FrictViscoPhys().dict()
    assert set(p) == {'cn_crit', 'cn', 'normalViscous', 'tangensOfFrictionAngle', 'ks', 'shearForce', 'kn', 'normalForce'}
    assert math.isnan(p['cn_crit']) and math.isnan(p['cn']) and tuple(p['normalViscous']) == (0, 0, 0)
    for ip2 in (Ip2_FrictMat_FrictViscoMat_FrictViscoPhys, Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys):
        assert ip2().dict() == dict(kn=None, kRatio=None, frictAngle=None, label='')
    law = Law2_ScGeom_FrictViscoPhys_CundallStrackVisco()
    assert law.dict() == dict(neverErase=False, sphericalBodies=True, traceEnergy=False, label='')
    assert law.elasticEnergy() == 0 and law.plasticDissipation() == 0


def test_keyword_constructors_and_matchmakers():
    m = FrictViscoMat(betan=0.25, young=2e7, label='visco')
    assert (m.betan, m.young, m.label) == (0.25, 2e7, 'visco')
    p = FrictViscoPhys(cn=3., cn_crit=10., normalViscous=(1, 2, 3))
    assert (p.cn, p.cn_crit, tuple(p.normalViscous)) == (3, 10, (1, 2, 3))
    ip2 = Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(kn=5e4, kRatio=MatchMaker(matches=((0, 1, 0.7),)), frictAngle=0.1)
    assert (ip2.kn.algo, ip2.kn.val, ip2.frictAngle.val) == ('val', 5e4, 0.1)
    assert list(ip2.kRatio.matches[0]) == [0, 1, 0.7]
    law = Law2_ScGeom_FrictViscoPhys_CundallStrackVisco(neverErase=True, sphericalBodies=False, traceEnergy=True)
    assert (law.neverErase, law.sphericalBodies, law.traceEnergy) == (True, False, True)
    law.initPlasticDissipation(2.5)
    assert law.plasticDissipation() == 2.5
    law.initPlasticDissipation()
    assert law.plasticDissipation() == 0


# ---------------------------------------------------------------- against the reference's numbers

# kn, ks, cn, cn_crit, tan(phi), normalForce, normalViscous, shearForce after one step, for each rule of the Ip2 functors
# (betan: the mean, or the one that is not 0; the effective mass; kn, kRatio, frictAngle; a FrictMat with a FrictViscoMat)
def test_contact_constants_equal_the_reference():
    here = scenes.constants()
    assert sorted(here) == sorted(REFERENCE['constants'])
    for name in here:
        assert_close(here[name], REFERENCE['constants'][name], rel=1e-15)  # (seen: the same bits)


# Trajectories: the forces are the reference's bits for the same state; the states drift by one ulp at times (the angular
# velocity's update in NewtonIntegrator), so the comparison allows 1e-11 (seen: 4e-12 at most; the pile's smallest velocities
# 2e-15 m/s away).
@pytest.mark.parametrize("name, run", [
    ('headOn', lambda: scenes.headOn()),
    ('oblique', lambda: scenes.oblique()),
    ('neverErase', lambda: scenes.oblique(neverErase=True)),
    ('facetAndWall', lambda: scenes.facetAndWall(True)),
    ('facetAndWallArms', lambda: scenes.facetAndWall(False)),
    ('pile', lambda: scenes.pile()),
])
def test_trajectories_and_forces_equal_the_reference(name, run):
    assert_close(run(), REFERENCE[name], rel=1e-11, abs_=1e-13)


def test_energies_equal_the_reference():
    """O.energy's elastPotential and plastDissip with O.trackEnergy; with traceEnergy the law sums the dissipation itself
    (plasticDissipation()), and, as in the reference, elastPotential is added to at every step even without
    O.trackEnergy (it then grows: the instantaneous terms are reset only while energy is tracked)."""
    here = scenes.energy()
    assert sorted(here) == sorted(REFERENCE['energy'])
    for mode in here:
        for row, ref in zip(here[mode], REFERENCE['energy'][mode]):
            # ('kinetic' is NewtonIntegrator's, taken with the velocities after its update here, before it in the reference)
            terms = {k: v for k, v in row[0] if k != 'kinetic'}
            refTerms = {k: v for k, v in ref[0] if k != 'kinetic'}
            assert sorted(terms) == sorted(refTerms)
            assert_close(terms, refTerms, rel=1e-11)
            assert_close(row[1:], ref[1:], rel=1e-11)


# ---------------------------------------------------------------- the rules

def real():
    return O.interactions.has(0, 1) and O.interactions[0, 1].isReal


def pair(betan1=0.3, betan2=0.3, r=0.01, v=0.05, overlap=0.0):
    """two equal spheres meeting head on at relative speed 2v"""
    m1 = O.materials.append(FrictViscoMat(betan=betan1, density=2000, young=1e7, poisson=0.3, frictionAngle=0.3))
    m2 = O.materials.append(FrictViscoMat(betan=betan2, density=2000, young=1e7, poisson=0.3, frictionAngle=0.3))
    O.bodies.append(sphere((0, 0, 0), r, material=m1))
    O.bodies.append(sphere((0, 0, 2 * r - overlap), r, material=m2))
    O.bodies[0].state.vel = (0, 0, v)
    O.bodies[1].state.vel = (0, 0, -v)
    scenes.engines()


def test_normal_force_is_elastic_minus_viscous_and_may_pull():
    pair(betan1=0.5, betan2=0.5, v=1, overlap=1e-6)
    O.dt = 1e-6
    pulled = 0
    while O.iter < 2000:
        w = O.bodies[1].state.vel[2] - O.bodies[0].state.vel[2]
        O.step()
        if not real():
            break
        i = O.interactions[0, 1]
        p, u = i.phys, i.geom.penetrationDepth
        m = O.bodies[0].state.mass / 2
        assert p.cn_crit == pytest.approx(2 * math.sqrt(m * p.kn), rel=1e-15) and p.cn == pytest.approx(0.5 * p.cn_crit, rel=1e-15)
        # the normal velocity of points at the radii: (r1 + r2)/(r1 + r2 - u) times the centres'
        assert p.normalViscous[2] == pytest.approx(p.cn * w * 0.02 / (0.02 - u), rel=1e-12)
        assert p.normalForce[2] == pytest.approx(p.kn * u - p.normalViscous[2], rel=1e-9, abs=1e-12)
        pulled += p.normalForce[2] < 0
    assert 0 < O.iter < 2000 and pulled > 50  # the viscous force pulls while they part (no cut at zero)


@pytest.mark.parametrize("beta", [0.05, 0.3, 0.7])
def test_restitution_and_contact_time_of_a_head_on_impact(beta):
    """A linear spring and dashpot whose force may pull, the contact ending where the overlap does: the spheres part after
    half a damped period, pi/(w0*sqrt(1 - beta^2)), w0 = sqrt(kn/m*), with the restitution coefficient
    exp(-pi*beta/sqrt(1 - beta^2)). (Within 0.14 %: the time step, and the normal velocity of points at the radii, which
    is (r1 + r2)/(r1 + r2 - u) times the centres'.)"""
    pair(betan1=beta, betan2=beta, v=0.01)
    O.dt = 1e-7
    O.step()
    p = O.interactions[0, 1].phys
    w0 = math.sqrt(p.kn / (O.bodies[0].state.mass / 2))
    start = O.iter
    while real():
        O.step()
    duration = (O.iter - start) * O.dt
    e = (O.bodies[1].state.vel[2] - O.bodies[0].state.vel[2]) / 0.02
    assert e == pytest.approx(math.exp(-math.pi * beta / math.sqrt(1 - beta ** 2)), rel=2e-3)
    assert duration == pytest.approx(math.pi / (w0 * math.sqrt(1 - beta ** 2)), abs=3 * O.dt)


def test_betan_of_two_materials():
    """the mean; the other one when one is 0; no damping (cn 0, cn_crit not computed) when both are"""
    for b1, b2, expected in [(0.2, 0.6, 0.4), (0, 0.6, 0.6), (0.6, 0, 0.6), (-0.2, 0.6, 0.2)]:
        O.reset()
        pair(b1, b2, overlap=1e-6)
        O.dt = 1e-7
        O.step()
        p = O.interactions[0, 1].phys
        assert p.cn == pytest.approx(expected * p.cn_crit, rel=1e-15)
    O.reset()
    pair(0, 0, overlap=1e-6)
    O.dt = 1e-7
    O.step()
    p = O.interactions[0, 1].phys
    assert p.cn == 0 and math.isnan(p.cn_crit) and tuple(p.normalViscous) == (0, 0, 0)


def test_a_frictviscomat_with_a_frictmat_in_either_order():
    """The reference stops on a failed assertion (`!swap`) when the FrictViscoMat body is the first; here both orders give
    the same contact, betan the FrictViscoMat's."""
    out = []
    for order in (0, 1):
        O.reset()
        a = O.materials.append(FrictMat(density=3000, young=2e7, poisson=0.2, frictionAngle=0.5))
        b = O.materials.append(FrictViscoMat(betan=0.4, density=2000, young=1e7, poisson=0.3, frictionAngle=0.3))
        mats = (a, b) if order == 0 else (b, a)
        O.bodies.append(sphere((0, 0, 0), 0.01, material=mats[0]))
        O.bodies.append(sphere((0, 0, 0.02 - 1e-5), 0.01, material=mats[1]))
        scenes.engines(ip2s=[Ip2_FrictMat_FrictViscoMat_FrictViscoPhys()])
        O.dt = 1e-7
        O.step()
        p = O.interactions[0, 1].phys
        out.append((p.kn, p.ks, p.cn, p.cn_crit, p.tangensOfFrictionAngle))
    assert out[0] == out[1]
    assert out[0][2] == pytest.approx(0.4 * out[0][3], rel=1e-15)


def test_stiffness_matchmaker_without_values_is_an_error():
    """kn and kRatio MatchMakers get no materials' values (the reference aborts the process: std::invalid_argument)"""
    pair(overlap=1e-6)
    scenes.engines(ip2s=[Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(kn=MatchMaker(algo='avg'))])
    O.dt = 1e-7
    with pytest.raises(RuntimeError, match="MatchMaker: no match for \\(0,1\\), and values required for algo computation 'avg'"):
        O.step()


def test_never_erase_keeps_the_viscous_force_after_the_bodies_part():
    pair(betan1=0.5, betan2=0.5, v=1, overlap=1e-6)
    O.engines[2].lawDispatcher.functors[0].neverErase = True
    O.dt = 1e-6
    O.step()
    while O.interactions[0, 1].geom.penetrationDepth >= 0:
        O.step()
    O.run(20, True)
    i = O.interactions[0, 1]
    assert i.isReal and i.geom.penetrationDepth < 0
    assert tuple(i.phys.normalForce) == tuple(-x for x in i.phys.normalViscous) and i.phys.normalViscous[2] > 0
    w = O.bodies[1].state.vel[2] - O.bodies[0].state.vel[2]
    O.step()
    assert O.bodies[1].state.vel[2] - O.bodies[0].state.vel[2] < w  # still braked


def test_saved_and_loaded_scene_goes_on_the_same(tmp_path):
    O.materials.append(FrictMat(density=3000, young=2e7, poisson=0.2, frictionAngle=0.5))
    m = O.materials.append(FrictViscoMat(betan=0.4, density=2000, young=1e7, poisson=0.3, frictionAngle=0.3))
    O.bodies.append(sphere((0, 0, 0), 0.01, material=0))
    O.bodies.append(sphere((0.003, 0, 0.0195), 0.01, material=m))
    O.bodies.append(sphere((0.004, 0.001, 0.0385), 0.01, material=m))
    O.bodies[2].state.vel = (0.1, 0, -0.5)
    O.bodies[2].state.angVel = (0, 3, 0)
    scenes.engines(law=Law2_ScGeom_FrictViscoPhys_CundallStrackVisco(traceEnergy=True, sphericalBodies=False))
    O.dt = 1e-6
    O.run(200, True)
    for f in ('s.yade.gz', 's.xml'):
        path = str(tmp_path / f)
        O.save(path)
        O.run(100, True)
        after = scenes.bodies([0, 1, 2]), scenes.phys(0, 1), scenes.phys(1, 2)
        O.load(path)
        assert isinstance(O.interactions[1, 2].phys, FrictViscoPhys) and O.materials[m].betan == 0.4
        law = O.engines[2].lawDispatcher.functors[0]
        assert (law.traceEnergy, law.sphericalBodies) == (True, False)
        O.run(100, True)
        assert (scenes.bodies([0, 1, 2]), scenes.phys(0, 1), scenes.phys(1, 2)) == after
