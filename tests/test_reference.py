"""Agreement with the reference Yade: the scripts in tests/reference/ run here and their output is
compared with what the reference printed (tests/reference/data/, made by regenerate.sh)."""
import os
import subprocess
import sys

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
BUILD = os.environ.get('YADE_BUILD_DIR', os.path.join(REPO, 'build'))


def runHere(name):
    env = dict(os.environ, PYTHONPATH=BUILD)
    out = subprocess.run([sys.executable, os.path.join(HERE, 'reference', name + '.py')], env=env, check=True,
                         capture_output=True, text=True, timeout=600).stdout
    return np.array([[float(x) for x in l.split()] for l in out.splitlines() if l and l[0].isdigit()])


@pytest.mark.parametrize('name, steps', [('bouncing_sphere', 6000), ('oblique_impact', 4000)])
def test_trajectory_equals_reference(name, steps):
    ref = np.loadtxt(os.path.join(HERE, 'reference', 'data', name + '.txt'))
    ours = runHere(name)
    assert ours.shape == ref.shape
    assert ref[-1, 0] == steps
    np.testing.assert_array_equal(ours[:, :2], ref[:, :2])  # same iterations and bodies
    # positions, velocities and angular velocities: deviation below 1e-6 of each column's scale
    dev = np.abs(ours[:, 2:] - ref[:, 2:])
    scale = np.abs(ref[:, 2:]).max(axis=0)
    scale[scale == 0] = 1
    assert (dev / scale).max() < 1e-6
    # and where a value is not tiny, also pointwise relative
    big = np.abs(ref[:, 2:]) > 1e-3 * scale
    assert (dev[big] / np.abs(ref[:, 2:])[big]).max() < 1e-6
