# Tutorial 2.6.2 of the manual: spheres fall into a box under gravity; the history of the
# unbalanced force and of the energies is plotted and saved, and the run stops itself once
# the packing is at rest.

from yade import pack, plot

# a box of facets, open at the top (wallMask=31: every face but +z)
O.bodies.append(geom.facetBox((.5, .5, .5), (.5, .5, .5), wallMask=31))

# a loose random cloud of spheres (geometry only) in the box, then particles from it
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.05, rRelFuzz=.5)
sp.toSimulation()

O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
        InteractionLoop(
                # sphere+sphere and facet+sphere contacts
                [Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()],
                [Ip2_FrictMat_FrictMat_FrictPhys()],
                [Law2_ScGeom_FrictPhys_CundallStrack()]
        ),
        NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4),
        # every 2 seconds of wall-clock time: is the packing at rest?
        PyRunner(command='checkUnbalanced()', realPeriod=2),
        # every 100 steps: record the history
        PyRunner(command='addPlotData()', iterPeriod=100)
]
O.dt = .5 * PWaveTimeStep()

# engines that can report energy do so from now on (O.energy['name'])
O.trackEnergy = True


def checkUnbalanced():
    # at rest when the resultant forces are small compared to the contact forces
    if unbalancedForce() < .05:
        O.pause()
        plot.saveDataTxt('bbb.txt.bz2')


def addPlotData():
    # one row of history: step, unbalanced force, and every energy term (**O.energy)
    plot.addData(i=O.iter, unbalanced=unbalancedForce(), **O.energy)


# step number on x; unbalanced force on the left axis, the energies (whatever terms exist
# when the plot is drawn: O.energy.keys is called then) on the right axis
plot.plots = {'i': ('unbalanced', None, O.energy.keys)}

plot.plot()

O.saveTmp()
