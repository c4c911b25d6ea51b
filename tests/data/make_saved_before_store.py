# Writes tests/data/saved-before-store.yade.gz and .xml and the positions after 50 more steps
# (saved-before-store.json). Run once with the build of commit 802e60c, the last before the body
# store (the files prove that scenes saved before that change still load and run the same):
#   PYTHONPATH=<old build> /usr/bin/python3 tests/data/make_saved_before_store.py tests/data
import json, os, sys
from yade import *
from yade import geom
from yade.utils import *

out = sys.argv[1]
O.reset()
O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label='mat'))
O.bodies.append(geom.facetBox((0.03, 0.03, 0.03), (0.04, 0.04, 0.04), wallMask=63))
r = 0.01
for k in range(3):
    for j in range(3):
        for i in range(3):
            O.bodies.append(sphere((i * 0.0199, j * 0.0199, k * 0.0199 + 0.001 * i), r))
O.bodies[14].state.vel = (0.1, -0.2, 0.05)
O.bodies[15].state.angVel = (3, 1, -2)
O.bodies[16].state.blockedDOFs = 'xZ'
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                    [Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.3, label='newton'),
]
O.dt = .5 * PWaveTimeStep()
O.run(40, True)
O.save(os.path.join(out, 'saved-before-store.yade.gz'))
O.save(os.path.join(out, 'saved-before-store.xml'))
O.run(50, True)
json.dump({'iter': O.iter, 'real': O.interactions.countReal(),
           'pos': [list(b.state.pos) for b in O.bodies], 'vel': [list(b.state.vel) for b in O.bodies],
           'ori': [list(b.state.ori) for b in O.bodies]},
          open(os.path.join(out, 'saved-before-store.json'), 'w'), indent=0)
