"""The module layout of the reference (yade.wrapper, system, config, math, minieigenHP,
_customConverters, ymport, export) and the text formats of ymport/export.

Expected file contents and imported values were produced by the reference, Yade 2023.02a, on the
same scenes: `yade-double -n -x exp.py` (export.text / textExt) and `yade-double -n -x imp.py`
(ymport.text / textExt / textFacets / stl), scripts doing what each test below does."""
import struct

import pytest

import yade
from yade import O, utils, Vector3, FrictMat, export, ymport

pytestmark = pytest.mark.usefixtures("fresh_scene")


def test_wrapper_has_every_class():
    from yade import wrapper
    names = yade._yade._classNames()
    assert set(names) <= set(wrapper.__all__) and 'Omega' in wrapper.__all__ and 'O' in wrapper.__all__
    ns = {}
    exec('from yade.wrapper import *', ns)
    assert ns['Sphere'] is yade.Sphere and ns['O'] is O
    assert yade.Sphere.__module__ == 'yade.wrapper'


def test_system_child_classes():
    from yade import system
    assert system.childClasses('Shape') >= {'Sphere', 'Facet', 'Wall', 'Box'}
    assert 'Shape' not in system.childClasses('Shape')
    assert 'Shape' in system.childClasses('Shape', includeBase=True)
    assert 'FrictMat' in system.childClasses('Material') and 'FrictMat' not in system.childClasses('Material', recurse=False)
    assert system.childClasses('NoSuchClass') == set()  # (as the reference)
    with pytest.raises(TypeError):
        system.childClasses(yade.Shape)
    d = system.cxxCtorsDict()
    assert d['Sphere'] is yade.Sphere
    with pytest.warns(DeprecationWarning, match='FrictMat'):
        m = d['GranularMat'](young=5.)
    assert type(m) is FrictMat and m.young == 5.
    ns = {}
    exec('from yade import *', ns)  # the old names are at top level too, as in the reference's launcher
    assert 'InteractionGeometry' in ns and 'GranularMat' in ns


def test_config():
    from yade import config
    assert config.version == config.revision == yade.version
    assert ('OPENMP' in config.features) == yade._yade.openmp
    assert config.highPrecisionDecimalPlaces == 15 and config.highPrecisionName == 'PrecisionDouble'


def test_math_modules():
    from yade import math as ymath, minieigenHP
    assert minieigenHP.Vector3 is Vector3 and 'Quaternion' in minieigenHP.__all__
    assert ymath.sqrt(4.) == 2 and ymath.Pi() == pytest.approx(3.141592653589793)
    assert ymath.RealHPConfig.getSupportedByMinieigen() == (1,) and ymath.getDigits10(1) == 15
    assert ymath.round(2.5) == 3.0 and ymath.rint(2.5) == 2.0 and ymath.sgn(-2.) == -1
    with pytest.raises(ValueError):
        ymath.getDigits10(2)
    # abs() of a vector, matrix or quaternion is its norm, as the reference's (3.7416573867739413, 1.7320508075688772)
    from yade import Matrix3, Quaternion
    assert abs(Vector3(-1, 2, -3)) == pytest.approx(3.7416573867739413, rel=1e-15)
    assert abs(Matrix3(-1, 0, 0, 0, 1, 0, 0, 0, 1)) == pytest.approx(1.7320508075688772, rel=1e-15)
    assert abs(Quaternion.Identity) == 1.0
    ns = {}
    exec('import math\nfrom yade import *', ns)
    assert ns['math'].pi == 3.141592653589793  # `from yade import *` does not hide Python's math
    exec('from yade._customConverters import *', ns)


def _exportScene():
    O.materials.append(FrictMat(young=1e6, label='m2'))
    O.bodies.append([utils.sphere((0, 0, 0), 1), utils.sphere((1.5, 0.25, -3.125), 0.5, material='m2'),
                     utils.sphere((1e-7, 123456.789, 1 / 3.), 2e-3), utils.facet([(0, 0, 0), (1, 0, 0), (0, 1, 0)]),
                     utils.wall(0, axis=2)])
    O.bodies[0].state.vel = (1, 2, 3)


def test_export_text_as_the_reference(tmp_path):
    _exportScene()
    rows = '0\t0\t0\t1\n1.5\t0.25\t-3.125\t0.5\n1e-07\t123457\t0.333333\t0.002\n'
    assert export.text(str(tmp_path / 't.txt')) == 3
    assert (tmp_path / 't.txt').read_text() == '#format x_y_z_r\n' + rows
    export.textExt(str(tmp_path / 'c.txt'), format='x_y_z_r', comment='my comment')
    assert (tmp_path / 'c.txt').read_text() == '#format x_y_z_r\n# my comment\n' + rows
    export.textExt(str(tmp_path / 'm.txt'), format='x_y_z_r_matId', comment='my comment')
    assert (tmp_path / 'm.txt').read_text() == ('#format x_y_z_r_matId\n# my comment\n0\t0\t0\t1\t0\n1.5\t0.25\t-3.125\t0.5\t0\n'
                                                 '1e-07\t123457\t0.333333\t0.002\t0\n')
    export.textExt(str(tmp_path / 'a.txt'), format='x_y_z_r_attrs', comment='my comment', attrs=['b.state.vel[0]', 'b.state.mass'])
    assert (tmp_path / 'a.txt').read_text() == ('#format x_y_z_r_attrs\n# x y z r my comment\n0\t0\t0\t1\t1\t4188.79\n'
                                                 '1.5\t0.25\t-3.125\t0.5\t0\t523.599\n1e-07\t123457\t0.333333\t0.002\t0\t3.35103e-05\n')
    export.textExt(str(tmp_path / 'v.txt'), format='x_y_z_r_attrs', comment='vx vy vz', attrs=['b.state.vel'])
    assert (tmp_path / 'v.txt').read_text().split('\n')[2] == '0\t0\t0\t1\t1\t2\t3'
    with pytest.raises(ValueError, match='unknown format'):
        export.textExt(str(tmp_path / 'x.txt'), format='nonexistent')
    with pytest.raises(RuntimeError):  # (the reference raises RuntimeError)
        export.textExt(str(tmp_path / 'x.txt'), format='nonexistent')


def _materials():
    O.materials.append(FrictMat(young=1e6, label='m0'))
    O.materials.append(FrictMat(young=2e6, label='m1'))


def test_ymport_spheres_as_the_reference(tmp_path):
    _materials()
    (tmp_path / 'va.txt').write_text('#format x_y_z_r_attrs\n# x y z r vx vy vz m\n0\t0\t0\t1\t0\t0\t0\t4188.79\n'
                                     '1.5\t0.25\t-3.125\t0.5\t0\t0\t0\t523.599\n')
    attrs = []
    bs = ymport.textExt(str(tmp_path / 'va.txt'), format='x_y_z_r_attrs', attrs=attrs, shift=(1, 0, 0), scale=2)
    assert attrs == [['0', '0', '0', '4188.79'], ['0', '0', '0', '523.599']]
    assert [(b.state.pos, b.shape.radius) for b in bs] == [(Vector3(1, 0, 0), 2.0), (Vector3(4, 0.5, -6.25), 1.0)]
    (tmp_path / 'mi.txt').write_text('#format x_y_z_r_matId\n0\t0\t0\t1\t1\n1.5\t0.25\t-3.125\t0.5\t0\n')
    assert [b.material.label for b in ymport.textExt(str(tmp_path / 'mi.txt'), format='x_y_z_r_matId')] == ['m1', 'm0']
    (tmp_path / 't.txt').write_text('#format x_y_z_r\n0\t0\t0\t1\n1.5\t0.25\t-3.125\t0.5\n1e-07\t123457\t0.333333\t0.002\n\n')
    bs = ymport.text(str(tmp_path / 't.txt'), shift=Vector3(0, 0, 1), scale=0.5)
    assert [b.shape.radius for b in bs] == [0.5, 0.25, 0.001] and all(b.material.label == 'm1' for b in bs)
    assert bs[1].state.pos == Vector3(0.75, 0.125, -0.5625)
    assert bs[2].state.pos[2] == pytest.approx(1.1666665)
    (tmp_path / 'bad.txt').write_text('1 2 3\n')
    with pytest.raises(ValueError, match='bad.txt:1'):
        ymport.text(str(tmp_path / 'bad.txt'))
    with pytest.raises(FileNotFoundError):
        ymport.text(str(tmp_path / 'missing.txt'))


def test_ymport_facets_as_the_reference(tmp_path):
    _materials()
    a, b = 0.5857864376269049655, 1.414213562373094923
    (tmp_path / 'f.txt').write_text('# facets\n0 0 0 1 0 0 0 1 0\n0 0 1 1 0 1 0 1 1\n')
    fs = ymport.textFacets(str(tmp_path / 'f.txt'), shift=Vector3(0, 0, 1), scale=2)
    for f, z in zip(fs, (1, 3)):
        assert (f.state.pos - Vector3(a, a, z)).norm() < 1e-15 and not f.dynamic
        for v, ref in zip(f.shape.vertices, [(-a, -a, 0), (b, -a, 0), (-a, b, 0)]):
            assert (v - Vector3(ref)).norm() < 1e-15
    (tmp_path / 'fm.txt').write_text('0 0 0 1 0 0 0 1 0 1\n')
    assert [f.material.label for f in ymport.textFacets(str(tmp_path / 'fm.txt'), format='x1_y1_z1_x2_y2_z2_x3_y3_z3_matId')] == ['m1']
    (tmp_path / 'fid.txt').write_text('7 0 0 0 1 0 0 0 1 0 0\n')
    assert [f.material.label for f in ymport.textFacets(str(tmp_path / 'fid.txt'), format='id_x1_y1_z1_x2_y2_z2_x3_y3_z3_matId')] == ['m0']


def test_ymport_stl(tmp_path):
    a, b = 0.5857864376269049655, 1.414213562373094923
    (tmp_path / 'a.stl').write_text('solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n'
                                    '  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n   vertex 1 0 0\n   vertex 1 1 0\n'
                                    '   vertex 0 1 0\n  endloop\n endfacet\nendsolid t\n')
    fs = ymport.stl(str(tmp_path / 'a.stl'), shift=Vector3(0, 0, 1), scale=2)
    assert len(fs) == 2 and all(f.shape.wire and not f.dynamic for f in fs)
    assert (fs[0].state.pos - Vector3(a, a, 1)).norm() < 1e-15 and (fs[1].state.pos - Vector3(b, b, 1)).norm() < 1e-15
    assert (fs[1].shape.vertices[0] - Vector3(a, -b, 0)).norm() < 1e-15
    with open(tmp_path / 'b.stl', 'wb') as f:  # the same first triangle, binary, scaled by 2 in the file
        f.write(b'\0' * 80 + struct.pack('<I', 1) + struct.pack('<12fH', 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0))
    fb = ymport.stl(str(tmp_path / 'b.stl'), shift=(0, 0, 1))
    assert len(fb) == 1 and (fb[0].state.pos - fs[0].state.pos).norm() < 1e-15
    (tmp_path / 'c.stl').write_text('not an stl')
    with pytest.raises(ValueError, match='STL'):
        ymport.stl(str(tmp_path / 'c.stl'))


def test_export_ymport_round_trip(tmp_path):
    O.bodies.append([utils.sphere((i * 0.25, 1 - i * 0.5, 2.5), 0.125 * (i + 1)) for i in range(4)])
    export.textExt(str(tmp_path / 'r.txt'), format='x_y_z_r_matId')
    bs = ymport.textExt(str(tmp_path / 'r.txt'), format='x_y_z_r_matId')
    assert [(b.state.pos, b.shape.radius) for b in bs] == [(b.state.pos, b.shape.radius) for b in O.bodies]


def test_ymport_gmsh_as_the_reference(tmp_path):
    import math
    from yade import Quaternion
    (tmp_path / 'm.mesh').write_text('MeshVersionFormatted 1\nDimension\n3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n'
                                     'Triangles\n2\n1 2 3 0\n1 2 4 0\nEnd\n')
    fs = ymport.gmsh(str(tmp_path / 'm.mesh'), shift=Vector3(1, 2, 3), scale=2, orientation=Quaternion((0, 0, 1), math.pi / 2))
    # reference: [(1,2,3), (1,4,3), (-1,2,3)] and [(1,2,3), (1,4,3), (1,2,5)], fixed, wire
    ref = [[(1, 2, 3), (1, 4, 3), (-1, 2, 3)], [(1, 2, 3), (1, 4, 3), (1, 2, 5)]]
    assert len(fs) == 2
    for f, r in zip(fs, ref):
        assert not f.dynamic and f.shape.wire
        for v, rv in zip(f.shape.vertices, r):
            assert (f.state.pos + f.state.ori * v - Vector3(rv)).norm() < 1e-14
    (tmp_path / 'bad.mesh').write_text('Vertices\n2\n0 0 0 0\n')
    with pytest.raises(ValueError, match='bad.mesh'):
        ymport.gmsh(str(tmp_path / 'bad.mesh'))


HEADER = 'FoamFile\n{\n    version 2.0; // a comment\n    format ascii;\n}\n/* a block\n comment */\n'


def test_ymport_openfoam_block_mesh_dict(tmp_path):
    # a unit cube in mm: two facets per quadrilateral of the boundary (v0 v1 v2, v2 v3 v0), as the reference
    (tmp_path / 'blockMeshDict').write_text(HEADER + """
convertToMeters 0.001;
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1) );
blocks ( hex (0 1 2 3 4 5 6 7) (2 2 2) simpleGrading (1 1 1) );
boundary
(
    bottom { type wall; faces ( (0 3 2 1) ); }
    sides { type patch; faces ( (0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7) ); }
    top { type empty; faces ( (4 5 6 7) ); }
    other { type symmetry; faces ( (4 5 6 7) ); }
);
""")
    fs = ymport.blockMeshDict(str(tmp_path / 'blockMeshDict'))
    assert len(fs) == 12
    first = [fs[0].state.pos + fs[0].state.ori * v for v in fs[0].shape.vertices]
    for v, ref in zip(first, [(0, 0, 0), (0, 0.001, 0), (0.001, 0.001, 0)]):
        assert (v - Vector3(ref)).norm() < 1e-15
    assert len(ymport.blockMeshDict(str(tmp_path / 'blockMeshDict'), patchasWall=False)) == 4
    assert len(ymport.blockMeshDict(str(tmp_path / 'blockMeshDict'), patchasWall=False, emptyasWall=False)) == 2


def test_ymport_openfoam_poly_mesh(tmp_path):
    # the boundary faces of a polyMesh: n facets around the center of each n-gon (320 for the
    # reference's own test mesh of 80 quadrilaterals, as there)
    d = tmp_path / 'polyMesh'
    d.mkdir()
    (d / 'points').write_text(HEADER + '8\n(\n(0 0 0)\n(1 0 0)\n(1 1 0)\n(0 1 0)\n(0 0 1)\n(1 0 1)\n(1 1 1)\n(0 1 1)\n)\n')
    (d / 'faces').write_text(HEADER + '6\n(\n4(0 3 2 1)\n4(0 1 5 4)\n4(1 2 6 5)\n4(2 3 7 6)\n4(3 0 4 7)\n4(4 5 6 7)\n)\n')
    (d / 'boundary').write_text(HEADER + """2
(
    walls { type wall; inGroups List<word> 1(wall); nFaces 5; startFace 0; }
    lid { type patch; nFaces 1; startFace 5; }
)
""")
    fs = ymport.polyMesh(str(d))
    assert len(fs) == 24
    assert len(ymport.polyMesh(str(d), patchasWall=False)) == 20
    corners = [fs[0].state.pos + fs[0].state.ori * v for v in fs[0].shape.vertices]
    for v, ref in zip(corners, [(0, 0, 0), (0, 1, 0), (0.5, 0.5, 0)]):
        assert (v - Vector3(ref)).norm() < 1e-15


def test_ymport_stl_reads_single_precision_as_the_reference(tmp_path):
    """The reference reads an ASCII STL's coordinates in single precision, as a binary STL holds them; the facet's
    position (the inscribed circle's center) then has its bits too (a triangle of its baraban.stl example)."""
    (tmp_path / 'd.stl').write_text('solid t\nfacet normal 0 0 1\n outer loop\n  vertex -4.534013748168945 -2.114242792129517 -4.386539459228516\n'
                                    '  vertex -4.832266330718994 -1.2947998046875 -4.386539459228516\n'
                                    '  vertex -4.80000114440918 -1.300000667572021 4.613460063934326\n endloop\nendfacet\nendsolid t\n')
    f = ymport.stl(str(tmp_path / 'd.stl'))[0]
    assert list(f.state.pos + f.shape.vertices[0]) == [-4.5340137481689453, -2.1142427921295166, -4.3865394592285156]
    assert list(f.state.pos) == [-4.6888485157800499, -1.6849897814324837, -3.9715659316910608]
