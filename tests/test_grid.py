"""Grid elements (yade.gridpfacet: GridNode, GridConnection, GridNodeGeom6D and the node bonds).

Checked against the reference's numbers on the same script (tests/reference/grid.py, its output tests/reference/data/grid.json),
against Euler-Bernoulli beam theory (a cantilever of connections), and for clear errors on bad input."""
import math
import os

import pytest
from reference_data import flat, scenes_and_data

from yade import O, Vector3, gridpfacet
from yade import (Body, Bo1_GridConnection_Aabb, CohFrictMat, GridConnection, GridNode, GridNodeGeom6D,
                  Ig2_GridNode_GridNode_GridNodeGeom6D)

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

HERE = os.path.dirname(os.path.abspath(__file__))
scenes, REFERENCE = scenes_and_data('grid.py', 'grid.json')  # (tests/reference_data.py)


def assert_close(here, ref, abs_):
    a, b = flat(here), flat(ref)
    assert len(a) == len(b)
    for x, y in zip(a, b):
        assert x == pytest.approx(y, rel=0, abs=abs_)


def test_attributes_and_defaults_as_in_reference():
    assert GridNode().dict()['radius'] != GridNode().dict()['radius']  # NaN
    c = GridConnection().dict()
    assert c['node1'] is None and c['node2'] is None and c['periodic'] is False and tuple(c['cellDist']) == (0, 0, 0)
    assert Bo1_GridConnection_Aabb().dict() == dict(aabbEnlargeFactor=-1.0, label='')
    assert Ig2_GridNode_GridNode_GridNodeGeom6D().dict() == dict(updateRotations=True, creep=False, interactionDetectionFactor=1.0,
                                                                  avoidGranularRatcheting=True, label='')
    assert GridNodeGeom6D().dict()['connectionBody'] is None


@pytest.mark.parametrize('scene, kw', [('chain', {}), ('undamped', dict(n=4, steps=2000, damping=0.0))])
def test_falling_chain_equals_the_reference(scene, kw):
    """a chain of 0.1 m connections, node 0 fixed, falling under gravity (damped and undamped): masses to 1e-16, the nodes'
    positions, velocities and spins to 1e-10 and the bonds' forces and moments (up to 9 N) to 1e-9 after up to 3000 steps
    (seen: 1e-11 and 2e-10)"""
    here, ref = scenes.chain(**kw), REFERENCE[scene]
    for k in ('mass', 'inertia', 'connMass'):
        assert_close(here[k], ref[k], abs_=1e-15)
    for row, rrow in zip(here['rows'], ref['rows']):
        assert_close(row['nodes'], rrow['nodes'], abs_=1e-10)
        assert_close(row['bonds'], rrow['bonds'], abs_=1e-9)
    # the bond's length: the connection's, as the nodes moved
    for L in here['length']:
        assert L == pytest.approx(0.1, abs=1e-4)


def test_bond_is_a_beam_of_the_node_material():
    """kn = EA/L, ks = 12EI/L³, kr = EI/L, ktw = GJ/L with node 1's material, unp = the initial penetration (the reference's values)"""
    scenes.engines()
    O.materials.append(CohFrictMat(young=1e7, poisson=0.3, density=1000, alphaKr=3, label='a'))
    O.materials.append(CohFrictMat(young=3e7, poisson=0.1, density=1000, label='b'))
    a = O.bodies.append(gridpfacet.gridNode((0, 0, 0), 0.02, material='a'))
    b = O.bodies.append(gridpfacet.gridNode((0.1, 0, 0), 0.03, material='b'))
    c = O.bodies.append(gridpfacet.gridConnection(a, b, 0.02))
    i = O.interactions[a, b]
    p = i.phys
    E, nu, r, L = 1e7, 0.3, 0.02, 0.1
    I = math.pi * r ** 4 / 4
    assert p.kn == pytest.approx(E * math.pi * r * r / L, rel=1e-14) == 125663.70614359173
    assert p.ks == pytest.approx(12 * E * I / L ** 3, rel=1e-14) == pytest.approx(15079.644737231003, rel=1e-15)
    assert p.kr == pytest.approx(12.566370614359172, rel=1e-15)
    assert p.ktw == pytest.approx(E / (2 * (1 + nu)) * 2 * I / L, rel=1e-14) == pytest.approx(9.66643893412244, rel=1e-15)
    assert p.unp == pytest.approx(-0.05, abs=1e-16)
    assert i.geom.connectionBody.id == c
    assert [x.id for x in O.bodies[a].shape.getConnections()] == [c]
    assert O.bodies[c].shape.getLength() == pytest.approx(0.1)


def test_masses_and_flags_of_nodes_and_connections():
    """each node gets half of every cylinder, pi·r²·L·rho/2 (rho of node id1's material), inertia 2/5·m·r²; nodes have no bound
    and mask 0; the connection does not move, has mask 1 and sits at node 1 (the reference's values)"""
    scenes.engines()
    O.materials.append(CohFrictMat(density=1000, label='i'))
    O.materials.append(CohFrictMat(density=3000, label='e'))
    nodes, cyls = [], []
    gridpfacet.cylinderConnection([(0, 0, 0), (0, 0.7, 0), (0, 0.7, 0.5)], 0.1, nodes, cyls, intMaterial='i', extMaterial='e')
    half1, half2 = math.pi * 0.01 * 0.7 * 1000 / 2, math.pi * 0.01 * 0.5 * 1000 / 2
    assert [O.bodies[i].state.mass for i in nodes] == pytest.approx([half1, half1 + half2, half2], rel=1e-15)
    assert O.bodies[nodes[1]].state.inertia[0] == pytest.approx(0.4 * (half1 + half2) * 0.01, rel=1e-14)
    assert [O.bodies[i].state.mass for i in cyls] == pytest.approx([math.pi * 0.01 * 0.7 * 3000 / 2, math.pi * 0.01 * 0.5 * 3000 / 2])
    for i in nodes:
        assert (O.bodies[i].mask, O.bodies[i].bounded, O.bodies[i].dynamic) == (0, False, True)
    for i, n in zip(cyls, nodes):
        assert (O.bodies[i].mask, O.bodies[i].dynamic, O.bodies[i].state.pos) == (1, False, O.bodies[n].state.pos)
    assert sorted((i.id1, i.id2) for i in O.interactions) == [(nodes[0], nodes[1]), (nodes[1], nodes[2])]


def test_bound_holds_both_node_spheres():
    scenes.engines(gravity=(0, 0, 0))
    O.materials.append(CohFrictMat(label='i'))
    nodes, cyls = [], []
    gridpfacet.cylinder((0, 0, 0), (1, 2, -1), 0.1, nodes, cyls, intMaterial='i', extMaterial='i')
    O.dt = 1e-6
    O.step()
    bb = O.bodies[cyls[0]].bound
    for k, lo, hi in ((0, 0, 1), (1, 0, 2), (2, -1, 0)):
        assert lo - 0.1 - 0.05 - 1e-12 <= bb.min[k] <= lo - 0.1 + 1e-12  # (plus the collider's Verlet distance)
        assert hi + 0.1 - 1e-12 <= bb.max[k] <= hi + 0.1 + 0.05 + 1e-12


def test_cantilever_of_connections_against_euler_bernoulli_and_the_reference():
    """a horizontal cantilever of 5 connections (node 0 clamped) under a small transverse tip force, run to the static state:
    the tip rotation is Euler-Bernoulli's F·l²/(2EI) (seen: 4e-9 relative); the deflection is 1.5 % above F·l³/(3EI) (the
    shear springs give 2.5 times the compliance of 12EI/L³ here), and equals the reference's static deflection on the same
    scene, 3.3654638854911646e-05 m (yade -n -j1 -x on this scene, 4 × 6000 steps; seen: 1e-16 relative)"""
    E, r, L, n, F = 1e7, 0.02, 0.1, 6, 1e-3
    scenes.engines(damping=0.8, gravity=(0, 0, 0))
    O.materials.append(CohFrictMat(young=E, poisson=0.3, density=1000, normalCohesion=1e12, shearCohesion=1e12, momentRotationLaw=True,
                                   label='i'))
    nodes, cyls = [], []
    gridpfacet.cylinderConnection([(L * i, 0, 0) for i in range(n)], r, nodes, cyls, intMaterial='i', extMaterial='i')
    O.bodies[nodes[0]].state.blockedDOFs = 'xyzXYZ'
    O.dt = 4e-4
    O.step()
    O.forces.setPermF(nodes[-1], (0, F, 0))
    O.run(18000, True)
    I, l = math.pi * r ** 4 / 4, L * (n - 1)
    tip = O.bodies[nodes[-1]].state
    assert tip.rot()[2] == pytest.approx(F * l ** 2 / (2 * E * I), rel=1e-7)
    assert tip.pos[1] == pytest.approx(3.3654638854911646e-05, rel=1e-9)
    assert tip.pos[1] == pytest.approx(F * l ** 3 / (3 * E * I), rel=0.016)


def test_bad_input_is_a_clear_error():
    scenes.engines()
    O.materials.append(CohFrictMat(label='i'))
    a = O.bodies.append(gridpfacet.gridNode((0, 0, 0), 0.1))
    b = O.bodies.append(gridpfacet.gridNode((0, 0, 0), 0.1))
    s = O.bodies.append(Body())
    with pytest.raises(ValueError, match='same place'):
        gridpfacet.gridConnection(a, b, 0.1)
    with pytest.raises(ValueError, match='same node'):
        gridpfacet.gridConnection(a, a, 0.1)
    with pytest.raises(TypeError, match='not a GridNode'):
        gridpfacet.gridConnection(a, s, 0.1)
    with pytest.raises(IndexError):
        gridpfacet.gridConnection(a, 99, 0.1)
    with pytest.raises(ValueError, match='radius'):
        gridpfacet.gridNode((0, 0, 0), -1)
    with pytest.raises(ValueError, match='2 vertices'):
        gridpfacet.cylinderConnection([(0, 0, 0)])
    with pytest.raises(RuntimeError, match='node1 and node2'):
        GridConnection(radius=0.1).getLength()


def test_saved_grid_runs_on_as_before(tmp_path):
    """O.save then O.load: the loaded grid continues exactly as the one that was not saved (its connections find their nodes by
    id; GridNodeGeom6D.connectionBody and GridNode.getConnections() are not saved)"""
    scenes.engines()
    O.materials.append(CohFrictMat(young=1e7, poisson=0.3, density=1000, normalCohesion=1e12, shearCohesion=1e12, momentRotationLaw=True,
                                   label='i'))
    nodes, cyls = [], []
    gridpfacet.cylinderConnection([(0.1 * i, 0, 0) for i in range(4)], 0.02, nodes, cyls, intMaterial='i', extMaterial='i')
    O.bodies[nodes[0]].state.blockedDOFs = 'xyzXYZ'
    O.dt = 1e-4
    O.run(100, True)
    f = str(tmp_path / 'grid.yade')
    O.save(f)
    O.run(100, True)
    a = [tuple(b.state.pos) for b in O.bodies]
    O.load(f)
    O.run(100, True)
    assert [tuple(b.state.pos) for b in O.bodies] == a
    assert O.bodies[cyls[0]].shape.node2.id == nodes[1]
    assert O.bodies[cyls[0]].shape.getLength() == pytest.approx(0.1, abs=1e-5)


def test_connection_without_its_nodes_stops_the_step_with_an_error():
    """a GridConnection made by hand without nodes, or whose node was erased: the collider's Bo1 raises RuntimeError (not a crash)"""
    from yade import Aabb
    from yade.utils import sphere
    scenes.engines()
    O.bodies.append(sphere((0, 0, 0), 0.1))
    b = Body()
    b.shape, b.material, b.bound = GridConnection(radius=0.1), CohFrictMat(), Aabb()
    O.bodies.append(b)
    with pytest.raises(RuntimeError, match='node1 and node2'):
        O.step()
    n = O.bodies.append(gridpfacet.gridNode((0, 0, 0), 0.1))
    b.shape.node1, b.shape.node2 = O.bodies[n], O.bodies[0]
    O.bodies.erase(n)
    with pytest.raises(RuntimeError, match='not in O.bodies'):
        O.step()
