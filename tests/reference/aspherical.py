# Aspherical rotation (NewtonIntegrator, 3.5.2): a box of unequal sides given an angular momentum, with and
# without a torque, damping and gravity. A plain Yade script that runs unchanged in the reference Yade and
# in this engine; run as a script it prints one JSON line (ASPHERICAL {...}) that
# tests/test_aspherical_rotation.py compares with:
#     yade -n -x -j1 aspherical.py | grep '^ASPHERICAL ' | sed 's/^ASPHERICAL //' > data/aspherical.json
# (tests/reference/regenerate.sh). The reference 2023.02a turns such a body by Fincham's scheme (the
# default rotAlgorithm here); doc/compatibility.md says how well the two agree.
import json

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *

# a unit quaternion given by its coefficients (Quaternion(axis, angle) normalizes differently in the two engines)
TURNED = (0.5907507033036815, 0.21564084004695758, 0.43128168009391515, 0.6469225201408727)
SNAPSHOTS = (1, 2, 3, 10, 100, 1000)

# (name, keyword arguments of scene())
CASES = [
    ('free', dict()),
    ('freeTurned', dict(ori=TURNED)),
    ('torque', dict(torque=(1, -2, 3), ori=TURNED)),
    ('damped', dict(torque=(1, -2, 3), damping=.2, ori=TURNED)),
    ('dampedGravity', dict(torque=(1, -2, 3), damping=.2, gravity=(0, 0, -9.81), ori=TURNED)),
    # the damping reads the stored spin: set here (inconsistent with angMom) it decides the first step's sign
    ('dampedSpinSet', dict(torque=(-1000, 0, 0), damping=.2, angVel=(1e-6, .39, 1.17))),
    ('strongTorque', dict(torque=(30, 50, -20), damping=0, ori=TURNED, angMom=(1, 2, 3))),
    ('spinOnly', dict(angMom=None, angVel=(1, 2, 3))),  # a spin set alone: nothing turns (angMom drives)
]


def scene(torque=None, damping=0., gravity=(0, 0, 0), ori=None, angMom=(10, 20, 30), angVel=None, dt=1e-3):
    O.reset()
    b = box((0, 0, 0), (.2, .4, .6))
    if ori is not None:
        b.state.ori = Quaternion(*ori)
    O.bodies.append(b)
    if angMom is not None:
        b.state.angMom = angMom
    if angVel is not None:
        b.state.angVel = angVel
    engines = [ForceResetter()]
    if torque is not None:
        engines.append(TorqueEngine(ids=[0], moment=torque))
    engines.append(NewtonIntegrator(damping=damping, gravity=gravity))
    O.engines = engines
    O.dt = dt
    return b


def record(b):
    s = b.state
    return dict(iter=O.iter, ori=[float(s.ori[i]) for i in range(4)], angVel=[float(x) for x in s.angVel],
                angMom=[float(x) for x in s.angMom], pos=[float(x) for x in s.pos], vel=[float(x) for x in s.vel])


def run(kw, snapshots=SNAPSHOTS):
    b = scene(**kw)
    out = []
    for n in snapshots:
        O.run(n - O.iter, True)
        out.append(record(b))
    return out


def everything():
    return dict(inertia=[float(x) for x in box((0, 0, 0), (.2, .4, .6)).state.inertia],
                cases={name: run(kw) for name, kw in CASES})


if RUN:
    print('ASPHERICAL ' + json.dumps(everything()))
