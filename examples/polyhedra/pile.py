# Random convex polyhedra (yade.polyhedra_utils.fillBox) falling into a box of walls under gravity, with the volumetric
# law (doc/polyhedra.md). Runs in the reference Yade too: yade -n -x pile.py
from yade import polyhedra_utils, utils

mat = PolyhedraMat(young=1e8, poisson=0.3, density=2000, frictionAngle=0.5)
O.materials.append(mat)
polyhedra_utils.fillBox((0, 0, 0), (0.3, 0.3, 0.6), mat, sizemin=[0.04] * 3, sizemax=[0.07] * 3, seed=1)
n = len(O.bodies)
O.bodies.append([utils.wall(0, axis=2, material=mat), utils.wall(0, axis=0, material=mat), utils.wall(0.3, axis=0, material=mat),
                 utils.wall(0, axis=1, material=mat), utils.wall(0.3, axis=1, material=mat)])
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Wall_Aabb()], verletDist=0.001),
    InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom(), Ig2_Wall_Polyhedra_PolyhedraGeom()],
                    [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()], [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
    NewtonIntegrator(damping=0.3, gravity=(0, 0, -9.81))
]
O.dt = 2e-5
O.run(10000, True)
top = max(O.bodies[i].state.pos[2] for i in range(n))
print('%d polyhedra, %d contacts, highest center at %.4f m, unbalanced force %.3g' % (n, len([i for i in O.interactions if i.isReal]), top,
                                                                                       utils.unbalancedForce()))
