"""Writes reference.json beside this file: for each call below, run by the reference Yade 2023.02a, each facet's
body position and its world-space vertices (b.state.pos + b.state.ori * v), in the order returned; for
facetSphere(..., returnElementMap=True) also the nodes and elements. tests/test_geom_facets.py evaluates the
same call strings here and compares to 1e-12. Run once, in this directory's parent or anywhere:

    yade -n -x tests/data/geom_facets/make_reference.py

(The orientations are built from unit axes: the reference's Quaternion(axis, angle) does not normalize the axis.)
Only calls both engines accept belong here; where this engine deliberately differs (doc/compatibility.md), the
test checks that separately."""
import json
import math  # noqa: F401 (the call strings use it)
import os
import sys

from yade import geom, Quaternion, Vector3  # noqa: F401 (the call strings use them)

Q1 = 'Quaternion(Vector3(0.48, -0.6, 0.64), 0.7)'  # a unit axis
Q2 = 'Quaternion(Vector3(0, 0.6, 0.8), -2.1)'
CALLS = [
    # facetCylinder (already here; now with the reference's vertex order, closeGap with and without caps)
    'geom.facetCylinder((1, 2, 3), 1.5, 2, segmentsNumber=5)',
    'geom.facetCylinder((1, 2, 3), 1.5, 2, orientation=%s, segmentsNumber=4, angleRange=(0.2, 2.0), closeGap=True,'
    ' radiusTopInner=0.3, radiusBottomInner=0.5)' % Q1,
    'geom.facetCylinder((0, 0, 0), 1, 3, segmentsNumber=3, angleRange=(0, 1.5 * math.pi), closeGap=True, wallMask=3)',
    'geom.facetCylinder((-1, 0, 2), 1, 3, orientation=%s, segmentsNumber=4, angleRange=(-1, math.pi - 1),'
    ' closeGap=True, wallMask=7)' % Q2,
    # facetCone
    'geom.facetCone((0, 0, 0), 1, 2, 3, segmentsNumber=4)',
    'geom.facetCone((1, -2, 0.5), 0.6, 1.5, 2, orientation=%s, segmentsNumber=5, wallMask=5)' % Q1,
    'geom.facetCone((0, 0, 0), 0, 2, 3, segmentsNumber=4, angleRange=(0, 1.5 * math.pi), closeGap=True, wallMask=7)',
    'geom.facetCone((0, 1, 0), 1.2, 0, 3, orientation=%s, segmentsNumber=3, angleRange=(0.5, 2), closeGap=True)' % Q2,
    'geom.facetCone((0, 0, 0), 1, 2, 3, segmentsNumber=3, angleRange=(0, 1.3 * math.pi), closeGap=True,'
    ' radiusTopInner=0.5, radiusBottomInner=0.2)',
    'geom.facetCone((0, 0, 0), 1, 2, 0, segmentsNumber=3, wallMask=4)',
    # facetBunker
    'geom.facetBunker((0, 0, 0), 2, 1, 3, 1, 0.5, segmentsNumber=4, wallMask=7)',
    'geom.facetBunker((1, 2, 3), 2.2, 0.8, 1.5, 1.1, orientation=%s, segmentsNumber=5)' % Q1,
    'geom.facetBunker((0, 0, 0), 2, 1, 3, 1, segmentsNumber=3, wallMask=7, angleRange=(0, 1.5 * math.pi),'
    ' closeGap=True)',
    'geom.facetBunker((0, 0, -1), 2, 1, 0, 1, 0.5, orientation=%s, segmentsNumber=3, wallMask=6,'
    ' angleRange=(0.3, 2.1), closeGap=True)' % Q2,
    'geom.facetBunker((0, 0, 0), 2, 1, 3, 1, 0.5, segmentsNumber=3, wallMask=7, radiusTopInner=0.4,'
    ' radiusBottomInner=0.2)',
    # facetPolygon (the reference fails on angleRange=None: every call here gives one)
    'geom.facetPolygon((1, 2, 3), 1.7, segmentsNumber=6, angleRange=(0, 2 * math.pi))',
    'geom.facetPolygon((0, 0, 0), 1, orientation=%s, segmentsNumber=3, angleRange=(0, math.pi / 2),'
    ' radiusInner=0.5)' % Q1,
    'geom.facetPolygon((0, 1, 0), 2, segmentsNumber=4, angleRange=(2.5, -1))',
    # facetHelix
    'geom.facetHelix((0, 0, 0), 1, 2, segmentsNumber=6)',
    'geom.facetHelix((1, 2, 3), 1.7, 0.3, orientation=%s, segmentsNumber=5, angleRange=(0, 5 * math.pi),'
    ' radiusInner=0.5)' % Q2,
    'geom.facetHelix((0, 0, 0), 1, 2, segmentsNumber=3, angleRange=(2, 1))',
    # facetSphere
    'geom.facetSphere((0, 0, 0), 1, 4, 3)',
    'geom.facetSphere((1, 2, 3), 1.5, 5, 6, returnElementMap=True)',
    'geom.facetSphere((-1, 0, 2), 0.4, 3, 4)',
    # facetParallelepiped
    'geom.facetParallelepiped((0, 0, 0), (1, 2, 3), 1)',
    'geom.facetParallelepiped((1, 2, 3), (1.2, 0.7, 2), 1.5, orientation=%s, wallMask=45)' % Q1,
    'geom.facetParallelepiped((0, 0, 0), (1, 2, 3), 3)',
    'geom.facetParallelepiped((0, 0, 0), (1, 2, 3), 0)',
    'geom.facetParallelepiped((0, 1, 0), (0, 2, 3), 1, orientation=%s)' % Q2,
    # facetBox (already here)
    'geom.facetBox((1, 2, 3), (1, 0.5, 2), orientation=%s, wallMask=31)' % Q2,
]


def world(b):
    return [list(b.state.pos)] + [list(b.state.pos + b.state.ori * v) for v in b.shape.vertices]


def dump(call):
    r = eval(call)
    if isinstance(r, tuple):
        facets, nodes, elements = r
        return {'call': call, 'facets': [world(b) for b in facets], 'nodes': [list(n) for n in nodes],
                'elements': [list(e) for e in elements]}
    return {'call': call, 'facets': [world(b) for b in r]}


out = os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), 'reference.json')  # (__file__ is the launcher's there)
with open(out, 'w') as f:
    json.dump([dump(c) for c in CALLS], f, separators=(',', ':'))
    f.write('\n')
print('wrote %d calls to %s' % (len(CALLS), out))
