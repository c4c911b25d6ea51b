# Tutorial 2.6.3 of the manual: a packing is deposited in a box, then a plate compresses it
# until the force reaches maxLoad and goes back until the force falls below minLoad. The
# parameters may come from a batch table (yade-batch); these are the defaults.

readParamsFromTable(rMean=.05, rRelFuzz=.3, maxLoad=1e6, minLoad=1e4)
# the parameters as plain variables
from yade.params.table import *

from yade import pack, plot

# box with a free top, and a loose packing in it
O.bodies.append(geom.facetBox((.5, .5, .5), (.5, .5, .5), wallMask=31))
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=rMean, rRelFuzz=rRelFuzz)
sp.toSimulation()

O.engines = [
        ForceResetter(),
        # the plate added later is a Wall: its bounds need Bo1_Wall_Aabb
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop(
                # sphere+sphere, sphere+facet and sphere+wall contacts
                [Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                [Ip2_FrictMat_FrictMat_FrictPhys()],
                [Law2_ScGeom_FrictPhys_CundallStrack()]
        ),
        NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.5),
        # the label makes this engine reachable as `checker` below; every 100 steps (the manual has realPeriod=2,
        # every 2 s of wall-clock time: a fast run then moves the plate so far between two checks that it can
        # pass the maximum load, crush the packing through the box and go on forever)
        PyRunner(command='checkUnbalanced()', iterPeriod=100, label='checker')
]
O.dt = .5 * PWaveTimeStep()


# deposition done? then put the plate on top and start loading
def checkUnbalanced():
    # let the spheres fall for a while first
    if O.iter < 5000:
        return
    # not at rest yet
    if unbalancedForce() > .1:
        return
    # a wall touching the topmost sphere, acting downwards only
    O.bodies.append(wall(max([b.state.pos[2] + b.shape.radius for b in O.bodies if isinstance(b.shape, Sphere)]), axis=2, sense=-1))
    global plate  # so that the other functions see it
    plate = O.bodies[-1]
    # walls are fixed: they keep the velocity given to them
    plate.state.vel = (0, 0, -.1)
    # record the history from now on
    O.engines = O.engines + [PyRunner(command='addPlotData()', iterPeriod=200)]
    # the checker now watches the load
    checker.command = 'unloadPlate()'


def unloadPlate():
    # the maximum load is reached: move the plate back up
    if abs(O.forces.f(plate.id)[2]) > maxLoad:
        plate.state.vel *= -1
        checker.command = 'stopUnloading()'


def stopUnloading():
    if abs(O.forces.f(plate.id)[2]) < minLoad:
        # O.tags['d.id'] is unique for each run (and names the batch job)
        plot.saveDataTxt(O.tags['d.id'] + '.txt')
        O.pause()


def addPlotData():
    if not isinstance(O.bodies[-1].shape, Wall):
        plot.addData()
        return
    Fz = O.forces.f(plate.id)[2]
    plot.addData(Fz=Fz, w=plate.state.pos[2] - plate.state.refPos[2], unbalanced=unbalancedForce(), i=O.iter)


# unbalanced force against steps; the plate force against its displacement
plot.plots = {'i': ('unbalanced',), 'w': ('Fz',)}
plot.plot()

O.run()
# in a batch, wait for the end before the next job
waitIfBatch()
