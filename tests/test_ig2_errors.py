"""An exception thrown by an Ig2 (geometry) functor inside the interaction loop's parallel pass ends
O.step() / O.run() with a RuntimeError naming the functor and the bodies (it used to abort the process),
and leaves the contact as it was, as the Ip2 and Law2 errors do. Trigger: the geometry functor changed
under an existing contact (Ig2_Sphere_Sphere_ScGeom6D finds a ScGeom and refuses it)."""
import pytest

from yade import (O, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop, NewtonIntegrator, Ig2_Sphere_Sphere_ScGeom,
                  Ig2_Sphere_Sphere_ScGeom6D, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack)
from yade.utils import sphere

MESSAGE = r'^InteractionLoop: Ig2_Sphere_Sphere_ScGeom6D \(bodies #0 and #1\): .*already have a ScGeom, not a ScGeom6D'


def pair_in_contact(fused):
    O.reset()
    O.bodies.append([sphere((0, 0, 0), 1), sphere((1.9, 0, 0), 1)])
    loop = InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()], [Law2_ScGeom_FrictPhys_CundallStrack()], fusedPasses=fused)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]), loop, NewtonIntegrator()]
    O.dt = 1e-6
    O.step()
    i = O.interactions[0, 1]
    assert i.isReal and type(i.geom).__name__ == 'ScGeom'
    return loop


@pytest.mark.parametrize('fused', [False, True])
def test_a_throwing_ig2_is_a_runtime_error_naming_functor_and_bodies(fused):
    loop = pair_in_contact(fused)
    g = O.interactions[0, 1].geom
    penetration, normal = g.penetrationDepth, tuple(g.normal)
    loop.geomDispatcher.functors = [Ig2_Sphere_Sphere_ScGeom6D()]
    with pytest.raises(RuntimeError, match=MESSAGE):
        O.step()
    assert O.iter == 1  # the step did not complete
    i = O.interactions[0, 1]  # the contact is left as it was
    assert i.isReal and type(i.geom).__name__ == 'ScGeom'
    assert i.geom.penetrationDepth == penetration and tuple(i.geom.normal) == normal
    with pytest.raises(RuntimeError, match=MESSAGE):
        O.run(5, True)
    loop.geomDispatcher.functors = [Ig2_Sphere_Sphere_ScGeom()]  # put back, the run goes on
    O.run(3, True)
    assert O.interactions[0, 1].isReal and O.iter >= 4
    O.reset()
