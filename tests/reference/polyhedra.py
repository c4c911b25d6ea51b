# Scenes of the polyhedra family (Polyhedra, PolyhedraMat, Law2_PolyhedraGeom_PolyhedraPhys_Volumetric): a plain Yade
# script that runs unchanged in the reference Yade and in this engine. Run as a script it prints, as JSON, what
# tests/test_polyhedra_reference.py compares. Regenerate its data (in tests/reference/) with:
#   yade -n -x -j1 polyhedra.py 2>/dev/null | grep '^{' > data/polyhedra.json
import json
from math import pi

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade import polyhedra_utils, utils

CUBE = [Vector3(x, y, z) for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)]


def vec(v):
    return [float(x) for x in v]


def engines(ig2s, damping=0.3, gravity=(0, 0, -9.81)):
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()], verletDist=0.001),
        InteractionLoop(ig2s, [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()], [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
        NewtonIntegrator(damping=damping, gravity=gravity)
    ]


def cube_on(support, a=0.1, steps=6000):
    """a cube of side a (density 2000) let go 1 mm above a wall or two facets at z = 0; its state at rest"""
    O.reset()
    mat = PolyhedraMat(young=1e8, poisson=0.3, density=2000, frictionAngle=0.5)
    O.materials.append(mat)
    if support == 'wall':
        O.bodies.append(utils.wall(0, axis=2, sense=0, material=mat))
        engines([Ig2_Wall_Polyhedra_PolyhedraGeom()])
    else:
        O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (1, 1, 0)], material=mat))
        O.bodies.append(utils.facet([(-1, -1, 0), (1, 1, 0), (-1, 1, 0)], material=mat))
        engines([Ig2_Facet_Polyhedra_PolyhedraGeom()])
    c = polyhedra_utils.polyhedra(mat, v=[x * a + Vector3(0, 0, a / 2 + 0.001) for x in CUBE])
    cid = O.bodies.append(c)
    O.dt = 1e-4
    O.run(steps, True)
    b = O.bodies[cid]
    out = {'pos': vec(b.state.pos), 'vel': vec(b.state.vel), 'mass': b.state.mass, 'inertia': vec(b.state.inertia), 'force': vec(O.forces.f(cid))}
    i = [i for i in O.interactions if i.isReal][0]
    out['volume'] = sum(i.geom.penetrationVolume for i in O.interactions if i.isReal)
    out['kn'] = i.phys.kn
    out['ks'] = i.phys.ks
    out['normal'] = vec(i.geom.normal)
    out['normalForce'] = vec(sum((i.phys.normalForce for i in O.interactions if i.isReal), Vector3.Zero))
    return out


def cube_pair(offset, axis, angle):
    """two unit cubes, the second at offset turned by angle around axis: the contact after one step"""
    O.reset()
    mat = PolyhedraMat(young=1e8, poisson=0.3, density=2000, frictionAngle=0.4)
    O.materials.append(mat)
    a = polyhedra_utils.polyhedra(mat, v=CUBE)
    b = polyhedra_utils.polyhedra(mat, v=CUBE)
    O.bodies.append([a, b])
    b.state.pos = offset
    b.state.ori = Quaternion(axis, angle)
    engines([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()], damping=0, gravity=(0, 0, 0))
    O.dt = 1e-6
    O.step()
    i = O.interactions[0, 1]
    g, p = i.geom, i.phys
    return {'volume': g.penetrationVolume, 'crossSection': g.equivalentCrossSection, 'depth': g.equivalentPenetrationDepth,
            'contactPoint': vec(g.contactPoint), 'normal': vec(g.normal), 'kn': p.kn, 'ks': p.ks, 'tan': p.tangensOfFrictionAngle,
            'normalForce': vec(p.normalForce), 'force1': vec(O.forces.f(1))}


def sphere_cube(center, r=0.3, young=(1e8, 3e7), poisson=(0.3, 0.2)):
    """a sphere (FrictMat) touching a unit cube (PolyhedraMat) at a face, an edge, a vertex or with its center inside"""
    O.reset()
    pm = PolyhedraMat(young=young[0], poisson=poisson[0], density=2000, frictionAngle=0.4)
    fm = FrictMat(young=young[1], poisson=poisson[1], density=1000, frictionAngle=0.3)
    O.materials.append([pm, fm])
    O.bodies.append(polyhedra_utils.polyhedra(pm, v=CUBE))
    O.bodies.append(utils.sphere(center, r, material=fm))
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Polyhedra_ScGeom()], [Ip2_FrictMat_PolyhedraMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(damping=0)
    ]
    O.dt = 1e-6
    O.step()
    i = O.interactions[0, 1]
    g, p = i.geom, i.phys
    return {'ids': [i.id1, i.id2], 'penetrationDepth': g.penetrationDepth, 'normal': vec(g.normal), 'contactPoint': vec(g.contactPoint),
            'refR': [g.refR1, g.refR2], 'kn': p.kn, 'ks': p.ks, 'tan': p.tangensOfFrictionAngle, 'force0': vec(O.forces.f(0))}


def shapes():
    """volume, inertia, centroid and orientation of a few shapes given by their vertices"""
    out = {}
    for name, v in [('cube', [x + Vector3(1, 2, 3) for x in CUBE]), ('box', [Vector3(2 * x[0], x[1], 3 * x[2]) for x in CUBE]),
                    ('tetra', [Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(0, 1, 0), Vector3(0, 0, 1)])]:
        p = Polyhedra(v=v)
        p.Initialize()
        out[name] = {'volume': p.GetVolume(), 'inertia': vec(p.GetInertia()), 'centroid': vec(p.GetCentroid()), 'nv': len(p.v),
                     'nf': len(p.GetSurfaces())}
    return out


def scenes():
    return {
        'shapes': shapes(),
        'pairs': {
            'x': cube_pair(Vector3(0.9, 0, 0), Vector3(0, 0, 1), 0),
            'xy': cube_pair(Vector3(0.9, 0.8, 0), Vector3(0, 0, 1), 0),
            'rot45': cube_pair(Vector3(1.1, 0, 0), Vector3(0, 0, 1), pi / 4),
        },
        'sphere': {
            'face': sphere_cube(Vector3(0.7, 0, 0)),
            'edge': sphere_cube(Vector3(0.6, 0.55, 0)),
            'vertex': sphere_cube(Vector3(0.62, 0.6, 0.58)),
            'small': sphere_cube(Vector3(0.58, 0, 0), r=0.1),
            'stiffer': sphere_cube(Vector3(0.7, 0, 0), young=(2e8, 6e7), poisson=(0.5, 0.2)),
        },
        'wall': cube_on('wall'),
        'facets': cube_on('facets'),
    }


if RUN:
    print(json.dumps(scenes()))
