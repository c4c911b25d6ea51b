# Peri3dController: a loose periodic cloud is first compressed by prescribed strains on all six
# components (isotropic compression), then (doneHook: triaxial()) loaded triaxially: the strain zz
# is shortened by 2 % while the stresses xx and yy stay at the value they had, the shear strains at 0.
# doc/periodic.md describes the controller. Run: yade -n -x examples/peri3d-triaxial.py
from yade import pack

O.periodic = True
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (1, 1, 1), rMean=.1, rRelFuzz=.2, periodic=True, seed=5)
sp.toSimulation()

O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
        # phase 1: every component a strain (stressMask 0): -22 % on the three axes in 600 steps
        Peri3dController(label='p3d', goal=(-.22, -.22, -.22, 0, 0, 0), stressMask=0, nSteps=600, doneHook='triaxial()'),
        NewtonIntegrator(damping=.4),
]
O.dt = .5 * PWaveTimeStep()


def triaxial():
    s = p3d.stress
    print('compressed: step %d, stress (xx, yy, zz) = (%.4g, %.4g, %.4g) Pa, %d contacts' % (O.iter, s[0], s[1], s[2], O.interactions.countReal()))
    # phase 2: xx and yy stresses (stressMask bits 1 and 2) kept at their mean, zz shortened by 2 %
    lateral = (s[0] + s[1]) / 2
    O.cell.trsf = Matrix3.Identity  # (strains counted from here)
    p3d.progress = 0
    p3d.strain = Vector6.Zero
    p3d.stressIdeal = Vector6(lateral, lateral, 0, 0, 0, 0)
    p3d.goal = (0, 0, -.02, 0, 0, 0)  # (the stress goals are increments from stressIdeal)
    p3d.stressMask = 0b000011
    p3d.nSteps = 800
    p3d.doneHook = 'finished()'


def finished():
    s, e = p3d.stress, p3d.strain
    print('triaxial: step %d, strain zz %.4f, stress (xx, yy, zz) = (%.4g, %.4g, %.4g) Pa' % (O.iter, e[2], s[0], s[1], s[2]))
    O.pause()


O.run(3000, True)
