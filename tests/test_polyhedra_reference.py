"""The polyhedra family against the reference's numbers (Yade 2023.02a): the scenes are tests/reference/polyhedra.py, a plain
Yade script; tests/reference/data/polyhedra.json is what the reference printed running it. Where the reference's rules differ
(its contact normal, its facets), the test says how, and doc/polyhedra.md gives the figures."""
import importlib.util
import json
import math
import os

import pytest

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location('polyhedra_scenes', os.path.join(HERE, 'reference', 'polyhedra.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)
with open(os.path.join(HERE, 'reference', 'data', 'polyhedra.json')) as _f:
    REFERENCE = json.load(_f)


def close(a, b, rel, abs_=0.0):
    a, b = (a if isinstance(a, list) else [a]), (b if isinstance(b, list) else [b])
    return len(a) == len(b) and all(math.isclose(x, y, rel_tol=rel, abs_tol=abs_) for x, y in zip(a, b))


def test_shapes_equal_the_reference():
    here, ref = scenes.shapes(), REFERENCE['shapes']
    for name in ref:
        for key in ('volume', 'inertia', 'centroid', 'nv', 'nf'):
            assert close(here[name][key], ref[name][key], 1e-13, 1e-15), (name, key, here[name][key], ref[name][key])


@pytest.mark.parametrize("name, args", [('x', ((0.9, 0, 0), (0, 0, 1), 0)), ('xy', ((0.9, 0.8, 0), (0, 0, 1), 0)),
                                        ('rot45', ((1.1, 0, 0), (0, 0, 1), math.pi / 4))])
def test_cube_pairs_volume_and_force_magnitude_equal_the_reference(name, args):
    """volume, centroid, cross-section, stiffnesses and |normal force| = kn·V are the reference's; the normal direction is
    not (the reference's depends on how its intersection is triangulated: (0.994, -0.075, -0.075) for an overlap along x;
    here the area vector of body 1's faces in the overlap, (1, 0, 0) there)"""
    from yade import Vector3
    here, ref = scenes.cube_pair(Vector3(args[0]), Vector3(args[1]), args[2]), REFERENCE['pairs'][name]
    rel = 1e-13 if name != 'rot45' else 1e-8  # (the reference's volume of the turned cube is 7e-9 off the analytic one)
    for key in ('volume', 'crossSection', 'depth', 'kn', 'ks', 'tan'):
        assert close(here[key], ref[key], rel), (key, here[key], ref[key])
    assert close(here['contactPoint'], ref['contactPoint'], rel, 1e-8)
    norm = lambda v: math.sqrt(sum(x * x for x in v))  # noqa: E731
    assert close(norm(here['normalForce']), norm(ref['normalForce']), rel)
    assert close(norm(here['force1']), norm(ref['force1']), rel)
    # the normals are 6.1° apart (overlap along x), 1.7° (corner), 3e-9 rad (turned cube)
    cos = sum(a * b for a, b in zip(here['normal'], ref['normal']))
    assert cos > math.cos(math.radians(6.1))


def test_cube_on_a_wall_rests_where_the_reference_rests():
    here, ref = scenes.cube_on('wall'), REFERENCE['wall']
    assert close(here['pos'], ref['pos'], 1e-12, 1e-16)
    assert close(here['vel'], ref['vel'], 0, 1e-12)
    for key in ('mass', 'inertia', 'kn', 'ks', 'normal'):
        assert close(here[key], ref[key], 1e-13, 1e-16), key
    assert close(here['volume'], ref['volume'], 1e-9)
    assert close(here['normalForce'], ref['normalForce'], 1e-9, 1e-12)
    assert close(here['force'], ref['force'], 1e-9, 1e-12)


def test_cube_on_facets_rests_at_the_reference_height():
    """the same height and overlap volume; the reference's facet contact also has a tilted normal (4e-4 rad) that makes the
    cube creep sideways (0.5 mm/s after 0.6 s, a lateral force of 8 N on a weight of 19.6 N); here the normal is the facets'
    and the cube is still"""
    here, ref = scenes.cube_on('facets'), REFERENCE['facets']
    assert close(here['pos'][2], ref['pos'][2], 1e-8)
    assert close(here['volume'], ref['volume'], 2e-5)
    assert close(here['normalForce'][2], ref['normalForce'][2], 1e-5)
    assert abs(here['pos'][0]) < 1e-12 and abs(here['pos'][1]) < 1e-12 and max(abs(x) for x in here['vel']) < 1e-9


@pytest.mark.parametrize("name, center, kw", [('face', (0.7, 0, 0), {}), ('edge', (0.6, 0.55, 0), {}), ('vertex', (0.62, 0.6, 0.58), {}),
                                              ('small', (0.58, 0, 0), {'r': 0.1}),
                                              ('stiffer', (0.7, 0, 0), {'young': (2e8, 6e7), 'poisson': (0.5, 0.2)})])
def test_sphere_on_a_cube_equals_the_reference(name, center, kw):
    """Ig2_Sphere_Polyhedra_ScGeom and Ip2_FrictMat_PolyhedraMat_FrictPhys: the same bits as the reference (the sphere is body 1;
    the reference's kn, ks take 1e9 Pa for the polyhedron's young, whatever PolyhedraMat.young is: 'stiffer' doubles it)"""
    from yade import Vector3
    here, ref = scenes.sphere_cube(Vector3(center), **kw), REFERENCE['sphere'][name]
    assert here == ref
