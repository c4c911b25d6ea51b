"""yade.bodiesHandling against the reference: every figure below is what the reference printed for the
same calls on the same bodies (the functions are used by its packs, lubrication and performance examples)."""
import math

import pytest

from yade import O, FrictMat, Quaternion, Vector3, bodiesHandling as bh
from yade.utils import facet, sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py


def vec(v):
    return [float(v[i]) for i in range(3)]


def scene():
    O.bodies.append([sphere((0, 0, 0), 1), sphere((3, 1, 0), 0.5), sphere((1, -2, 4), 0.25, mask=2)])
    O.bodies.append(facet([(0, 0, 0), (1, 0, 0), (0, 1, 1)]))
    O.bodies.append(facet([(5, 0, 0), (6, 0, 0), (5, 1, -1)], mask=2))


def test_spheres_pack_dimensions_as_in_reference():
    scene()
    d = bh.spheresPackDimensions([0, 1, 2])
    assert vec(d['min']) == [-1, -2.25, -1] and vec(d['max']) == [3.5, 1.5, 4.25]
    assert vec(d['minId']) == [0, 2, 0] and vec(d['maxId']) == [1, 1, 2]
    assert vec(d['center']) == [1.25, -0.375, 1.625] and vec(d['extends']) == [4.5, 3.75, 5.25]
    assert d['volume'] == pytest.approx(4.777838827334477, rel=1e-14) and d['mass'] == pytest.approx(4777.838827334477, rel=1e-14)
    assert d['number'] == 3
    d = bh.spheresPackDimensions([O.bodies[0], O.bodies[1]])  # bodies instead of ids
    assert vec(d['center']) == [1.25, 0.25, 0] and vec(d['extends']) == [4.5, 2.5, 2] and d['number'] == 2
    assert d['mass'] == pytest.approx(4712.38898038469, rel=1e-14)
    for d in (bh.spheresPackDimensions([], mask=2), bh.spheresPackDimensions([0, 1, 2], mask=2)):
        assert vec(d['min']) == [0.75, -2.25, 3.75] and vec(d['minId']) == [2, 2, 2] and d['number'] == 1
        assert d['volume'] == pytest.approx(0.06544984694978735, rel=1e-14)
    d = bh.spheresPackDimensions([3])  # a facet: left out
    assert d['number'] == 0 and vec(d['extends']) == [0, 0, 0] and d['mass'] == 0
    with pytest.raises(ValueError, match='mask'):  # (the reference raises RuntimeWarning)
        bh.spheresPackDimensions([])


def test_facets_dimensions_as_in_reference():
    scene()
    d = bh.facetsDimensions([3, 4])
    assert vec(d['min']) == [0, 0, -1] and vec(d['max']) == [6, 1, 1]
    assert vec(d['minId']) == [3, 3, 4] and vec(d['maxId']) == [4, 3, 3]
    assert vec(d['center']) == [3, 0.5, 0] and vec(d['extends']) == [6, 1, 2] and d['number'] == 2
    d = bh.facetsDimensions([], mask=2)  # (the reference fails here on the sphere of mask 2)
    assert vec(d['min']) == [5, 0, -1] and vec(d['max']) == [6, 1, 0] and d['number'] == 1


def test_sphere_duplicate_as_in_reference():
    m = O.materials.append(FrictMat(density=2000, label='mm'))
    O.bodies.append([sphere((0, 0, 0), 1, material=m, color=(1, 0, 0)), sphere((3, 1, 0), 0.5, material=m)])
    s = O.bodies[0].state
    s.vel, s.angVel, s.ori = (1, 2, 3), (0, 0, 1), Quaternion((1, 0, 0), 0.3)
    b = bh.sphereDuplicate(0)
    assert b.id == -1 and len(O.bodies) == 2  # not inserted
    assert vec(b.state.pos) == [0, 0, 0] and vec(b.state.vel) == [0, 0, 0] and vec(b.state.angVel) == [0, 0, 0]
    assert b.shape.radius == 1 and vec(b.shape.color) == [1, 0, 0] and b.material.label == 'mm' and b.dynamic
    assert vec(b.state.inertia) == pytest.approx([3351.032163829112505] * 3, rel=1e-14)
    O.bodies[1].state.blockedDOFs = 'xyz'
    assert bh.sphereDuplicate(1).dynamic and bh.sphereDuplicate(1).state.blockedDOFs == ''
    with pytest.raises(IndexError):
        bh.sphereDuplicate(5)


def test_spheres_modify_as_in_reference():
    scene()
    turn = Quaternion((0, 0, 1), math.pi / 2)
    assert bh.spheresModify([0, 1], shift=(1, 0, 0), scale=2.0, orientation=turn, copy=False) is True
    # turned and scaled about the center (1.25, 0.25, 0) of their box, then shifted
    assert vec(O.bodies[0].state.pos) == pytest.approx([2.75, -2.25, 0], abs=1e-15)
    assert vec(O.bodies[1].state.pos) == pytest.approx([0.75, 3.75, 0], abs=1e-15)
    assert (O.bodies[0].shape.radius, O.bodies[1].shape.radius) == (2.0, 1.0)
    assert O.bodies[0].state.mass == pytest.approx(33510.32163829113, rel=1e-14)
    assert O.bodies[1].state.mass == pytest.approx(4188.790204786391, rel=1e-14)
    copies = bh.spheresModify([0], shift=(0, 0, 1), copy=True)
    assert len(copies) == 1 and copies[0].id == -1 and len(O.bodies) == 5
    assert vec(copies[0].state.pos) == pytest.approx([2.75, -2.25, 1], abs=1e-15) and copies[0].shape.radius == 2.0
    assert vec(O.bodies[0].state.pos) == pytest.approx([2.75, -2.25, 0], abs=1e-15)  # the original stays


def test_spheres_modify_keeps_velocity_and_orientation_and_scales_inertia():
    m = O.materials.append(FrictMat(density=2000))
    O.bodies.append([sphere((0, 0, 0), 1, material=m), sphere((3, 1, 0), 0.5, material=m)])
    s = O.bodies[0].state
    s.vel, s.angVel, s.ori = (1, 2, 3), (0, 0, 1), Quaternion((1, 0, 0), 0.3)
    bh.spheresModify([0, 1], scale=2.0, orientation=Quaternion((0, 0, 1), math.pi / 2))
    assert vec(s.inertia) == pytest.approx([107233.0292425316002] * 3, rel=1e-14)  # the reference's: scale⁵
    assert vec(s.vel) == [1, 2, 3] and vec(s.angVel) == [0, 0, 1] and s.ori.toAxisAngle()[1] == pytest.approx(0.3)
    copies = bh.spheresModify([], mask=1, shift=(1, 1, 1), copy=True)
    assert vec(copies[0].state.pos) == pytest.approx([2.75, -1.25, 1], abs=1e-15)
    assert vec(copies[1].state.pos) == pytest.approx([0.75, 4.75, 1], abs=1e-15)
    with pytest.raises(ValueError, match='scale'):
        bh.spheresModify([0], scale=0)


def test_runtime_opts_from_python():
    import yade.runtime
    assert yade.runtime.opts.nogui is True and yade.runtime.opts.stdperformance is None and yade.runtime.hasDisplay is False
