"""TriaxialTest.load(): builds the classic triaxial test scene into O from the generator's attributes
(pkg/dem/triaxial/TriaxialTest.hpp declares them; doc/triaxial.md)."""
import math

from ._yade import (O, Vector3, FrictMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Box_Aabb, InteractionLoop,
                    Ig2_Sphere_Sphere_ScGeom, Ig2_Box_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack,
                    GlobalStiffnessTimeStepper, TriaxialCompressionEngine, TriaxialStateRecorder, NewtonIntegrator, PWaveTimeStep)
from . import utils
from .pack import SpherePack


def _check(g):
    if g.facetWalls or g.wallWalls:
        raise ValueError('TriaxialTest: facetWalls and wallWalls are not supported here (the walls are boxes)')
    if g.fixedBoxDims:
        raise ValueError('TriaxialTest.fixedBoxDims is not supported here (leave it empty)')
    lo, hi = Vector3(g.lowerCorner), Vector3(g.upperCorner)
    if not all(hi[i] > lo[i] for i in range(3)):
        raise ValueError('TriaxialTest: upperCorner must be above lowerCorner along every axis, got %s and %s' % (lo, hi))
    return lo, hi


def _packing(g, lo, hi):
    sp = SpherePack()
    if g.importFilename:
        sp.load(g.importFilename)
        # the box becomes the imported spheres' bounding box (as the reference writes it back)
        g.lowerCorner = Vector3([min(c[i] - r for c, r in sp) for i in range(3)])
        g.upperCorner = Vector3([max(c[i] + r for c, r in sp) for i in range(3)])
        return sp
    if g.radiusMean > 0:
        sp.makeCloud(lo, hi, rMean=g.radiusMean, rRelFuzz=g.radiusStdDev, num=g.numberOfGrains, seed=g.seed)
    else:
        sp.makeCloud(lo, hi, rMean=-1, rRelFuzz=g.radiusStdDev, num=g.numberOfGrains, porosity=0.8, seed=g.seed)
    return sp


def _walls(g, lo, hi, material):
    """six boxes outside the box lo-hi, in the order bottom, top, left, right, back, front (ids 0-5)"""
    center, half, t = (lo + hi) / 2, (hi - lo) / 2, g.thickness
    walls = []
    for axis, side in ((1, -1), (1, 1), (0, -1), (0, 1), (2, -1), (2, 1)):
        c, ext = Vector3(center), Vector3([g.wallOversizeFactor * h + t for h in half])
        c[axis] = (hi[axis] + t / 2) if side > 0 else (lo[axis] - t / 2)
        ext[axis] = t / 2
        walls.append(utils.box(c, ext, fixed=True, material=material))
    return walls


def load(g):
    """Replace the scene of O by the triaxial test that the TriaxialTest g describes"""
    lo, hi = _check(g)
    sp = _packing(g, lo, hi)
    lo, hi = Vector3(g.lowerCorner), Vector3(g.upperCorner)
    O.reset()
    wallMat = FrictMat(young=g.boxYoungModulus, poisson=g.boxKsDivKn, frictionAngle=math.radians(g.boxFrictionDeg))
    sphereMat = FrictMat(young=g.sphereYoungModulus, poisson=g.sphereKsDivKn, frictionAngle=math.radians(g.compactionFrictionDeg), density=g.density)
    O.bodies.append(_walls(g, lo, hi, wallMat))
    sp.toSimulation(material=sphereMat)
    dt = g.defaultDt if g.defaultDt > 0 else PWaveTimeStep()
    g.defaultDt = dt  # (written back, as the reference)
    triax = TriaxialCompressionEngine(
        wall_bottom_id=0, wall_top_id=1, wall_left_id=2, wall_right_id=3, wall_back_id=4, wall_front_id=5,
        sigmaIsoCompaction=g.sigmaIsoCompaction, sigmaLateralConfinement=g.sigmaLateralConfinement, strainRate=g.strainRate,
        StabilityCriterion=g.StabilityCriterion, autoCompressionActivation=g.autoCompressionActivation, autoUnload=g.autoUnload,
        autoStopSimulation=g.autoStopSimulation, internalCompaction=g.internalCompaction, maxMultiplier=g.maxMultiplier,
        finalMaxMultiplier=g.finalMaxMultiplier, radiusControlInterval=g.radiusControlInterval, max_vel=g.maxWallVelocity,
        thickness=g.thickness, stiffnessUpdateInterval=g.wallStiffnessUpdateInterval, frictionAngleDegree=g.sphereFrictionDeg,
        Key=g.Key, noFiles=g.noFiles)
    engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]),
               InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                               [Law2_ScGeom_FrictPhys_CundallStrack()]),
               GlobalStiffnessTimeStepper(timeStepUpdateInterval=g.timeStepUpdateInterval, defaultDt=dt), triax]
    if not g.noFiles:
        engines.append(TriaxialStateRecorder(file=g.WallStressRecordFile + g.Key, iterPeriod=g.recordIntervalIter))
    engines.append(NewtonIntegrator(damping=g.dampingForce))
    O.engines = engines
    O.dt = dt


def generate(g, fileName):
    """Build the scene (as load does: it becomes O's scene) and save it to fileName (O.save)"""
    load(g)
    O.save(fileName)
