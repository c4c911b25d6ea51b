"""utils.totalForceInVolume, bodyNumInteractionsHistogram, interactionAnglesHistogram, coordsAndDisplacements,
approxSectionArea, pointInsidePolygon, spiralProject, setNewVerticesOfFacet, vmData, voxelPorosity, defaultEngines,
TableParamReader. The figures are the reference's (Yade 2023.02a, `yade -n -x`) printed on the same scenes."""
import math

import pytest

import yade
from yade import O, utils, Vector3
from yade.wrapper import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb, InteractionLoop,
                          Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                          Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator)

A = lambda x: pytest.approx(x, rel=1e-9, abs=1e-12)  # noqa: E731


@pytest.fixture
def scene():
    O.reset()
    O.bodies.append([utils.facet([(-1, -1, 0), (2, -1, 0), (-1, 2, 0)]), utils.facet([(2, 2, 0), (-1, 2, 0), (2, -1, 0)])])
    O.bodies.append([utils.sphere((0, 0, .09), .1), utils.sphere((.15, 0.02, .09), .1), utils.sphere((.05, .16, .1), .1),
                     utils.sphere((.07, .06, .26), .1), utils.sphere((.5, .5, .3), .12)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81))]
    O.dt = 1e-4
    O.run(5, True)
    yield
    O.reset()


def test_totalForceInVolume(scene):
    f, k = utils.totalForceInVolume()
    # reference: (Vector3(76003.19162955967477,63922.40361963110627,49320.85689924020699), 592592.5925925924)
    assert tuple(f) == A((76003.19162955967477, 63922.40361963110627, 49320.85689924020699))
    assert k == A(592592.5925925924)
    O.reset()
    assert utils.totalForceInVolume() == (Vector3(0, 0, 0), -1.0)  # reference


def test_bodyNumInteractionsHistogram(scene):
    # reference's figures
    assert utils.bodyNumInteractionsHistogram(utils.aabbExtrema()) == ([0, 3, 4], [1, 1, 3])
    assert utils.bodyNumInteractionsHistogram(((-1, -1, -1), (0.1, 1, 1))) == ([3, 4], [2, 2])
    assert utils.bodyNumInteractionsHistogram(((-1, -1, -1), (2, 2, 2))) == ([0, 3, 4], [2, 2, 3])
    with pytest.raises(TypeError):
        utils.bodyNumInteractionsHistogram([(-1, -1, -1), (2, 2, 2)])
    with pytest.raises(ValueError):
        utils.bodyNumInteractionsHistogram(((-1, -1, -1),))


STARTS20 = [i * math.pi / 20 for i in range(20)]
STARTS5 = [0.0, 0.6283185307179586, 1.2566370614359172, 1.8849555921538759, 2.5132741228718345]


def test_interactionAnglesHistogram(scene):
    # reference's figures
    s, h = utils.interactionAnglesHistogram(0)
    assert s == A(STARTS20)
    assert h == A([1.767254615782297, 0, 0, 0, 0, 0, 0, 0, 0.9305484362657162, 0.906975551570879, 3.0, 0, 0, 0, 0.9944083791948243, 0, 0, 0, 0, 0])
    assert utils.interactionAnglesHistogram(1)[1] == A([3.0, 0.847911908847672, 0, 0.9499334140770643, 0, 0, 0, 0, 0, 0.3055112805330566,
                                                        0.9911579346568676, 0.5845278680917361, 0, 0, 0, 0, 0, 0.977947825485701, 0, 0])
    assert utils.interactionAnglesHistogram(2)[1] == A([0, 0.9999999940200626, 0, 0, 0.4813586153621048, 0, 0, 0, 0.9983380064779039, 0, 0,
                                                        0.5405528375852073, 0, 0, 0.9984145616074043, 0, 0, 0.4701206222667635, 0, 0])
    s, h = utils.interactionAnglesHistogram(2, bins=5)
    assert s == A(STARTS5)
    assert h == A([0.9999999940200626, 0.4813586153621048, 0.9983380064779039, 1.5389673991926116, 0.4701206222667635])
    assert utils.interactionAnglesHistogram(2, bins=5, aabb=((-1, -1, -1), (0.1, 1, 0.15)))[1] == A(
        [0.9999999940200626, 0.4813586153621048, 0.9983380064779039, 1.5389673991926116, 0.0])
    assert utils.interactionAnglesHistogram(2, bins=5, minProjLen=0.5)[1] == A([0.9999999940200626, 0, 0.9983380064779039, 1.5389673991926116, 0])
    assert utils.interactionAnglesHistogram(0, bins=4, sphSph=True)[1] == A([1.767254615782297, 0.0, 1.8375239878365952, 0.9944083791948243])
    assert utils.interactionAnglesHistogram(0, bins=4)[1] == A([1.767254615782297, 0.0, 4.837523987836595, 0.9944083791948243])
    assert utils.interactionAnglesHistogram(2, bins=1)[0] == [0.0]
    assert utils.interactionAnglesHistogram(2, bins=1)[1] == A([2.479696615860071])
    assert utils.interactionAnglesHistogram(1, bins=3)[1] == A([4.797845322924736, 0.3055112805330566, 1.5756858027486036])
    assert utils.interactionAnglesHistogram(2, bins=0) == ([], [])
    O.bodies[5].mask = 2
    assert utils.interactionAnglesHistogram(2, mask=1, bins=5)[1] == A([0.9999999940200626, 0, 0.9983380064779039, 0.9984145616074043, 0])
    assert utils.interactionAnglesHistogram(2, mask=2, bins=5)[1] == [0.0] * 5
    assert utils.interactionAnglesHistogram(2, mask=3, bins=5)[1] == A(
        [0.9999999940200626, 0.4813586153621048, 0.9983380064779039, 1.5389673991926116, 0.4701206222667635])
    for bad in (3, -1):
        with pytest.raises(ValueError, match='Axis must be from'):
            utils.interactionAnglesHistogram(bad)
    with pytest.raises(ValueError, match='bins'):
        utils.interactionAnglesHistogram(2, bins=-1)


def test_coordsAndDisplacements(scene):
    # reference's figures
    c, d = utils.coordsAndDisplacements(0)
    assert c == A([-0.1213203435596425, 1.1213203435596424, -0.0016966664349338943, 0.1519044121961154, 0.04978713235776696, 0.07000480775131337, 0.5])
    assert d == A([0.0, 0.0, -0.0016966664349338943, 0.001904412196115396, -0.00021286764223304305, 4.8077513133681915e-06, 0.0])
    c, d = utils.coordsAndDisplacements(2)
    assert c == A([0.0, 0.0, 0.09016348465211278, 0.0901382913356004, 0.09985684046520327, 0.2605997267155791, 0.2999988228])
    assert d == A([0.0, 0.0, 0.00016348465211278584, 0.0001382913356004073, -0.00014315953479673849, 0.0005997267155791186, -1.1771999999798943e-06])
    c, d = utils.coordsAndDisplacements(0, ((-1, -1, -1), (0.1, 1, 0.15)))
    assert c == A([-0.1213203435596425, -0.0016966664349338943, 0.04978713235776696])
    assert d == A([0.0, -0.0016966664349338943, -0.00021286764223304305])
    with pytest.raises(ValueError):
        utils.coordsAndDisplacements(3)
    with pytest.raises(ValueError):
        utils.coordsAndDisplacements(0, ((0, 0, 0),))


def test_approxSectionArea(scene):
    # reference's figures
    ref = {(0.05, 0): 0.13895420247752852, (0.05, 1): 0.14713739428150338, (0.05, 2): 0.13341338647053363,
           (0.1, 0): 0.13168251449917162, (0.1, 1): 0.13295094386226036, (0.1, 2): 0.13341338647053363,
           (0.2, 0): 0.05196152422706632, (0.2, 1): 0.05196152422706632, (0.2, 2): 0.27564856211556155,
           (0.3, 0): 0.0, (0.5, 0): 0.07482459488697552, (0.5, 1): 0.07482459488697549, (0.5, 2): 0.0, (2.0, 1): 0.0}
    for (coord, axis), v in ref.items():
        assert utils.approxSectionArea(coord, axis) == A(v), (coord, axis)
    with pytest.raises(ValueError):
        utils.approxSectionArea(0.1, 3)
    O.reset()
    O.bodies.append([utils.sphere((0, 0, 0), .1), utils.sphere((1, 0, 0), .3)])
    assert utils.approxSectionArea(0, 2) == A(1.0219099764656374)  # reference
    O.reset()
    O.bodies.append([utils.sphere((0, 0, 0), .1), utils.sphere((1, 1, 0), .1)])
    assert utils.approxSectionArea(0, 2) == A(0.4983716857408418)  # reference
    assert utils.approxSectionArea(0.1, 2) == A(0.4983716857408418)  # touching the plane counts (reference)


def test_pointInsidePolygon():
    sq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    assert utils.pointInsidePolygon((0.5, 0.5), sq)
    assert not utils.pointInsidePolygon((1.5, 0.5), sq)
    assert utils.pointInsidePolygon((0.9, 0.3), [(0, 0), (2, 0), (1, 1)])
    assert not utils.pointInsidePolygon((0.9, 0.5), [(0, 0), (2, 0), (0, 2), (1, 0.4)])  # in the notch of a concave one
    with pytest.raises(ValueError):
        utils.pointInsidePolygon((0.5, 0.5), [(0, 0), (1, 0)])
    with pytest.raises(TypeError):
        utils.pointInsidePolygon((0.5,), sq)


@pytest.mark.parametrize('args,ref', [  # the reference's figures
    ((Vector3(1, 0, 0), 1), ((1.0, 0.0), 0.0)),
    ((Vector3(0, 1, 0), 1), ((1.0, -1.5707963267948966), 1.5707963267948966)),
    ((Vector3(-1, 0, 0.5), 1), ((1.0, 3.6415926535897927), 3.141592653589793)),
    ((Vector3(0, -2, 3), 0.5), ((2.0, 3.7853981633974483), 4.71238898038469)),
    ((Vector3(0, -2, 3), 0.5, 2, 1), ((2.0, 0.6438055098076552), 4.71238898038469)),
    ((Vector3(0, -2, 3), 0.5, 2, float('nan'), 0.3), ((2.0, 0.7938055098076551), 4.71238898038469)),
    ((Vector3(0, -2, 3), 0.5, 2, 10, 0.3), ((2.0, -2.347787143782138), 10.995574287564276)),
    ((Vector3(0, -2, 3), 0.5, 2, -10, 0.3), ((2.0, 7.076990816987241), -7.853981633974483)),
    ((Vector3(0.3, -2, 3), 0.5, 0), ((3.605551275463989, 2.362193188418561), 2.1587989303424644)),
    ((Vector3(0.3, -2, 3), 0.5, 1), ((3.014962686336267, 1.0917583273442122), 0.09966865249116186)),
    ((Vector3(0, 0, 3), 0.5), ((0.0, -0.14159265358979312), 0.0)),
    (((1, 1, 3), 1), ((1.4142135623730951, 2.2146018366025517), 0.7853981633974484)),
    ((Vector3(1, 1, 3), -1), ((1.4142135623730951, -2.497787143782138), 0.7853981633974484)),
    ((Vector3(1, -1, -3), 1, 2, 0.5, 1), ((1.4142135623730951, -7.497787143782138), 5.497787143782138)),
    ((Vector3(1, -1, -3), 2, 2, -7, 4), ((1.4142135623730951, 6.570796326794897), -0.7853981633974492)),
])
def test_spiralProject(args, ref):
    (r, h), t = utils.spiralProject(*args)
    assert (r, h, t) == A((ref[0][0], ref[0][1], ref[1]))


def test_spiralProject_bad():
    with pytest.raises(ValueError):
        utils.spiralProject(Vector3(0.3, -2, 3), 0.5, 3)  # the reference aborts (Eigen assertion)
    assert math.isnan(utils.spiralProject(Vector3(1, 1, 3), 0)[0][1])  # reference: nan


def test_setNewVerticesOfFacet():
    O.reset()
    f = utils.facet([(0, 0, 0), (1, 0, 0), (0, 1, 0)])
    O.bodies.append(f)
    assert utils.setNewVerticesOfFacet(f, Vector3(1, 1, 1), Vector3(3, 1, 1), (1, 2, 2)) is None
    # reference's figures
    assert tuple(f.state.pos) == A((1.482361909794958521, 1.341081377402108865, 1.341081377402108865))
    vs = [tuple(v) for v in f.shape.vertices]
    assert vs[0] == A((-0.482361909794958521, -0.3410813774021088651, -0.3410813774021088651))
    assert vs[1] == A((1.517638090205041479, -0.3410813774021088651, -0.3410813774021088651))
    assert vs[2] == A((-0.482361909794958521, 0.6589186225978911349, 0.6589186225978911349))
    s = utils.sphere((0, 0, 0), 1)
    with pytest.raises(TypeError):  # the reference crashes
        utils.setNewVerticesOfFacet(s, Vector3(1, 1, 1), Vector3(3, 1, 1), Vector3(1, 2, 2))
    O.reset()


def test_vmData():
    v = utils.vmData()
    assert type(v) is int and v > 0


def test_voxelPorosity():
    O.reset()
    with pytest.raises(ValueError, match='start==end'):
        utils.voxelPorosity()
    with pytest.raises(ValueError, match='below 50'):
        utils.voxelPorosity(10, (0, 0, 0), (1, 1, 1))
    O.bodies.append(utils.sphere((0.5, 0.5, 0.5), 0.3))
    # the reference's figures; its voxel count differs from ours by a few voxels on the sphere's surface
    assert utils.voxelPorosity(50, (0, 0, 0), (1, 1, 1)) == pytest.approx(0.887688, abs=1e-3)
    assert utils.voxelPorosity(200, (0, 0, 0), (1, 1, 1)) == pytest.approx(0.887002375, abs=1e-4)
    assert utils.voxelPorosity(100, (0, 0, 0), (1, 0.5, 1)) == pytest.approx(0.88847, abs=1e-4)
    assert utils.voxelPorosity(50, (0, 0, -1), (1, 1, 1)) == pytest.approx(0.944128, abs=1e-3)
    assert utils.voxelPorosity(51, (-.2, 0.1, 0), (1, 1, 1.3)) == pytest.approx(0.9195030568936533, abs=1e-4)
    assert utils.voxelPorosity(60, (1, 1, 1), (0, 0, 0)) == 1.0
    assert utils.voxelPorosity(50, (0, 0, 0), (0, 1, 1)) == 1.0
    O.bodies.append([utils.sphere((0.9, 0.5, 0.5), 0.2), utils.facet([(0, 0, 0), (1, 0, 0), (0, 1, 0)])])
    assert utils.voxelPorosity(77, (0, 0, 0), (1, 1, 1)) == pytest.approx(0.8625115818571714, abs=1e-9)
    O.reset()


def test_defaultEngines():
    e = utils.defaultEngines
    # reference: [('ForceResetter', ''), ('InsertionSortCollider', 'collider'), ('InteractionLoop', 'interactionLoop'),
    #             ('GlobalStiffnessTimeStepper', 'timeStepper'), ('NewtonIntegrator', 'newton')]
    assert [(type(x).__name__, x.label) for x in e] == [('ForceResetter', ''), ('InsertionSortCollider', 'collider'),
                                                         ('InteractionLoop', 'interactionLoop'), ('GlobalStiffnessTimeStepper', 'timeStepper'),
                                                         ('NewtonIntegrator', 'newton')]
    assert [type(f).__name__ for f in e[1].boundDispatcher.functors] == ['Bo1_Sphere_Aabb', 'Bo1_Facet_Aabb', 'Bo1_Box_Aabb']
    assert [type(f).__name__ for f in e[2].geomDispatcher.functors + e[2].physDispatcher.functors + e[2].lawDispatcher.functors] == [
        'Ig2_Sphere_Sphere_ScGeom', 'Ig2_Facet_Sphere_ScGeom', 'Ig2_Box_Sphere_ScGeom', 'Ip2_FrictMat_FrictMat_FrictPhys',
        'Law2_ScGeom_FrictPhys_CundallStrack']
    assert (e[3].timeStepUpdateInterval, e[4].damping, tuple(e[4].gravity)) == (10, 0.2, (0, 0, 0))  # reference
    assert utils.defaultEngines is e


def test_TableParamReader(tmp_path):
    p = tmp_path / 't.txt'
    p.write_text("# comment\na b! c   # trailing\n\n1 2 x\n= 5 'y z'\n3 = =\n")
    # reference's answer
    assert utils.TableParamReader(str(p)).paramDict() == {
        4: {'a': '1', 'b': '2', 'c': 'x', 'description': 'b=2'}, 5: {'a': '1', 'b': '5', 'c': "'y", 'description': 'b=5'},
        6: {'a': '3', 'b': '5', 'c': "'y", 'description': 'b=5__line=6__'}}
    p.write_text('a description c\n1 first 3.5\n2 second =\n')
    assert utils.TableParamReader(str(p)).paramDict() == {2: {'a': '1', 'description': 'first', 'c': '3.5'},
                                                          3: {'a': '2', 'description': 'second', 'c': '3.5'}}
    with pytest.raises(FileNotFoundError):
        utils.TableParamReader(str(tmp_path / 'none.txt'))
    p.write_text('a b\n1 2\n3\n')
    with pytest.raises(ValueError):  # the reference: IndexError
        utils.TableParamReader(str(p))
