# Scenes of the local-frame geometries (L3Geom, L6Geom, their Ig2 functors and the laws
# Law2_L3Geom_FrictPhys_ElPerfPl, Law2_L6Geom_FrictPhys_Linear): a plain Yade script that runs unchanged
# in the reference Yade and in this engine. Run as a script it prints one JSON line, what
# tests/test_localframe.py compares; the data file is made (in tests/reference/) with
#   yade -n -x -j1 localframe.py 2>/dev/null | grep '^LOCALFRAME ' | sed 's/^LOCALFRAME //' > data/localframe.json
import json
import math

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade.utils import *

HEAVY = 1e300  # [kg/m³] the density of driven bodies: their velocities do not change to the last bit


def vec(v):
    return [float(x) for x in v]


def mat(m):
    return [float(m[i, j]) for i in range(3) for j in range(3)]


def engines(ig2s, law, gravity=(0, 0, 0)):
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop(ig2s, [Ip2_FrictMat_FrictMat_FrictPhys()], [law]),
        NewtonIntegrator(damping=0, gravity=gravity)
    ]


def record(a, b):
    """the contact's geometry and forces, and the forces on the two bodies (None: no contact)"""
    out = {'f': [vec(O.forces.f(i)) + vec(O.forces.t(i)) for i in (a, b)]}
    if not (O.interactions.has(a, b) and O.interactions[a, b].isReal):
        out['i'] = None
        return out
    I = O.interactions[a, b]
    g, p = I.geom, I.phys
    row = vec(g.u) + vec(g.u0) + mat(g.trsf) + vec(g.F) + vec(g.normal) + vec(g.contactPoint) + [g.refR1, g.refR2]
    if hasattr(g, 'phi'):
        row += vec(g.phi) + vec(g.phi0)
    row += [p.kn, p.ks, p.tangensOfFrictionAngle] + vec(p.normalForce) + vec(p.shearForce)
    out['i'] = row
    return out


def mat0(frict=0.3, density=2600):
    return FrictMat(young=1e7, poisson=0.3, density=density, frictionAngle=frict)


def driven(b, vel, angVel):
    """a body moved at the given velocities: so heavy (its material's density) that the contact does not change them (a body
    with all its DOFs blocked would not do: this engine's collider pairs no two non-dynamic bodies)"""
    b.state.vel = vel
    b.state.angVel = angVel


def two_spheres(ig2, law, vel1=(0, 0, 0), ang1=(0, 0, 0), vel2=(0, 0, 0), ang2=(0, 0, 0), direction=(1, .3, -.2), gap=-1e-4,
                r1=0.01, r2=0.015, frict=0.3, steps=40, every=1):
    """two spheres driven at constant velocities, touching along `direction`"""
    O.reset()
    m = O.materials.append(mat0(frict, HEAVY))
    # (in plain floats: the two engines' Vector3 may round normalized() differently)
    norm = math.sqrt(sum(x * x for x in direction))
    x1 = (0.001, -0.002, 0.003)
    x2 = tuple(x1[i] + direction[i] / norm * (r1 + r2 + gap) for i in range(3))
    O.bodies.append(sphere(x1, r1, material=m))
    O.bodies.append(sphere(x2, r2, material=m))
    driven(O.bodies[0], vel1, ang1)
    driven(O.bodies[1], vel2, ang2)
    engines([ig2], law)
    O.dt = 1e-5
    out = []
    for k in range(steps):
        O.step()
        if k % every == every - 1:
            out.append(record(0, 1))
    return out


def on_wall(ig2=None, law=None, steps=40):
    """a sphere driven into and along a wall (axis z), spinning"""
    O.reset()
    m = O.materials.append(mat0(0.4, HEAVY))
    O.bodies.append(wall((0, 0, 0.001), axis=2, material=m))
    O.bodies.append(sphere((0.002, 0.001, 0.001 + 0.01 - 1e-5), 0.01, material=m))
    driven(O.bodies[1], (0.3, -0.1, -0.2), (5, 20, -30))
    engines([ig2 or Ig2_Wall_Sphere_L3Geom()], law or Law2_L3Geom_FrictPhys_ElPerfPl())
    O.dt = 1e-5
    return [record(0, 1) for k in range(steps) if O.step() is None]


def on_facet(steps=40):
    """a sphere driven into and along a facet, spinning"""
    O.reset()
    m = O.materials.append(mat0(0.4, HEAVY))
    O.bodies.append(facet([(-0.1, -0.1, 0.002), (0.1, -0.1, 0.001), (0, 0.1, 0)], material=m))
    O.bodies.append(sphere((0.002, 0.001, 0.0007325 + 0.01 - 2e-5), 0.01, material=m))
    driven(O.bodies[1], (0.3, -0.1, -0.2), (5, 20, -30))
    engines([Ig2_Facet_Sphere_L3Geom()], Law2_L3Geom_FrictPhys_ElPerfPl())
    O.dt = 1e-5
    return [record(0, 1) for k in range(steps) if O.step() is None]


def on_facet_edge(steps=40):
    """a sphere driven across a facet's edge, then its vertex"""
    O.reset()
    m = O.materials.append(mat0(0.4, HEAVY))
    O.bodies.append(facet([(0, 0, 0), (0.05, 0, 0), (0, 0.05, 0.01)], material=m))
    O.bodies.append(sphere((0.02, -0.006, 0.008), 0.01, material=m))
    driven(O.bodies[1], (0.5, 0.05, -0.1), (5, 20, -30))
    engines([Ig2_Facet_Sphere_L3Geom()], Law2_L3Geom_FrictPhys_ElPerfPl())
    O.dt = 1e-5
    return [record(0, 1) for k in range(steps) if O.step() is None]


def energy(steps=30):
    """O.energy's elastPotential and plastDissip of a sliding contact"""
    two_spheres(Ig2_Sphere_Sphere_L3Geom(), Law2_L3Geom_FrictPhys_ElPerfPl(), vel1=(0.01, 0.02, -0.005), ang1=(1., -2., 3.),
                vel2=(-0.3, 0.25, 0.1), ang2=(-4., 0.5, 2.), frict=0.1, steps=0)
    O.trackEnergy = True
    O.run(steps, True)
    return [O.energy['elastPotential'], O.energy['plastDissip']]


def pile(steps=3000):
    """free spheres falling on a wall under gravity (L3 law), the bodies' states after 300, 1000 and `steps` steps"""
    O.reset()
    m = O.materials.append(mat0(0.5))
    O.bodies.append(wall((0, 0, 0), axis=2, material=m))
    for k in range(6):
        O.bodies.append(sphere((0.004 * (k % 3) - 0.004 + 0.0003 * k, 0.0011 * (k // 3), 0.012 + 0.019 * k), 0.01, material=m))
    engines([Ig2_Sphere_Sphere_L3Geom(), Ig2_Wall_Sphere_L3Geom()], Law2_L3Geom_FrictPhys_ElPerfPl(), gravity=(0, 0, -9.81))
    O.dt = 2e-5
    out = []
    for n in (300, 1000, steps):
        if n > O.iter:
            O.run(n - O.iter, True)
        out.append([vec(b.state.pos) + vec(b.state.vel) + vec(b.state.angVel) for b in O.bodies])
    return out


def scenes():
    L3, L6 = Ig2_Sphere_Sphere_L3Geom, Ig2_Sphere_Sphere_L6Geom
    ElPerfPl, Linear = Law2_L3Geom_FrictPhys_ElPerfPl, Law2_L6Geom_FrictPhys_Linear
    motion = dict(vel1=(0.01, 0.02, -0.005), ang1=(1., -2., 3.), vel2=(-0.3, 0.25, 0.1), ang2=(-4., 0.5, 2.))
    return {
        'pressed': lambda: two_spheres(L3(), ElPerfPl(), vel2=(-0.1, -0.03, 0.02)),
        'sheared': lambda: two_spheres(L3(), ElPerfPl(), vel2=(0.0, 0.5, 0.3), frict=0.6),
        'sliding': lambda: two_spheres(L3(), ElPerfPl(), **motion, frict=0.1),
        'noSlip': lambda: two_spheres(L3(), ElPerfPl(noSlip=True), **motion, frict=0.1),
        'separating': lambda: two_spheres(L3(), ElPerfPl(), vel2=(0.3, 0.1, 0.), gap=-2e-5, steps=20),
        'noBreak': lambda: two_spheres(L3(), ElPerfPl(noBreak=True), vel2=(0.3, 0.1, 0.), gap=-2e-5, steps=20),
        'ratchet': lambda: two_spheres(L3(noRatch=False), ElPerfPl(), **motion),
        'approx1': lambda: two_spheres(L3(approxMask=1), ElPerfPl(), **motion),
        'approx2': lambda: two_spheres(L3(approxMask=2), ElPerfPl(), **motion),
        'approx6': lambda: two_spheres(L3(approxMask=6), ElPerfPl(), **motion),
        'renorm': lambda: two_spheres(L3(trsfRenorm=3), ElPerfPl(), **motion),
        'distFactor': lambda: two_spheres(L3(distFactor=1.5), ElPerfPl(), vel2=(-0.1, -0.03, 0.02), gap=1e-3, steps=60, every=3),
        'distFactorNeg': lambda: two_spheres(L3(distFactor=-1.5), ElPerfPl(), vel2=(-0.1, -0.03, 0.02), gap=1e-3, steps=60, every=3),
        'rolled': lambda: two_spheres(L6(), Linear(), ang1=(0, 0, 10.), ang2=(0, 0, -10.)),
        'twisted': lambda: two_spheres(L6(), Linear(charLen=0.3), ang1=(-5, -1.5, 1.), ang2=(5, 1.5, -1.)),
        'l6general': lambda: two_spheres(L6(), Linear(charLen=2.), **motion, steps=60),
        'l6elperfpl': lambda: two_spheres(L6(), ElPerfPl(), **motion, frict=0.1),
        'l6separating': lambda: two_spheres(L6(), Linear(), vel2=(0.3, 0.1, 0.), gap=-2e-5, steps=20),
        'l6noSlip': lambda: two_spheres(L6(), Linear(), vel2=(0.0, 0.5, 0.3), frict=0.05),
        'wall': lambda: on_wall(),
        'facet': lambda: on_facet(),
        'facetEdge': lambda: on_facet_edge(),
        'pile': lambda: pile(),
        'energy': lambda: energy(),
    }


if RUN:
    print('LOCALFRAME ' + json.dumps({name: f() for name, f in scenes().items()}))
