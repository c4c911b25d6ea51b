"""Fuzzing of the Python interface (scripts/fuzz/fuzz_api.py, doc/fuzzing.md): a fixed seed and a fixed
number of random call sequences (bad ids, NaN and infinities, wrong types, erased bodies, views kept past
erasure or O.reset(), engines changed during a run), each followed by three steps: no crash, no hang,
every refusal an ordinary exception with a message, never a non-finite body state. The counts are
printed (pytest -s) and recorded.

Below: one regression test for each bug the harness found.
"""
import json
import math
import pathlib

import pytest

import yade
from yade import O
from test_fuzz_loader import run_harness

REPO = pathlib.Path(__file__).resolve().parent.parent
SCRIPT = REPO / 'scripts' / 'fuzz' / 'fuzz_api.py'
CASES = 1500
SEED = 7


def test_random_calls_never_crash_nor_leave_a_non_finite_state(tmp_path, record_property):
    summary, report = run_harness(SCRIPT, CASES, SEED, tmp_path)
    counts = summary['counts']
    record_property('fuzz_api_cases', sum(counts.values()))
    record_property('fuzz_api_counts', json.dumps(counts))
    assert sum(counts.values()) == CASES, report
    assert summary['failures'] == [], report
    assert counts.get('ran', 0) > CASES // 4, report


# ====================================================================== regressions

def small_scene():
    from yade.utils import sphere
    O.bodies.append([sphere((0, 0, 0), .1), sphere((.19, 0, 0), .1)])
    O.engines = [yade.ForceResetter(), yade.InsertionSortCollider([yade.Bo1_Sphere_Aabb()]),
                 yade.InteractionLoop([yade.Ig2_Sphere_Sphere_ScGeom()], [yade.Ip2_FrictMat_FrictMat_FrictPhys()],
                                      [yade.Law2_ScGeom_FrictPhys_CundallStrack()]),
                 yade.NewtonIntegrator()]
    O.dt = 1e-5


@pytest.mark.parametrize('engine, attr', [(2, 'geomDispatcher'), (2, 'physDispatcher'), (2, 'lawDispatcher'),
                                          (1, 'boundDispatcher')])
def test_a_dispatcher_set_to_None_stops_the_step_with_an_error(fresh_scene, engine, attr):
    """Bug (case 2 of seed 7): InteractionLoop.geomDispatcher = None, then O.step(): segmentation fault.
    Fix (pkg/common/InteractionLoop.cpp, InsertionSortCollider.cpp): the engine refuses to run without its
    dispatchers (ValueError), from Python as from a file."""
    small_scene()
    O.step()
    setattr(O.engines[engine], attr, None)
    with pytest.raises(ValueError, match=attr):
        O.step()
    O.stringToScene(O.sceneToString())  # the same scene read from a file
    with pytest.raises(ValueError, match=attr):
        O.step()


@pytest.mark.parametrize('ids, exc', [(('3', 1), TypeError), ((None, 1), TypeError), ((1.5, 1), TypeError),
                                      ((2 ** 63, 0), IndexError), ((0, -2 ** 31 - 1), IndexError)])
def test_interactions_indexed_with_a_bad_id_raise_a_clear_error(fresh_scene, ids, exc):
    """Bug: O.interactions['3', 1] (or None, 1.5, 2**63) raised 'RuntimeError: Unable to cast Python
    instance to C++ type'. Fix (py/wrapper/OmegaWrapper.cpp): TypeError naming the id, or IndexError
    ('No such interaction') for an int beyond the range of ids."""
    small_scene()
    O.step()
    with pytest.raises(exc, match='body id must be an int|No such interaction'):
        O.interactions[ids]
    assert O.interactions[0, 1].id1 == 0


@pytest.mark.parametrize('key, exc', [(None, TypeError), (1.5, TypeError), ((1, 2), TypeError), (2 ** 63, IndexError)])
def test_materials_indexed_with_a_bad_key_raise_a_clear_error(fresh_scene, key, exc):
    """Bug: O.materials[None] (or 1.5, (1, 2), 2**63) raised 'RuntimeError: Unable to cast Python instance to
    C++ type'. Fix (py/wrapper/OmegaWrapper.cpp): TypeError naming the key, or IndexError for an int beyond
    the range of ids."""
    O.materials.append(yade.FrictMat())
    with pytest.raises(exc, match='expected an int id or a str label|out of range'):
        O.materials[key]
    assert O.materials[0].id == 0


def test_a_bool_attribute_takes_an_int_of_any_size(fresh_scene):
    """Bug: a bool attribute set to an int beyond 64 bits (2**64) raised 'RuntimeError: Unable to cast'.
    Fix (py/wrapper/Attributes.cpp): any int, non-zero is true."""
    e = yade.NewtonIntegrator()
    e.dead = 2 ** 64
    assert e.dead is True
    e.dead = 0
    assert e.dead is False


def test_an_orientation_written_non_finite_or_zero_into_a_view_stops_the_next_step():
    """Found by scripts/fuzz/fuzz_api.py (a NaN or zero written into an item of b.state.ori or of
    O.bodies.arrays().ori skips the setter's check): NewtonIntegrator's stability guard now checks
    orientations too, and the step refuses with the body named."""
    import numpy as np
    from yade import O
    from yade import StabilityError
    from yade.wrapper import ForceResetter, NewtonIntegrator
    from yade.utils import sphere
    for how in ('nan-view', 'zero-array'):
        O.reset()
        O.engines = [ForceResetter(), NewtonIntegrator()]
        O.dt = 1e-4
        O.bodies.append([sphere((0, 0, 0), 1), sphere((5, 0, 0), 1)])
        O.step()
        if how == 'nan-view':
            np.asarray(O.bodies.arrays().ori)[1, 0] = float('nan')  # (State.ori is read as a copy, as in the reference)
        else:
            np.asarray(O.bodies.arrays().ori)[1] = 0
        with pytest.raises(StabilityError, match='orientation'):
            O.step()
