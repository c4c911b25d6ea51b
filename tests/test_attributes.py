"""Attributes of the Python classes: keyword constructors, defaults, type and value checks,
dict(), docstrings, read-only attributes, views, pointer attributes and dispatch helpers."""
import gc
import math
import re

import pytest

from yade import *  # noqa: F401,F403
from yade import (O, Aabb, Body, Bo1_Sphere_Aabb, Bound, BoundDispatcher, BoundFunctor, ElastMat, Engine,
                  ForceResetter, FrictMat, Functor, GlobalEngine, Interaction, Material, PeriodicEngine,
                  Quaternion, Serializable, Shape, Sphere, State, Vector3)
from yade.utils import sphere


@pytest.fixture(autouse=True)
def fresh_scene():
    O.pause()
    O.reset()
    yield
    O.pause()


def vec(v):
    return tuple(float(x) for x in v)


# ------------------------------------------------------------------ keyword constructors

def test_keyword_constructor_sets_the_attribute():
    assert Sphere(radius=3).radius == 3
    assert isinstance(Sphere(radius=3).radius, float)


def test_keyword_constructor_sets_several_attributes_including_inherited_ones():
    m = FrictMat(young=1e9, label='steel', density=7800, frictionAngle=.3)
    assert m.young == 1e9
    assert m.label == 'steel'
    assert m.density == 7800
    assert m.frictionAngle == .3


def test_keyword_constructor_accepts_vectors_as_tuples_and_objects_for_pointers():
    s = Sphere(radius=1, color=(0, 1, 0), wire=True)
    assert vec(s.color) == (0, 1, 0)
    assert s.wire is True
    m = FrictMat()
    b = Body(shape=s, material=m, mask=5)
    assert b.shape is s and b.material is m and b.mask == 5


def test_keyword_constructor_accepts_python_side_properties():
    assert State(blockedDOFs='xz').blockedDOFs == 'xz'


def test_dispatcher_accepts_functors_as_keyword_too():
    bd = BoundDispatcher(functors=[Bo1_Sphere_Aabb()])
    assert len(bd.functors) == 1 and isinstance(bd.functors[0], Bo1_Sphere_Aabb)


def test_unknown_keyword_raises_attribute_error_naming_it():
    with pytest.raises(AttributeError, match='nonexistentAttr'):
        Sphere(nonexistentAttr=1)
    with pytest.raises(AttributeError, match='rad'):
        Sphere(rad=1)


def test_hidden_attribute_is_not_accepted_as_keyword():
    with pytest.raises(AttributeError, match='blockedDOFsMask'):
        State(blockedDOFsMask=3)


def test_positional_arguments_to_an_ordinary_class_raise_type_error():
    with pytest.raises(TypeError):
        Sphere(1)
    with pytest.raises(TypeError):
        ForceResetter(1)


# ------------------------------------------------------------------ defaults

def test_frictmat_defaults():
    m = FrictMat()
    assert m.density == 1000
    assert m.young == 1e9
    assert m.poisson == .25
    assert m.frictionAngle == .5
    assert m.label == ''
    assert m.id == -1


def test_sphere_radius_defaults_to_nan():
    assert math.isnan(Sphere().radius)


def test_shape_defaults():
    s = Sphere()
    assert vec(s.color) == (1, 1, 1)
    assert s.wire is False and s.highlight is False


def test_state_defaults_to_zero_position_and_identity_orientation():
    st = State()
    assert vec(st.pos) == (0, 0, 0)
    assert st.ori == Quaternion((1, 0, 0), 0)
    assert vec(st.ori) == (0, 0, 0, 1)  # (x, y, z, w)
    assert vec(st.vel) == (0, 0, 0) and vec(st.angVel) == (0, 0, 0)
    assert st.mass == 0 and vec(st.inertia) == (0, 0, 0)
    assert vec(st.refPos) == (0, 0, 0)
    assert st.blockedDOFs == ''
    assert st.isDamped is True


def test_body_defaults():
    b = Body()
    assert b.id == -1 and b.mask == 1 and b.dynamic is True
    assert b.shape is None and b.material is None and b.bound is None
    assert isinstance(b.state, State)


def test_bound_defaults_to_nan_box():
    a = Aabb()
    assert all(math.isnan(x) for x in a.min) and all(math.isnan(x) for x in a.max)


def test_engine_defaults():
    e = ForceResetter()
    assert e.dead is False and e.label == '' and e.ompThreads == -1
    assert BoundDispatcher().functors == []
    assert Bo1_Sphere_Aabb().aabbEnlargeFactor < 0


def test_periodic_engine_defaults():
    pe = PeriodicEngine()
    assert pe.iterPeriod == 0 and pe.nDo == -1 and pe.initRun is False
    assert pe.virtPeriod == 0 and pe.realPeriod == 0 and pe.nDone == 0 and pe.firstIterRun == 0


# ------------------------------------------------------------------ unknown attributes, types and values

def test_setting_an_unknown_attribute_raises_attribute_error():
    s = Sphere()
    with pytest.raises(AttributeError, match='foo'):
        s.foo = 1
    assert not hasattr(s, 'foo')


def test_wrong_type_raises_type_error_naming_class_and_attribute():
    with pytest.raises(TypeError, match=r'Sphere\.radius'):
        Sphere(radius='a')
    s = Sphere(radius=2)
    with pytest.raises(TypeError, match=r'Sphere\.radius'):
        s.radius = 'a'
    assert s.radius == 2


@pytest.mark.parametrize('obj, name, value', [
    (FrictMat(), 'label', 3),
    (Body(), 'mask', 1.5),
    (Sphere(), 'wire', 'yes'),
    (Sphere(), 'radius', True),
    (State(), 'pos', 'abc'),
    (State(), 'pos', (1, 2)),
])
def test_other_wrong_types_raise_type_error(obj, name, value):
    with pytest.raises(TypeError, match=re.escape(type(obj).__name__ + '.' + name)):
        setattr(obj, name, value)


@pytest.mark.parametrize('bad', [-1, 0, float('nan'), float('inf'), -float('inf')])
def test_sphere_radius_must_be_positive_and_finite(bad):
    with pytest.raises(ValueError, match=r'Sphere\.radius'):
        Sphere(radius=bad)
    s = Sphere(radius=1)
    with pytest.raises(ValueError):
        s.radius = bad
    assert s.radius == 1


def test_density_must_be_non_negative():
    """0 is accepted, as in the reference: its scripts give walls (fixed boxes) a material of density 0
    (triax-tutorial, triax-basic, the thermal and PFV examples)."""
    assert FrictMat(density=0).density == 0
    with pytest.raises(ValueError, match='density'):
        FrictMat(density=-5)
    m = FrictMat()
    for bad in (-1, float('nan'), float('inf')):
        with pytest.raises(ValueError):
            m.density = bad
    assert m.density == 1000


def test_walls_of_density_zero_run_and_a_free_massless_body_is_named():
    O.reset()
    walls = O.materials.append(FrictMat(density=0, young=1e7, frictionAngle=0))
    grains = O.materials.append(FrictMat(density=2600, young=1e7))
    O.bodies.append(utils.box((0, 0, -0.1), (1, 1, 0.1), fixed=True, material=walls))
    O.bodies.append(utils.sphere((0, 0, 0.099), 0.1, material=grains))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -10), damping=0.4)]
    O.dt = 1e-4
    O.run(8000, True)
    assert O.bodies[0].state.mass == 0 and O.interactions.countReal() == 1
    m = O.bodies[1].state.mass
    assert O.interactions[0, 1].phys.normalForce.norm() == pytest.approx(10 * m, rel=1e-2)  # resting on the wall
    # a free body of density 0: the step is refused, naming the mass (the reference goes on with NaN)
    O.bodies.append(utils.sphere((5, 5, 5), 0.1, material=walls))
    with pytest.raises(StabilityError, match=r'body #2.*its mass is 0 \(a material of density 0\?\)'):
        O.step()
    O.reset()


def test_other_value_checks():
    with pytest.raises(ValueError):
        FrictMat(young=0)
    with pytest.raises(ValueError):
        FrictMat(poisson=float('nan'))
    with pytest.raises(ValueError):
        FrictMat(frictionAngle=-.1)
    with pytest.raises(ValueError):
        State(mass=-1)
    with pytest.raises(ValueError, match=r'State\.pos'):
        State(pos=(float('nan'), 0, 0))
    with pytest.raises(ValueError):
        State(ori=Quaternion(0, 0, 0, 0))


def test_integer_accepted_for_float_attribute():
    m = FrictMat(young=5)
    assert m.young == 5.0 and isinstance(m.young, float)


def test_integer_out_of_range_raises_overflow_or_value_error():
    b = Body()
    with pytest.raises((OverflowError, ValueError)):
        b.mask = 2 ** 40


# ------------------------------------------------------------------ dict(), inheritance, docs, repr

def test_dict_contains_all_visible_attributes_with_their_values():
    d = FrictMat(young=2e9, label='x').dict()
    assert d == {'id': -1, 'label': 'x', 'density': 1000.0, 'young': 2e9, 'poisson': .25, 'frictionAngle': .5}


def test_sphere_dict_has_shape_and_sphere_attributes():
    d = Sphere(radius=2).dict()
    assert set(d) == {'color', 'wire', 'highlight', 'radius'}
    assert d['radius'] == 2


def test_dict_omits_hidden_attributes():
    sd = State().dict()
    assert 'blockedDOFsMask' not in sd
    assert {'pos', 'ori', 'vel', 'angVel', 'mass', 'inertia', 'refPos', 'refOri'} <= set(sd)
    assert 'refPos' not in Aabb().dict()
    assert {'min', 'max', 'color'} <= set(Aabb().dict())
    assert 'iterLastSeen' not in Interaction().dict()


def test_hidden_attribute_is_not_a_python_attribute():
    assert not hasattr(State(), 'blockedDOFsMask')
    assert not hasattr(Aabb(), 'refPos')


def test_update_attrs_sets_from_a_dict():
    s = Sphere()
    s.updateAttrs({'radius': 2, 'wire': True})
    assert s.radius == 2 and s.wire is True
    st = State()
    st.updateAttrs({'blockedDOFs': 'xy', 'mass': 3})
    assert st.blockedDOFs == 'xy' and st.mass == 3


def test_update_attrs_with_unknown_name_raises_attribute_error():
    with pytest.raises(AttributeError, match='foo'):
        Sphere().updateAttrs({'foo': 2})


def test_dict_round_trips_through_constructor():
    m = FrictMat(young=3e8, poisson=.2, label='q')
    d = m.dict()
    del d['id']  # read-only
    m2 = FrictMat(**d)
    assert m2.dict() == m.dict()


def test_inherited_attributes():
    m = FrictMat()
    assert hasattr(m, 'density') and hasattr(m, 'young') and hasattr(m, 'label')
    assert issubclass(FrictMat, ElastMat) and issubclass(ElastMat, Material) and issubclass(Material, Serializable)
    assert issubclass(Sphere, Shape) and issubclass(Aabb, Bound)
    assert issubclass(ForceResetter, GlobalEngine) and issubclass(GlobalEngine, Engine)
    assert issubclass(Bo1_Sphere_Aabb, BoundFunctor) and issubclass(BoundFunctor, Functor)
    assert isinstance(FrictMat(), Material)


def test_properties_have_docstrings():
    for cls, name in [(Sphere, 'radius'), (FrictMat, 'density'), (FrictMat, 'young'), (State, 'pos'),
                      (Body, 'shape'), (Engine, 'dead'), (State, 'blockedDOFs'), (Body, 'mat')]:
        doc = getattr(cls, name).__doc__
        assert isinstance(doc, str) and doc.strip(), (cls, name)


def test_repr_gives_class_name_and_address():
    assert re.fullmatch(r'<Sphere instance at 0x[0-9a-f]+>', repr(Sphere()))
    assert re.fullmatch(r'<FrictMat instance at 0x[0-9a-f]+>', repr(FrictMat()))


def test_repr_differs_for_different_objects_and_is_stable_for_one():
    a, b = Sphere(), Sphere()
    assert repr(a) != repr(b)
    assert repr(a) == repr(a)


# ------------------------------------------------------------------ read-only attributes

def test_body_id_is_read_only():
    b = Body()
    with pytest.raises(AttributeError):
        b.id = 3
    assert b.id == -1


def test_material_id_is_read_only():
    m = FrictMat()
    with pytest.raises(AttributeError):
        m.id = 3
    assert m.id == -1


def test_other_read_only_attributes():
    with pytest.raises(AttributeError):
        Body().clumpId = 2
    with pytest.raises(AttributeError):
        Aabb().min = (1, 2, 3)
    with pytest.raises(AttributeError):
        Interaction().id1 = 3
    with pytest.raises(AttributeError):
        Sphere().dispIndex = 3


# ------------------------------------------------------------------ views write through

def test_vector_item_assignment_writes_through():
    b = Body()
    b.state.vel[2] = 3
    assert vec(b.state.vel) == (0, 0, 3)


def test_in_place_multiplication_negates_the_stored_vector():
    b = Body()
    b.state.vel = (1, -2, 3)
    b.state.vel *= -1
    assert vec(b.state.vel) == (-1, 2, -3)


def test_in_place_addition_changes_the_stored_vector():
    st = State()
    st.pos += Vector3(1, 2, 3)
    st.pos += Vector3(1, 2, 3)
    assert vec(st.pos) == (2, 4, 6)


def test_tuple_accepted_for_vector_attribute():
    b = Body()
    b.state.pos = (1, 2, 3)
    assert vec(b.state.pos) == (1, 2, 3)
    b.state.pos = [4, 5, 6]
    assert vec(b.state.pos) == (4, 5, 6)


def test_a_view_sees_later_assignments():
    st = State()
    v = st.vel
    st.vel = (7, 8, 9)
    assert vec(v) == (7, 8, 9)


def test_pos_and_ori_are_read_as_copies_as_in_the_reference():
    # The reference's State.pos and State.ori are properties (copies) while vel, angVel... are views:
    # `p0 = b.state.pos` then keeps the position of that moment (a script's displacement `pos - p0`).
    O.reset()
    O.bodies.append(sphere((0, 0, 0), 1))
    b = O.bodies[0]
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -10))]
    O.dt = 1e-3
    p0, q0, v = b.state.pos, b.state.ori, b.state.vel
    b.state.angVel = (0, 0, 1)
    O.run(100, True)
    assert vec(p0) == (0, 0, 0)
    assert vec(b.state.pos - p0) == pytest.approx((0, 0, -0.0404), rel=1e-12)  # (the reference: -0.040400000000000026)
    assert b.state.ori != q0
    assert vec(v) == pytest.approx((0, 0, -0.8), rel=1e-12)  # a view follows its body (damping 0.2: as the reference)
    q = b.state.pos
    q[0] = 5  # changes the copy only, as there
    assert b.state.pos[0] == 0
    pos, ori = b.state.se3
    assert vec(pos) == vec(b.state.pos) and ori == b.state.ori
    b.state.se3 = ((1, 2, 3), Quaternion((0, 0, 1), 0.5))
    assert vec(b.state.pos) == (1, 2, 3) and b.state.ori.toAxisAngle()[1] == pytest.approx(0.5)
    with pytest.raises(Exception):
        b.state.se3 = ((4, 5, 6), "not a quaternion")
    assert vec(b.state.pos) == (1, 2, 3)  # left as it was
    with pytest.raises(TypeError):
        b.state.se3 = (1, 2, 3)


def test_a_view_keeps_its_owner_alive():
    st = State(vel=(1, 2, 3))
    v = st.vel
    del st
    gc.collect()
    v[0] = 4
    assert vec(v) == (4, 2, 3)


def test_quaternion_attribute_is_normalized():
    st = State()
    st.ori = Quaternion(2, 0, 0, 0)
    assert st.ori.norm() == pytest.approx(1, abs=1e-15)


# ------------------------------------------------------------------ pointer attributes, identity

def test_shape_accepts_a_shape():
    b = Body()
    b.shape = Sphere(radius=1)
    assert isinstance(b.shape, Sphere) and b.shape.radius == 1


def test_shape_rejects_a_material():
    b = Body()
    with pytest.raises(TypeError, match=r'Body\.shape'):
        b.shape = FrictMat()
    assert b.shape is None
    with pytest.raises(TypeError, match=r'Body\.material'):
        b.material = Sphere()
    with pytest.raises(TypeError):
        b.shape = 3


def test_shape_accepts_none():
    b = Body(shape=Sphere(radius=1))
    b.shape = None
    assert b.shape is None


def test_pointer_attribute_returns_the_same_object():
    s = Sphere(radius=1)
    b = Body(shape=s)
    assert b.shape is s
    assert b.shape is b.shape
    assert b.state is b.state


def test_pointer_attribute_shares_the_object():
    b = Body(shape=Sphere(radius=1))
    sh = b.shape
    sh.radius = 5
    assert b.shape.radius == 5


def test_mat_is_an_alias_of_material():
    m = FrictMat(label='a')
    b = Body(material=m)
    assert b.mat is m
    m2 = FrictMat(label='b')
    b.mat = m2
    assert b.material is m2


def test_equality_is_identity():
    a = Sphere(radius=1)
    assert a == a
    assert a != Sphere(radius=1)
    assert len({a, a}) == 1


# ------------------------------------------------------------------ State helpers

@pytest.mark.parametrize('dofs', ['xyzXYZ', '', 'xZ', 'x', 'XYZ', 'yz'])
def test_blocked_dofs_round_trip(dofs):
    st = State()
    st.blockedDOFs = dofs
    assert st.blockedDOFs == dofs


def test_blocked_dofs_are_given_back_in_canonical_order():
    st = State()
    st.blockedDOFs = 'Zx'
    assert st.blockedDOFs == 'xZ'
    st.blockedDOFs = 'xx'
    assert st.blockedDOFs == 'x'


def test_blocked_dofs_bad_letter_raises_value_error_and_changes_nothing():
    st = State(blockedDOFs='y')
    with pytest.raises(ValueError):
        st.blockedDOFs = 'xq'
    with pytest.raises(ValueError):
        st.blockedDOFs = 'a'
    assert st.blockedDOFs == 'y'


def test_displ_is_position_minus_reference_position():
    st = State()
    st.pos = (1, 2, 3)
    assert vec(st.displ()) == (1, 2, 3)
    st.refPos = (1, 1, 1)
    assert vec(st.displ()) == (0, 1, 2)


def test_displ_of_a_moved_sphere_body():
    b = sphere((1, 2, 3), .5)
    assert vec(b.state.displ()) == (0, 0, 0)
    b.state.pos = (1.5, 2, 2)
    assert b.state.displ()[0] == pytest.approx(.5) and b.state.displ()[2] == pytest.approx(-1)


def test_rot_is_rotation_from_reference_orientation_as_axis_times_angle():
    st = State()
    assert vec(st.rot()) == (0, 0, 0)
    st.ori = Quaternion((0, 0, 1), .5)
    r = st.rot()
    assert r[0] == pytest.approx(0, abs=1e-15) and r[1] == pytest.approx(0, abs=1e-15)
    assert r[2] == pytest.approx(.5, rel=1e-14)


def test_rot_takes_the_shortest_way():
    st = State()
    st.ori = Quaternion((0, 0, 1), 4)
    assert st.rot()[2] == pytest.approx(4 - 2 * math.pi, rel=1e-12)


def test_rot_is_measured_from_ref_ori():
    st = State()
    st.refOri = Quaternion((1, 0, 0), .3)
    st.ori = Quaternion((1, 0, 0), .5)
    assert st.rot()[0] == pytest.approx(.2, rel=1e-12)


# ------------------------------------------------------------------ dispatchers

def test_bound_dispatcher_takes_a_list_of_functors():
    bd = BoundDispatcher([Bo1_Sphere_Aabb()])
    assert len(bd.functors) == 1
    assert isinstance(bd.functors[0], Bo1_Sphere_Aabb)


def test_bound_dispatcher_rejects_a_material_as_functor():
    with pytest.raises(TypeError):
        BoundDispatcher([FrictMat()])
    with pytest.raises(TypeError):
        BoundDispatcher([None])
    with pytest.raises(TypeError):
        BoundDispatcher(Bo1_Sphere_Aabb())  # not a list
    bd = BoundDispatcher()
    with pytest.raises(TypeError):
        bd.functors = [ForceResetter()]


def test_bound_dispatcher_rejects_more_than_one_positional_list():
    with pytest.raises((TypeError, ValueError)):
        BoundDispatcher([Bo1_Sphere_Aabb()], [Bo1_Sphere_Aabb()])


def test_disp_index_of_sphere_differs_from_shape_and_is_per_class():
    assert Sphere().dispIndex != Shape().dispIndex
    assert Sphere().dispIndex == Sphere(radius=2).dispIndex
    assert isinstance(Sphere().dispIndex, int)
    assert FrictMat().dispIndex == FrictMat().dispIndex != ElastMat().dispIndex


def test_disp_functor_gives_the_functor_for_a_sphere():
    f = Bo1_Sphere_Aabb()
    bd = BoundDispatcher([f])
    assert bd.dispFunctor(Sphere()) is f
    assert isinstance(BoundDispatcher([Bo1_Sphere_Aabb()]).dispFunctor(Sphere(radius=1)), Bo1_Sphere_Aabb)


def test_disp_functor_is_none_for_a_shape_without_functor():
    bd = BoundDispatcher([Bo1_Sphere_Aabb()])
    assert bd.dispFunctor(Shape()) is None
    assert BoundDispatcher().dispFunctor(Sphere()) is None


def test_disp_functor_follows_a_change_of_functors():
    bd = BoundDispatcher([Bo1_Sphere_Aabb()])
    assert bd.dispFunctor(Sphere()) is not None
    bd.functors = []
    assert bd.dispFunctor(Sphere()) is None
    f = Bo1_Sphere_Aabb()
    bd.functors = [f]
    assert bd.dispFunctor(Sphere()) is f


def test_disp_matrix_as_in_reference():
    """The dictionaries the reference prints for the same dispatchers (its test-sphere-facet.py example
    prints them); names=False gives this engine's class indices, which are not the reference's."""
    from yade import (IGeomDispatcher, IPhysDispatcher, LawDispatcher, Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom,
                      Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack)
    gd = IGeomDispatcher([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()])
    assert gd.dispMatrix() == {('Sphere', 'Sphere'): 'Ig2_Sphere_Sphere_ScGeom', ('Sphere', 'Facet'): 'Ig2_Facet_Sphere_ScGeom',
                               ('Facet', 'Sphere'): 'Ig2_Facet_Sphere_ScGeom'}
    assert IPhysDispatcher([Ip2_FrictMat_FrictMat_FrictPhys()]).dispMatrix() == {('FrictMat', 'FrictMat'): 'Ip2_FrictMat_FrictMat_FrictPhys'}
    assert LawDispatcher([Law2_ScGeom_FrictPhys_CundallStrack()]).dispMatrix() == \
        {('ScGeom', 'FrictPhys'): 'Law2_ScGeom_FrictPhys_CundallStrack'}
    assert BoundDispatcher([Bo1_Sphere_Aabb()]).dispMatrix() == {('Sphere',): 'Bo1_Sphere_Aabb'}
    indices = gd.dispMatrix(False)
    s, f = Sphere().dispIndex, Facet().dispIndex
    assert indices == {(s, s): 'Ig2_Sphere_Sphere_ScGeom', (s, f): 'Ig2_Facet_Sphere_ScGeom', (f, s): 'Ig2_Facet_Sphere_ScGeom'}
    assert IGeomDispatcher().dispMatrix() == {}


# ------------------------------------------------------------------ identity through containers

def test_body_in_container_is_the_appended_object():
    b = Body(shape=Sphere(radius=1))
    O.bodies.append(b)
    assert O.bodies[0] is b
    assert O.bodies[0].shape is b.shape


def test_labels_are_attributes_of_engines_and_functors():
    f = Bo1_Sphere_Aabb(label='bo')
    assert f.label == 'bo'
    assert BoundDispatcher([f], label='bd').label == 'bd'
