"""Checkpoints in the block format (doc/file-format.md, "Binary encoding: blocks"): exact resume for
every contact law, every compression, the contacts restored into their pools, the checks that only
the content can fail (a damaged file whose checksums were made right), and bounded memory."""
import gzip
import os
import random
import struct
import subprocess
import sys
import textwrap
import zlib

import pytest

import yade
from yade import O
from test_persistence import BINARY_MAGIC, blocks, reblocked, refused, signature

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DENSE = os.path.join(ROOT, 'scripts', 'bench', 'dense.py')  # (the benchmark's dense lattice)

LAWS = {  # (physics maker, law, material) of each contact law with a pool of its own
    'frict': ('Ip2_FrictMat_FrictMat_FrictPhys()', 'Law2_ScGeom_FrictPhys_CundallStrack()',
              "FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600)"),
    'mindlin': ('Ip2_FrictMat_FrictMat_MindlinPhys()', 'Law2_ScGeom_MindlinPhys_Mindlin()',
                "FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600)"),
    'viscel': ('Ip2_ViscElMat_ViscElMat_ViscElPhys()', 'Law2_ScGeom_ViscElPhys_Basic()',
               "ViscElMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, en=.5, et=.5, tc=1e-3)"),
}


def lattice(law='frict', n=4, threads=1):
    """n³ spheres on a compressed lattice in a facet box, under gravity: every contact live, with
    shear history, sphere-sphere and facet-sphere pools."""
    ns = {}
    exec('from yade import *\nfrom yade import geom, utils', ns)
    ip2, law2, mat = LAWS[law]
    yade.setNumThreads(threads)
    O.materials.append(eval(mat, ns))
    r, a = .01, .02 * .995
    half = ((n - 1) * a + 2 * r - .01 * r) / 2
    O.bodies.append(ns['geom'].facetBox(((n - 1) * a / 2,) * 3, (half,) * 3, wallMask=63))
    rnd = random.Random(5)
    for k in range(n):
        for j in range(n):
            for i in range(n):
                O.bodies.append(ns['utils'].sphere((i * a + rnd.uniform(-1e-4, 1e-4), j * a, k * a), r))
    O.engines = [ns['ForceResetter'](),
                 ns['InsertionSortCollider']([ns['Bo1_Sphere_Aabb'](), ns['Bo1_Facet_Aabb']()]),
                 ns['InteractionLoop']([ns['Ig2_Sphere_Sphere_ScGeom'](), ns['Ig2_Facet_Sphere_ScGeom']()],
                                       [eval(ip2, ns)], [eval(law2, ns)]),
                 ns['NewtonIntegrator'](gravity=(0, 0, -9.81), damping=.2)]
    O.dt = .3 * ns['utils'].PWaveTimeStep()


def state():
    """Every body's position, velocity and angular velocity and every contact's forces, as bits."""
    out = []
    for b in O.bodies:
        out.append(struct.pack('<9d', *b.state.pos, *b.state.vel, *b.state.angVel))
    for i in O.interactions:
        if i.isReal:
            out.append(struct.pack('<2i6d', i.id1, i.id2, *i.phys.normalForce, *i.phys.shearForce))
    return out


@pytest.mark.parametrize('law', sorted(LAWS))
@pytest.mark.parametrize('name', ['s.yade', 's.yade.gz', 's.yade.bz2', 's.yade.zst', 'tmp'])
def test_a_loaded_checkpoint_continues_bit_for_bit(tmp_path, law, name):
    if name.endswith('.zst') and 'zstd' not in O._codecs:
        pytest.skip('built without zstd')
    lattice(law)
    O.run(30, True)
    contacts = O.interactions.countReal()
    assert contacts > 100
    if name == 'tmp':
        O.saveTmp('chk')
    else:
        O.save(str(tmp_path / name))
    O.run(40, True)
    expected, iters = state(), O.iter
    O.reset()
    if name == 'tmp':
        O.loadTmp('chk')
    else:
        O.load(str(tmp_path / name))
    assert O.iter == 30 and O.interactions.countReal() == contacts
    O.run(40, True)
    assert O.iter == iters
    assert state() == expected


@pytest.mark.parametrize('name', ['s.yade', 's.xml', 'tmp'])
def test_two_threads_continue_as_two_threads_did(tmp_path, name):
    """The interaction loop splits the pairs between threads by their work when the pairs change; a
    loaded scene is split as the saved one was (InteractionLoop.threadSplit), not from the contacts
    it holds, so that the sums of the two threads' forces round the same way. (Before 7 Dec the
    loaded scene was split anew and drifted from the original in the last bits.)"""
    lattice('frict', n=5, threads=2)
    O.run(20, True)
    if name == 'tmp':
        O.saveTmp('two')
    else:
        O.save(str(tmp_path / name))
    O.run(30, True)
    expected = state()
    if name == 'tmp':
        O.loadTmp('two')
    else:
        O.load(str(tmp_path / name))
    O.run(30, True)
    assert state() == expected


def test_contacts_are_restored_into_their_pools_in_their_order(tmp_path):
    lattice('frict')
    O.run(10, True)
    before = O.interactions.arrays()
    ids = [(int(a), int(b)) for a, b in zip(before['id1'], before['id2'])]
    forces = before['normalForce'].copy()
    O.save(str(tmp_path / 's.yade'))
    O.load(str(tmp_path / 's.yade'))
    after = O.interactions.arrays()  # one pool per kind: views of the records, in their slot order
    assert [(int(a), int(b)) for a, b in zip(after['id1'], after['id2'])] == ids
    assert (after['normalForce'] == forces).all()
    # the pairs keep their entries: potential pairs included
    O.run(1, True)


def test_the_same_scene_gives_the_same_bytes_and_compression_changes_nothing_inside(tmp_path):
    lattice('mindlin')
    O.run(5, True)
    for name in ['a.yade', 'b.yade', 'c.yade.gz', 'd.yade.bz2']:
        O.save(str(tmp_path / name))
    raw = (tmp_path / 'a.yade').read_bytes()
    assert raw.startswith(BINARY_MAGIC)
    assert (tmp_path / 'b.yade').read_bytes() == raw
    assert gzip.decompress((tmp_path / 'c.yade.gz').read_bytes()) == raw
    import bz2
    assert bz2.decompress((tmp_path / 'd.yade.bz2').read_bytes()) == raw
    if 'zstd' in O._codecs:
        O.save(str(tmp_path / 'e.yade.zst'))
        assert (tmp_path / 'e.yade.zst').read_bytes()[:4] == b'\x28\xb5\x2f\xfd'
    # and the memory slot holds the same bytes
    O.saveTmp('x')
    assert O.sceneToString() == raw


def test_blocks_are_the_documented_ones(tmp_path):
    lattice('frict')
    O.run(3, True)
    O.forces.setPermF(10, (1, 2, 3))
    O.save(str(tmp_path / 's.yade'))
    kinds = [k for k, _ in blocks((tmp_path / 's.yade').read_bytes())]
    assert kinds[0] == b'HEAD' and kinds[-1] == b'END '
    assert {b'TABL', b'ROWS', b'LIST', b'PAIR', b'POOL', b'CONT', b'PERM'} <= set(kinds)
    # two pools: sphere-sphere and facet-sphere contacts share ScGeom + FrictPhys, so one
    assert kinds.count(b'POOL') == 1
    tables = [p for k, p in blocks((tmp_path / 's.yade').read_bytes()) if k == b'TABL']
    names = [t[2:2 + t[1]].decode() for t in tables]  # (size table < 128, then the class name)
    for cls in ['FrictMat', 'Body', 'State', 'Sphere', 'Facet', 'Aabb', 'NewtonIntegrator', 'InteractionLoop']:
        assert cls in names


# ---------------------------------------------------------------- damaged files

@pytest.fixture
def saved(tmp_path):
    lattice('frict')
    O.run(10, True)
    O.save(str(tmp_path / 'good.yade'))
    return (tmp_path / 'good.yade').read_bytes()


def test_any_flipped_byte_is_refused_by_the_checksums(tmp_path, saved):
    rnd = random.Random(11)
    for _ in range(40):
        data = bytearray(saved)
        i = rnd.randrange(len(BINARY_MAGIC), len(data))
        data[i] ^= 1 << rnd.randrange(8)
        msg = refused(tmp_path, bytes(data))
        assert 'checksum' in msg or 'corrupt' in msg or 'truncated' in msg, msg


def test_a_file_cut_anywhere_is_refused(tmp_path, saved):
    ends, i = [], len(BINARY_MAGIC)
    for kind, payload in blocks(saved):
        i += 16 + len(payload)
        ends.append(i)
    for cut in ends[:-1] + [ends[-1] - 1, ends[3] - 5, len(BINARY_MAGIC) + 3, 100]:
        assert 'truncated' in refused(tmp_path, saved[:cut])
    assert 'extra bytes' in refused(tmp_path, saved + b'\0')


def test_values_the_setters_refuse_are_refused_under_good_checksums(tmp_path, saved):
    r = struct.pack('<d', .01)
    assert 'Sphere.radius must be positive' in refused(tmp_path, reblocked(saved, lambda k, p: p.replace(r, struct.pack('<d', -.01))))
    # a position: the first sphere's x (0 + jitter) is somewhere in the State rows; make every
    # copy of the mass not finite instead (one value for all the spheres: one place to hit)
    O.reset()
    lattice('frict')
    m = struct.pack('<d', O.bodies[20].state.mass)
    assert 'State.mass must be non-negative' in refused(tmp_path, reblocked(saved, lambda k, p: p.replace(m, struct.pack('<d', float('inf'))) if k == b'ROWS' else p))


def test_inconsistent_structure_is_refused_under_good_checksums(tmp_path, saved):
    # an unknown block type
    assert 'unknown block type' in refused(tmp_path, reblocked_kind(saved, b'PERM', b'XXXX'))
    # an unknown attribute
    assert "has no attribute 'radiux'" in refused(tmp_path, reblocked(saved, lambda k, p: p.replace(b'\x06radius', b'\x06radiux') if k == b'TABL' else p))
    # contacts that name a pair the file does not hold: the pairs dropped
    assert 'pair' in refused(tmp_path, drop_blocks(saved, b'PAIR'))
    # bodies without the end of their objects: a table's rows missing
    rows = [i for i, (k, _) in enumerate(blocks(saved)) if k == b'ROWS']
    assert refused(tmp_path, drop_blocks(saved, None, rows[-1]))
    # the end block missing
    assert 'truncated' in refused(tmp_path, drop_blocks(saved, b'END '))


def reblocked_kind(data, kind, new):
    out = BINARY_MAGIC
    for k, payload in blocks(data):
        out += struct.pack('<4sQI', new if k == kind else k, len(payload), zlib.crc32(payload)) + payload
    return out


def drop_blocks(data, kind, index=None):
    out = BINARY_MAGIC
    for i, (k, payload) in enumerate(blocks(data)):
        if k == kind or i == index:
            continue
        out += struct.pack('<4sQI', k, len(payload), zlib.crc32(payload)) + payload
    return out


def test_a_newer_format_version_is_refused_by_name(tmp_path, saved):
    msg = refused(tmp_path, reblocked(saved, lambda k, p: b'\x04' + p[1:] if k == b'HEAD' else p))
    assert 'format version 4 by a newer build' in msg


# ---------------------------------------------------------------- memory

MEMORY = textwrap.dedent('''
    import os, sys
    from yade import *
    from yade import geom, utils
    sys.argv = ['dense.py', '%(n)d', '0']
    exec(open(%(dense)r).read().replace('O.run(STEPS, True)', 'pass').replace('print(', 'str('))
    def rss(field):
        for line in open('/proc/self/status'):
            if line.startswith(field):
                return int(line.split()[1]) / 1024.
    scene = rss('VmRSS')
    for name in %(names)r:
        open('/proc/self/clear_refs', 'w').write('5')  # resets VmHWM, the peak
        O.save(os.path.join(%(dir)r, name))
        print(name, scene, rss('VmHWM'))
''')


@pytest.mark.skipif('libasan' in os.environ.get('LD_PRELOAD', ''),
                    reason='under AddressSanitizer freed memory is held in quarantine: the peak says nothing of the writer')
def test_saving_takes_little_memory_beyond_the_scene(tmp_path):
    names = ['s.yade', 's.yade.gz'] + (['s.yade.zst'] if 'zstd' in O._codecs else [])
    code = MEMORY % dict(n=8000, dense=DENSE, names=names, dir=str(tmp_path))
    r = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, timeout=600,
                       env=dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path)))
    assert r.returncode == 0, r.stderr[-3000:]
    for line in r.stdout.split('\n'):
        if line.split() and line.split()[0] in names:
            name, scene, peak = line.split()[0], float(line.split()[1]), float(line.split()[2])
            # a block at a time (at most 4096 rows), the compressor's buffers: a few MB, where the
            # tree of format version 1 took 25 times the scene
            assert peak - scene < 12, (name, scene, peak)
