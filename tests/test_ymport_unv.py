"""ymport.unv: facets of the linear triangles (FE descriptor 41) of an I-DEAS universal file (.unv).

1. Against the reference Yade 2023.02a: tests/data/unv/reference.json holds, for 7 calls on the .unv files beside
   it (a cube's surface laid out as Salome writes it, a tetrahedron's with its elements before its nodes and its
   nodes in two datasets, the reference's own example shell.unv where it is installed), each facet's position and
   world-space vertices, the nodes and elements of returnConnectivityTable=True and the facets' attributes given
   by keywords (made by make_reference.py beside it, run with `yade -n -x`); here the same calls give the same
   facets in the same order with the same vertex order, to 1e-12, and the same connectivity table.
2. Analytic checks: the cube's surface has area 6, encloses volume 1 (divergence theorem), is closed and
   consistently oriented with outward normals; the tetrahedron's likewise; shift and scale move and scale them.
3. Where this engine differs from the reference on purpose (ymport.unv's docstring): nodes found by label, elements
   after a skipped element read, Fortran 'D' exponents, a warning for skipped 2D elements.
4. Bad files: ymport.ImportFormatError (a ValueError) naming the file and the line, nothing made or appended."""
import json
import os
import pathlib
import warnings

import numpy as np
import pytest

from yade import O, FrictMat, Vector3, ymport

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

DATA = pathlib.Path(__file__).parent / 'data' / 'unv'
REFERENCE = json.loads((DATA / 'reference.json').read_text())
SHELL = '/usr/share/doc/yade/examples/test/unv-read/shell.unv'
CUBE, TETRA = str(DATA / 'cube.unv'), str(DATA / 'tetra.unv')


def world(b):
    """The facet's position and its vertices in world coordinates."""
    return [list(b.state.pos)] + [list(b.state.pos + b.state.ori * v) for v in b.shape.vertices]


def triangles(facets):
    return np.array([world(b)[1:] for b in facets], dtype=float).reshape(-1, 3, 3)


def area(tris):
    return 0.5 * np.linalg.norm(np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]), axis=1).sum()


def volume(tris):
    """Volume enclosed by a closed surface whose triangles turn counterclockwise seen from outside (divergence theorem)."""
    return np.einsum('ij,ij->i', tris[:, 0], np.cross(tris[:, 1], tris[:, 2])).sum() / 6


def assertClosedAndOriented(elements):
    """Each edge is walked once in each direction: the surface is closed and its triangles turn the same way."""
    edges = [(t[k], t[(k + 1) % 3]) for t in elements for k in range(3)]
    assert len(set(edges)) == len(edges)
    assert set(edges) == {(b, a) for a, b in edges}


def assertOutward(facets, inside):
    for b in facets:
        t = np.array(world(b)[1:])
        n = np.array(list(b.state.ori * b.shape.normal))
        cross = np.cross(t[1] - t[0], t[2] - t[0])
        assert np.allclose(n, cross / np.linalg.norm(cross), atol=1e-12)  # the normal follows the vertices' order
        assert np.dot(n, t.mean(axis=0) - np.asarray(inside)) > 0


# ------------------------------------------------------------------ 1. the reference's output

@pytest.mark.parametrize('ref', REFERENCE, ids=[r['call'] for r in REFERENCE])
def test_as_the_reference(ref):
    if 'SHELL' in ref['call'] and not os.path.exists(SHELL):
        pytest.skip('the reference example %s is not installed here' % SHELL)
    O.materials.append(FrictMat(label='m1'))
    with warnings.catch_warnings():
        warnings.simplefilter('error')  # (none of these files has 2D elements to skip)
        ret = eval(ref['call'], {'ymport': ymport, 'Vector3': Vector3, 'D': str(DATA) + os.sep, 'SHELL': SHELL})
    facets = ret[0] if isinstance(ret, tuple) else ret
    assert isinstance(facets, list) and len(O.bodies) == 0  # returned, not appended
    assert len(facets) == len(ref['facets'])
    for b, r in zip(facets, ref['facets']):
        assert np.allclose(world(b), r, rtol=0, atol=1e-12)
    assert isinstance(ret, tuple) == ('nodes' in ref)
    if 'nodes' in ref:
        assert len(ret) == 3
        assert np.allclose(np.array(ret[1]), np.array(ref['nodes']), rtol=0, atol=1e-12)
        assert [list(e) for e in ret[2]] == ref['elements']
        assert all(isinstance(n, tuple) for n in ret[1]) and all(isinstance(e, tuple) for e in ret[2])
    for b, a in zip(facets, ref.get('attrs', [])):
        assert list(b.shape.color) == a['color'] and b.shape.wire == a['wire'] and b.shape.highlight == a['highlight']
        assert b.mask == a['mask'] and b.dynamic == a['dynamic'] and b.state.blockedDOFs == a['blockedDOFs']
        assert b.material.label == a['material']


# ------------------------------------------------------------------ 2. analytic checks

def test_cube_area_volume_outward():
    facets, nodes, elements = ymport.unv(CUBE, returnConnectivityTable=True)
    assert len(facets) == 12 and len(nodes) == 8
    tris = triangles(facets)
    assert area(tris) == pytest.approx(6, abs=1e-12)
    assert volume(tris) == pytest.approx(1, abs=1e-12)
    assertClosedAndOriented(elements)
    assertOutward(facets, (0.5, 0.5, 0.5))
    # the connectivity table gives the facets' vertices
    assert np.allclose(tris, np.array(nodes)[np.array(elements)], rtol=0, atol=1e-12)


def test_tetra_area_volume_outward():
    facets, nodes, elements = ymport.unv(TETRA, returnConnectivityTable=True)
    assert len(facets) == 4 and len(nodes) == 4
    a, b, c, d = np.array(nodes)
    tris = triangles(facets)
    assert volume(tris) == pytest.approx(abs(np.dot(np.cross(b - a, c - a), d - a)) / 6, rel=1e-13)
    faces = [(a, b, c), (a, b, d), (a, c, d), (b, c, d)]
    assert area(tris) == pytest.approx(sum(0.5 * np.linalg.norm(np.cross(q - p, r - p)) for p, q, r in faces), rel=1e-13)
    assertClosedAndOriented(elements)
    assertOutward(facets, (a + b + c + d) / 4)


@pytest.mark.parametrize('shift,scale', [((1, -2, 3.5), 2.5), (Vector3(0.25, 0, -1), 1e-3), ([0, 0, 0], -1.0)])
def test_shift_and_scale(shift, scale):
    facets, nodes, elements = ymport.unv(CUBE, shift=shift, scale=scale, returnConnectivityTable=True)
    plain = ymport.unv(CUBE, returnConnectivityTable=True)
    assert elements == plain[2]
    s = np.array(list(shift), dtype=float)
    assert np.allclose(np.array(nodes), s + scale * np.array(plain[1]), rtol=0, atol=1e-12)
    tris = triangles(facets)
    assert np.allclose(tris, s + scale * triangles(plain[0]), rtol=0, atol=1e-12)
    assert area(tris) == pytest.approx(6 * scale ** 2, rel=1e-12)
    assert volume(tris) == pytest.approx(scale ** 3, rel=1e-12)  # (a negative scale turns the normals inward)


def test_keywords_go_to_utils_facet():
    m = O.materials.append(FrictMat(label='steel', density=7800))
    fs = ymport.unv(CUBE, color=(0.1, 0.2, 0.3), wire=False, fixed=False, mask=6, material='steel', highlight=True)
    assert all(list(b.shape.color) == [0.1, 0.2, 0.3] and not b.shape.wire and b.shape.highlight for b in fs)
    assert all(b.dynamic and b.mask == 6 and b.material is O.materials[m] for b in fs)
    fs = ymport.unv(CUBE, dynamic=False, material=m, noBound=True)
    assert all(not b.dynamic and b.state.blockedDOFs == 'xyzXYZ' and b.material is O.materials[m] and b.bound is None
               and not b.bounded for b in fs)
    fs = ymport.unv(CUBE)  # utils.facet's defaults: fixed, wire, mask 1, the default material
    assert all(not b.dynamic and b.shape.wire and b.mask == 1 and b.bounded and b.bound is None for b in fs)  # (the collider makes the bound, as the reference)
    with pytest.raises(TypeError):
        ymport.unv(CUBE, colour=(1, 0, 0))
    ids = O.bodies.append(ymport.unv(CUBE))
    assert len(ids) == 12 and all(type(O.bodies[i].shape).__name__ == 'Facet' for i in ids)


# ------------------------------------------------------------------ 3. where this engine differs from the reference

def unvText(nodes, elements, labels=None):
    """A .unv file's text: dataset 2411 of the nodes (labelled 1, 2... or by `labels`), then 2412 of the elements
    [(FE descriptor, [node labels])] (beams get their beam record)."""
    labels = labels or list(range(1, len(nodes) + 1))
    s = '    -1\n  2411\n'
    for n, p in zip(labels, nodes):
        s += '%10d%10d%10d%10d\n%25.16E%25.16E%25.16E\n' % (n, 1, 1, 11, p[0], p[1], p[2])
    s += '    -1\n    -1\n  2412\n'
    for i, (d, ns) in enumerate(elements):
        s += '%10d%10d%10d%10d%10d%10d\n' % (i + 1, d, 2, 1, 7, len(ns))
        if d in (11, 21, 22, 23, 24, 31, 32):
            s += '%10d%10d%10d\n' % (0, 0, 0)
        for k in range(0, len(ns), 8):
            s += ''.join('%10d' % n for n in ns[k:k + 8]) + '\n'
    return s + '    -1\n'


def cubeTable():
    f, nodes, elements = ymport.unv(CUBE, returnConnectivityTable=True)
    return triangles(f), nodes, elements


def write(tmp_path, text, name='f.unv'):
    p = tmp_path / name
    p.write_bytes(text.encode())
    return str(p)


def test_nodes_are_found_by_label(tmp_path):
    """The reference takes label - 1 as the node's index: other labels give an IndexError or the wrong nodes there."""
    tris, nodes, elements = cubeTable()
    for labels in ([100, 7, 55, 3, 9, 21, 42, 1000], [8, 7, 6, 5, 4, 3, 2, 1]):
        f = write(tmp_path, unvText(nodes, [(41, [labels[i] for i in t]) for t in elements], labels))
        got = ymport.unv(f, returnConnectivityTable=True)
        assert got[2] == elements and np.allclose(triangles(got[0]), tris, rtol=0, atol=1e-12)


@pytest.mark.parametrize('before', [(91, [1, 2, 3]), (94, [1, 2, 3, 4]), (44, [1, 2, 3, 4]), (111, [1, 2, 3, 5]),
                                    (11, [1, 2]), (21, [1, 2]), (161, [3])])
def test_elements_after_a_skipped_one_are_read(tmp_path, before):
    """The reference loses the two triangles after a skipped 2D or solid element; skipped 2D elements warn here."""
    tris, nodes, elements = cubeTable()
    f = write(tmp_path, unvText(nodes, [before] + [(41, [i + 1 for i in t]) for t in elements] + [before]))
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter('always')
        got = ymport.unv(f, returnConnectivityTable=True)
    assert got[2] == elements and np.allclose(triangles(got[0]), tris, rtol=0, atol=1e-12)
    messages = [str(x.message) for x in w if issubclass(x.category, RuntimeWarning)]
    if 40 < before[0] < 100:
        assert len(messages) == 1 and f in messages[0] and 'skipped 2 elements of FE descriptor %d' % before[0] in messages[0]
    else:
        assert messages == []


def test_other_triangles_and_quadrilaterals_are_skipped_as_there(tmp_path):
    """As in the reference: only descriptor 41 makes facets (91 triangles, as gmsh writes them, and quadrilaterals
    44/94 give none), with a warning here."""
    _, nodes, elements = cubeTable()
    f = write(tmp_path, unvText(nodes, [(91, [i + 1 for i in t]) for t in elements] + [(94, [1, 2, 3, 4])]))
    with pytest.warns(RuntimeWarning, match='12 elements of FE descriptor 91, 1 element of FE descriptor 94'):
        assert ymport.unv(f, returnConnectivityTable=True) == ([], [tuple(n) for n in nodes], [])


def test_fortran_exponents_and_line_ends(tmp_path):
    """'D' exponents (a ValueError there) and CRLF line ends."""
    tris, _, _ = cubeTable()
    text = pathlib.Path(CUBE).read_text()
    assert 'E+00' in text
    for t in (text.replace('E+', 'D+').replace('E-', 'D-'), text.replace('\n', '\r\n'), text.replace('\n', '  \n')):
        assert np.allclose(triangles(ymport.unv(write(tmp_path, t))), tris, rtol=0, atol=1e-12)


def test_no_elements_gives_nothing(tmp_path):
    _, nodes, _ = cubeTable()
    f = write(tmp_path, unvText(nodes, []))
    assert ymport.unv(f) == [] and ymport.unv(f, returnConnectivityTable=True) == ([], [tuple(n) for n in nodes], [])


# ------------------------------------------------------------------ 4. bad files

def lineOf(text, s, after=0):
    """The number (from 1) of the first line from line `after` on that is `s` once stripped."""
    lines = text.splitlines()
    return next(i + 1 for i in range(after, len(lines)) if lines[i].strip() == s.strip())


def badFiles():
    """[(name, text, line or None, part of the message)]"""
    cube = pathlib.Path(CUBE).read_text()
    nodes = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (2, 1, 0)]
    good = unvText(nodes, [(41, [1, 2, 3]), (41, [1, 3, 4])])
    open2412 = lineOf(good, '2412') - 1
    out = [
        ('empty', '', None, 'empty file'),
        ('blank', '\n   \n\n', None, 'empty file'),
        ('not unv', 'solid cube\nfacet normal 0 0 1\n', 1, 'expected the line -1'),
        ('no opening -1', good.replace('    -1\n  2412', '  2412'), open2412, "expected the line -1 that opens a dataset, got '2412'"),
        ('no closing -1', good[:good.rindex('    -1')], open2412, 'dataset 2412 is not closed by a line -1'),
        ('cube cut short', cube[:cube.index('         5         6         7')], lineOf(cube, '2412') - 1, 'not closed'),
        ('no dataset number', '    -1\n    -1\n', 1, 'no dataset number'),
        ('dataset number not a number', '    -1\n  24x1\n    -1\n', 2, "dataset number '24x1'"),
        ('undefined node', good.replace('         1         3         4\n', '         1         3        99\n'),
         lineOf(good, '1         3         4'), 'refers to node 99, which no dataset 2411 defines'),
        ('node 0', good.replace('         1         3         4\n', '         1         0         4\n'),
         lineOf(good, '1         3         4'), 'refers to node 0'),
        ('coordinate not a number', good.replace('1.0000000000000000E+00', '1.0x00000000000000E+00', 1),
         lineOf(good, '2         1         1        11') + 1, "could not convert string to float: '1.0x00000000000000E+00'"),
        ('coordinate not finite', good.replace('1.0000000000000000E+00', 'nan', 1),
         lineOf(good, '2         1         1        11') + 1, "node 2's coordinates are not finite"),
        ('two coordinates', good.replace('   0.0000000000000000E+00\n', '\n', 1), 4, "a node's coordinates needs exactly 3 columns"),
        ('node label not a number', good.replace('         2         1         1        11', '         b         1         1        11'),
         lineOf(good, '2         1         1        11'), "invalid literal for int() with base 10: 'b'"),
        ('node without coordinates', good.replace('    -1\n    -1\n  2412', '         9         1         1        11\n    -1\n    -1\n  2412'),
         lineOf(good, '2412') - 2, 'a node record without its coordinates line'),
        ('node defined twice', good.replace('         3         1         1        11', '         1         1         1        11'),
         lineOf(good, '3         1         1        11'), 'node 1 is defined twice'),
        ('element field not a number', good.replace('        41         2         1         7         3', '        4x         2         1         7         3', 1),
         open2412 + 2, "invalid literal for int() with base 10: '4x'"),
        ('element record short', good.replace('         2        41         2         1         7         3\n', '         2        41         2         1         7\n'),
         lineOf(good, '2        41         2         1         7         3'), 'needs exactly 6 columns'),
        ('element cut short', good.replace('         1         3         4\n', ''), lineOf(good, '2        41         2         1         7         3'),
         'element 2 has 3 nodes, the dataset ends after 0'),
        ('too many node labels', good.replace('         1         3         4\n', '         1         3         4         5\n'),
         lineOf(good, '2        41         2         1         7         3'), 'element 2 has 3 nodes, its node lines list 4'),
        ('no nodes', good.replace('        41         2         1         7         3\n         1         2         3\n',
                                  '        41         2         1         7         0\n'),
         open2412 + 2, 'element 1 has 0 nodes'),
        ('triangle of 4 nodes', unvText(nodes, [(41, [1, 2, 3, 4])]), lineOf(good, '2412') + 1, 'has 4 nodes, not 3'),
        ('node twice', unvText(nodes, [(41, [1, 2, 3]), (41, [1, 3, 1])]), lineOf(good, '2        41         2         1         7         3'),
         'element 2 is a triangle of zero area (nodes 1 3 1)'),
        ('collinear', unvText(nodes, [(41, [1, 2, 3]), (41, [4, 3, 5])]), lineOf(good, '2        41         2         1         7         3'),
         'zero area (nodes 4 3 5)'),
        ('beam without its record', unvText(nodes, [(41, [1, 2, 3])])[:-len('    -1\n')] + '         2        11         2         1         7         2\n    -1\n',
         lineOf(good, '2        41         2         1         7         3'), 'element 2 (a beam) has no beam record'),
        ('beam record missing', good.replace('        41         2         1         7         3\n         1         3         4\n',
                                             '        11         2         1         7         2\n         1         3\n'),
         lineOf(good, '1         3         4'), 'the beam record of element 2 needs exactly 3 columns, the line has 2'),
    ]
    return out


BAD = badFiles()


@pytest.mark.parametrize('name,text,line,message', BAD, ids=[b[0] for b in BAD])
def test_bad_file(tmp_path, name, text, line, message):
    f = write(tmp_path, text)
    with pytest.raises(ymport.ImportFormatError) as e:
        O.bodies.append(ymport.unv(f, color=(1, 0, 0)))
    assert isinstance(e.value, ValueError)
    assert str(e.value).startswith(f + (':%d: ' % line if line else ': ')), str(e.value)
    assert message in str(e.value)
    assert len(O.bodies) == 0


def test_missing_file(tmp_path):
    with pytest.raises(FileNotFoundError):
        ymport.unv(str(tmp_path / 'missing.unv'))
