"""Grid elements (Effeindzourou et al. 2016; Bourrier et al. 2013): nodes, cylinders between nodes, chains of cylinders.

A grid is a set of GridNode bodies, which carry all the mass and move, linked two by two by GridConnection bodies, the
cylinders that other bodies touch. Each connection makes a cohesive contact between its two nodes (GridNodeGeom6D with the
nodes' material, e.g. CohFrictPhys and Law2_ScGeom6D_CohFrictPhys_CohesionMoment), so the engines must be set (O.engines)
before connections are made."""
import math

from ._yade import O, Body, GridNode, GridConnection, Vector3, Vector3i
from .utils import _resolveMaterial, _finiteVector, randomColor, createInteraction

__all__ = ['gridNode', 'gridConnection', 'cylinder', 'cylinderConnection']


def _positiveRadius(radius):
    if isinstance(radius, bool) or not isinstance(radius, (int, float)):
        raise TypeError('radius must be a number, not %s' % type(radius).__name__)
    if not (math.isfinite(radius) and radius > 0):
        raise ValueError('radius must be positive and finite, got %r' % radius)
    return float(radius)


def gridNode(center, radius, dynamic=None, fixed=False, wire=False, color=None, highlight=False, material=-1):
    """A GridNode body (not appended): a sphere of no mass of its own (its connections give it theirs), without a bound
    (other bodies touch the connections, not the nodes) and with mask 0. Parameters as in yade.utils.sphere."""
    center = _finiteVector('center', center)
    radius = _positiveRadius(radius)
    if dynamic is not None:
        fixed = not dynamic
    b = Body()
    b.shape = GridNode(radius=radius, color=color if color is not None else randomColor(), wire=wire, highlight=highlight)
    b.material = _resolveMaterial(material)
    b.state.pos = b.state.refPos = center
    b.state.mass = 0
    b.state.inertia = Vector3(0, 0, 0)
    b.dynamic = not fixed
    b.mask = 0
    b.bounded = False
    return b


def _gridNodeBody(i, name):
    if isinstance(i, bool) or not isinstance(i, int):
        raise TypeError('%s must be a body id (int), not %s' % (name, type(i).__name__))
    if i < 0 or i >= len(O.bodies) or O.bodies[i] is None:
        raise IndexError('%s=%d is not a body in O.bodies' % (name, i))
    b = O.bodies[i]
    if not isinstance(b.shape, GridNode):
        raise TypeError('%s=%d is not a GridNode (its shape is %s)' % (name, i, type(b.shape).__name__))
    return b


def gridConnection(id1, id2, radius, wire=False, color=None, highlight=False, material=-1, mask=1, cellDist=None):
    """A GridConnection body (not appended) between the GridNodes id1 and id2, and the cohesive contact of the two nodes.

    Each node gets half the cylinder's mass, pi·radius²·L·density/2 with the density of node id1's material, and the inertia
    2/5·(that mass)·radius². The connection itself does not move (its position is node id1's) and has the mass of the
    cylinder with its own material's density, pi·radius²·L·density/2. Its material is the one of its contacts with other
    bodies; the nodes' material makes the bond between the nodes. cellDist: node id2's periodic image (see
    GridConnection.cellDist)."""
    n1, n2 = _gridNodeBody(id1, 'id1'), _gridNodeBody(id2, 'id2')
    if id1 == id2:
        raise ValueError('gridConnection: id1 and id2 are the same node (#%d)' % id1)
    radius = _positiveRadius(radius)
    shape = GridConnection(radius=radius, node1=n1, node2=n2, color=color if color is not None else randomColor(), wire=wire,
                           highlight=highlight)
    p2 = n2.state.pos
    if cellDist is not None:
        shape.periodic, shape.cellDist = True, Vector3i(cellDist)
        p2 = p2 + O.cell.hSize * Vector3(shape.cellDist)
    length = (p2 - n1.state.pos).norm()
    if not length > 0:
        raise ValueError('gridConnection: nodes #%d and #%d are at the same place (a connection of length 0)' % (id1, id2))
    b = Body()
    b.shape = shape
    b.material = _resolveMaterial(material)
    b.state.pos = b.state.refPos = n1.state.pos
    b.state.mass = math.pi * radius ** 2 * length * b.material.density / 2
    b.state.inertia = Vector3(1, 1, 1) * (2. / 5. * b.state.mass * radius ** 2)
    b.dynamic = False
    b.mask = mask
    i = createInteraction(id1, id2)  # (first: nothing is changed when the engines cannot make the bond)
    i.geom.connectionBody = b
    half = math.pi * radius ** 2 * length * n1.material.density / 2
    for n in (n1, n2):
        n.state.mass = n.state.mass + half
        n.state.inertia = n.state.inertia + Vector3(1, 1, 1) * (2. / 5. * half * radius ** 2)
        n.shape.addConnection(b)
    return b


def cylinder(begin=Vector3(0, 0, 0), end=Vector3(1, 0, 0), radius=0.2, nodesIds=[], cylIds=[], dynamic=None, fixed=False, wire=False,
             color=None, highlight=False, intMaterial=-1, extMaterial=-1, mask=1):
    """A cylinder with rounded ends from begin to end: two new GridNodes (intMaterial, the bond's material) and their
    GridConnection (extMaterial, the material of contacts with other bodies), all appended; their ids are appended to
    nodesIds and cylIds."""
    color = color if color is not None else randomColor()
    ids = [O.bodies.append(gridNode(p, radius, dynamic, fixed, wire, color, highlight, intMaterial)) for p in (begin, end)]
    nodesIds.extend(ids)
    cylIds.append(O.bodies.append(gridConnection(ids[0], ids[1], radius, wire, color, highlight, extMaterial, mask)))


def cylinderConnection(vertices, radius=0.2, nodesIds=[], cylIds=[], dynamic=None, fixed=False, wire=False, color=None, highlight=False,
                       intMaterial=-1, extMaterial=-1, mask=1):
    """A chain of cylinders through the vertices: a GridNode at each vertex and a GridConnection between consecutive ones,
    all appended (ids appended to nodesIds and cylIds). Other parameters as in cylinder."""
    vertices = list(vertices)
    if len(vertices) < 2:
        raise ValueError('cylinderConnection needs at least 2 vertices, got %d' % len(vertices))
    color = color if color is not None else randomColor()
    ids = [O.bodies.append(gridNode(p, radius, dynamic, fixed, wire, color, highlight, intMaterial)) for p in vertices]
    nodesIds.extend(ids)
    for a, b in zip(ids[:-1], ids[1:]):
        cylIds.append(O.bodies.append(gridConnection(a, b, radius, wire, color, highlight, extMaterial, mask)))
