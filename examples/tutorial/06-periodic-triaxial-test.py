# Tutorial 2.6.6 of the manual: a loose periodic cloud is compacted isotropically to sigmaIso by
# PeriTriaxController (the cell moves as a mass: dynCell), then (compactionFinished) the stress
# stays sigmaIso on x and y while z is shortened to a strain of -0.2. The packing is a cloud of
# three-sphere clumps, as in the manual (set `clumps = False` for spheres). doc/periodic.md describes
# the controller, doc/clumps.md the clumps.
from yade import pack, plot

sigmaIso = -1e5
clumps = True

O.periodic = True
sp = pack.SpherePack()
if not clumps:
    sp.makeCloud((0, 0, 0), (2, 2, 2), rMean=.1, rRelFuzz=.3, periodic=True)
else:
    # the clump's template: its members' centres and radii, relative to the clump
    c1 = pack.SpherePack([((0, 0, 0), .08), ((.07, 0, 0), .04), ((0, .07, 0), .04)])
    sp.makeClumpCloud((0, 0, 0), (2, 2, 2), [c1], periodic=True, num=500)
sp.toSimulation()

O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
        PeriTriaxController(
                label='triax',
                # stress on all three axes (stressMask bits 1, 2, 4)
                goal=(sigmaIso, sigmaIso, sigmaIso),
                stressMask=7,
                # the cell moves as a mass pushed by the stress error
                dynCell=True,
                maxStrainRate=(10, 10, 10),
                # wait until the unbalanced force goes below this value
                maxUnbalanced=.1,
                relStressTol=1e-3,
                # called when the goal is reached
                doneHook='compactionFinished()'
        ),
        NewtonIntegrator(damping=.2),
        PyRunner(command='addPlotData()', iterPeriod=100),
]
O.dt = .5 * PWaveTimeStep()


def addPlotData():
    plot.addData(
            unbalanced=unbalancedForce(),
            i=O.iter,
            sxx=triax.stress[0],
            syy=triax.stress[1],
            szz=triax.stress[2],
            exx=triax.strain[0],
            eyy=triax.strain[1],
            ezz=triax.strain[2],
            # the energies are tracked (O.trackEnergy below): their total should stay small
            Etot=O.energy.total(),
            **O.energy
    )


O.trackEnergy = True
plot.plots = {'i': ('unbalanced',), 'i ': ('sxx', 'syy', 'szz'), ' i': ('exx', 'eyy', 'ezz'), '  i': (O.energy.keys, None, 'Etot')}


def compactionFinished():
    # the strain is measured from here on
    O.cell.trsf = Matrix3.Identity
    # stress on x and y, strain on z
    triax.goal = (sigmaIso, sigmaIso, -.2)
    triax.stressMask = 3
    # the strain rate is prescribed (and the stress axes follow it)
    triax.maxStrainRate = (1., 1., 1.)
    triax.doneHook = 'triaxFinished()'
    # the unbalanced force does not matter any more
    triax.maxUnbalanced = 10
    print('compaction finished at step', O.iter)


def triaxFinished():
    print('Finished: stress', triax.stress, 'strain', triax.strain)
    O.pause()
