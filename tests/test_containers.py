"""O's containers and scene-wide settings: O.bodies, O.materials, utils.sphere, O.interactions,
O.forces, O.tags, O.periodic, O.dt, O.reset() and O.switchWorld()."""
import math

import pytest

from yade import *  # noqa: F401,F403
from yade import O, Aabb, Body, FrictMat, ElastMat, ForceResetter, Sphere, Vector3
from yade import utils
from yade.utils import sphere, wall


@pytest.fixture(autouse=True)
def fresh_scene():
    O.pause()
    O.reset()
    yield
    O.pause()


def vec(v):
    return tuple(float(x) for x in v)


# ------------------------------------------------------------------ O.bodies

def test_append_body_returns_its_id():
    assert O.bodies.append(Body()) == 0
    b = Body()
    assert O.bodies.append(b) == 1
    assert b.id == 1


def test_append_list_returns_list_of_ids():
    first = O.bodies.append(Body())
    ids = O.bodies.append([Body(), Body(), Body()])
    assert first == 0
    assert ids == [1, 2, 3]
    assert [b.id for b in O.bodies] == [0, 1, 2, 3]


def test_append_empty_list_returns_empty_list():
    assert O.bodies.append([]) == []
    assert len(O.bodies) == 0


def test_appended_body_is_the_same_object():
    b = sphere((0, 0, 0), 1)
    O.bodies.append(b)
    assert O.bodies[0] is b
    assert O.bodies[0] is O.bodies[0]


def test_appending_the_same_body_twice_raises_index_error_and_appends_nothing():
    b = Body()
    O.bodies.append(b)
    with pytest.raises(IndexError, match='second time'):
        O.bodies.append(b)
    assert len(O.bodies) == 1
    assert b.id == 0


def test_list_with_a_duplicate_appends_nothing():
    a, b = Body(), Body()
    with pytest.raises(IndexError):
        O.bodies.append([a, b, a])
    assert len(O.bodies) == 0
    assert a.id == -1 and b.id == -1


def test_list_with_an_already_appended_body_appends_nothing():
    old = Body()
    O.bodies.append(old)
    new = Body()
    with pytest.raises(IndexError):
        O.bodies.append([new, old])
    assert len(O.bodies) == 1
    assert new.id == -1


def test_append_rejects_non_bodies():
    with pytest.raises(TypeError):
        O.bodies.append(None)
    with pytest.raises(TypeError):
        O.bodies.append(Sphere())
    with pytest.raises(TypeError):
        O.bodies.append([Body(), 3])
    assert len(O.bodies) == 0


def test_negative_index_counts_from_the_end():
    O.bodies.append([Body(), Body(), Body()])
    assert O.bodies[-1].id == 2
    assert O.bodies[-3].id == 0


def test_index_past_the_end_raises_index_error():
    O.bodies.append([Body(), Body()])
    with pytest.raises(IndexError):
        O.bodies[2]
    with pytest.raises(IndexError):
        O.bodies[-3]
    with pytest.raises(IndexError):
        O.bodies[100]


def test_index_on_empty_container_raises_index_error():
    with pytest.raises(IndexError):
        O.bodies[0]
    with pytest.raises(IndexError):
        O.bodies[-1]


def test_len_counts_appended_bodies():
    assert len(O.bodies) == 0
    O.bodies.append([Body() for _ in range(5)])
    assert len(O.bodies) == 5


def test_iteration_gives_bodies_in_id_order():
    bodies = [Body() for _ in range(4)]
    O.bodies.append(bodies)
    assert [b.id for b in O.bodies] == [0, 1, 2, 3]
    assert all(x is y for x, y in zip(O.bodies, bodies))


def test_erase_leaves_a_hole():
    O.bodies.append([Body(), Body(), Body()])
    b1 = O.bodies[1]
    O.bodies.erase(1)
    assert O.bodies[1] is None
    assert len(O.bodies) == 3
    assert [b.id for b in O.bodies] == [0, 2]
    assert b1.id == -1


def test_ids_are_not_reused_after_erase():
    O.bodies.append([Body(), Body()])
    O.bodies.erase(1)
    assert O.bodies.append(Body()) == 2
    assert O.bodies[1] is None


def test_erased_body_can_be_appended_again():
    b = Body()
    O.bodies.append(b)
    O.bodies.erase(0)
    assert O.bodies.append(b) == 1
    assert O.bodies[1] is b


def test_erase_returns_true():
    O.bodies.append(Body())
    assert O.bodies.erase(0) is True


def test_erase_of_an_id_past_the_end_raises_index_error():
    O.bodies.append(Body())
    with pytest.raises(IndexError):
        O.bodies.erase(5)
    assert len(O.bodies) == 1 and O.bodies[0].id == 0


def test_erasing_an_erased_body_returns_false():
    O.bodies.append([Body(), Body()])
    O.bodies.erase(0)
    assert O.bodies.erase(0) is False
    assert O.bodies[0] is None and O.bodies[1].id == 1


def test_clear_removes_all_bodies():
    bodies = [Body(), Body()]
    O.bodies.append(bodies)
    O.bodies.clear()
    assert len(O.bodies) == 0
    assert list(O.bodies) == []
    with pytest.raises(IndexError):
        O.bodies[0]
    assert O.bodies.append(Body()) == 0


# ------------------------------------------------------------------ O.materials

def test_material_append_returns_id():
    assert O.materials.append(FrictMat()) == 0
    m = FrictMat()
    assert O.materials.append(m) == 1
    assert m.id == 1
    assert O.materials.append([FrictMat(), ElastMat()]) == [2, 3]


def test_material_lookup_by_label_and_by_id():
    steel = FrictMat(label='steel', density=7800)
    O.materials.append([FrictMat(label='sand'), steel])
    assert O.materials['steel'] is steel
    assert O.materials[1] is steel
    assert O.materials[-1] is steel
    assert O.materials['sand'].id == 0


def test_unknown_material_label_raises_key_error():
    O.materials.append(FrictMat(label='a'))
    with pytest.raises(KeyError):
        O.materials['nope']


def test_material_id_out_of_range_raises_index_error():
    O.materials.append(FrictMat())
    with pytest.raises(IndexError):
        O.materials[1]


def test_materials_len_and_iteration():
    mats = [FrictMat(label='a'), FrictMat(label='b'), ElastMat(label='c')]
    assert len(O.materials) == 0
    O.materials.append(mats)
    assert len(O.materials) == 3
    assert [m.label for m in O.materials] == ['a', 'b', 'c']
    assert all(x is y for x, y in zip(O.materials, mats))


def test_material_shared_by_two_bodies_is_the_same_object():
    m = FrictMat(label='m')
    O.materials.append(m)
    b1 = sphere((0, 0, 0), 1, material='m')
    b2 = sphere((3, 0, 0), 1, material='m')
    O.bodies.append([b1, b2])
    assert O.bodies[0].material is O.bodies[1].material
    assert O.bodies[0].material is m
    m.density = 2000
    assert b2.material.density == 2000


# ------------------------------------------------------------------ utils.sphere

def test_sphere_without_materials_appends_and_uses_the_default_material():
    assert len(O.materials) == 0
    b = sphere((0, 0, 0), 1)
    assert len(O.materials) == 1
    m = O.materials[0]
    assert b.material is m
    assert isinstance(m, FrictMat)
    assert m.density == 1e3 and m.young == 1e7 and m.poisson == .3 and m.frictionAngle == .5


def test_second_sphere_reuses_the_default_material():
    b1 = sphere((0, 0, 0), 1)
    b2 = sphere((0, 0, 0), 1)
    assert len(O.materials) == 1
    assert b1.material is b2.material


def test_sphere_uses_the_last_defined_material():
    O.materials.append([FrictMat(label='a'), FrictMat(label='b')])
    assert sphere((0, 0, 0), 1).material.label == 'b'
    assert len(O.materials) == 2


def test_sphere_material_by_id_label_or_object():
    a, b = FrictMat(label='a'), FrictMat(label='b')
    O.materials.append([a, b])
    assert sphere((0, 0, 0), 1, material=0).material is a
    assert sphere((0, 0, 0), 1, material='a').material is a
    c = FrictMat(label='c', density=5)
    assert sphere((0, 0, 0), 1, material=c).material is c
    assert len(O.materials) == 2


def test_sphere_with_unknown_material_label_raises_key_error():
    with pytest.raises(KeyError):
        sphere((0, 0, 0), 1, material='nothing')


def test_sphere_with_material_id_out_of_range_raises_index_error():
    O.materials.append(FrictMat())
    with pytest.raises(IndexError):
        sphere((0, 0, 0), 1, material=5)


@pytest.mark.parametrize('r, rho', [(1, 1000), (.01, 2600), (3.5, 7800)])
def test_sphere_mass_and_inertia(r, rho):
    O.materials.append(FrictMat(density=rho))
    b = sphere((0, 0, 0), r)
    m = 4. / 3. * math.pi * r ** 3 * rho
    assert b.state.mass == pytest.approx(m, rel=1e-12)
    for i in range(3):
        assert b.state.inertia[i] == pytest.approx(2. / 5. * m * r * r, rel=1e-12)


def test_sphere_geometry_and_state():
    b = sphere((1, 2, 3), .5)
    assert isinstance(b.shape, Sphere) and b.shape.radius == .5
    assert vec(b.state.pos) == (1, 2, 3)
    assert vec(b.state.refPos) == (1, 2, 3)
    assert b.dynamic is True
    assert b.mask == 1
    assert b.id == -1


def test_sphere_options():
    b = sphere((0, 0, 0), 1, wire=True, color=(1, 0, 0), highlight=True, mask=6)
    assert b.shape.wire is True and b.shape.highlight is True
    assert vec(b.shape.color) == (1, 0, 0)
    assert b.mask == 6


def test_fixed_sphere_is_not_dynamic():
    assert sphere((0, 0, 0), 1, fixed=True).dynamic is False
    assert sphere((0, 0, 0), 1, dynamic=False).dynamic is False
    assert sphere((0, 0, 0), 1, fixed=False).dynamic is True


@pytest.mark.parametrize('radius', [0, -1, float('nan'), float('inf')])
def test_sphere_with_bad_radius_raises_value_error_at_once(radius):
    with pytest.raises(ValueError):
        sphere((0, 0, 0), radius)


@pytest.mark.parametrize('center', [(float('nan'), 0, 0), (0, 0, float('inf'))])
def test_sphere_with_non_finite_center_raises_value_error(center):
    with pytest.raises(ValueError):
        sphere(center, 1)


def test_sphere_accepts_vector3_center_and_integer_radius():
    b = sphere(Vector3(1, 2, 3), 2)
    assert vec(b.state.pos) == (1, 2, 3) and b.shape.radius == 2.0


def test_default_material_helper():
    m = utils.defaultMaterial()
    assert isinstance(m, FrictMat)
    assert (m.density, m.young, m.poisson, m.frictionAngle) == (1e3, 1e7, .3, .5)
    assert m.id == -1


# ------------------------------------------------------------------ O.interactions

def test_interactions_are_empty_at_start():
    O.bodies.append([sphere((0, 0, 0), 1), sphere((1, 0, 0), 1)])
    assert len(O.interactions) == 0
    assert O.interactions.countReal() == 0
    assert O.interactions.has(0, 1) is False
    assert list(O.interactions) == []


def test_missing_interaction_raises_index_error():
    O.bodies.append([Body(), Body()])
    with pytest.raises(IndexError):
        O.interactions[0, 1]


# ------------------------------------------------------------------ O.forces

def test_force_is_zero_at_start():
    O.bodies.append(sphere((0, 0, 0), 1))
    assert vec(O.forces.f(0)) == (0, 0, 0)
    assert vec(O.forces.t(0)) == (0, 0, 0)


def test_add_force_before_any_step():
    O.bodies.append([sphere((0, 0, 0), 1), sphere((3, 0, 0), 1)])
    O.forces.addF(1, (1, 2, 3))
    assert vec(O.forces.f(1)) == (1, 2, 3)
    assert vec(O.forces.f(0)) == (0, 0, 0)
    O.forces.addF(1, Vector3(1, 0, 0))
    assert vec(O.forces.f(1)) == (2, 2, 3)


def test_add_torque():
    O.bodies.append(sphere((0, 0, 0), 1))
    O.forces.addT(0, (4, 5, 6))
    assert vec(O.forces.t(0)) == (4, 5, 6)
    assert vec(O.forces.f(0)) == (0, 0, 0)


def test_force_of_a_missing_body_raises_index_error():
    with pytest.raises(IndexError):
        O.forces.f(999)
    O.bodies.append(Body())
    with pytest.raises(IndexError):
        O.forces.f(1)
    with pytest.raises(IndexError):
        O.forces.addF(999, (1, 0, 0))
    with pytest.raises(IndexError):
        O.forces.t(-1)


def test_add_non_finite_force_raises_value_error():
    O.bodies.append(Body())
    with pytest.raises(ValueError):
        O.forces.addF(0, (float('nan'), 0, 0))
    assert vec(O.forces.f(0)) == (0, 0, 0)


def test_force_resetter_zeroes_forces():
    O.bodies.append(sphere((0, 0, 0), 1))
    O.forces.addF(0, (1, 2, 3))
    O.forces.addT(0, (1, 1, 1))
    O.engines = [ForceResetter()]
    O.step()
    assert vec(O.forces.f(0)) == (0, 0, 0)
    assert vec(O.forces.t(0)) == (0, 0, 0)


@pytest.mark.parametrize("threads", [1, 2])
def test_forces_added_after_a_read_are_added_to_what_was_read(threads):
    # with several threads a read adds the remote contributions (here: from Python to body 2999,
    # in the second thread's range) to the totals; what is added afterwards must still add up,
    # permanent forces included
    setNumThreads(threads)
    O.bodies.append([sphere((0, 0, 0), 1) for i in range(3000)])
    O.forces.addF(2999, (0, 4, 0))
    O.forces.addF(2999, (0, 0.25, 0))
    assert vec(O.forces.f(2999)) == (0, 4.25, 0)
    O.forces.addT(2999, (0, 1, 0))
    O.forces.addF(2999, (1, 0, 0), permanent=True)
    assert vec(O.forces.f(2999)) == (1, 4.25, 0) and vec(O.forces.t(2999)) == (0, 1, 0)
    O.forces.addF(7, (1, 2, 3))
    O.forces.addT(7, (0, 0, 1))
    assert vec(O.forces.f(7)) == (1, 2, 3)
    O.forces.addF(7, (0.5, 0, 0))
    O.forces.addT(7, (0, 0, 2))
    assert vec(O.forces.f(7)) == (1.5, 2, 3)
    assert vec(O.forces.t(7)) == (0, 0, 3)
    O.forces.addF(7, (0, 0, 10), permanent=True)
    assert vec(O.forces.f(7)) == (1.5, 2, 13)
    assert vec(O.forces.f(8)) == (0, 0, 0)
    setNumThreads(3 - threads)  # the totals survive a change of the thread count
    assert vec(O.forces.f(7)) == (1.5, 2, 13)
    assert vec(O.forces.t(7)) == (0, 0, 3)
    O.engines = [ForceResetter()]
    O.step()  # the per-step forces go, the permanent one stays
    assert vec(O.forces.f(7)) == (0, 0, 10)
    assert vec(O.forces.t(7)) == (0, 0, 0)
    O.forces.addF(7, (1, 0, 0))
    O.step()
    assert vec(O.forces.f(7)) == (0, 0, 10)
    assert vec(O.forces.f(2999)) == (1, 0, 0) and vec(O.forces.t(2999)) == (0, 0, 0)


def settlingPile():
    """300 spheres falling on a wall: contact forces only in O.forces (gravity is the integrator's)."""
    from yade import pack
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (.16, .16, .25), rMean=.01, rRelFuzz=.2, num=300, seed=3)
    sp.toSimulation()
    O.bodies.append(wall((0, 0, 0), axis=2))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4)]
    O.dt = .5 * PWaveTimeStep()


@pytest.mark.parametrize("threads", [1, 2])
def test_each_contact_force_is_added_once_to_both_bodies(threads):
    # with two threads about half the contacts join bodies of both threads' ranges: one of the two
    # forces is a remote contribution. Each body's force must be the sum of its contacts' forces,
    # and they must cancel over the whole pile and the wall (action and reaction).
    setNumThreads(threads)
    settlingPile()
    O.run(1500, True)
    checked = 0
    for step in range(40):
        O.run(25, True)
        expected = [Vector3(0, 0, 0) for b in O.bodies]
        for i in O.interactions:
            f = i.phys.normalForce + i.phys.shearForce
            expected[i.id1] -= f  # (Law2: the force on body 2, its opposite on body 1)
            expected[i.id2] += f
        scale = max(sum(abs(x) for x in vec(e)) for e in expected)
        if scale == 0:
            continue
        for b in O.bodies:
            assert vec(O.forces.f(b.id)) == pytest.approx(vec(expected[b.id]), abs=1e-12 * scale)
        total = sum((O.forces.f(b.id) for b in O.bodies), Vector3(0, 0, 0))
        assert max(abs(x) for x in vec(total)) < 1e-12 * scale * len(O.bodies)
        checked += 1
    assert checked > 20 and O.interactions.countReal() > 30


def test_two_threads_repeat_a_run_to_the_last_bit():
    setNumThreads(2)
    runs = []
    for attempt in range(2):
        O.reset()
        settlingPile()
        O.run(2000, True)
        assert O.interactions.countReal() > 30
        runs.append([tuple(b.state.pos) + tuple(b.state.vel) + tuple(b.state.angVel) for b in O.bodies])
    assert runs[0] == runs[1]


@pytest.mark.parametrize("threads", [1, 2])
def test_forces_of_a_step_are_readable_after_it(threads):
    # two touching spheres pressed together, with gravity: after each step O.forces holds the
    # contact force of that step (read after the integrator has used it)
    setNumThreads(threads)
    O.bodies.append([sphere((0, 0, 0), 1, fixed=True), sphere((0, 0, 1.9), 1)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-6
    for i in range(3):
        O.step()
        i = O.interactions[0, 1]
        fn = i.phys.normalForce
        assert vec(O.forces.f(1)) == pytest.approx((0, 0, abs(fn[2])), abs=1e-9 * abs(fn[2]))  # pushed up
        assert vec(O.forces.f(0)) == pytest.approx((0, 0, -abs(fn[2])), abs=1e-9 * abs(fn[2]))
        assert abs(fn[2]) > 1e3


# ------------------------------------------------------------------ O.tags, O.periodic, O.dt

def test_tags_id_and_d_id_exist_and_are_strings():
    assert isinstance(O.tags['id'], str) and O.tags['id']
    assert isinstance(O.tags['d.id'], str) and O.tags['d.id']
    assert isinstance(O.tags['description'], str)


def test_setting_a_tag():
    O.tags['description'] = 'my test'
    assert O.tags['description'] == 'my test'
    O.tags['foo'] = 'bar'
    assert O.tags['foo'] == 'bar'
    assert 'foo' in O.tags


def test_unknown_tag_raises_key_error():
    with pytest.raises(KeyError):
        O.tags['nonexistent-tag']


def test_scene_is_not_periodic():
    assert O.periodic is False


def test_default_time_step():
    assert O.dt == 1e-8
    assert O.iter == 0 and O.time == 0


def test_setting_dt():
    O.dt = 1e-5
    assert O.dt == 1e-5


# (a negative O.dt activates the time stepper: tests/test_stability.py)
@pytest.mark.parametrize('bad', [float('nan'), float('inf')])  # (0 is accepted: test_stability.py)
def test_bad_dt_raises_value_error_and_leaves_dt_unchanged(bad):
    O.dt = 2e-6
    with pytest.raises(ValueError):
        O.dt = bad
    assert O.dt == 2e-6


# ------------------------------------------------------------------ O.reset, O.switchWorld

def test_reset_empties_the_scene():
    O.materials.append(FrictMat())
    O.bodies.append([sphere((0, 0, 0), 1), sphere((3, 0, 0), 1)])
    O.engines = [ForceResetter()]
    O.dt = 1e-3
    O.step()
    O.step()
    assert O.iter == 2
    O.reset()
    assert len(O.bodies) == 0
    assert len(O.materials) == 0
    assert list(O.engines) == []
    assert O.iter == 0
    assert O.time == 0
    assert O.dt == 1e-8


def test_reset_forgets_tags_set_by_the_user():
    O.tags['foo'] = 'bar'
    O.reset()
    assert 'foo' not in O.tags
    assert isinstance(O.tags['id'], str)


def test_switch_world_gives_an_empty_second_scene_and_back_the_first():
    O.bodies.append([Body(), Body()])
    O.materials.append(FrictMat(label='first'))
    O.engines = [ForceResetter()]
    O.step()
    O.step()
    O.switchWorld()
    try:
        assert len(O.bodies) == 0
        assert len(O.materials) == 0
        assert O.iter == 0
        O.bodies.append(Body())
        O.step()
    finally:
        O.switchWorld()
    assert len(O.bodies) == 2
    assert O.iter == 2
    assert O.materials[0].label == 'first'
    O.switchWorld()
    try:
        assert len(O.bodies) == 1 and O.iter == 1
        O.reset()  # leave the second world empty for other tests
    finally:
        O.switchWorld()
    assert len(O.bodies) == 2


def test_interaction_lookup_with_ids_out_of_range():
    assert O.interactions.has(-5, 999) is False
    with pytest.raises(IndexError):
        O.interactions[5, -1]
    assert O.interactions.withBody(99) == []


def test_a_body_kept_from_before_reset_cannot_be_appended_again():
    b = Body()
    O.bodies.append(b)
    O.reset()
    assert b.id == 0  # as in Yade: the id stays
    with pytest.raises(IndexError):
        O.bodies.append(b)
    assert len(O.bodies) == 0


def test_permanent_forces_api_as_the_reference():
    # The reference on this script: addF(permanent=True) is deprecated and sets (a second call replaces the
    # first: (2,0,0)); setPermF/setPermT replace; reset() (resetAll=True) drops the permanent ones too.
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 0.5), sphere((3, 0, 0), 0.5)])
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-3
    with pytest.warns(RuntimeWarning, match='setPermF'):
        O.forces.addF(0, (1, 0, 0), permanent=True)
        O.forces.addF(0, (2, 0, 0), permanent=True)
    with pytest.warns(RuntimeWarning, match='setPermT'):
        O.forces.addT(0, (0, 1, 0), permanent=True)
    O.step()
    assert tuple(O.forces.f(0)) == (2, 0, 0) and tuple(O.forces.permF(0)) == (2, 0, 0)
    assert tuple(O.forces.t(0)) == (0, 1, 0) and tuple(O.forces.permT(0)) == (0, 1, 0)
    O.forces.setPermF(0, (5, 0, 0))
    O.forces.setPermT(1, (0, 0, 7))
    O.step()
    assert tuple(O.forces.f(0)) == (5, 0, 0) and tuple(O.forces.t(1)) == (0, 0, 7) and tuple(O.forces.m(0)) == (0, 1, 0)
    assert O.forces.getPermForceUsed()
    O.forces.setPermF(1, (0, 1, 0))  # between steps, after the totals got the permanent ones: the total follows
    assert tuple(O.forces.f(1)) == (0, 1, 0)
    O.forces.reset(resetAll=False)
    assert tuple(O.forces.f(0)) == (5, 0, 0) and tuple(O.forces.permF(0)) == (5, 0, 0)
    O.forces.reset()
    assert tuple(O.forces.f(0)) == (0, 0, 0) and tuple(O.forces.permF(0)) == (0, 0, 0) and not O.forces.getPermForceUsed()
    O.step()
    assert tuple(O.forces.f(0)) == (0, 0, 0) and tuple(O.forces.t(1)) == (0, 0, 0)
    O.forces.addF(1, (0, 3, 0))
    assert tuple(O.forces.f(1)) == (0, 3, 0)
    with pytest.raises(ValueError):
        O.forces.setPermF(0, (float('nan'), 0, 0))
    with pytest.raises(IndexError):
        O.forces.setPermT(7, (0, 0, 1))
    assert isinstance(O.forces.syncCount, int)
