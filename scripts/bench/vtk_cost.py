#!/usr/bin/python3
"""What VTKRecorder costs a run (issue 38: under 5 % when recording every 1 000 steps).

Runs the dense-lattice benchmark (shared/bench/dense.py, unchanged but for one VTKRecorder appended to its
engines, recorders=['all'], iterPeriod=1000, into a temporary folder) against the same benchmark without it,
in turn, pinned to one core, and prints each pair's iter/s and the median ratio.

    python3 scripts/bench/vtk_cost.py [--spheres 50000] [--steps 3000] [--pairs 3] [--cpu 0]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DENSE = os.path.join(os.path.dirname(ROOT), 'shared', 'bench', 'dense.py')
if not os.path.exists(DENSE):
    DENSE = os.path.join(ROOT, 'scripts', 'bench', 'dense.py')
INTEGRATOR = 'NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4),'


def script(folder, vtk):
    src = open(DENSE).read()
    if vtk:
        assert INTEGRATOR in src, 'dense.py changed: the recorder goes after %s' % INTEGRATOR
        src = src.replace(INTEGRATOR, INTEGRATOR + "\n    VTKRecorder(fileName=%r, recorders=['all'], iterPeriod=1000)," % os.path.join(folder, 'd-'))
    path = os.path.join(folder, 'vtk.py' if vtk else 'plain.py')
    open(path, 'w').write(src)
    return path


def run(path, args):
    cmd = ['taskset', '-c', str(args.cpu), '/usr/bin/python3', os.path.join(ROOT, 'yade'), '-n', '-x', '-j1', path,
           str(args.spheres), str(args.steps)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return float(re.search(r'iter_per_s=([0-9.]+)', out).group(1))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--spheres', type=int, default=50000)
    p.add_argument('--steps', type=int, default=3000)
    p.add_argument('--pairs', type=int, default=3)
    p.add_argument('--cpu', type=int, default=0)
    args = p.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        plain, vtk = script(folder, False), script(folder, True)
        ratios = []
        for k in range(args.pairs):
            a = run(plain, args)
            b = run(vtk, args)
            written = sum(os.path.getsize(os.path.join(folder, f)) for f in os.listdir(folder) if f.startswith('d-'))
            ratios.append(b / a)
            print('pair %d: without %.2f iter/s, with VTKRecorder %.2f iter/s, ratio %.4f (%.1f MB written)'
                  % (k + 1, a, b, b / a, written / 1e6), flush=True)
            for f in os.listdir(folder):
                if f.startswith('d-'):
                    os.remove(os.path.join(folder, f))
    med = statistics.median(ratios)
    print('median ratio %.4f: recording every 1000 steps costs %.2f %% of the run (pairs %s)'
          % (med, 100 * (1 / med - 1), ', '.join('%.4f' % r for r in ratios)))


if __name__ == '__main__':
    sys.exit(main())
