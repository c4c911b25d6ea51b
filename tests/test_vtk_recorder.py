"""VTKRecorder: the files are read back with VTK's own Python module (python3-vtk9), and what they hold is
compared, number by number, with the engine's state: spheres, facets, boxes, force chains, the periodic
cell, the arrays the recorders add, the multiblock and the .pvd series, and bad input."""
import math
import os

import numpy as np
import pytest

vtk = pytest.importorskip('vtk')
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

import yade  # noqa: E402
from yade import O, utils  # noqa: E402
from yade.wrapper import (Bo1_Box_Aabb, Bo1_Facet_Aabb, Bo1_Sphere_Aabb, Box, ForceResetter,  # noqa: E402
                          Ig2_Box_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ig2_Sphere_Sphere_ScGeom,
                          InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys,
                          Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator, Sphere, VTKRecorder)
from yade.minieigenHP import Matrix3, Vector3  # noqa: E402

pytestmark = pytest.mark.skipif(not yade._yade.vtk, reason='built without the VTK library (libvtk9-dev)')


def read(path):
    readers = {'.vtu': vtk.vtkXMLUnstructuredGridReader, '.vtp': vtk.vtkXMLPolyDataReader,
               '.vtm': vtk.vtkXMLMultiBlockDataReader}
    r = readers[os.path.splitext(path)[1]]()
    r.SetFileName(str(path))
    r.Update()
    return r.GetOutput()


def arrays(data, cells=False):
    d = data.GetCellData() if cells else data.GetPointData()
    return {d.GetArrayName(i): vtk_to_numpy(d.GetArray(i)) for i in range(d.GetNumberOfArrays())}


def points(data):
    return vtk_to_numpy(data.GetPoints().GetData()) if data.GetNumberOfPoints() else np.zeros((0, 3))


def engines(recorder, extra=()):
    return [ForceResetter(),
            InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Box_Aabb()]),
            InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],
                            [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
            NewtonIntegrator(damping=.4, gravity=(0, 0, -10)), recorder] + list(extra)


def pile(tmp_path, recorders=('all',), **kw):
    """A block of 5×5×3 spheres, each touching its neighbours, resting on a facet, with a box aside; a
    recorder every 50 steps; 101 steps."""
    O.reset()
    for i in range(5):
        for j in range(5):
            for k in range(3):
                O.bodies.append(utils.sphere((.1 + .1199 * i, .1 + .1199 * j, -.0401 + .1199 * k), .06, color=(.2, .4, .6)))
    O.bodies.append(utils.facet([(-1, -1, -.1), (2, -1, -.1), (-1, 2, -.1)], color=(1, 0, 0)))
    O.bodies.append(utils.box((3, 3, -.1), (.3, .2, .1), color=(0, 1, 0), fixed=True))
    rec = VTKRecorder(fileName=str(tmp_path / 'out' / 'p-'), recorders=list(recorders), iterPeriod=50, **kw)
    O.engines = engines(rec)
    O.dt = .5 * utils.PWaveTimeStep()
    O.run(101, True)
    return rec


def sphere_ids():
    return [b.id for b in O.bodies if isinstance(b.shape, Sphere)]


def test_file_names_series_and_initial_run(tmp_path):
    pile(tmp_path)
    out = tmp_path / 'out'  # (made by the recorder)
    names = sorted(os.listdir(out))
    for kind, ext in (('spheres', 'vtu'), ('facets', 'vtu'), ('boxes', 'vtu'), ('intrs', 'vtp')):
        assert sorted('p-%s.%d.%s' % (kind, i, ext) for i in (0, 50, 100)) == [n for n in names if n.startswith('p-%s.' % kind) and n.endswith(ext)]
        assert 'p-%s.pvd' % kind in names
    assert not any('pericell' in n for n in names)  # aperiodic: no cell
    pvd = vtk.vtkXMLCollectionReader if hasattr(vtk, 'vtkXMLCollectionReader') else None
    text = (out / 'p-spheres.pvd').read_text()
    assert text.count('<DataSet ') == 3 and 'file="p-spheres.100.vtu"' in text
    t100 = float(text.split('file="p-spheres.100.vtu"')[0].rsplit('timestep="', 1)[1].split('"')[0])
    assert t100 == pytest.approx(100 * O.dt, rel=1e-12)
    if pvd:
        r = pvd()
        r.SetFileName(str(out / 'p-spheres.pvd'))
        r.Update()
        assert r.GetNumberOfOutputPorts() >= 1


def test_spheres_hold_the_engine_state(tmp_path):
    pile(tmp_path)
    d = read(tmp_path / 'out' / 'p-spheres.100.vtu')
    ids = sphere_ids()
    assert d.GetNumberOfPoints() == len(ids) == d.GetNumberOfCells()
    a = arrays(d)
    assert list(a['id']) == ids
    np.testing.assert_array_equal(points(d), [list(O.bodies[i].state.pos) for i in ids])
    np.testing.assert_array_equal(a['radii'], [O.bodies[i].shape.radius for i in ids])
    np.testing.assert_array_equal(a['linVelVec'], [list(O.bodies[i].state.vel) for i in ids])
    np.testing.assert_array_equal(a['angVelVec'], [list(O.bodies[i].state.angVel) for i in ids])
    np.testing.assert_allclose(a['linVelLen'], [O.bodies[i].state.vel.norm() for i in ids], rtol=1e-15)
    np.testing.assert_array_equal(a['mass'], [O.bodies[i].state.mass for i in ids])
    np.testing.assert_array_equal(a['mask'], [O.bodies[i].mask for i in ids])
    np.testing.assert_array_equal(a['clumpId'], [-1] * len(ids))
    np.testing.assert_array_equal(a['materialId'], [O.bodies[i].material.id for i in ids])
    np.testing.assert_allclose(a['color'], [[.2, .4, .6]] * len(ids))
    assert 'sigI' not in a  # bstresses is not part of 'all'


def test_facets_and_boxes(tmp_path):
    pile(tmp_path)
    f = read(tmp_path / 'out' / 'p-facets.100.vtu')
    assert f.GetNumberOfCells() == 1 and f.GetCellType(0) == vtk.VTK_TRIANGLE
    np.testing.assert_allclose(points(f), [(-1, -1, -.1), (2, -1, -.1), (-1, 2, -.1)], atol=1e-14)
    fa = arrays(f, cells=True)
    fid = [b.id for b in O.bodies if b.shape.__class__.__name__ == 'Facet'][0]
    np.testing.assert_allclose(fa['stressVec'][0], np.array(O.forces.f(fid)) / O.bodies[fid].shape.area, rtol=1e-14)
    np.testing.assert_allclose(fa['color'][0], (1, 0, 0))
    b = read(tmp_path / 'out' / 'p-boxes.100.vtu')
    assert b.GetNumberOfCells() == 1 and b.GetCellType(0) == vtk.VTK_HEXAHEDRON
    corners = points(b)
    np.testing.assert_allclose(corners.min(axis=0), (2.7, 2.8, -.2), atol=1e-14)
    np.testing.assert_allclose(corners.max(axis=0), (3.3, 3.2, 0), atol=1e-14)
    cell = vtk.vtkHexahedron()
    cell.DeepCopy(b.GetCell(0))
    # a well-ordered hexahedron has a positive volume in VTK's mesh quality
    q = vtk.vtkMeshQuality.HexVolume(cell)
    assert q == pytest.approx(.6 * .4 * .2, rel=1e-12)


def test_force_chains(tmp_path):
    pile(tmp_path)
    d = read(tmp_path / 'out' / 'p-intrs.100.vtp')
    real = [i for i in O.interactions if i.isReal and isinstance(O.bodies[i.id1].shape, Sphere)
            and isinstance(O.bodies[i.id2].shape, Sphere)]
    assert len(real) > 20
    assert d.GetNumberOfCells() == len(real) and d.GetNumberOfLines() == len(real)
    c = arrays(d, cells=True)
    p = points(d)
    byEnds = {frozenset((tuple(p[2 * k]), tuple(p[2 * k + 1]))): k for k in range(len(real))}
    for i in real:
        k = byEnds[frozenset((tuple(O.bodies[i.id1].state.pos), tuple(O.bodies[i.id2].state.pos)))]
        assert c['forceN'][k] == pytest.approx(i.phys.normalForce.norm(), rel=1e-15)
        assert c['absForceT'][k] == pytest.approx(i.phys.shearForce.norm(), rel=1e-15, abs=1e-300)
        np.testing.assert_array_equal(c['forceNvec'][k], list(i.phys.normalForce))


def test_intrs_with_facets_when_asked(tmp_path):
    pile(tmp_path, recorders=['intr'], skipFacetIntr=False)
    d = read(tmp_path / 'out' / 'p-intrs.100.vtp')
    assert d.GetNumberOfCells() == len([i for i in O.interactions if i.isReal])


def test_periodic_cell_wrapped_spheres_and_chains_across_the_boundary(tmp_path):
    O.reset()
    O.periodic = True
    O.cell.hSize = Matrix3(1, .2, 0, 0, 1, 0, 0, 0, 1)
    # two spheres touching across the x boundary, one outside the cell (it is written at its image inside)
    O.bodies.append([utils.sphere((.05, .5, .5), .1), utils.sphere((1.1, .5, .5), .1)])
    O.bodies[0].state.vel = (-1, 0, 0)
    rec = VTKRecorder(fileName=str(tmp_path / 'c-'), recorders=['spheres', 'intr', 'pericell'], iterPeriod=1)
    O.engines = engines(rec)
    O.engines[3].gravity = (0, 0, 0)
    O.dt = 1e-5
    O.run(2, True)
    cell = read(tmp_path / 'c-pericell.1.vtu')
    H = np.array([list(O.cell.hSize.row(i)) for i in range(3)])
    frac = [(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1), (0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)]
    np.testing.assert_allclose(points(cell), [H @ np.array(f) for f in frac], atol=1e-15)
    assert cell.GetCellType(0) == vtk.VTK_HEXAHEDRON
    s = points(read(tmp_path / 'c-spheres.1.vtu'))
    frac = np.linalg.solve(H, s.T).T
    assert ((frac >= 0) & (frac < 1)).all()
    np.testing.assert_allclose(s[1], list(O.cell.wrap(O.bodies[1].state.pos)), atol=1e-15)
    intrs = read(tmp_path / 'c-intrs.1.vtp')
    assert intrs.GetNumberOfCells() == 1
    p = points(intrs)
    i = O.interactions[0, 1]
    # the line has the contact's real length: the distance to the image
    branch = np.array(list(O.bodies[1].state.pos)) + H @ np.array(list(i.cellDist)) - np.array(list(O.bodies[0].state.pos))
    np.testing.assert_allclose(p[1] - p[0], branch, atol=1e-14)
    assert np.linalg.norm(branch) < .2


# The reference (Yade 2023.02a) on the same three spheres, two steps (normalStress, normalStressNorm):
# 'stress' sums each contact's normalForce over π·min(r1, r2)²; its shearStress is left out of the
# comparison (doc/vtk.md: the reference's values do not follow from the contacts' shear forces).
REFERENCE_NORMAL_STRESS = [[848826.3558744026, 318310.4916632865, 0.0], [848826.3558584047, 0.6063913860106986, 0.0],
                           [1.5997937596760074e-05, 318309.8852719005, 0.0]]
REFERENCE_SIG = [(0.0, -151197.19473607742, -226795.79335887244), (0.0, 0.0, -572957.7926972276),
                 (0.0, 0.0, -226795.79335881685)]


def test_stress_arrays_match_the_reference_and_body_stress_tensors(tmp_path):
    O.reset()
    O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((1.4, 0, 0), .5), utils.sphere((0, 1.9, 0), 1)])
    rec = VTKRecorder(fileName=str(tmp_path / 'st-'), recorders=['spheres', 'stress', 'bstresses', 'velocity'], iterPeriod=1)
    O.engines = engines(rec)
    O.engines[3].gravity = (0, 0, 0)
    O.bodies[1].state.vel = (0, 1, 0)
    O.bodies[0].state.angVel = (0, 0, 1)
    O.dt = 1e-6
    O.run(2, True)
    a = arrays(read(tmp_path / 'st-spheres.1.vtu'))
    np.testing.assert_allclose(a['normalStress'], REFERENCE_NORMAL_STRESS, rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(a['normalStressNorm'], np.linalg.norm(REFERENCE_NORMAL_STRESS, axis=1), rtol=1e-9)
    # shear: the same rule as the normal part, with each contact's shearForce
    expect = np.zeros((3, 3))
    for i in O.interactions:
        r = min(O.bodies[i.id1].shape.radius, O.bodies[i.id2].shape.radius)
        for b in (i.id1, i.id2):
            expect[b] += np.array(list(i.phys.shearForce)) / (math.pi * r * r)
    np.testing.assert_allclose(a['shearStress'], expect, rtol=1e-12, atol=1e-300)
    # principal stresses: the reference's large ones, and the eigen-decomposition of utils.bodyStressTensors
    sig = np.stack([a['sigI'], a['sigII'], a['sigIII']], axis=1)
    for b, t in enumerate(utils.bodyStressTensors()):
        m = np.array([list(t.row(k)) for k in range(3)])
        w, v = np.linalg.eigh(.5 * (m + m.T))
        np.testing.assert_allclose(sig[b], w[::-1], rtol=1e-12, atol=1e-6)
        np.testing.assert_allclose(abs(np.dot(a['dirIII'][b], v[:, 0])), 1, atol=1e-9)
    big = np.abs(REFERENCE_SIG) > 1
    np.testing.assert_allclose(sig[big], np.array(REFERENCE_SIG)[big], rtol=1e-9)


@pytest.mark.parametrize('mode', [dict(ascii=True), dict(compress=True), dict()])
def test_ascii_and_compressed_files_hold_the_same_values(tmp_path, mode):
    pile(tmp_path, recorders=['spheres', 'velocity'], **mode)
    path = tmp_path / 'out' / 'p-spheres.100.vtu'
    head = path.read_bytes()[:400]
    assert (b'format="ascii"' in head) == bool(mode.get('ascii'))
    assert (b'vtkZLibDataCompressor' in head) == bool(mode.get('compress'))
    d = read(path)
    ids = sphere_ids()
    tol = dict(rtol=1e-15) if not mode.get('ascii') else dict(rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(points(d), [list(O.bodies[i].state.pos) for i in ids], **tol)
    np.testing.assert_allclose(arrays(d)['linVelVec'], [list(O.bodies[i].state.vel) for i in ids], **tol)


def test_multiblock(tmp_path):
    pile(tmp_path, multiblock=True)
    out = tmp_path / 'out'
    assert (out / 'p-100.vtm').exists() and (out / 'p-series.pvd').exists()
    m = read(out / 'p-100.vtm')
    names = [m.GetMetaData(k).Get(vtk.vtkCompositeDataSet.NAME()) for k in range(m.GetNumberOfBlocks())]
    assert names == ['spheres', 'facets', 'boxes', 'intrs']
    assert m.GetBlock(0).GetNumberOfPoints() == len(sphere_ids())
    assert m.GetBlock(1).GetNumberOfCells() == 1


def test_mask_and_skip_nondynamic(tmp_path):
    O.reset()
    O.bodies.append([utils.sphere((0, 0, 0), .1, mask=1), utils.sphere((1, 0, 0), .1, mask=2),
                     utils.sphere((2, 0, 0), .1, fixed=True, mask=3)])
    rec = VTKRecorder(fileName=str(tmp_path / 'm-'), recorders=['spheres', 'ids'], iterPeriod=1, mask=2)
    rec2 = VTKRecorder(fileName=str(tmp_path / 'n-'), recorders=['spheres', 'ids'], iterPeriod=1, skipNondynamic=True)
    O.engines = engines(rec, [rec2])
    O.dt = 1e-5
    O.step()
    assert list(arrays(read(tmp_path / 'm-spheres.0.vtu'))['id']) == [1, 2]
    assert list(arrays(read(tmp_path / 'n-spheres.0.vtu'))['id']) == [0, 1]


def test_bad_input(tmp_path):
    with pytest.raises(ValueError, match="unknown recorder 'sphere'.*spheres"):
        VTKRecorder(recorders=['sphere'])
    r = VTKRecorder()
    with pytest.raises(ValueError):
        r.recorders = ['spheres', 'forces']
    assert r.recorders == ['all']
    O.reset()
    O.bodies.append(utils.sphere((0, 0, 0), .1))
    blocker = tmp_path / 'file'
    blocker.write_text('not a folder')
    O.engines = engines(VTKRecorder(fileName=str(blocker / 'x-'), iterPeriod=1))
    O.dt = 1e-5
    with pytest.raises(RuntimeError, match='VTKRecorder: cannot make the folder .*file'):
        O.step()


def test_the_build_says_it_has_vtk():
    assert 'VTK' in yade.config.features
    assert yade.libVersions.getAllVersionsCpp()['vtk'][0][0] == 9
