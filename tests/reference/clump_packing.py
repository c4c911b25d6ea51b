# Clumps on the packing side (SpherePack.makeClumpCloud, clump ids in SpherePack, toSimulation with clumps,
# utils.clumpTemplate, ymport/export.textClumps): a plain Yade script that runs unchanged in the reference Yade
# and in this engine. Run as a script it prints one JSON line (CLUMPPACK {...}) that
# tests/test_clump_packing.py compares with:
#     yade -n -x -j1 clump_packing.py | grep '^CLUMPPACK ' | sed 's/^CLUMPPACK //' > data/clump_packing.json
# (tests/reference/regenerate.sh).
import json
import math
import os
import tempfile

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade import pack, utils, export, ymport

DUMBBELL = [((0, 0, 0), .1), ((.1, 0, 0), .1)]
# a template whose box is not centred on its origin: the reference puts the members at c + q·(p + C)
TRIANGLE = [((.3, .1, 0), .05), ((.4, .1, .02), .08), ((.35, .2, -.05), .06)]
SINGLE = [((0, 0, 0), .07)]

# (name, minCorner, maxCorner, templates, periodic, num, seed)
CLOUDS = [
    ('dumbbell', (0, 0, 0), (1, 1, 1), [DUMBBELL], False, -1, 1),
    ('mixed', (-1, 0, 2), (1, 1, 3), [DUMBBELL, TRIANGLE, SINGLE], False, 40, 7),
    ('periodic', (0, 0, 0), (1, 1.5, 1.2), [DUMBBELL], True, -1, 3),
    ('periodicMixed', (-.5, -.5, -.5), (.5, .5, .5), [TRIANGLE, SINGLE], True, 30, 11),
    ('tooMany', (0, 0, 0), (1, 1, 1), [DUMBBELL], False, 60, 2),
]


def vec(v):
    return [float(x) for x in v]


def items(sp):
    """[x, y, z, r, clumpId] per sphere (-1: none)"""
    return [vec(t[0]) + [float(t[1]), t[2] if len(t) > 2 else -1] for t in sp.toList()]


def cloud(name):
    _, lo, hi, templates, periodic, num, seed = [c for c in CLOUDS if c[0] == name][0]
    sp = pack.SpherePack()
    n = sp.makeClumpCloud(lo, hi, [pack.SpherePack(t) for t in templates], periodic=periodic, num=num, seed=seed)
    return sp, n


def clouds():
    out = {}
    for c in CLOUDS:
        sp, n = cloud(c[0])
        out[c[0]] = dict(returned=n, spheres=items(sp), clumps=sp.getClumps(), cellSize=vec(sp.cellSize))
    return out


def loaded(tmp):
    """A file with clump ids in the 5th column (not in order, a negative one for none), loaded."""
    f = os.path.join(tmp, 'ids.txt')
    with open(f, 'w') as o:
        o.write('0 0 0 1 5\n1 1 1 1 2\n2 2 2 .5 5\n3 3 3 1 -1\n4 4 4 1 -3\n5 5 5 1 2\n')
    sp = pack.SpherePack()
    sp.load(f)
    return dict(spheres=items(sp), clumps=sp.getClumps(), hasClumps=sp.hasClumps(), iterated=[len(t) for t in sp])


def simulation():
    """A small cloud (with a sphere alone before it) given to the simulation."""
    O.reset()
    sp = pack.SpherePack([((-.5, .5, 2.5), .05)])
    sp.makeClumpCloud((-1, 0, 2), (1, 1, 3), [pack.SpherePack(t) for t in (DUMBBELL, TRIANGLE)], num=4, seed=5)
    ids = sp.toSimulation()
    bodies = [[b.id, b.isClump, b.clumpId] + vec(b.state.pos) + [b.state.mass] for b in O.bodies]
    return dict(spheres=items(sp), ids=ids, bodies=bodies)


def exported(tmp):
    """Clumps made by appendClumped, spheres alone around them, members of other masks."""
    O.reset()
    O.bodies.append(utils.sphere((5, 5, 5), 1))
    O.bodies.appendClumped([utils.sphere((0.123456789, 0, 0), 1, mask=2), utils.sphere((1.5, 0, 0), .5, mask=2)])
    O.bodies.appendClumped([utils.sphere((0, 3, 0), 1), utils.sphere((0, 4, 0), 1), utils.sphere((0, 5, 1e-7), .25, mask=2)])
    O.bodies.append(utils.sphere((-5, 5, 5), .3, mask=2))
    out = {}
    for name, kw in (('all', {}), ('comment', dict(comment='made by clump_packing.py')), ('mask2', dict(mask=2)), ('mask4', dict(mask=4))):
        f = os.path.join(tmp, name + '.txt')
        out[name] = dict(returned=list(export.textClumps(f, **kw)), text=open(f).read())
    return out


def imported(tmp):
    """export.textClumps' format read back, with and without shift, scale, orientation and sphere keywords."""
    f = os.path.join(tmp, 'clumps.txt')
    with open(f, 'w') as o:
        o.write('#format x_y_z_r_clumpId\n1\t0\t0\t1\t5\n0\t1\t0\t0.5\t2\n2\t0\t0\t1\t5\n0\t2\t0\t.5\t2\n'
                '# a comment\n3\t3\t3\t.25\t2\n4\t4\t4\t.5\t7\n5\t4\t4\t.5\t7\n')
    out = {}
    for name, kw in (('plain', {}), ('moved', dict(shift=Vector3(10, 0, 0), scale=2, orientation=Quaternion((0, 0, 1), math.pi / 2),
                                                  color=(1, 0, 0)))):
        O.reset()
        ret = ymport.textClumps(f, **kw)
        bodies = [[b.id, b.isClump, b.clumpId] + vec(b.state.pos) + [b.shape.radius if b.isClumpMember else 0.]
                  + (vec(b.shape.color) if b.isClumpMember and 'color' in kw else []) for b in O.bodies]
        out[name] = dict(returned=[[c, list(m)] for c, m in ret], bodies=bodies)
    return out


def templates():
    t = utils.clumpTemplate(relRadii=[1, .5, .25], relPositions=[[0, 0, 0], [1, 0, 0], (0, 1, 0)])
    errors = {}
    for name, args in (('default', ()), ('lengths', ([1, 2], [[0, 0, 0]])), ('short', ([1], [[0, 0, 0]]))):
        try:
            utils.clumpTemplate(*args)
            errors[name] = None
        except Exception as e:
            errors[name] = [type(e).__name__, str(e)]
    return dict(numCM=t.numCM, relRadii=t.relRadii, relPositions=[list(p) for p in t.relPositions], errors=errors)


def everything():
    tmp = tempfile.mkdtemp()
    return dict(clouds=clouds(), loaded=loaded(tmp), simulation=simulation(), exported=exported(tmp), imported=imported(tmp),
                templates=templates())


if RUN:
    print('CLUMPPACK ' + json.dumps(everything()))
