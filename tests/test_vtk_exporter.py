"""yade.export.VTKExporter: VTK legacy ASCII files read back with VTK's own readers (python3-vtk9),
their values against the engine's, their names and counters, the error cases, and byte-for-byte
comparison with files the reference Yade (2023.02a) wrote for the same scenes
(tests/data/vtk/make_reference.py, scenes in tests/data/vtk/scenes.py)."""
import importlib.util
import os
import warnings

import numpy as np
import pytest

vtk = pytest.importorskip('vtk')
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

from yade import O, export, utils, Vector3, Matrix3  # noqa: E402
from yade import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop, Ig2_Sphere_Sphere_ScGeom,  # noqa: E402
                  Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator)

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'data', 'vtk')
_spec = importlib.util.spec_from_file_location('vtk_test_scenes', os.path.join(DATA, 'scenes.py'))
scenes = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scenes)

# the files keep 6 significant digits
RTOL, ATOL = 5e-6, 1e-12


def _close(a, b):
    np.testing.assert_allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=RTOL, atol=ATOL)


def _read(path):
    """The dataset of a legacy VTK file, every data array read (the reader keeps only the first
    SCALARS/VECTORS/TENSORS otherwise)."""
    with open(path) as f:
        head = f.read(200)
    reader = vtk.vtkUnstructuredGridReader() if 'UNSTRUCTURED_GRID' in head else vtk.vtkPolyDataReader()
    reader.SetFileName(str(path))
    reader.ReadAllScalarsOn()
    reader.ReadAllVectorsOn()
    reader.ReadAllTensorsOn()
    reader.Update()
    data = reader.GetOutput()
    assert data is not None and data.GetNumberOfPoints() > 0, path
    return data


def _points(data):
    return vtk_to_numpy(data.GetPoints().GetData())


def _pointArray(data, name):
    a = data.GetPointData().GetArray(name)
    assert a is not None, (name, [data.GetPointData().GetArrayName(k) for k in range(data.GetPointData().GetNumberOfArrays())])
    return vtk_to_numpy(a)


def _cellArray(data, name):
    a = data.GetCellData().GetArray(name)
    assert a is not None, name
    return vtk_to_numpy(a)


def _cells(data, lines=False):
    """The cells of a polydata (polygons, or lines) as lists of point numbers."""
    cells = data.GetLines() if lines else data.GetPolys()
    out, ids = [], vtk.vtkIdList()
    cells.InitTraversal()
    while cells.GetNextCell(ids):
        out.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    return out


def _worldCorners(b):
    return [b.state.pos + b.state.ori * v for v in b.shape.vertices]


def _sphereIds():
    return [b.id for b in O.bodies if b is not None and isinstance(b.shape, utils.Sphere)]


# --- the reference's files -------------------------------------------------------------------------

def test_files_as_the_reference(tmp_path, fresh_scene):
    scenes.runExports(export, str(tmp_path))
    expected = sorted(f for f in os.listdir(DATA) if f.endswith('.vtk'))
    assert len(expected) == 11
    assert sorted(os.listdir(str(tmp_path))) == expected
    for name in expected:
        with open(os.path.join(DATA, name)) as f:
            ref = f.read()
        with open(str(tmp_path / name)) as f:
            mine = f.read()
        assert mine == ref, name


def test_reference_files_read_by_vtk():
    for name in sorted(f for f in os.listdir(DATA) if f.endswith('.vtk')):
        path = os.path.join(DATA, name)
        with open(path) as f:
            declared = int([line for line in f if line.startswith('POINTS ')][0].split()[1])
        assert _read(path).GetNumberOfPoints() == declared, name
    tensors = _pointArray(_read(os.path.join(DATA, 'A-spheres-00000003.vtk')), 'mat')
    _close(tensors, [range(1, 10)] * 3)


# --- values read back ------------------------------------------------------------------------------

def test_spheres_read_back(tmp_path, fresh_scene):
    scenes.sceneA()
    O.bodies[0].state.vel = Vector3(1.5, -2.25, 1e-7)
    ex = export.VTKExporter(str(tmp_path / 's'))
    ex.exportSpheres(what=dict(vel='b.state.vel', mass='b.state.mass', id='b.id', speed='b.state.vel.norm()',
                               M='Matrix3(b.id,1,2,3,4,5,6,7,b.shape.radius)'))
    data = _read(str(tmp_path / 's-spheres-00000000.vtk'))
    ids = _sphereIds()
    assert ids == [0, 1, 3]
    assert data.GetNumberOfPoints() == 3
    _close(_points(data), [O.bodies[i].state.pos for i in ids])
    _close(_pointArray(data, 'radius'), [O.bodies[i].shape.radius for i in ids])
    _close(_pointArray(data, 'vel'), [O.bodies[i].state.vel for i in ids])
    _close(_pointArray(data, 'mass'), [O.bodies[i].state.mass for i in ids])
    _close(_pointArray(data, 'id'), ids)
    _close(_pointArray(data, 'speed'), [O.bodies[i].state.vel.norm() for i in ids])
    M = _pointArray(data, 'M').reshape(-1, 3, 3)
    _close(M[:, 0, 0], ids)
    _close(M[:, 2, 2], [O.bodies[i].shape.radius for i in ids])
    # the array kinds as the legacy format names them
    with open(str(tmp_path / 's-spheres-00000000.vtk')) as f:
        text = f.read()
    assert 'VECTORS vel double\n' in text and 'SCALARS mass double 1\nLOOKUP_TABLE default\n' in text and 'TENSORS M double\n' in text


def test_spheres_of_a_list_and_reference_positions(tmp_path, fresh_scene):
    scenes.sceneA()
    for i in (0, 1, 3):
        O.bodies[i].state.pos += Vector3(0.25, 0, 0)
    ex = export.VTKExporter(str(tmp_path / 's'))
    with pytest.warns(RuntimeWarning, match='body 2 is not of type'):
        ex.exportSpheres(ids=[3, 2, 0], useRef=True)
    ex.exportSpheres(ids=[3, 0])
    ref = _read(str(tmp_path / 's-spheres-00000000.vtk'))
    cur = _read(str(tmp_path / 's-spheres-00000001.vtk'))
    _close(_points(ref), [O.bodies[3].state.refPos, O.bodies[0].state.refPos])
    _close(_points(cur), [O.bodies[3].state.pos, O.bodies[0].state.pos])
    _close(_pointArray(cur, 'radius'), [0.3, 0.5])


def test_clump_members_are_spheres(tmp_path, fresh_scene):
    O.bodies.append(utils.sphere((0, 0, 0), .1))
    O.bodies.appendClumped([utils.sphere((1, 0, 0), .2), utils.sphere((1.3, 0, 0), .2)])
    ex = export.VTKExporter(str(tmp_path / 'c'))
    ex.exportSpheres(what=dict(clump='b.clumpId'))
    data = _read(str(tmp_path / 'c-spheres-00000000.vtk'))
    assert data.GetNumberOfPoints() == 3
    _close(_pointArray(data, 'radius'), [.1, .2, .2])
    assert list(_pointArray(data, 'clump')[1:]) == [3, 3]


def test_facets_read_back(tmp_path, fresh_scene):
    scenes.sceneA()
    O.bodies[4].state.pos += Vector3(0, 0, 0.5)  # moved: the corners are written in world coordinates
    ex = export.VTKExporter(str(tmp_path / 'f'))
    ex.exportFacets(what=dict(n='b.shape.normal', area='b.shape.area', id='b.id'))
    data = _read(str(tmp_path / 'f-facets-00000000.vtk'))
    assert data.GetNumberOfPoints() == 6 and data.GetNumberOfPolys() == 2
    _close(_points(data), _worldCorners(O.bodies[2]) + _worldCorners(O.bodies[4]))
    _close(_points(data)[3:], [(2, -1, 0.05), (2, 2, 0.05), (0, 2, 0.05)])
    assert _cells(data) == [[0, 1, 2], [3, 4, 5]]
    _close(_cellArray(data, 'n'), [O.bodies[2].shape.normal, O.bodies[4].shape.normal])
    _close(_cellArray(data, 'area'), [4.5, 3])
    assert list(_cellArray(data, 'id')) == [2, 4]


def test_facets_as_mesh(tmp_path, fresh_scene):
    scenes.sceneA()
    ex = export.VTKExporter(str(tmp_path / 'm'))
    ex.exportFacetsAsMesh(what=dict(id='b.id'))  # nodes: corners at the same place are one
    ex.exportFacetsAsMesh(ids=[4, 2], connectivityTable=[(0, 1, 2), (3, 0, 2)])
    auto = _read(str(tmp_path / 'm-facets-00000000.vtk'))
    assert auto.GetNumberOfPoints() == 4
    _close(_points(auto), [(-1, -1, -0.45), (2, -1, -0.45), (0, 2, -0.45), (2, 2, -0.45)])
    assert _cells(auto) == [[0, 1, 2], [1, 3, 2]]
    assert list(_cellArray(auto, 'id')) == [2, 4]
    table = _read(str(tmp_path / 'm-facets-00000001.vtk'))
    _close(_points(table), [(2, -1, -0.45), (2, 2, -0.45), (0, 2, -0.45), (-1, -1, -0.45)])
    assert _cells(table) == [[0, 1, 2], [3, 0, 2]]
    assert ex.facetsSnapCount == 2
    with pytest.raises(ValueError, match='one row of 3 node numbers per facet'):
        ex.exportFacetsAsMesh(connectivityTable=[(0, 1, 2)])
    with pytest.raises(ValueError, match='does not match the facets'):
        ex.exportFacetsAsMesh(connectivityTable=[(0, 1, 2), (0, 3, 2)])
    with pytest.raises(ValueError, match='node 3 is a corner of no facet'):
        ex.exportFacetsAsMesh(connectivityTable=[(0, 1, 2), (1, 4, 2)])
    assert ex.facetsSnapCount == 2 and len(os.listdir(str(tmp_path))) == 2


def _checkInteractions(path):
    data = _read(path)
    n = O.interactions.countReal()
    assert n == 3 and data.GetNumberOfLines() == n and data.GetNumberOfPoints() == 2 * n
    pts = _points(data)
    fn = _cellArray(data, 'fn')
    seen = set()
    for k, (a, b) in enumerate(_cells(data, lines=True)):
        assert (a, b) == (2 * k, 2 * k + 1)
        # the two ends are bodies' centres: find which interaction this line is
        ends = [min(range(len(O.bodies)), key=lambda j: (O.bodies[j].state.pos - Vector3(*p)).norm()) for p in pts[a:b + 1]]
        i = O.interactions[ends[0], ends[1]]
        assert (i.id1, i.id2) == tuple(ends)
        _close(pts[a:b + 1], [O.bodies[i.id1].state.pos, O.bodies[i.id2].state.pos])
        _close(fn[k], i.phys.normalForce)
        seen.add(tuple(ends))
    assert seen == {(i.id1, i.id2) for i in O.interactions if i.isReal}
    return data


def test_interactions_read_back(tmp_path, fresh_scene):
    scenes.sceneA()
    ex = export.VTKExporter(str(tmp_path / 'i'))
    ex.exportInteractions(what=dict(fn='i.phys.normalForce', kn='i.phys.kn'),
                          verticesWhat=dict(mass='b.state.mass', vel='b.state.vel', other='b2.id if b is b1 else b1.id'))
    data = _checkInteractions(str(tmp_path / 'i-intrs-00000000.vtk'))
    ends = [j for pair in _cells(data, lines=True) for j in pair]
    pts = _points(data)
    ids = [min(range(len(O.bodies)), key=lambda j: (O.bodies[j].state.pos - Vector3(*pts[e])).norm()) for e in ends]
    # verticesWhat: one value per point (the reference writes the header only), scalars as SCALARS
    _close(_pointArray(data, 'mass'), [O.bodies[j].state.mass for j in ids])
    _close(_pointArray(data, 'vel'), [O.bodies[j].state.vel for j in ids])
    assert list(_pointArray(data, 'other')) == [ids[k + 1] if k % 2 == 0 else ids[k - 1] for k in range(len(ids))]
    _close(_cellArray(data, 'kn'), [O.interactions[ids[2 * k], ids[2 * k + 1]].phys.kn for k in range(3)])


class _NoArrays(object):
    """O.interactions without its NumPy arrays, so that the exporter takes its loop over the
    interactions (the path for contacts the arrays do not cover)."""

    def __init__(self, real):
        self._real = real

    def __getattr__(self, name):
        return getattr(self._real, name)

    def __iter__(self):
        return iter(self._real)

    def __getitem__(self, key):
        return self._real[key]

    def arrays(self):
        return {'id1': np.zeros(0, dtype=int)}


class _OWithoutArrays(object):
    interactions = _NoArrays(O.interactions)

    def __getattr__(self, name):
        return getattr(O, name)


def test_interactions_without_arrays(tmp_path, fresh_scene, monkeypatch):
    scenes.sceneA()
    monkeypatch.setattr(export, 'O', _OWithoutArrays())
    ex = export.VTKExporter(str(tmp_path / 'i'))
    ex.exportInteractions(what=dict(fn='i.phys.normalForce'))
    ex.exportContactPoints()
    _checkInteractions(str(tmp_path / 'i-intrs-00000000.vtk'))
    cps = _read(str(tmp_path / 'i-cps-00000000.vtk'))
    assert sorted(map(tuple, np.round(_points(cps), 6))) == sorted(tuple(np.round(tuple(i.geom.contactPoint), 6)) for i in O.interactions)


def test_contact_points_read_back(tmp_path, fresh_scene):
    scenes.sceneA()
    ex = export.VTKExporter(str(tmp_path / 'c'))
    ex.exportContactPoints(what=dict(fn='i.phys.normalForce', pen='i.geom.penetrationDepth', id1='i.id1', id2='i.id2'))
    data = _read(str(tmp_path / 'c-cps-00000000.vtk'))
    assert data.GetNumberOfPoints() == 3
    id1, id2 = _pointArray(data, 'id1').astype(int), _pointArray(data, 'id2').astype(int)
    intrs = [O.interactions[int(a), int(b)] for a, b in zip(id1, id2)]
    _close(_points(data), [i.geom.contactPoint for i in intrs])
    _close(_pointArray(data, 'fn'), [i.phys.normalForce for i in intrs])
    _close(_pointArray(data, 'pen'), [i.geom.penetrationDepth for i in intrs])


def test_periodic_scene(tmp_path, fresh_scene):
    scenes.sceneC()
    i = O.interactions[0, 1]
    assert tuple(i.cellDist) == (-1, 0, 0)
    h = O.cell.hSize
    ex = export.VTKExporter(str(tmp_path / 'p'))
    ex.exportInteractions(what=dict(fn='i.phys.normalForce'))
    ex.exportInteractions(ids=[(1, 0)])
    ex.exportPeriodicCell()
    # the line goes to body 1's image that touches body 0: it has the contact's length (0.25), not 1.75
    branch = O.bodies[1].state.pos + h * Vector3(i.cellDist) - O.bodies[0].state.pos
    assert branch.norm() < 0.3
    for name, first, second in (('p-intrs-00000000.vtk', O.bodies[0].state.pos, O.bodies[0].state.pos + branch),
                                ('p-intrs-00000001.vtk', O.bodies[1].state.pos, O.bodies[1].state.pos - branch)):
        pts = _points(_read(str(tmp_path / name)))
        _close(pts, [first, second])
        assert abs(np.linalg.norm(pts[1] - pts[0]) - branch.norm()) < 1e-5
    _close(_cellArray(_read(str(tmp_path / 'p-intrs-00000000.vtk')), 'fn'), [i.phys.normalForce])
    # the cell: hSize times the unit cube's corners, one hexahedron
    cell = _read(str(tmp_path / 'p-periCell-00000002.vtk'))
    assert isinstance(cell, vtk.vtkUnstructuredGrid)
    corners = [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1), (0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)]
    _close(_points(cell), [h * Vector3(*c) for c in corners])
    assert cell.GetNumberOfCells() == 1 and cell.GetCellType(0) == vtk.VTK_HEXAHEDRON
    assert cell.GetCell(0).GetNumberOfPoints() == 8
    assert ex.intrsSnapCount == 2  # the cell's file took intrsSnapCount's number and left it


def test_periodic_cell_follows_the_cell(tmp_path, fresh_scene):
    scenes.sceneC()
    O.cell.hSize = Matrix3(3, 0, 0.5, 0, 1.5, 0, 0.25, 0, 2.5)
    ex = export.VTKExporter(str(tmp_path / 'p'), startSnap=7)
    ex.exportPeriodicCell(numLabel=11, comment='sheared')
    cell = _read(str(tmp_path / 'p-periCell-00000011.vtk'))
    h = np.array(O.cell.hSize)
    _close(_points(cell)[2], h.dot((1, 1, 1)))
    _close(_points(cell)[7], h.dot((1, 0, 0)))


# --- names and counters ----------------------------------------------------------------------------

def test_file_names_and_counters(tmp_path, fresh_scene):
    scenes.sceneA()
    base = str(tmp_path / 'run')
    ex = export.VTKExporter(base, startSnap=5)
    assert ex.baseName == base
    assert (ex.spheresSnapCount, ex.facetsSnapCount, ex.intrsSnapCount, ex.contactPointsSnapCount, ex.polyhedraSnapCount,
            ex.PotentialBlocksSnapCount) == (5,) * 6
    ex.exportSpheres()
    ex.exportSpheres(numLabel=100)  # a given number still counts as a file written
    ex.exportSpheres()
    ex.exportFacets()
    ex.exportInteractions()
    ex.exportContactPoints(numLabel=3)
    assert (ex.spheresSnapCount, ex.facetsSnapCount, ex.intrsSnapCount, ex.contactPointsSnapCount) == (8, 6, 6, 6)
    assert sorted(os.listdir(str(tmp_path))) == ['run-cps-00000003.vtk', 'run-facets-00000005.vtk', 'run-intrs-00000005.vtk',
                                                 'run-spheres-00000005.vtk', 'run-spheres-00000007.vtk', 'run-spheres-00000100.vtk']
    O.periodic = True
    ex.exportPeriodicCell()  # numbered as the next interactions' file, as the reference does
    assert os.path.exists(base + '-periCell-00000006.vtk') and ex.intrsSnapCount == 6


def test_comment(tmp_path, fresh_scene):
    scenes.sceneA()
    ex = export.VTKExporter(str(tmp_path / 'c'))
    ex.exportSpheres(comment='two\nlines')
    with open(str(tmp_path / 'c-spheres-00000000.vtk')) as f:
        lines = f.read().split('\n')
    assert lines[:5] == ['# vtk DataFile Version 3.0.', 'two lines', 'ASCII', '', 'DATASET POLYDATA']


def test_what_sees_the_callers_names(tmp_path, fresh_scene):
    scenes.sceneA()
    scale = 2.5  # noqa: F841 (used by the expressions)

    def double(x):
        return 2 * x
    ex = export.VTKExporter(str(tmp_path / 'n'))
    ex.exportSpheres(what=dict(s='scale*b.shape.radius', d='double(b.id)', q='Quaternion(1,0,0,0).norm()', v='Vector3(b.id,0,0)',
                               g='sum(b.id for k in range(2))'))
    data = _read(str(tmp_path / 'n-spheres-00000000.vtk'))
    _close(_pointArray(data, 's'), [1.25, 1.25, 0.75])
    _close(_pointArray(data, 'd'), [0, 2, 6])
    _close(_pointArray(data, 'q'), [1, 1, 1])
    _close(_pointArray(data, 'g'), [0, 2, 6])  # a comprehension sees b


def test_number_format(tmp_path, fresh_scene):
    O.bodies.append(utils.sphere((1234567.89, -0.0, 1e-300), .5))
    ex = export.VTKExporter(str(tmp_path / 'g'))
    ex.exportSpheres(what=dict(big='12345678', neg='-0.0', nan='float("nan")', inf='-float("inf")', v='Vector3(12345678,1e-7,0.1)'))
    with open(str(tmp_path / 'g-spheres-00000000.vtk')) as f:
        text = f.read()
    # as the reference (C++ stream output: 6 significant digits)
    for piece in ('POINTS 1 double\n1.23457e+06 -0 1e-300\n', 'SCALARS big double 1\nLOOKUP_TABLE default\n1.23457e+07\n',
                  'LOOKUP_TABLE default\n-0\n', 'LOOKUP_TABLE default\nnan\n', 'LOOKUP_TABLE default\n-inf\n',
                  'VECTORS v double\n1.23457e+07 1e-07 0.1\n'):
        assert piece in text, piece


# --- errors ----------------------------------------------------------------------------------------

def test_a_failing_expression_names_itself_and_writes_nothing(tmp_path, fresh_scene):
    scenes.sceneA()
    ex = export.VTKExporter(str(tmp_path / 'e'))
    with pytest.raises(AttributeError, match=r"what\['x'\] = 'b.nonexistent' failed for body 0"):
        ex.exportSpheres(what=dict(v='b.state.vel', x='b.nonexistent'))
    with pytest.raises(ZeroDivisionError, match=r"'1/\(b.id-3\)' failed for body 3"):
        ex.exportSpheres(what=dict(x='1/(b.id-3)'))
    with pytest.raises(AttributeError, match=r"failed for interaction \(0, 1\)"):
        ex.exportInteractions(ids=[(0, 1)], what=dict(x='i.phys.nothing'))
    with pytest.raises(AttributeError, match=r"failed for body 1 of interaction \(0, 1\)"):
        ex.exportInteractions(ids=[(0, 1)], verticesWhat=dict(x='b.nothing if b.id == 1 else 0'))
    with pytest.raises(AttributeError, match=r"'b.shape.radius' failed for body 2"):
        ex.exportFacets(what=dict(r='b.shape.radius'))
    with pytest.raises(SyntaxError, match='is not a Python expression'):
        ex.exportSpheres(what=dict(x='b.id +'))
    with pytest.raises(TypeError, match=r"gives 'abc' for body 0: only a number, a 3-vector or a 3x3 matrix"):
        ex.exportSpheres(what=dict(x='"abc"'))
    with pytest.raises(TypeError, match='gives None'):
        ex.exportSpheres(what=dict(x='None'))
    with pytest.raises(TypeError, match='only a number'):
        ex.exportSpheres(what=dict(x='Quaternion(1,0,0,0)'))
    with pytest.raises(TypeError, match='gives a 3-vector for body 1 but a number for body 0'):
        ex.exportSpheres(what=dict(x='b.id if b.id == 0 else b.state.vel'))
    with pytest.raises(ValueError, match='cannot name a VTK array'):
        ex.exportSpheres(what={'two words': 'b.id'})
    with pytest.raises(TypeError, match='as a str'):
        ex.exportSpheres(what=dict(x=3))
    # nothing written, nothing counted, no temporary file left
    assert os.listdir(str(tmp_path)) == []
    assert (ex.spheresSnapCount, ex.facetsSnapCount, ex.intrsSnapCount) == (0, 0, 0)


def test_bad_ids(tmp_path, fresh_scene):
    scenes.sceneA()
    O.bodies.erase(3)
    ex = export.VTKExporter(str(tmp_path / 'e'))
    with pytest.raises(IndexError, match='no body with id 17'):
        ex.exportSpheres(ids=[0, 17])
    with pytest.raises(IndexError, match='no body with id 3'):
        ex.exportSpheres(ids=[3])
    with pytest.raises(IndexError, match='no body with id -1'):
        ex.exportFacets(ids=[-1])
    with pytest.raises(TypeError, match='is not an integer'):
        ex.exportSpheres(ids=[0.5])
    with pytest.raises(ValueError, match="ids must be 'all'"):
        ex.exportSpheres(ids='spheres')
    with pytest.raises(TypeError, match="ids must be 'all' or a list"):
        ex.exportSpheres(ids=3)
    with pytest.raises(IndexError, match='no interaction between bodies 0 and 3'):
        ex.exportInteractions(ids=[(0, 1), (0, 3)])
    with pytest.raises(IndexError, match='no interaction between bodies 0 and 17'):
        ex.exportContactPoints(ids=[(0, 17)])
    with pytest.raises(TypeError, match=r'is not an \(id1, id2\) pair'):
        ex.exportInteractions(ids=[0, 1])
    assert os.listdir(str(tmp_path)) == []


def test_an_interaction_that_is_not_real(tmp_path, fresh_scene):
    O.bodies.append([utils.sphere((0, 0, 0), .5), utils.sphere((1.05, 0, 0), .5)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()], verletDist=0.2),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-3
    O.run(1, True)
    assert O.interactions.has(0, 1) and not O.interactions[0, 1].isReal
    ex = export.VTKExporter(str(tmp_path / 'e'))
    with pytest.raises(IndexError, match='is not real'):
        ex.exportInteractions(ids=[(0, 1)])
    with pytest.warns(RuntimeWarning, match='no interactions to export'):
        ex.exportInteractions()  # 'all' is the real ones: none
    assert os.listdir(str(tmp_path)) == [] and ex.intrsSnapCount == 0


def test_nothing_to_export(tmp_path, fresh_scene):
    ex = export.VTKExporter(str(tmp_path / 'e'))
    with pytest.warns(RuntimeWarning, match='the scene is not periodic'):
        ex.exportPeriodicCell()
    with pytest.warns(RuntimeWarning, match='no spheres'):
        ex.exportSpheres()
    O.bodies.append(utils.sphere((0, 0, 0), 1))
    with pytest.warns(RuntimeWarning, match='no facets'):
        ex.exportFacets()
    with pytest.warns(RuntimeWarning):
        ex.exportFacets(ids=[0])  # not a facet: skipped, then nothing left
    with pytest.warns(RuntimeWarning, match='no interactions'):
        ex.exportContactPoints()
    with pytest.raises(NotImplementedError, match='no Polyhedra'):
        ex.exportPolyhedra()
    with pytest.raises(NotImplementedError, match='no PotentialBlock'):
        ex.exportPotentialBlocks()
    assert os.listdir(str(tmp_path)) == []
    assert (ex.spheresSnapCount, ex.facetsSnapCount, ex.intrsSnapCount, ex.contactPointsSnapCount) == (0, 0, 0, 0)
    with warnings.catch_warnings():
        warnings.simplefilter('error')
        ex.exportSpheres()
    assert os.listdir(str(tmp_path)) == ['e-spheres-00000000.vtk']
