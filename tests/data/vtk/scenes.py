"""The small scenes of tests/test_vtk_exporter.py, built the same way by this engine and by the
reference Yade (make_reference.py, run with `yade -n -x`): plain yade API only."""
from yade import O, utils, Matrix3
from yade import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb, InteractionLoop,
                  Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                  Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator)


def _engines(gravity):
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=gravity)]


def sceneA():
    """Two touching spheres on a facet, one lone sphere, a second facet; one step: 3 contacts
    (0-1, facet 2 with 0 and 1)."""
    O.reset()
    O.bodies.append([utils.sphere((0, 0, 0), .5), utils.sphere((0.9, 0, 0), .5),
                     utils.facet([(-1, -1, -0.45), (2, -1, -0.45), (0, 2, -0.45)]),
                     utils.sphere((5, 5, 5), .3),
                     utils.facet([(2, -1, -0.45), (2, 2, -0.45), (0, 2, -0.45)])])
    _engines((0, 0, -10))
    O.dt = 1e-3
    O.run(1, True)


def sceneB():
    """Two facets sharing an edge, bodies 0 and 1 (the reference's exportFacetsAsMesh works only
    when the facets are the first bodies), and a sphere."""
    O.reset()
    O.bodies.append([utils.facet([(-1, -1, -0.45), (2, -1, -0.45), (0, 2, -0.45)]),
                     utils.facet([(2, -1, -0.45), (2, 2, -0.45), (0, 2, -0.45)]),
                     utils.sphere((5, 5, 5), .3)])


def sceneC():
    """A sheared periodic cell with two spheres touching across its x boundary and one alone; one
    step: one contact, cellDist (-1,0,0)."""
    O.reset()
    O.periodic = True
    O.cell.hSize = Matrix3(2, 0.2, 0, 0, 2, 0, 0, 0, 2)
    O.bodies.append([utils.sphere((0.1, 1, 1), .3), utils.sphere((1.85, 1, 1), .3), utils.sphere((1, 1, 1), .2)])
    _engines((0, 0, 0))
    O.dt = 1e-4
    O.run(1, True)


# the exports whose files are compared with the reference's; each is (scene, method, keyword arguments)
EXPORTS = [
    ('A', 'exportSpheres', dict(what=dict(v='b.state.vel', m='b.state.mass', I='b.state.inertia', mat='Matrix3(1,2,3,4,5,6,7,8,9)',
                                          i='b.id'), comment='spheres of scene A')),
    ('A', 'exportSpheres', dict(ids=[1, 0], useRef=True, numLabel=42)),
    ('A', 'exportFacets', dict(what=dict(n='b.shape.normal', i='b.id', area='b.shape.area'))),
    ('A', 'exportInteractions', dict(ids=[(0, 1), (2, 0), (2, 1)], what=dict(fn='i.phys.normalForce', kn='i.phys.kn'))),
    ('A', 'exportInteractions', dict(ids=[(1, 0)], useRef=True)),
    ('A', 'exportContactPoints', dict(ids=[(0, 1), (2, 0), (2, 1)], what=dict(fn='i.phys.normalForce', n='i.geom.normal'))),
    ('B', 'exportFacetsAsMesh', dict(connectivityTable=[(0, 1, 2), (1, 3, 2)], what=dict(i='b.id', n='b.shape.normal'))),
    ('C', 'exportSpheres', dict()),
    ('C', 'exportInteractions', dict(what=dict(fn='i.phys.normalForce'))),
    ('C', 'exportContactPoints', dict(what=dict(fn='i.phys.normalForce'))),
    ('C', 'exportPeriodicCell', dict(comment='periodic cell')),
]

SCENES = {'A': sceneA, 'B': sceneB, 'C': sceneC}


def runExports(export, directory):
    """Run EXPORTS, one VTKExporter per scene (base name directory/<scene>), startSnap 3."""
    import os
    exporters = {}
    for scene, method, kw in EXPORTS:
        if scene not in exporters:
            SCENES[scene]()
            exporters[scene] = export.VTKExporter(os.path.join(directory, scene), startSnap=3)
        getattr(exporters[scene], method)(**kw)
    return exporters
