"""Each contact law is one kernel (core/ContactKernel.hpp): these scenes pin the bits every law gave
before the laws were rewritten as kernels (tests/data/kernel_bits.json, recorded with the
functors of commit 1bb95d0), on the general path and on the fast pass alike. Sphere-sphere and
facet-sphere contacts, sliding, rolling, ending and starting again, for every law of the library.

Record again (only when a law's physics changes on purpose):
    PYTHONPATH=build /usr/bin/python3 tests/test_kernel_bits.py --record
"""
import json
import os
import sys

import pytest

from yade import *  # noqa: F401,F403
from yade import O, pack, geom
from yade.utils import *  # noqa: F401,F403

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'data', 'kernel_bits.json')


def _materials(law):
    if law.startswith('frictvisco'):
        return FrictViscoMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, betan=.3)
    if law == 'viscel':
        return ViscElMat(kn=3e5, ks=1e5, cn=5., cs=2., frictionAngle=.5, density=2600, mR=1e-6, mRtype=1)
    return FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600)


def _functors(law):
    if law == 'frict':
        return Ip2_FrictMat_FrictMat_FrictPhys(), Law2_ScGeom_FrictPhys_CundallStrack()
    if law == 'mindlin':
        return Ip2_FrictMat_FrictMat_MindlinPhys(betan=.3, betas=.2), Law2_ScGeom_MindlinPhys_Mindlin()
    if law == 'mindlin-moment':
        return (Ip2_FrictMat_FrictMat_MindlinPhys(betan=.3, betas=.2, krot=.1, ktwist=.1, eta=.5, gamma=.01),
                Law2_ScGeom_MindlinPhys_Mindlin(includeMoment=True, includeAdhesion=True, calcEnergy=True))
    if law == 'hertz-linear-shear':
        return Ip2_FrictMat_FrictMat_MindlinPhys(), Law2_ScGeom_MindlinPhys_HertzWithLinearShear(nonLin=1)
    if law == 'viscel':
        return Ip2_ViscElMat_ViscElMat_ViscElPhys(), Law2_ScGeom_ViscElPhys_Basic()
    if law == 'frictvisco':
        return Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(), Law2_ScGeom_FrictViscoPhys_CundallStrackVisco()
    if law == 'frictvisco-apart':
        return (Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(),
                Law2_ScGeom_FrictViscoPhys_CundallStrackVisco(neverErase=True, sphericalBodies=False))
    raise ValueError(law)


LAWS = ['frict', 'mindlin', 'mindlin-moment', 'hertz-linear-shear', 'viscel']


def run(law, fused, steps=3000, energy=False):
    O.reset()
    O.materials.append(_materials(law))
    O.bodies.append(geom.facetBox((.05, .05, .1), (.05, .05, .1), wallMask=31))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (.1, .1, .2), rMean=.006, rRelFuzz=.3, num=300, seed=5)
    sp.toSimulation()
    for b in O.bodies:
        if isinstance(b.shape, Sphere):
            b.state.angVel = (b.id % 7 - 3, b.id % 5 - 2, b.id % 3 - 1)
    ip2, law2 = _functors(law)
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [ip2], [law2])
    loop.fusedPasses = fused
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]), loop,
                 NewtonIntegrator(gravity=(0, 0, -300), damping=0.1)]
    O.trackEnergy = energy
    O.dt = 2e-5
    O.run(steps, True)
    out = {}
    for b in O.bodies:
        if isinstance(b.shape, Sphere) and b.id % 10 == 0:
            out['b%d' % b.id] = [list(map(float, b.state.pos)), list(map(float, b.state.vel)), list(map(float, b.state.angVel))]
    contacts = sorted((i.id1, i.id2) for i in O.interactions if i.isReal)
    out['contacts'] = len(contacts)
    for (a, b) in contacts[::25]:
        i = O.interactions[a, b]
        out['c%d-%d' % (a, b)] = [list(map(float, i.phys.normalForce)), list(map(float, i.phys.shearForce)),
                                  list(map(float, i.geom.shearInc)), float(i.geom.penetrationDepth)]
    if energy:
        out['energy'] = {k: float(v) for k, v in O.energy.items()}
    return out


@pytest.fixture(scope='module')
def recorded():
    with open(DATA) as f:
        return json.load(f)


@pytest.mark.parametrize('law', LAWS)
@pytest.mark.parametrize('fused', [True, False], ids=['fast-pass', 'general'])
def test_kernel_gives_the_bits_recorded_before_the_kernels(recorded, law, fused):
    got = run(law, fused)
    want = recorded[law]
    assert got['contacts'] == want['contacts'] and got['contacts'] > 100
    assert got == want


@pytest.mark.parametrize('law', ['frictvisco', 'frictvisco-apart'])
def test_a_law_added_as_a_kernel_gives_the_same_bits_on_both_paths(law):
    """Law2_ScGeom_FrictViscoPhys_CundallStrackVisco came after the kernels (no recorded bits): its fast
    pass, two contacts at a time, and its general path agree bit for bit, also for contacts kept after
    their bodies separated (neverErase: the dashpot still acts) and with torques from the contact point."""
    fast, general = run(law, True), run(law, False)
    assert fast['contacts'] > 100
    assert fast == general


def test_energy_terms_keep_their_bits(recorded):
    assert run('frict', True, energy=True) == recorded['frict-energy']
    assert run('frict', False, energy=True) == recorded['frict-energy']


if __name__ == '__main__' and '--record' in sys.argv:
    data = {law: run(law, False) for law in LAWS}
    data['frict-energy'] = run('frict', False, energy=True)
    with open(DATA, 'w') as f:
        json.dump(data, f, indent=0, sort_keys=True)
    print('recorded', DATA, {k: v['contacts'] for k, v in data.items()})
