# Tutorial 2.6.1 of the manual: a sphere dropped on a fixed one bounces and settles.

O.bodies.append(
        [
                # a fixed sphere: it keeps its place whatever hits it
                sphere(center=(0, 0, 0), radius=.5, fixed=True),
                # a free sphere, 2 m above, that will fall on it
                sphere((0, 0, 2), .5)
        ]
)

O.engines = [
        ForceResetter(),  # zero the forces left from the last step
        InsertionSortCollider([Bo1_Sphere_Aabb()]),  # find pairs whose boxes overlap
        InteractionLoop(
                [Ig2_Sphere_Sphere_ScGeom()],  # contact geometry of two spheres
                [Ip2_FrictMat_FrictMat_FrictPhys()],  # contact stiffness and friction from the materials
                [Law2_ScGeom_FrictPhys_CundallStrack()]  # forces from the overlap and the shear
        ),
        NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.1)  # move the bodies
]

# half of the critical step estimated from the P-wave speed
O.dt = .5 * PWaveTimeStep()

# keep this initial state in memory (O.loadTmp() restores it)
O.saveTmp()
