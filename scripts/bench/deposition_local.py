# The local performance benchmark, run by `./yade --performance [-j T]`
# (or directly: /usr/bin/python3 scripts/bench/deposition_local.py [-j T]).
#
# 1. the plain deposition benchmark at 5000 spheres (600 timed steps after 2000 untimed),
#    3 runs, median iter/s, particle-steps/s, peak RSS;
# 2. the cost of each optional feature (trackEnergy, a PyRunner every 100 steps, an unused Wall
#    shape in the dispatchers), quicker (fewer untimed steps), each variant interleaved with a plain run.
#
# Every run is a fresh ./yade process (see run_bench.py, which also compares with the reference
# Yade: /usr/bin/python3 scripts/bench/run_bench.py). About a minute on a 2-core machine.
# Timings are noisy (±25% between identical runs): read the ratios, not the absolute figures.
import os
import sys

_here = os.path.dirname(os.path.abspath(globals().get('__file__') or sys.argv[0]))
if _here not in sys.path:
    sys.path.insert(0, _here)
import run_bench  # noqa: E402


def _threads():
    # ./yade -j T sets OMP_NUM_THREADS before running this script; a direct run may pass -j T
    argv = sys.argv[1:]
    for k, a in enumerate(argv):
        if a in ('-j', '--threads') and k + 1 < len(argv):
            return argv[k + 1]
        if a.startswith('-j') and a[2:].isdigit():
            return a[2:]
    t = os.environ.get('OMP_NUM_THREADS', '1')
    return t if t.isdigit() and int(t) > 0 else '1'


def _main():
    t = _threads()
    time_args = ['--memory'] if os.access(run_bench.TIME_BIN, os.X_OK) else []
    print("=== ./yade --performance: plain deposition benchmark (here only), %s thread(s) ===" % t)
    rc1 = run_bench.main(['--no-reference', '--sizes', '5000', '--steps', '600', '--settle', '2000',
                          '--repeats', '3', '--threads', t, '--quiet'] + time_args)
    print()
    print("=== feature costs (quicker: 5000 spheres, 600 timed steps after 1000 untimed, 5 repeats) ===")
    rc2 = run_bench.main(['--no-reference', '--sizes', '5000', '--steps', '600', '--settle', '1000',
                          '--repeats', '5', '--threads', t, '--features', '--quiet'])
    print()
    print("full comparison with the reference Yade: /usr/bin/python3 scripts/bench/run_bench.py --threads 1,2 --features")
    sys.stdout.flush()
    return max(rc1, rc2)


_rc = _main()
if _rc:
    sys.exit(_rc)
