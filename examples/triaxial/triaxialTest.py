# The classic triaxial test from its generator (doc/triaxial.md): 200 spheres compacted to 50 kPa by
# the walls, then loaded axially at 0.1/s under 50 kPa of lateral stress.
# Run: yade -n -x examples/triaxial/triaxialTest.py
from yade import *

TriaxialTest(numberOfGrains=200, noFiles=True).load()
e = [x for x in O.engines if isinstance(x, TriaxialCompressionEngine)][0]
while e.currentState != 3 and O.iter < 5000:
    O.run(100, True)
print('compacted at iteration %d: mean stress %.0f Pa, porosity %.4f' % (O.iter, e.meanStress, e.porosity))
for k in range(10):
    O.run(200, True)
    q = -e.stress(3)[1] + (e.stress(0)[0] + e.stress(1)[0] + e.stress(4)[2] + e.stress(5)[2]) / 4
    print('axial strain %.4f  deviator %.0f Pa  volumetric strain %.4f' % (-e.strain[1], q, e.volumetricStrain))
