"""SpheresFactory, BoxFactory, CircularFactory: the rules observed by running the reference Yade 2023.02a
on small scenes (its random draws cannot be matched, so the statistics and the rules are tested)."""
import math
import time
import warnings

import pytest

from yade import (O, Vector3, ForceResetter, InsertionSortCollider, InteractionLoop, NewtonIntegrator, Bo1_Sphere_Aabb, Bo1_Box_Aabb,
                  Bo1_Wall_Aabb, Ig2_Sphere_Sphere_ScGeom, Ig2_Wall_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                  Law2_ScGeom_FrictPhys_CundallStrack, FrictMat, SpheresFactory, BoxFactory, CircularFactory)
from yade.utils import sphere, box, wall

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

NAN = float('nan')

# The reference's defaults, as printed by {k: getattr(o, k) for k in o.dict()} in Yade 2023.02a.
REF_BASE = {'massFlowRate': NAN, 'rMin': NAN, 'rMax': NAN, 'vMin': NAN, 'vMax': NAN, 'vAngle': NAN, 'normal': (NAN,) * 3,
            'normalVel': (NAN,) * 3, 'materialId': -1, 'mask': -1, 'color': (-1., -1., -1.), 'ids': [], 'totalMass': 0.0,
            'totalVolume': 0.0, 'goalMass': 0.0, 'maxParticles': 100, 'maxMass': -1.0, 'numParticles': 0, 'maxAttempt': 5000,
            'silent': False, 'blockedDOFs': '', 'PSDsizes': [], 'PSDcum': [], 'PSDcalculateMass': True, 'stopIfFailed': True,
            'exactDiam': True, 'dead': False, 'ompThreads': -1, 'label': ''}
REF_DEFAULTS = {
    SpheresFactory: REF_BASE,
    BoxFactory: dict(REF_BASE, extents=(NAN,) * 3, center=(NAN,) * 3),
    CircularFactory: dict(REF_BASE, radius=NAN, length=0.0, center=(NAN,) * 3),
}


def same(a, b):
    if isinstance(b, tuple):
        return len(a) == 3 and all(same(a[i], b[i]) for i in range(3))
    if isinstance(b, float) and math.isnan(b):
        return math.isnan(a)
    return a == b and type(a) is type(b)


def scene(factory, dt=1e-3, contacts=False, density=2000):
    O.materials.append(FrictMat(density=density, label='m0'))
    loop = [InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()])] if contacts else []
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()])] + loop + [factory, NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = dt
    return factory


def still(**kw):
    """Spheres at rest (vMin = vMax = 0), along z."""
    d = dict(normal=(0, 0, 1), vMin=0, vMax=0, vAngle=0, seed=7)
    d.update(kw)
    return d


def made(f):
    return [O.bodies[i] for i in f.ids]


def overlaps(bodies):
    """Pairs of spheres closer than the sum of their radii (a grid, for a few thousand spheres)."""
    spheres = [b for b in bodies if b is not None and hasattr(b.shape, 'radius')]
    if not spheres:
        return 0
    h = 2 * max(b.shape.radius for b in spheres)
    cells = {}
    for b in spheres:
        cells.setdefault(tuple(int(math.floor(x / h)) for x in b.state.pos), []).append(b)
    n = 0
    for (i, j, k), members in cells.items():
        for di in (-1, 0, 1):
            for dj in (-1, 0, 1):
                for dk in (-1, 0, 1):
                    for b in cells.get((i + di, j + dj, k + dk), []):
                        for a in members:
                            if a.id < b.id and (a.state.pos - b.state.pos).norm() < a.shape.radius + b.shape.radius - 1e-12:
                                n += 1
    return n


@pytest.mark.parametrize('cls', [SpheresFactory, BoxFactory, CircularFactory])
def test_defaults_are_the_references(cls):
    o = cls()
    d = o.dict()
    ref = REF_DEFAULTS[cls]
    for k, v in ref.items():
        got = d[k]
        if isinstance(v, tuple):
            got = tuple(got)
        assert same(got, v), (k, got, v)
    # ours has seed (the engine's mt19937) and the engines' timing counters besides
    assert set(d) - set(ref) <= {'seed', 'execTime', 'execCount'}
    assert d['seed'] == -1
    assert issubclass(BoxFactory, SpheresFactory) and issubclass(CircularFactory, SpheresFactory)


def test_goal_mass_grows_by_flow_rate_and_total_mass_follows_it():
    # reference (rate 1e4, dt 1e-3, rMin .05, rMax .1, density 2000): goalMass 10, 20, 30, 40, 50 and totalMass 11.83,
    # 20.76, 31.33, 41.90, 53.32: spheres are made while totalMass < goalMass (so it ends less than one sphere above)
    f = scene(BoxFactory(maxParticles=-1, extents=(1, 1, 1), center=(0, 0, 0), rMin=.05, rMax=.1, massFlowRate=1e4, **still()))
    mMax = 4 / 3 * math.pi * .1 ** 3 * 2000
    for i in range(1, 6):
        O.step()
        assert f.goalMass == pytest.approx(10 * i, rel=1e-12)
        assert f.goalMass <= f.totalMass < f.goalMass + mMax
        assert f.numParticles == len(f.ids) == len(O.bodies)
    bs = made(f)
    assert f.totalMass == pytest.approx(sum(b.state.mass for b in bs), rel=1e-12)
    assert f.totalVolume == pytest.approx(sum(4 / 3 * math.pi * b.shape.radius ** 3 for b in bs), rel=1e-12)
    # mass from the material's density, inertia of a solid sphere (reference: mass / volume = 2000, inertia 2/5 m r^2)
    for b in bs:
        assert b.state.mass == pytest.approx(2000 * 4 / 3 * math.pi * b.shape.radius ** 3, rel=1e-12)
        assert b.state.inertia[0] == pytest.approx(.4 * b.state.mass * b.shape.radius ** 2, rel=1e-12)
        assert tuple(b.state.refPos) == tuple(b.state.pos) and b.bound is not None
    # a change of dt and of the rate apply from the next step (reference: dt .01 -> .02: goal 10 -> 30; rate 0: 30)
    O.dt = 2e-3
    O.step()
    assert f.goalMass == pytest.approx(70, rel=1e-12)
    f.massFlowRate = 0
    O.step()
    assert f.goalMass == pytest.approx(70, rel=1e-12) and f.totalMass < 70 + mMax


def test_mass_flow_over_a_longer_run():
    f = scene(BoxFactory(maxParticles=-1, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.01, rMax=.02, massFlowRate=30, **still()), dt=1e-2)
    mMax = 4 / 3 * math.pi * .02 ** 3 * 2000
    O.run(40, True)
    assert f.totalMass == pytest.approx(30 * O.time, abs=mMax)
    assert f.totalMass >= 30 * O.time * (1 - 1e-12)


def test_box_radii_positions_and_no_overlap():
    # reference: centres uniform in center +- extents (extents are half-sizes; x in [0.0018, 1.997] for center 1,
    # extents 1), the sphere itself may stick out of the box
    f = scene(BoxFactory(maxParticles=-1, extents=(1, .5, .2), center=(1, 2, 3), rMin=.02, rMax=.04, massFlowRate=2e4, **still()))
    O.run(10, True)
    bs = made(f)
    assert len(bs) > 500
    rs = [b.shape.radius for b in bs]
    assert min(rs) >= .02 and max(rs) <= .04
    assert max(rs) - min(rs) > .015  # spread over the range
    lo, hi = Vector3(0, 1.5, 2.8), Vector3(2, 2.5, 3.2)
    for b in bs:
        assert all(lo[k] <= b.state.pos[k] <= hi[k] for k in range(3))
    assert overlaps(bs) == 0
    # uniform in each coordinate: the mean is the center
    for k, c in enumerate((1, 2, 3)):
        assert sum(b.state.pos[k] for b in bs) / len(bs) == pytest.approx(c, abs=.05 * (hi[k] - lo[k]))
    assert all(b.shape.color == Vector3(1, 1, 1) and b.mask == 1 and b.material.label == 'm0' for b in bs)  # reference defaults


def test_no_overlap_with_bodies_already_there():
    # reference: none of 142 spheres in a fixed sphere nor in the bound of a box body inside the region
    O.materials.append(FrictMat(density=2000))
    O.bodies.append(sphere((0, 0, 0), .4, fixed=True))
    O.bodies.append(box((.7, 0, 0), (.1, .5, .5), fixed=True))
    f = BoxFactory(maxParticles=-1, extents=(1, 1, 1), center=(0, 0, 0), rMin=.02, rMax=.03, massFlowRate=200, **still())
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]), f, NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-2
    O.run(10, True)
    bs = made(f)
    assert len(bs) > 100 and f.ids[0] == 2  # ids follow the bodies already there
    assert all(b.state.pos.norm() >= .4 + b.shape.radius for b in bs)
    for b in bs:
        p, r = b.state.pos, b.shape.radius
        assert not (abs(p[0] - .7) < .1 + r and abs(p[1]) < .5 + r and abs(p[2]) < .5 + r)
    assert overlaps(list(O.bodies)) == 0


def test_many_bodies_are_fast():
    O.materials.append(FrictMat(density=2000))
    O.bodies.append([sphere((.1 * i, .1 * j, .1 * k), .04, fixed=True) for i in range(20) for j in range(20) for k in range(10)])
    f = BoxFactory(maxParticles=-1, extents=(1, 1, .5), center=(.95, .95, .45), rMin=.01, rMax=.02, massFlowRate=1e3, **still())
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]), f, NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-2
    t = time.time()
    O.run(3, True)
    assert time.time() - t < 10
    assert len(f.ids) > 800
    assert overlaps(list(O.bodies)) == 0


def test_disc_positions():
    # reference (radius 1, length 0): centres on the disc plane (perpendicular to normal, through center), at most
    # radius - r from the axis (max radial + r: 0.990), the distance to the axis uniform (flat histogram, not uniform in area)
    f = scene(CircularFactory(maxParticles=-1, radius=1, center=(1, 2, 3), rMin=.02, rMax=.03, massFlowRate=2e3, **still(normal=(1, 1, 0))))
    O.run(10, True)
    bs = made(f)
    n, c = Vector3(1, 1, 0).normalized(), Vector3(1, 2, 3)
    assert len(bs) > 120  # reference: 148
    for b in bs:
        d = b.state.pos - c
        assert abs(d.dot(n)) < 1e-12
        assert (d - n * d.dot(n)).norm() <= 1 - b.shape.radius + 1e-12
    assert overlaps(bs) == 0


def test_cylinder_positions_and_uniform_distance_to_axis():
    # reference (radius 1, length 1, r .005, 1910 spheres): distance to the axis uniform in [0, radius - r] (mean square
    # 0.335 ~ (1 - r)^2 / 3; a flat histogram), axial uniform in [-length/2, length/2], angle uniform
    f = scene(CircularFactory(maxParticles=-1, radius=1, length=1, center=(0, 0, 0), rMin=.005, rMax=.005, massFlowRate=400, **still()))
    O.run(5, True)
    bs = made(f)
    assert len(bs) > 1800
    rad = [math.hypot(b.state.pos[0], b.state.pos[1]) for b in bs]
    ax = [b.state.pos[2] for b in bs]
    assert max(rad) <= 1 - .005 + 1e-12 and max(abs(a) for a in ax) <= .5
    assert sum(r * r for r in rad) / len(rad) == pytest.approx(.995 ** 2 / 3, abs=.03)
    hist = [0] * 5
    for r in rad:
        hist[min(4, int(r / .995 * 5))] += 1
    assert all(abs(h - len(bs) / 5) < .2 * len(bs) / 5 for h in hist)
    assert sum(ax) / len(ax) == pytest.approx(0, abs=.05)
    assert overlaps(bs) == 0


def test_velocities_follow_the_normal_with_one_speed_per_step():
    # reference: vAngle=.5 and normal (0,0,1): every velocity exactly along the normal (angle 0), the speed uniform in
    # [vMin, vMax] drawn once per step (all the spheres of a step share it; 10 distinct speeds over 10 steps)
    f = scene(BoxFactory(maxParticles=-1, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, vMin=1, vMax=2, vAngle=.5,
                         massFlowRate=2e3, normal=(0, 0, 1), seed=3))
    speeds = []
    for i in range(10):
        before = len(f.ids)
        O.step()
        new = [O.bodies[j] for j in f.ids[before:]]
        assert new
        v = new[0].state.vel
        assert all(b.state.vel == v for b in new)
        assert v[0] == 0 and v[1] == 0 and 1 <= v[2] <= 2
        speeds.append(v[2])
    assert len(set(speeds)) == 10
    assert all(b.state.angVel == Vector3(0, 0, 0) for b in made(f))


def test_normal_vel_is_used_as_direction():
    # reference: normalVel (0,3,0), normal (0,0,1), vMin 1, vMax 2 -> velocities (0, 1.2524, 0): normalized, scaled by the speed
    f = scene(BoxFactory(maxParticles=-1, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, vMin=1, vMax=2, vAngle=.5,
                         massFlowRate=2e3, normal=(0, 0, 1), normalVel=(0, 3, 0), seed=3))
    O.run(3, True)
    for b in made(f):
        v = b.state.vel
        assert v[0] == 0 and v[2] == 0 and 1 <= v[1] <= 2
    # reference: normal (0,0,2), vMin = vMax = 1 -> (0,0,1)
    O.reset()
    f = scene(BoxFactory(maxParticles=-1, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, vMin=1, vMax=1, vAngle=0,
                         massFlowRate=2e3, normal=(0, 0, 2)))
    O.step()
    assert all(b.state.vel == Vector3(0, 0, 1) for b in made(f))


def test_max_particles_stops_it():
    # reference (maxParticles 10): 10 spheres in the first step, then none; goalMass keeps growing (20, 40, ...),
    # massFlowRate is left unchanged
    f = scene(BoxFactory(maxParticles=10, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=2e4, **still()))
    for i in range(1, 5):
        O.step()
        assert f.numParticles == 10 and len(O.bodies) == 10
        assert f.goalMass == pytest.approx(20 * i) and f.massFlowRate == 2e4 and not f.dead


def test_max_mass_stops_it():
    # reference (maxMass 5, maxParticles -1, goal +2 per step): totalMass 2.26, 4.32, 5.16, 5.16: it stops once totalMass
    # reached maxMass (less than one sphere above it)
    f = scene(BoxFactory(maxMass=5, maxParticles=-1, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=2e3, **still()))
    mMax = 4 / 3 * math.pi * .04 ** 3 * 2000
    O.run(3, True)
    total = f.totalMass
    assert 5 <= total < 5 + mMax
    O.run(3, True)
    assert f.totalMass == total and f.goalMass == pytest.approx(12) and f.maxMass == 5


def test_max_mass_with_max_particles_is_dropped_with_a_warning():
    # reference: "Both maxMass and maxParticles cannot be > 0; Setting maxMass=-1" and the spheres go on past maxMass
    f = scene(BoxFactory(maxMass=5, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=2e3, **still()))
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter('always')
        O.run(4, True)
    assert any('maxMass' in str(x.message) for x in w)
    assert f.maxMass == -1 and f.totalMass > 7


def crowded(**kw):
    # 0.2 m box, spheres of radius .05: only a few fit (reference: 8 to 10)
    return scene(BoxFactory(maxParticles=-1, extents=(.1, .1, .1), center=(0, 0, 0), rMin=.05, rMax=.05, massFlowRate=2e4, maxAttempt=50,
                            **still(**kw)))


def run_warnings(n):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter('always')
        O.run(n, True)
    return [str(x.message) for x in w if 'Unable to place' in str(x.message)]


def test_stop_if_failed():
    # reference: "Unable to place new sphere after 50 attempts!", then massFlowRate = 0 and goalMass = totalMass
    f = crowded()
    msgs = run_warnings(3)
    assert len(msgs) == 1 and '50 attempts' in msgs[0]
    assert f.massFlowRate == 0 and f.goalMass == f.totalMass and 1 <= f.numParticles <= 27
    assert overlaps(made(f)) == 0


def test_go_on_if_not_stop_if_failed():
    # reference (stopIfFailed False): one warning per step, goalMass 20, 40, 60, massFlowRate unchanged
    f = crowded(stopIfFailed=False)
    msgs = run_warnings(3)
    assert len(msgs) == 3
    assert f.massFlowRate == 2e4 and f.goalMass == pytest.approx(60) and f.totalMass < 60


def test_silent():
    # reference: silent only drops the warning; stopIfFailed decides whether it stops
    f = crowded(silent=True)
    assert run_warnings(3) == [] and f.massFlowRate == 0 and f.goalMass == f.totalMass
    O.reset()
    f = crowded(silent=True, stopIfFailed=False)
    assert run_warnings(3) == [] and f.massFlowRate == 2e4 and f.goalMass == pytest.approx(60)


def psd_run(sizes, cum, calc, exact=True, steps=30):
    f = scene(BoxFactory(maxParticles=-1, extents=(2, 2, 2), center=(0, 0, 0), PSDsizes=sizes, PSDcum=cum, PSDcalculateMass=calc,
                         exactDiam=exact, massFlowRate=1e3, **still()))
    O.run(steps, True)
    return f, made(f)


def test_psd_by_number():
    # reference (sizes .02 .04 .06, cum .2 .5 1, by number): 45, 67, 112 of 224 spheres (0.201, 0.299, 0.5) and the
    # diameters 0.06 0.04 0.02 0.06 0.04 0.06 0.02 ... first: the class lagging most behind its share is made next
    f, bs = psd_run([.02, .04, .06], [.2, .5, 1.], False)
    ds = [round(2 * b.shape.radius, 9) for b in bs]
    assert ds[:7] == [.06, .04, .02, .06, .04, .06, .02]
    n = len(ds)
    for d, share in ((.02, .2), (.04, .3), (.06, .5)):
        assert ds.count(d) / n == pytest.approx(share, abs=1.5 / n)
    assert set(ds) == {.02, .04, .06}  # rMin/rMax are not used


def test_psd_by_mass():
    # reference (by mass): mass shares 0.198, 0.298, 0.503; first diameters 0.06 0.04 0.02 0.02 0.02
    f, bs = psd_run([.02, .04, .06], [.2, .5, 1.], True)
    ds = [round(2 * b.shape.radius, 9) for b in bs]
    assert ds[:5] == [.06, .04, .02, .02, .02]
    for d, share in ((.02, .2), (.04, .3), (.06, .5)):
        m = sum(b.state.mass for b in bs if round(2 * b.shape.radius, 9) == d)
        assert m / f.totalMass == pytest.approx(share, abs=.01)
    # reference, sizes .02 .04 and cum .5 1 by mass: 0 1 then eight small ones (the last at equal mass 8 : 8, a tie
    # decided by rounding), then 1, ...; here the first 11 and the mass shares
    O.reset()
    f, bs = psd_run([.02, .04], [.5, 1.], True, steps=2)
    assert ''.join('0' if b.shape.radius < .015 else '1' for b in bs[:11]) == '01000000001'
    m0 = sum(b.state.mass for b in bs if b.shape.radius < .015)
    assert m0 / f.totalMass == pytest.approx(.5, abs=.02)


def test_psd_ranges_when_not_exact():
    # reference (exactDiam False, sizes .01 .02 .04 .06, cum .2 .5 1 by number): number shares 0.202 0.298 0.5,
    # diameters within [.01, .06]
    f, bs = psd_run([.01, .02, .04, .06], [.2, .5, 1.], False, exact=False)
    ds = [2 * b.shape.radius for b in bs]
    assert min(ds) >= .01 and max(ds) <= .06
    n = len(ds)
    for lo, hi, share in ((.01, .02, .2), (.02, .04, .3), (.04, .06, .5)):
        assert sum(1 for d in ds if lo <= d < hi) / n == pytest.approx(share, abs=.03)


def test_mask_color_material_blocked_dofs():
    # reference: mask 6 -> 6, color used, materialId 0, blockedDOFs 'xYz' -> 'xzY'; materialId -2 counts from the end;
    # mask 0 (or -1) leaves the body's default mask 1
    O.materials.append(FrictMat(density=1000, label='m1'))
    f = scene(BoxFactory(maxParticles=5, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=2e4, mask=6,
                         color=(.1, .2, .3), materialId=0, blockedDOFs='xYz', **still()))
    O.step()
    for b in made(f):
        assert b.mask == 6 and b.shape.color == Vector3(.1, .2, .3) and b.material.label == 'm1' and b.state.blockedDOFs == 'xzY'
        assert b.state.mass == pytest.approx(1000 * 4 / 3 * math.pi * b.shape.radius ** 3)
    O.reset()
    O.materials.append(FrictMat(density=1000, label='m1'))
    f = scene(BoxFactory(maxParticles=5, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=2e4, mask=0, materialId=-2,
                         **still()))
    O.step()
    assert all(b.mask == 1 and b.material.label == 'm1' and b.state.blockedDOFs == '' for b in made(f))


def test_seed_repeats_the_spheres():
    def once(seed):
        O.reset()
        f = scene(BoxFactory(maxParticles=-1, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=200, vMin=1, vMax=2,
                             normal=(0, 0, 1), seed=seed))
        O.run(3, True)
        return [(tuple(b.state.pos), b.shape.radius, tuple(b.state.vel)) for b in made(f)]
    assert once(11) == once(11) and once(11) != once(12)


@pytest.mark.parametrize('factoryFirst', [False, True])
def test_spheres_fall_and_settle_in_a_box(factoryFirst):
    # the factory before the collider or after the interaction loop: the collider sees the new spheres either way
    O.materials.append(FrictMat(density=2600, young=1e7, frictionAngle=.5))
    O.bodies.append([wall(0, 2), wall(-.2, 0), wall(.2, 0), wall(-.2, 1), wall(.2, 1)])
    f = BoxFactory(maxParticles=150, extents=(.15, .15, .1), center=(0, 0, .4), rMin=.015, rMax=.02, massFlowRate=50, vMin=0, vMax=.1,
                   normal=(0, 0, -1), seed=5, label='factory')
    engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
               InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                               [Law2_ScGeom_FrictPhys_CundallStrack()]), NewtonIntegrator(gravity=(0, 0, -9.81), damping=.4)]
    O.engines = [f] + engines if factoryFirst else engines[:3] + [f] + engines[3:]
    O.dt = 2e-4
    O.run(6000, True)
    bs = made(f)
    assert len(bs) == 150 and f.numParticles == 150
    for b in bs:
        p = b.state.pos
        assert all(math.isfinite(x) for x in tuple(p) + tuple(b.state.vel))
        assert -.2 < p[0] < .2 and -.2 < p[1] < .2 and p[2] - b.shape.radius > -.002 and p[2] < .1  # settled on the floor
        assert b.state.vel.norm() < .25
    assert O.interactions.countReal() > 150  # the collider saw the new spheres


def test_bad_input_raises():
    base = dict(maxParticles=5, extents=(.5, .5, .5), center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=2e4, **still())
    cases = [('rMin', NAN, 'rMin'), ('rMax', NAN, 'rMax'), ('massFlowRate', NAN, 'massFlowRate'), ('extents', (NAN, 0, 0), 'extents'),
             ('center', (NAN, 0, 0), 'center'), ('rMin', .05, 'rMin'), ('vMin', NAN, 'vMin'), ('blockedDOFs', 'q', 'blockedDOFs'),
             ('materialId', 5, 'materialId'), ('materialId', -3, 'materialId')]
    for k, v, word in cases:
        O.reset()
        scene(BoxFactory(**dict(base, **{k: v})))
        with pytest.raises(ValueError, match=word):
            O.step()
        assert len(O.bodies) == 0
    # PSD tables (reference: RuntimeError with these messages)
    for sizes, cum, exact, word in [([.02, .04], [.5, .7, 1.], True, 'equal number'), ([.02, .04], [.5, 1.], False, '1 more'),
                                    ([.02, .04, .06], [.3, .2, 1.], True, 'PSDcum'), ([.02, .04, .06], [0., .5, 1.], True, 'PSDcum'),
                                    ([.02, .01, .06], [.2, .5, 1.], True, 'PSDsizes'), ([0., .02, .06], [.2, .5, 1.], True, 'PSDsizes')]:
        O.reset()
        scene(BoxFactory(**dict(base, PSDsizes=sizes, PSDcum=cum, exactDiam=exact)))
        with pytest.raises(ValueError, match=word):
            O.step()
    # no material at all (reference: "invalid material id -1")
    O.reset()
    O.engines = [BoxFactory(**base)]
    with pytest.raises(ValueError, match='materialId'):
        O.step()
    # the disc needs its normal; the base class has no region (reference: RuntimeError 'pickRandomPosition() called')
    O.reset()
    scene(CircularFactory(maxParticles=5, radius=1, center=(0, 0, 0), rMin=.02, rMax=.04, massFlowRate=200, vMin=0, vMax=0, normalVel=(0, 0, 1)))
    with pytest.raises(ValueError, match='normal'):
        O.step()
    O.reset()
    scene(SpheresFactory(maxParticles=5, rMin=.02, rMax=.04, massFlowRate=200, **still()))
    with pytest.raises(RuntimeError, match='pickRandomPosition'):
        O.step()
