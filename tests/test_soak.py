"""scripts/soak.py at a tiny size, so that it keeps working: a dense lattice run with saves and
reloads (in memory and to files) equals the uninterrupted run bit for bit, and the script prints
its memory figures (the real soak, 10^5..10^6 steps, is run by hand: doc/reliability.md)."""
import os
import pathlib
import re
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parent.parent


def soak(*args):
    r = subprocess.run([sys.executable, str(REPO / 'scripts' / 'soak.py'), '--quiet'] + [str(a) for a in args],
                       capture_output=True, text=True, timeout=600, env=dict(os.environ, OMP_NUM_THREADS='2'))
    return r.returncode, r.stdout + r.stderr


def test_tiny_soak_reloads_bit_for_bit_and_prints_a_memory_slope():
    rc, out = soak('--steps', 2000, '--save-every', 100, '--bodies', 125, '--warmup', 0)
    assert rc == 0, out
    assert 'soak: 125 spheres' in out
    assert '2000 steps, 19 reloads (every 100 steps)' in out
    contacts = int(re.search(r'spheres, (\d+) contacts', out).group(1))
    assert contacts > 300  # (every sphere touches its neighbours and the box: a dense scene)
    assert re.search(r'slope -?\d+\.\d+ KiB per 1e5 steps', out), out
    assert 'bit for bit: yes' in out


def test_tiny_soak_with_two_threads_reloads_bit_for_bit():
    """With two threads too (the loaded scene splits its pairs between the threads as the saved one
    did: InteractionLoop.threadSplit, doc/reliability.md); until 7 Dec they differed at rounding level."""
    rc, out = soak('--steps', 600, '--save-every', 150, '--bodies', 125, '--threads', 2, '--warmup', 0)
    assert rc == 0, out
    assert '125 spheres' in out and '2 threads' in out, out
    assert 'bit for bit: yes' in out


def test_bad_arguments_are_refused():
    rc, out = soak('--steps', 0)
    assert rc == 2 and '--steps and --save-every must be at least 1' in out
