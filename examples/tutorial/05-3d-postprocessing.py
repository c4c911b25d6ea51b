# Tutorial 2.6.5 of the manual (3d postprocessing): a periodic cloud is compressed by the cell for 20 000
# steps. VTKRecorder writes the spheres, the force chains and the cell every 1 000 steps for ParaView
# (open 3d-vtk-spheres.pvd, or the .vtu files as a series); SnapshotEngine saves the 3D view every 200
# steps (only when the view is open: without a display, -n, it takes nothing), and finish() makes a
# video of those snapshots.
from yade import pack, qt

# a loose periodic packing
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (2, 2, 2), rMean=.1, rRelFuzz=.6, periodic=True)
# put the spheres in the simulation (it becomes periodic)
sp.toSimulation()

O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(damping=.4),
        # save data for ParaView
        VTKRecorder(fileName='3d-vtk-', recorders=['all'], iterPeriod=1000),
        # save the 3D view, for a video
        qt.SnapshotEngine(fileBase='3d-', iterPeriod=200, label='snapshot'),
        # stop after 20 000 steps
        PyRunner(command='finish()', iterPeriod=20000)
]

# compress the cell: it shrinks at 10 % per second on each axis
O.dt = .5 * PWaveTimeStep()
O.cell.velGrad = Matrix3(-.1, 0, 0, 0, -.1, 0, 0, 0, -.1)
O.saveTmp()
# the 3D view, when there is a display
qt.View()


def finish():
    # the snapshots as a video (none were taken without a view)
    if snapshot.snapshots:
        makeVideo(snapshot.snapshots, '3d.mpeg', fps=10, bps=10000)
    O.pause()


# the view shows the force chains (contacts' normal forces) instead of the spheres
rr = yade.qt.Renderer()
rr.shape = False
rr.intrPhys = True
