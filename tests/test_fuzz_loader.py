"""Fuzzing of O.load (scripts/fuzz/fuzz_loader.py, doc/fuzzing.md): a fixed seed and a fixed number of
mutated saved scenes, each refused with FileFormatError leaving the scene byte for byte as it was, or
loaded as a valid scene; no crash, no hang. The counts are printed (pytest -s) and recorded.

Below: one regression test for each bug the harness found.
"""
import json
import math
import os
import pathlib
import struct
import subprocess
import sys

import pytest

import yade
from yade import O

REPO = pathlib.Path(__file__).resolve().parent.parent
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")
SCRIPT = REPO / 'scripts' / 'fuzz' / 'fuzz_loader.py'
CASES = 1200
SEED = 7


def run_harness(script, cases, seed, tmp_path):
    """Runs a fuzz harness in worker processes; returns (summary dict, printed report)."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(BUILD)] + os.environ.get('PYTHONPATH', '').split(os.pathsep)))
    out = tmp_path / 'summary.json'
    r = subprocess.run([sys.executable, str(script), '--cases', str(cases), '--seed', str(seed), '--chunk', str(cases),
                        '--json', str(out)], env=env, capture_output=True, text=True, timeout=900)
    print(r.stdout, r.stderr[-3000:])
    assert out.exists(), r.stderr[-3000:]
    return json.loads(out.read_text()), r.stdout


def test_fuzzed_files_are_refused_cleanly_or_load_a_valid_scene(tmp_path, record_property):
    summary, report = run_harness(SCRIPT, CASES, SEED, tmp_path)
    counts = summary['counts']
    record_property('fuzz_loader_cases', sum(counts.values()))
    record_property('fuzz_loader_counts', json.dumps(counts))
    assert sum(counts.values()) == CASES, report
    assert summary['failures'] == [], report
    # the harness reaches both sides: refusals and scenes that load and run
    refused = sum(n for k, n in counts.items() if k.startswith('refused'))
    loaded = sum(n for k, n in counts.items() if k.startswith('loaded'))
    assert refused > CASES // 4 and loaded > CASES // 20, report


# ====================================================================== regressions

@pytest.fixture
def saved(fresh_scene):
    """A small saved scene (binary bytes) with a sphere on a wall."""
    from yade.utils import sphere, wall
    O.bodies.append([wall((0, 0, 0), axis=2), sphere((0, 0, .1), .1)])
    return O.sceneToString()


sys.path.insert(0, str(REPO / 'scripts' / 'fuzz'))
import mutate  # noqa: E402


def edited(data, cls, attr, text):
    """A saved scene with the value of attribute attr of the first object of class cls replaced by the
    numbers or the string of `text`, in the file's own encoding (a column of the block format, or the
    text of the tree)."""
    if data.startswith(mutate.BLOCKS_MAGIC):
        kind = mutate.editColumn(data, cls, attr, b'')[1]  # (to learn the kind)
        if kind == 'String':
            raw = mutate._bytes(text)
            value = bytes([len(raw)]) + raw
        else:
            value = struct.pack('<%dd' % len(text.split()), *map(float, text.split()))
        return mutate.editColumn(data, cls, attr, value)[0]
    root, encoding = mutate.decode(data)
    for n, _ in root.walk():
        if n.tag == 'obj' and n.attrs.get('class') == cls:
            for a in n.children:
                if a.attrs.get('name') == attr:
                    a.text = text
                    return mutate.encode(root, encoding)
    raise LookupError('%s.%s not in the file' % (cls, attr))


def refused(data, match):
    before = O.sceneToString()
    with pytest.raises(yade.FileFormatError, match=match):
        O.stringToScene(data)
    assert O.sceneToString() == before


@pytest.mark.parametrize('cls, attr, text, match', [
    ('State', 'pos', '0 inf 0', 'State.pos must be finite, found inf'),          # found by case 3875
    ('State', 'vel', 'nan 0 0', 'State.vel must be finite'),
    ('State', 'angVel', '0 0 1e309', 'State.angVel must be finite'),              # found by case 2787
    ('State', 'ori', '-nan 0 0 1', 'State.ori must be a finite non-zero quaternion'),  # found by case 2113
    ('State', 'ori', '0 0 0 0', 'State.ori must be a finite non-zero quaternion'),
    ('State', 'mass', '-1', 'State.mass must be non-negative'),
    ('Sphere', 'radius', '-0.5', 'Sphere.radius must be positive'),
    ('FrictMat', 'density', '-1', 'FrictMat.density must be non-negative'),
])
def test_a_value_the_python_setter_refuses_is_refused_in_a_file(saved, cls, attr, text, match):
    """Bug: the reader stored any number, so a file could load a non-finite position, orientation or
    velocity (or a negative radius, mass or density) that Python refuses to set. Fix (core/SceneIO.cpp):
    the reader applies the attributes' positive / nonNegative / finite flags and checks quaternions."""
    for data in (saved, O._toBytes(True)):
        refused(edited(data, cls, attr, text), match)


def test_a_constructor_default_that_breaks_a_flag_still_round_trips(fresh_scene):
    """The flags do not refuse a value the constructor itself gave (Sphere().radius is NaN)."""
    O.bodies.append(yade.Body(shape=yade.Sphere(), state=yade.State(mass=1)))
    O.stringToScene(O.sceneToString())
    assert math.isnan(O.bodies[0].shape.radius)


@pytest.mark.parametrize('cls, attr, text', [
    ('Interaction', 'cellDist', '1e308 0 0'),
    ('Interaction', 'cellDist', 'nan 0 0'),
    ('ForceEngine', 'ids', '0 4294967296'),
    ('Body', 'mask', '4294967297'),
])
def test_an_integer_out_of_the_range_of_an_int_is_refused(fresh_scene, cls, attr, text):
    """Bug: components of int vectors and lists were cast from any double to int (undefined behaviour
    for NaN or 1e308) and int attributes wrapped around. Fix (core/SceneIO.cpp): refused as corrupt."""
    from yade.utils import sphere
    O.bodies.append([sphere((0, 0, 0), .1), sphere((.19, 0, 0), .1)])
    O.engines = [yade.ForceResetter(), yade.InsertionSortCollider([yade.Bo1_Sphere_Aabb()]),
                 yade.InteractionLoop([yade.Ig2_Sphere_Sphere_ScGeom()], [yade.Ip2_FrictMat_FrictMat_FrictPhys()],
                                      [yade.Law2_ScGeom_FrictPhys_CundallStrack()]),
                 yade.ForceEngine(ids=[0], force=(0, 0, 1)), yade.NewtonIntegrator()]
    O.dt = 1e-5
    O.step()
    # (in the text of XML files and of binary files of format version 1; a column of the block
    # format holds 32-bit integers and cannot say more)
    xml = O._toBytes(True)
    binaryTree = mutate.encode(mutate.decode(xml)[0], 'binary')
    for data in (xml, binaryTree):
        refused(edited(data, cls, attr, text), 'expected a 32-bit integer')


@pytest.mark.parametrize('cls, attr', [('FrictMat', 'label'), ('PyRunner', 'command')])
@pytest.mark.parametrize('junk', ['\udcff\udcfe', 'a\udce9b', '\udced\udca0\udc80'])  # (bytes ff fe; e9 alone; a surrogate)
def test_a_string_that_is_not_utf8_is_refused(fresh_scene, cls, attr, junk):
    """Bug (case 3593 of seed 11): a label with bytes that are not UTF-8 loaded, then the labels were bound
    in Python: UnicodeDecodeError, with the scene already replaced. Fix (core/SceneIO.cpp): strings,
    tags and energy term names must be valid UTF-8, else FileFormatError."""
    from yade.utils import sphere
    O.materials.append(yade.FrictMat(label='mat'))
    O.bodies.append(sphere((0, 0, 0), .1))
    O.engines = [yade.PyRunner(command='pass', iterPeriod=100)]
    for data in (O.sceneToString(), O._toBytes(True)):
        refused(edited(data, cls, attr, junk), 'not valid UTF-8')


def test_utf8_strings_round_trip(fresh_scene):
    O.materials.append(yade.FrictMat(label='ünïcödé ✓ 𝄞'))
    O.tags['clé ✓'] = 'valeur 𝄞'
    O.stringToScene(O.sceneToString())
    assert O.materials[0].label == 'ünïcödé ✓ 𝄞' and O.tags['clé ✓'] == 'valeur 𝄞'
