"""yade.utils functions of the manual and the reference's yade.utils, against the reference's numbers
on the same scene.

The reference figures were printed by Yade 2023.02a running the scene below followed by the same
calls: `yade-double -n -x probe.py` (scene: SCENE, then print(utils.<function>(...)))."""
import math

import pytest

from yade import (O, utils, Vector3, Matrix3, Bo1_Facet_Aabb, Bo1_Sphere_Aabb, ElastMat, ForceResetter, Ig2_Facet_Sphere_ScGeom,
                  Ig2_Sphere_Sphere_ScGeom, InsertionSortCollider, InteractionLoop, Ip2_FrictMat_FrictMat_FrictPhys,
                  Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator)

pytestmark = pytest.mark.usefixtures("fresh_scene")

SCENE = """
from yade import utils
O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb(), Bo1_Box_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()],
        [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.2)]
rs = [0.5, 0.45, 0.55, 0.5, 0.48, 0.52, 0.5, 0.47]
k = 0
for i in range(2):
    for j in range(2):
        for l in range(2):
            O.bodies.append(utils.sphere((i * 0.9 + 0.03 * l, j * 0.95, 0.5 + l * 0.9), rs[k])); k += 1
O.bodies.append(utils.wall(0.02, axis=2))
O.bodies.append(utils.facet([(-1, -1, 0.05), (3, -1, 0.05), (-1, 3, 0.05)]))
O.bodies.append(utils.box((2.3, 0.5, 0.5), (0.4, 0.4, 0.4), fixed=True))
O.bodies[0].state.vel = (0.1, -0.2, 0.3)
O.bodies[1].state.angVel = (1, 2, 3)
O.dt = 1e-4
O.run(3, True)
"""


@pytest.fixture
def scene():
    import yade
    ns = dict(vars(yade))
    exec(SCENE, ns)
    assert O.interactions.countReal() == 19  # (reference: 19)


def close(a, b, rel=1e-9, abs_=1e-6):
    a, b = list(a), list(b)
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert x == pytest.approx(y, rel=rel, abs=abs_), (a, b)


def test_aabb_and_volumes(scene):
    close(utils.aabbDim(), (2.000032607522708, 2.020020053193145, 1.9700066590773515))
    close(utils.aabbDim(0.2, True), (0.7440291015702161, 0.7600738620676496, 0.7200317783000665))
    assert utils.getSpheresMass() == pytest.approx(10754.969340443306, rel=1e-12)
    assert utils.getSpheresVolume() == pytest.approx(4.136526669401271, rel=1e-12)
    assert utils.porosity() == pytest.approx(0.48027288235059235, rel=1e-12)
    # the mass is the density times the volume
    assert utils.getSpheresMass() == pytest.approx(2600 * utils.getSpheresVolume(), rel=1e-12)


def test_forces_and_torques(scene):
    assert utils.sumForces([0, 1, 2, 8], (0, 0, 1)) == pytest.approx(183841.081468742, rel=1e-9)
    assert utils.sumTorques([0, 1, 2], (0, 0, 1), (0.1, 0.2, 0.3)) == pytest.approx(462589.8916513153, rel=1e-9)
    ref = (1854138.571758384351, 503.7992162926004767, 625133.0917667647591)
    close(utils.forcesOnPlane((0.45, 0, 0), (1, 0, 0)), ref)
    close(utils.forcesOnCoordPlane(0.45, 0), ref)
    with pytest.raises(IndexError):
        utils.sumForces([0, 99], (0, 0, 1))


def test_stress_tensors(scene):
    ref = [-209906.8077926127589, -7.035158536054715306, -7009.349525903930953, -51.65764083723838951, -103591.5098356469098,
           22.1012060766459264, -43352.30242386100144, -150902.9608673144248, -334466.0616610993748]
    s = utils.getStress()
    close([s[i, j] for i in range(3) for j in range(3)], ref, abs_=1e-5)
    s10 = utils.getStress(10.)
    assert s10[0, 0] == pytest.approx(-167065.5771147866617, rel=1e-9)
    assert s10[2, 1] == pytest.approx(-120104.204864741856, rel=1e-9)
    with pytest.raises(ValueError):
        utils.getStress(-1)
    bst = utils.bodyStressTensors()
    assert len(bst) == len(O.bodies)
    ref0 = [-344499.4080250939587, -75.9402365112375719, -7357.020923828861669, 92.41914525915599654, -449985.521666311135,
            77.36553162907945591, -7203.205826221221287, -105.5659872113341748, -606251.8008719056379]
    close([bst[0][i, j] for i in range(3) for j in range(3)], ref0, abs_=1e-5)
    assert bst[2][2, 2] == pytest.approx(-1324673.233316021506, rel=1e-9)
    assert bst[8] == Matrix3.Zero  # the wall has no volume
    # the reference refuses without a periodic cell
    with pytest.raises(RuntimeError, match="periodic"):
        utils.normalShearStressTensors()


def test_fabric_tensor(scene):
    F, = utils.fabricTensor()
    ref = [0.2107598986669095287, 1.932207591325487245e-06, 0.007004133723329148374, 1.932207591325487245e-06, 0.1578947369118595123,
           -3.222554709996796733e-07, 0.007004133723329148374, -3.222554709996796733e-07, 0.6313453644212309035]
    close([F[i, j] for i in range(3) for j in range(3)], ref, abs_=1e-12)
    assert F.trace() == pytest.approx(1.0)  # normals are unit vectors
    strong, weak = utils.fabricTensor(splitTensor=True)
    assert strong.trace() == pytest.approx(1.0) and weak.trace() == pytest.approx(1.0)  # each over its own contacts, as the reference


def test_fabric_tensor_cutoff_extrema_and_split_as_the_reference():
    # 600 random overlapping spheres (random.seed(3)); the reference on the same script printed these
    # (cutoff: the contact points in aabbExtrema(cutoff); extrema given: that box instead, cutoff ignored;
    # strong: signed normal force, negative in compression, below the threshold; each part over its own count)
    import random
    random.seed(3)
    O.bodies.append([utils.sphere((random.uniform(0, 2), random.uniform(0, 1), random.uniform(0, 1.5)), 0.1, color=(1, 0, 0)) for i in range(600)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, 0))]
    O.dt = 1e-6
    O.step()
    diag = lambda F: [F[0, 0], F[1, 1], F[2, 2], F[0, 1]]  # noqa: E731
    close(diag(utils.fabricTensor(cutoff=0.3)[0]), [0.3434009033038522563, 0.3352194512934237869, 0.3213796454027240679, -0.008469684683637264747], abs_=1e-12)
    box = [Vector3(0.5, 0.2, 0.3), Vector3(1.5, 0.8, 1.2)]
    E = [0.3583689907495123395, 0.3384743705268902225, 0.303156638723597438, -0.01718188244378577104]
    close(diag(utils.fabricTensor(extrema=box)[0]), E, abs_=1e-12)
    close(diag(utils.fabricTensor(cutoff=0.3, extrema=box)[0]), E, abs_=1e-12)
    s, w = utils.fabricTensor(cutoff=0.3, splitTensor=True)
    close(diag(s), [0.3630318653688365815, 0.3081114991405488057, 0.3288566354906139466, -0.01984144293883055923], abs_=1e-12)
    close(diag(w), [0.3284739642242506252, 0.3558317243455149659, 0.3156943114302347975, 0.0001771428198399076378], abs_=1e-12)
    s, w = utils.fabricTensor(splitTensor=True, thresholdForce=-1000)  # (both parts have contacts)
    assert s.trace() == pytest.approx(1) and w.trace() == pytest.approx(1)
    with pytest.warns(RuntimeWarning, match='strong'):
        s, w = utils.fabricTensor(splitTensor=True, thresholdForce=-1e20)  # none below: NaN, as there
    assert math.isnan(s.trace()) and w.trace() == pytest.approx(1)


def test_momenta_and_overlaps(scene):
    close(utils.momentum(), (88.11647352236869324, -272.2368498731293016, 905.4774094236934161))
    close(utils.angularMomentum(), (477.2785812986295468, -79.49440542168753154, 0.06171400964378648268))
    close(utils.angularMomentum((1, 2, 3)), (-2150.386787168145474, 561.6335834349001743, 448.5315109275102259))
    assert utils.maxOverlapRatio() == pytest.approx(0.2863170438527423, rel=1e-12)
    assert utils.kineticEnergy() == pytest.approx(765.2828371159965, rel=1e-12)
    assert utils.unbalancedForce() == pytest.approx(1.893476036184602, rel=1e-9)
    assert utils.avgNumInteractions() == pytest.approx(3.4545454545454546)


def test_interactions_of_bodies(scene):
    assert utils.numIntrsOfEachBody() == [5, 2, 5, 2, 5, 3, 5, 3, 4, 4, 0]
    ref = [[(0, 1), (0, 2), (0, 4), (8, 0), (9, 0)], [(0, 1), (1, 5)], [(0, 2), (2, 3), (2, 6), (8, 2), (9, 2)], [(2, 3), (3, 7)],
           [(0, 4), (4, 5), (4, 6), (8, 4), (9, 4)], [(1, 5), (4, 5), (5, 7)], [(2, 6), (4, 6), (6, 7), (8, 6), (9, 6)],
           [(3, 7), (5, 7), (6, 7)], [(8, 0), (8, 2), (8, 4), (8, 6)], [(9, 0), (9, 2), (9, 4), (9, 6)], []]
    assert [sorted((i.id1, i.id2) for i in l) for l in utils.intrsOfEachBody()] == ref
    assert sorted(utils.getBodyIdsContacts(0)) == [1, 2, 3, 4, 5, 6, 7, 8, 9]  # potential pairs too


def test_psd(scene):
    sizes, proc, cum = utils.psd()
    close(sizes, [0.9, 0.94, 0.98, 1.02, 1.06, 1.1])
    close(proc, [0.0, 0.19741109827315415, 0.30940038864917574, 0.6891383795617925, 0.8315229113651023, 1.0])
    close(cum, [0.0, 2123.150309391013, 3327.5916938431274, 7411.662143509858, 8943.00341760783, 10754.969340443304])
    sizes, proc, cum = utils.psd(bins=3, mass=False)
    close(sizes, [0.9, 0.96666667, 1.03333333, 1.1], rel=1e-7)
    close(proc, [0, .375, .75, 1])
    close(cum, [0, 3, 6, 8])


def test_geometry_helpers():
    close(utils.inscribedCircleCenter((0, 0, 0), (1, 0, 0), (0, 2, 0)), (0.381966011250105153, 0.381966011250105153, 0))
    # the reference's bits (the third was one ulp off when computed as (a·v0 + b·v1 + c·v2)/(a + b + c))
    for v, c in [([(1.2290169488970193, 2.4178698926072943, 2.9519356556569667), (4.424502837770504, 2.3989857473993066, 4.223249966654169),
                   (-4.709947717163852, -0.3437734562189467, 4.433567169983137)], [1.281479313090794, 1.9291663899944185, 3.6441587362933547]),
                 ([(1.489745531369242, 4.009004917506227, -3.8679403534685566), (-0.3093095221783626, -2.5342716738016966, 0.4376085923593038),
                   (0.7394118792810076, -4.868858104110978, -2.8327019953615187)], [0.4421117592344157, -2.1368050511141483, -1.649565119438881]),
                 ([(-2.205176339888897, 4.163453718085519, 2.6572545162914176), (-3.403957876419618, 2.9714699143120447, -3.6123258160109684),
                   (1.1745252046611663, -3.733007674497303, -4.982251377974654)], [-1.8937625771219109, 1.685476289925104, -1.9829930551808026])]:
        assert list(utils.inscribedCircleCenter(*v)) == c
        assert list(utils.facet(v).state.pos) == c
    assert utils.ptInAABB((0.5, 0.5, 0.5), (0, 0, 0), (1, 1, 1)) and not utils.ptInAABB((1.5, 0.5, 0.5), (0, 0, 0), (1, 1, 1))


def test_state_setters(scene):
    utils.setRefSe3()
    assert O.bodies[0].state.refPos == O.bodies[0].state.pos
    close(O.bodies[0].state.refPos, (8.846419636222525921e-06, -7.845433004926015723e-05, 0.5000965283854937882))
    utils.shiftBodies([2, 3], (1, 2, 3))
    close(O.bodies[2].state.pos, (0.9999784968527011264, 2.950013873254512475, 3.500008423210977604))
    utils.calm()
    assert O.bodies[0].state.vel == Vector3.Zero and O.bodies[1].state.angVel == Vector3.Zero
    utils.setBodyVelocity(0, (1, 2, 3), 'xz')
    assert O.bodies[0].state.vel == Vector3(1, 0, 3)
    with pytest.raises(ValueError):
        utils.setBodyVelocity(0, (1, 2, 3), 'q')
    utils.wireAll()
    assert all(b.shape.wire for b in O.bodies)
    utils.wireNoSpheres()
    assert not O.bodies[0].shape.wire and O.bodies[9].shape.wire


def test_no_contacts():
    O.bodies.append(utils.sphere((0, 0, 0), 1))
    assert utils.maxOverlapRatio() == -1.0  # (the reference's)
    assert utils.numIntrsOfEachBody() == [0]
    assert utils.getStress() == Matrix3.Zero
    with pytest.warns(RuntimeWarning, match='no contacts'):
        F, = utils.fabricTensor()  # NaN, as the reference, with a warning
    assert math.isnan(F[0, 0])


# ------------------------------------------------------------------ utils.createInteraction
# The reference (Yade 2023.02a, yade-double -n -x) on CREATE_SCENE then the calls below printed:
# createInteraction(0, 1) -> isReal True, iterBorn 1, iterMadeReal 1, penetrationDepth -1.0,
# kn 5000000.0, countReal 2, len 4; after one step (dt = 0): the pair is kept, not real;
# (0, 3) "Interaction #0+#3 already exists."; (0, 99) "No body #99"; no InteractionLoop:
# "No IGeomDispatcher in engines or inside InteractionLoop."; (1, 4) penetrationDepth -7.0.
CREATE_ENGINES = lambda: [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),  # noqa: E731
                          InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                          [Law2_ScGeom_FrictPhys_CundallStrack()]), NewtonIntegrator()]


def _create_scene():
    O.engines = CREATE_ENGINES()
    O.bodies.append([utils.sphere((0, 0, 0), .5), utils.sphere((2, 0, 0), .5), utils.sphere((0.9, 0.9, 0), .5),
                     utils.sphere((-0.99, 0, 0), .5), utils.sphere((10, 0, 0), .5)])
    O.dt = 0
    O.step()


def test_createInteraction_as_the_reference():
    _create_scene()
    assert (len(O.interactions), O.interactions.countReal()) == (3, 1)  # (0, 2), (1, 2) potential (bounds with the verlet distance), (0, 3) real
    i = utils.createInteraction(0, 1)
    assert i.isReal and (i.iterBorn, i.iterMadeReal) == (1, 1)
    assert i.geom.penetrationDepth == pytest.approx(-1.0) and i.phys.kn == pytest.approx(5e6)
    assert (O.interactions.countReal(), len(O.interactions)) == (2, 4)
    j = utils.createInteraction(0, 2)  # a potential pair (its bounds overlap) becomes real
    assert j.isReal and (j.iterBorn, j.iterMadeReal) == (1, 1)
    assert j.geom.penetrationDepth == pytest.approx(1 - math.sqrt(2 * 0.9 ** 2))
    assert (O.interactions.countReal(), len(O.interactions)) == (3, 4)
    with pytest.raises(RuntimeError, match=r'Interaction #0\+#3 already exists'):
        utils.createInteraction(0, 3)
    with pytest.raises(RuntimeError, match='No body #99'):
        utils.createInteraction(0, 99)
    with pytest.raises(RuntimeError, match='same body'):
        utils.createInteraction(0, 0)
    O.step()  # the law ends contacts whose bodies are apart (negative penetration)
    assert O.interactions.has(0, 1) and not O.interactions[0, 1].isReal
    assert O.interactions[0, 3].isReal
    k = utils.createInteraction(1, 4)
    assert k.geom.penetrationDepth == pytest.approx(-7.0) and k.iterBorn == 2
    O.dt = 1e-3
    O.step()  # bodies apart: the law ends the contact (the reference's collider also drops the pair (0, 1) then;
    # here the collider, which nothing moved, has not run: a potential pair stays until it does)
    assert not O.interactions.has(0, 1, True) and not O.interactions.has(1, 4, True) and O.interactions.countReal() == 1


def test_createInteraction_without_loop_virtual_and_swapped_functor(tmp_path):
    _create_scene()
    O.engines = []
    with pytest.raises(RuntimeError, match='No IGeomDispatcher'):
        utils.createInteraction(1, 4)
    assert not O.interactions.has(1, 4)
    O.engines = CREATE_ENGINES()
    v = utils.createInteraction(1, 4, virtualI=True)
    assert not v.isReal and v.iterBorn == 1 and O.interactions.has(1, 4) and not O.interactions.has(1, 4, True)
    # a facet and a sphere given in the other order than Ig2_Facet_Sphere_ScGeom takes them
    f = O.bodies.append(utils.facet([(-1, -1, -0.4), (3, -1, -0.4), (-1, 3, -0.4)]))
    c = utils.createInteraction(0, f)
    assert c.isReal and (c.id1, c.id2) == (f, 0) and c.geom.penetrationDepth == pytest.approx(0.1)
    # iterBorn is kept in saved files
    path = str(tmp_path / 's.yade')
    O.save(path)
    O.load(path)
    assert O.interactions[f, 0].iterBorn == 1 and O.interactions[0, 3].iterBorn == 0
    O.bodies.append(utils.sphere((20, 0, 0), 1, material=ElastMat()))  # no Ip2 functor for FrictMat+ElastMat
    with pytest.raises(RuntimeError, match='no Ip2 functor'):
        utils.createInteraction(4, len(O.bodies) - 1)
    assert not O.interactions.has(4, len(O.bodies) - 1)
