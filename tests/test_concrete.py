"""The concrete particle model (CpmMat, CpmPhys, CpmState, Ip2_CpmMat_CpmMat_CpmPhys, Ip2_FrictMat_CpmMat_FrictPhys,
Law2_ScGeom_CpmPhys_Cpm, CpmStateUpdater, UniaxialStrainer), doc/concrete.md.

The scenes are tests/reference/cpm.py, a plain Yade script; tests/reference/data/cpm.json is what the reference (Yade 2023.02a)
printed running it. The analytic checks (the damage law, the modulus of a chain, the crack onset) need no reference."""
import math
import os

import pytest
from reference_data import flat, scenes_and_data

from yade import (O, CpmMat, CpmPhys, CpmState, CpmStateUpdater, FrictMat, Ip2_CpmMat_CpmMat_CpmPhys, Ip2_FrictMat_CpmMat_FrictPhys,
                  Law2_ScGeom_CpmPhys_Cpm, State, UniaxialStrainer)
from yade.utils import sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
scenes, REFERENCE = scenes_and_data('cpm.py', 'cpm.json')  # (tests/reference_data.py)


def assert_close(here, ref, rel, abs_=0.0):
    """every number of `here` within rel (relative) or abs_ of the reference's; None (no contact) where it has one"""
    a, b = flat(here), flat(ref)
    assert len(a) == len(b)
    for k, (x, y) in enumerate(zip(a, b)):
        if y is None or isinstance(y, str):
            assert x == y, (k, x, y)
        else:
            assert x == pytest.approx(y, rel=rel, abs=abs_), (k, x, y)


# ---------------------------------------------------------------- the classes

def test_attributes_and_defaults_as_in_reference():
    m = CpmMat().dict()
    for k, v in dict(density=4800., young=1e9, poisson=.25, frictionAngle=.5, damLaw=1, dmgRateExp=0., dmgTau=-1., plRateExp=0., plTau=-1.,
                     isoPrestress=0., neverDamage=False, equivStrainShearContrib=0.).items():
        assert m[k] == v, k
    assert all(math.isnan(m[k]) for k in ('sigmaT', 'epsCrackOnset', 'relDuctility'))
    law = Law2_ScGeom_CpmPhys_Cpm()
    assert (law.yieldSurfType, law.yieldLogSpeed, law.omegaThreshold, law.epsSoft, law.relKnSoft) == (2, .1, 1., 1., .3)
    assert math.isnan(law.yieldEllipseShift)
    ip2 = Ip2_CpmMat_CpmMat_CpmPhys()
    assert ip2.cohesiveThresholdIter == 10 and ip2.E is None and Ip2_FrictMat_CpmMat_FrictPhys().frictAngle is None
    s = UniaxialStrainer()
    assert (s.axis, s.asymmetry, s.active, s.blockDisplacements, s.blockRotations, s.setSpeeds, s.initAccelTime, s.stressUpdateInterval,
            s.limitStrain, s.idleIterations, s.notYetReversed, s.posIds, s.negIds) == (2, 0, True, False, False, False, -200., 10, 0., 0, True, [], [])
    assert all(math.isnan(x) for x in (s.strainRate, s.absSpeed, s.stopStrain, s.crossSectionArea, s.originalLength))
    assert CpmStateUpdater().initRun is True and math.isnan(CpmStateUpdater().avgRelResidual)
    st = CpmState()
    assert (st.normDmg, st.numBrokenCohesive, st.numContacts, st.epsVolumetric) == (0, 0, 0, 0)
    p = CpmPhys()
    assert (p.omega, p.kappaD, p.dmgTau, p.damLaw, p.isCohesive) == (0, 0, -1, 1, False) and math.isnan(p.E)


def test_damage_law_funcG_and_its_inverse():
    # the reference's values (CpmPhys.funcG, funcGInv of Yade 2023.02a)
    assert CpmPhys.funcG(2e-4, 1e-4, 1e-3) == pytest.approx(0.5475812909820202, rel=1e-15)
    assert CpmPhys.funcG(2e-4, 1e-4, 1e-3, False, 0) == pytest.approx(0.5555555555555556, rel=1e-15)
    assert CpmPhys.funcG(1.1e-3, 1e-4, 1e-3, False, 0) == pytest.approx(1.01010101010101, rel=1e-14)  # (not capped)
    assert CpmPhys.funcG(1.5e-4, 1e-4, 1e-3, False, 1) == pytest.approx(0.36584705033285725, rel=1e-15)
    assert CpmPhys.funcG(1e-4, 1e-4, 1e-3) == 0 and CpmPhys.funcG(-1e-4, 1e-4, 1e-3) == 0 and CpmPhys.funcG(5e-3, 1e-4, 1e-3, True, 1) == 0
    assert CpmPhys.funcGInv(0.3, 1e-4, 1e-3, False, 0) == pytest.approx(0.00013698630136986303, rel=1e-14)
    assert CpmPhys.funcGInv(0.3, 1e-4, 1e-3, False, 1) == pytest.approx(0.00013758720372677912, rel=1e-12)
    assert CpmPhys.funcGInv(0.9, 1e-4, 1e-3, False, 1) == pytest.approx(0.0006040681894661348, rel=1e-12)
    assert CpmPhys.funcGInv(0, 1e-4, 1e-3) == 0
    for om in (0.1, 0.5, 0.99):  # inverse of each other
        assert CpmPhys.funcG(CpmPhys.funcGInv(om, 1e-4, 3e-3), 1e-4, 3e-3) == pytest.approx(om, rel=1e-13)
    with pytest.raises(RuntimeError, match='no convergence'):
        CpmPhys.funcGInv(1., 1e-4, 1e-3)
    with pytest.raises(ValueError, match='damLaw'):
        CpmPhys.funcG(1e-3, 1e-4, 1e-3, False, 3)
    p = CpmPhys(epsCrackOnset=1e-4, epsFracture=1e-3)
    p.setDamage(.5)
    assert p.omega == .5 and p.kappaD == pytest.approx(0.00018390391987786183, rel=1e-12)


def test_material_makes_its_bodies_state():
    O.materials.append(CpmMat(sigmaT=3e6, epsCrackOnset=1e-4, relDuctility=30))
    b = sphere((0, 0, 0), 1e-3)
    assert type(b.state) is CpmState and type(CpmMat().newAssocState()) is CpmState
    assert type(FrictMat().newAssocState()) is State and type(sphere((0, 0, 0), 1, material=FrictMat()).state) is State
    # in the scene, the state is a view of the body columns: the integrator moves it
    O.bodies.append(b)
    b.state.vel = (1, 2, 3)
    b.state.numBrokenCohesive = 7
    O.engines = [scenes.ForceResetter(), scenes.NewtonIntegrator(damping=0)]
    O.dt = 1e-3
    O.step()
    assert tuple(O.bodies[0].state.pos) == pytest.approx((1e-3, 2e-3, 3e-3), rel=1e-12)
    assert O.bodies[0].state.numBrokenCohesive == 7 and O.bodies[0].state.mass == pytest.approx(4800 * 4 / 3 * math.pi * 1e-9)


# ---------------------------------------------------------------- contacts against the reference

_PAIRS = {}


def pairs_here():
    """the pair scenes run here (once per session: plain numbers)"""
    if not _PAIRS:
        _PAIRS.update(scenes.pairs())
    return _PAIRS


@pytest.mark.parametrize('name', ['tension', 'linear', 'mixed', 'shear', 'noncohesive', 'broken', 'neverDamage', 'frict'])
def test_contact_equals_reference(name):
    assert_close(pairs_here()[name], REFERENCE['pairs'][name], rel=1e-9, abs_=1e-9)


def test_broken_contacts_are_counted_as_in_reference():
    # 41 on each body: the cohesive contact that broke, then the non-cohesive ones made again and removed as soon as stretched
    assert pairs_here()['brokenStates'] == REFERENCE['pairs']['brokenStates']


def test_facet_contact_equals_reference():
    assert_close(scenes.facet_contact(), REFERENCE['facet'], rel=1e-9, abs_=1e-9)


def test_state_updater_equals_reference():
    assert_close(scenes.updater_states(), REFERENCE['updater'], rel=1e-7, abs_=1e-6)


def test_state_updater_counts_the_broken_contacts_as_the_reference():
    assert_close(scenes.updater_broken(), REFERENCE['updaterBroken'], rel=1e-12, abs_=1e-15)


def test_uniaxial_strainer_kinematics_equal_reference():
    assert_close(scenes.strainer_runs(), REFERENCE['strainer'], rel=1e-12, abs_=1e-15)


# ---------------------------------------------------------------- specimens

def peak(curve):
    return max(curve, key=lambda p: abs(p[1]))


@pytest.mark.parametrize('test,rate,steps,every', [('tension', 1., 2000, 10), ('compression', -5., 4000, 20)])
def test_uniaxial_curve_agrees_with_reference(test, rate, steps, every):
    """the specimen's stress-strain curve: within 2 % of the reference's at the peak and before it"""
    here, ref = scenes.uniaxial(rate, steps, every=every), REFERENCE[test]
    assert here['contacts0'] == ref['contacts0'] and here['originalLength'] == pytest.approx(ref['originalLength'], rel=1e-15)
    (eh, sh), (er, sr) = peak(here['curve']), peak(ref['curve'])
    assert sh == pytest.approx(sr, rel=.02) and eh == pytest.approx(er, rel=.02)
    for (e1, s1), (e2, s2) in zip(here['curve'], ref['curve']):
        assert e1 == pytest.approx(e2, rel=1e-9)
        if abs(e2) <= abs(er):  # up to the peak: the same curve
            assert s1 == pytest.approx(s2, rel=.02, abs=.002 * abs(sr))


def chain(n=10, strainRate=1., steps=3000, r=1e-3, E=30e9):
    """a column of n spheres touching, pulled at its ends: (strain, avgStress, max omega, max kappaD) every 10 steps"""
    O.materials.append(CpmMat(young=E, poisson=.2, sigmaT=3e6, frictionAngle=.5, epsCrackOnset=1e-4, relDuctility=5, density=4800))
    ids = [O.bodies.append(sphere((0, 0, 2 * r * k), r)) for k in range(n)]
    strainer = UniaxialStrainer(strainRate=strainRate, axis=2, posIds=[ids[-1]], negIds=[ids[0]], crossSectionArea=math.pi * r * r, setSpeeds=True)
    scenes.engines([strainer], intRadius=1.5, damping=.8)  # (the neighbours only: the next ones are 4r apart)
    O.dt = .5 * r / math.sqrt(E / 4800)
    rows = []
    for k in range(steps // 10):
        O.run(10, True)
        ph = [i.phys for i in O.interactions if i.isReal]
        rows.append((strainer.strain, strainer.avgStress, max(p.omega for p in ph), max(p.kappaD for p in ph)))
    return rows


def test_elastic_slope_of_a_chain_is_the_contact_modulus():
    """Fn = E·crossSection·epsN: a chain of crossSection π·r² has the slope E (the model's contact modulus, 3.5.28)"""
    rows = chain()
    elastic = [(e, s) for e, s, om, k in rows if 2e-5 < e < 8e-5]
    assert len(elastic) > 5
    (e1, s1), (e2, s2) = elastic[0], elastic[-1]
    assert (s2 - s1) / (e2 - e1) == pytest.approx(30e9, rel=.01)


def test_damage_grows_only_after_the_crack_onset_strain():
    rows = chain()
    assert all(om == 0 for e, s, om, k in rows if k <= 1e-4)
    damaged = [(e, om) for e, s, om, k in rows if k > 1e-4]
    assert damaged and damaged[0][0] == pytest.approx(1e-4, rel=.1)  # the chain's first damage near epsCrackOnset
    oms = [om for e, om in damaged]
    assert all(b >= a for a, b in zip(oms, oms[1:])) and oms[-1] > .3  # non-decreasing, softening reached
    strengths = [s for e, s, om, k in rows]
    assert max(strengths) == pytest.approx(30e9 * 1e-4, rel=.05)  # the peak: E·epsCrackOnset


# ---------------------------------------------------------------- errors and persistence

def test_bad_parameters_are_refused():
    O.materials.append(CpmMat())  # sigmaT, epsCrackOnset, relDuctility not given
    O.bodies.append([sphere((0, 0, 0), 1e-3), sphere((0, 0, 1.9e-3), 1e-3)])
    scenes.engines()
    O.dt = 1e-8
    with pytest.raises(Exception, match='sigmaT'):
        O.step()
    O.reset()
    O.materials.append(CpmMat(sigmaT=3e6, epsCrackOnset=1e-4, relDuctility=.5, damLaw=0))
    O.bodies.append([sphere((0, 0, 0), 1e-3), sphere((0, 0, 1.9e-3), 1e-3)])
    scenes.engines()
    with pytest.raises(Exception, match='relDuctility'):
        O.step()
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 1, material=CpmMat(neverDamage=True)), sphere((0, 0, 5), 1, material=CpmMat(neverDamage=True))])
    O.dt = 1e-3
    for kw, what in [(dict(strainRate=1, posIds=[1], negIds=[0]), 'crossSectionArea'), (dict(strainRate=1, crossSectionArea=1), 'posIds'),
                     (dict(strainRate=1, posIds=[0], negIds=[1], crossSectionArea=1), 'further'),
                     (dict(strainRate=1, posIds=[1], negIds=[7], crossSectionArea=1), '#7'),
                     (dict(posIds=[1], negIds=[0], crossSectionArea=1), 'strainRate or absSpeed'),
                     (dict(strainRate=1, axis=5, posIds=[1], negIds=[0], crossSectionArea=1), 'axis')]:
        O.engines = [UniaxialStrainer(**kw)]
        with pytest.raises(Exception, match=what):
            O.step()
    with pytest.raises(ValueError):
        UniaxialStrainer(stressUpdateInterval=0)


@pytest.mark.parametrize('name', ['cpm.yade', 'cpm.xml'])
def test_save_and_load_keep_the_damage_and_resume_exactly(tmp_path, name):
    def run(steps):
        O.reset()
        neg, pos = scenes.specimen()
        strainer = UniaxialStrainer(strainRate=2., axis=2, posIds=pos, negIds=neg, crossSectionArea=(2 * scenes.R) ** 2 * 25, label='strainer')
        scenes.engines([strainer, CpmStateUpdater(iterPeriod=50)])
        O.dt = 3e-7
        O.run(steps, True)
    run(300)  # damaged: past the peak
    path = str(tmp_path / name)
    O.save(path)
    O.run(50, True)
    after = [(tuple(b.state.pos), b.state.normDmg) for b in O.bodies], [(i.id1, i.id2, i.phys.omega, tuple(i.phys.epsT)) for i in O.interactions if i.isReal]
    damaged = sum(1 for i in O.interactions if i.isReal and i.phys.omega > 0)
    O.load(path)
    assert type(O.bodies[0].state) is CpmState and O.iter == 300 and damaged > 0
    O.run(50, True)
    again = [(tuple(b.state.pos), b.state.normDmg) for b in O.bodies], [(i.id1, i.id2, i.phys.omega, tuple(i.phys.epsT)) for i in O.interactions if i.isReal]
    assert again == after


def test_two_threads_repeat_the_same_bits():
    """the law runs in the parallel interaction loop (a broken contact is counted with an atomic add): two runs on two threads
    give the same bits"""
    import yade
    yade.setNumThreads(2)
    first, second = scenes.uniaxial(1., 600), scenes.uniaxial(1., 600)
    assert first == second and first['curve'][-1][1] > 0
