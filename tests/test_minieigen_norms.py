"""Vector3/Vector2 norm, squaredNorm, normalized, normalize and dot give the reference's bits.

The reference's minieigen adds a 3-vector's terms as x + (y + z) (Vector3(1, .3, -.2).norm() is
1.0630145812734648 there, 1.063014581273465 with x + y + z); its numbers on 2000 random Vector3 and
500 Vector2 (tests/reference/minieigen_norms.py, same seeded draws in both engines) are stored in
tests/reference/data/minieigen_norms.json."""
import importlib.util
import json
import os

from yade import Vector3

HERE = os.path.dirname(os.path.abspath(__file__))


def test_the_example_of_the_report():
    assert Vector3(1, .3, -.2).norm() == 1.0630145812734648
    assert abs(Vector3(1, .3, -.2)) == 1.0630145812734648


def test_reductions_are_the_references_bit_for_bit():
    spec = importlib.util.spec_from_file_location('minieigen_norms', os.path.join(HERE, 'reference', 'minieigen_norms.py'))
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    with open(os.path.join(HERE, 'reference', 'data', 'minieigen_norms.json')) as f:
        ref = json.load(f)
    here = m.run()
    for key, n in (('v3', 2000), ('v2', 500)):
        assert len(ref[key]) == len(here[key]) == n
        bad = [i for i, (a, b) in enumerate(zip(here[key], ref[key])) if a != b]
        assert not bad, (key, len(bad), here[key][bad[0]], ref[key][bad[0]])


def test_a_zero_vector_stays_zero():
    v = Vector3(0, 0, 0)
    assert v.normalized() == Vector3(0, 0, 0) and v.norm() == 0
    v.normalize()
    assert v == Vector3(0, 0, 0)
