"""Writes reference.json beside this file: for each call below, run by the reference Yade 2023.02a on the .unv files
beside this file, each facet's body position and world-space vertices (b.state.pos + b.state.ori * v) in the order
returned, the nodes and elements when returnConnectivityTable=True, and for the call with keywords each facet's
color, wire, highlight, mask, dynamic, blockedDOFs and material label. tests/test_ymport_unv.py evaluates the same
call strings here and compares to 1e-12. Run once, from anywhere:

    yade -n -x tests/data/unv/make_reference.py

cube.unv: a unit cube's surface as 12 triangles (FE descriptor 41), outward, laid out as Salome writes it (units
164, coordinate system 2420, nodes 2411, elements 2412 with the 12 edges as rods (11) first, a group 2467).
tetra.unv: a tetrahedron's surface, outward, with coordinates that are not round, the elements' dataset before
the nodes, the nodes in two datasets, a beam (21) before the triangles and a solid tetrahedron (111) after them.
Only files both engines read alike belong here (doc: ymport.unv's docstring lists where this engine differs).
shell.unv, the reference's own example (examples/test/unv-read), is added where the reference installs it."""
import json
import os
import sys

from yade import O, FrictMat, Vector3, ymport  # noqa: F401 (the call strings use them)

HERE = os.path.dirname(os.path.abspath(sys.argv[0]))  # (__file__ is the launcher's there)
SHELL = '/usr/share/doc/yade/examples/test/unv-read/shell.unv'
CALLS = [
    "ymport.unv(D + 'cube.unv')",
    "ymport.unv(D + 'cube.unv', shift=(1, -2, 3.5), scale=2.5, returnConnectivityTable=True)",
    "ymport.unv(D + 'cube.unv', Vector3(-0.3, 0.7, 0.1), 0.1)",
    "ymport.unv(D + 'cube.unv', color=(1, 0, 0), wire=False, fixed=False, mask=5, highlight=True, material='m1')",
    "ymport.unv(D + 'tetra.unv', returnConnectivityTable=True)",
    "ymport.unv(D + 'tetra.unv', shift=(0.5, 0.25, -1), scale=1e-3, returnConnectivityTable=True, mask=3)",
    "ymport.unv(SHELL, returnConnectivityTable=True)",
]


def record(call, ret):
    out = {'call': call}
    facets = ret[0] if isinstance(ret, tuple) else ret
    out['facets'] = [[list(b.state.pos)] + [list(b.state.pos + b.state.ori * v) for v in b.shape.vertices] for b in facets]
    if isinstance(ret, tuple):
        out['nodes'] = [list(n) for n in ret[1]]
        out['elements'] = [list(e) for e in ret[2]]
    if 'color=' in call:
        out['attrs'] = [{'color': list(b.shape.color), 'wire': b.shape.wire, 'highlight': b.shape.highlight, 'mask': b.mask,
                         'dynamic': b.dynamic, 'blockedDOFs': b.state.blockedDOFs, 'material': b.material.label}
                        for b in facets]
    return out


O.materials.append(FrictMat(label='m1'))
env = {'ymport': ymport, 'Vector3': Vector3, 'D': HERE + os.sep, 'SHELL': SHELL}
result = []
for call in CALLS:
    if 'SHELL' in call and not os.path.exists(SHELL):
        continue
    result.append(record(call, eval(call, env)))
with open(os.path.join(HERE, 'reference.json'), 'w') as f:
    json.dump(result, f, separators=(',', ':'))
    f.write('\n')
print('wrote %d calls to %s' % (len(result), os.path.join(HERE, 'reference.json')))
