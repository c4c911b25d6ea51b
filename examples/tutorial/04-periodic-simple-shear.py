# Tutorial 2.6.4 of the manual: periodic simple shear. A loose periodic packing is compressed
# isotropically by the cell's velocity gradient until the mean stress reaches limitMeanStress,
# without friction; then friction is switched on, rotations blocked, and the cell is sheared (xz)
# until the shear strain reaches .5. yade.plot records the stress path.
from yade import pack, plot

O.periodic = True
O.cell.hSize = Matrix3(2, 0, 0, 0, 2, 0, 0, 0, 2)

sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (2, 2, 2), rMean=.1, rRelFuzz=.6, periodic=True)
sp.toSimulation()

# frictionless during the compaction (a denser packing)
O.materials[0].frictionAngle = 0

O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(damping=.4),
        # every second of wall-clock time: is the phase over?
        PyRunner(command='checkStress()', realPeriod=1, label='checker'),
        # every 100 steps: a line of the stress path
        PyRunner(command='addData()', iterPeriod=100)
]
O.dt = .5 * PWaveTimeStep()

# isotropic compression by the cell's velocity gradient (3.6.1)
O.cell.velGrad = Matrix3(-.1, 0, 0, 0, -.1, 0, 0, 0, -.1)

# the mean stress (compression negative) that ends the compaction
limitMeanStress = -5e5


def checkStress():
    # the mean stress, a third of the trace of the stress tensor
    stress = getStress().trace() / 3.
    print('mean stress', stress)
    # below the limit (compression negative): start shearing
    if stress < limitMeanStress:
        # simple shear in the xz plane, the cell's volume kept
        O.cell.velGrad = Matrix3(0, 0, .1, 0, 0, 0, 0, 0, 0)
        # the checker now watches the distortion
        checker.command = 'checkDistorsion()'
        # rotations blocked: the spheres slide on each other
        for b in O.bodies:
            b.state.blockedDOFs = 'XYZ'
            b.state.angVel = (0, 0, 0)
        # friction on, for new contacts (the material) and for the existing ones
        O.materials[0].frictionAngle = .5
        for i in O.interactions:
            i.phys.tangensOfFrictionAngle = tan(.5)


def checkDistorsion():
    # the shear strain of the cell (its deformation gradient's xz term) past .5: save the data and stop
    if abs(O.cell.trsf[0, 2]) > .5:
        plot.saveDataTxt(O.tags['id'] + '.txt')
        O.pause()


def addData():
    # the stress as the sum of its normal and shear parts
    stress = sum(normalShearStressTensors(), Matrix3.Zero)
    # the shear strain, the stresses and their ratio
    plot.addData(exz=O.cell.trsf[0, 2], szz=stress[2, 2], sxz=stress[0, 2], tanPhi=(stress[0, 2] / stress[2, 2]) if stress[2, 2] != 0 else 0, i=O.iter)
    # the spheres colored by how far they turned
    for b in O.bodies:
        b.shape.color = scalarOnColorScale(b.state.rot().norm(), 0, pi / 2.)


# stresses against the shear strain, and the friction mobilized (tanPhi)
plot.plots = {'i': ('exz',), 'exz': ('szz', 'sxz'), ' exz': ('tanPhi',)}
plot.plot()

O.saveTmp()
