#!/usr/bin/python3
"""Soak test: a dense scene run for many steps with periodic saves and reloads.

    YADE_BUILD_DIR=build /usr/bin/python3 scripts/soak.py [--steps 1e6] [--save-every 1e4]
        [--bodies 1000] [--threads 1] [--samples 200] [--warmup 0.2]

The scene is the dense lattice of the benchmarks (scripts/bench/dense.py: spheres on a simple
cubic lattice, each overlapping its six neighbours, held in a closed facet box; every contact
live), with --bodies spheres. It is run twice from the same start:

  * interrupted: every --save-every steps the scene is saved and loaded back, alternately in
    memory (O.saveTmp / O.loadTmp) and to a file (O.save / O.load, binary; every fourth time
    gzip-compressed XML), and the resident memory (VmRSS of /proc/self/status) is sampled;
  * uninterrupted: one O.run(steps, True).

Printed: the speed, the RSS samples' least-squares slope after the warm-up (the first --warmup
fraction of the steps) in KiB per 10^5 steps, the RSS range, and whether the final positions,
velocities, angular velocities, orientations, forces and torques of the two runs are equal byte
for byte (if not, the normwise deviation of each). Exit status 0 when they are equal.

They are, with one thread and with several (a loaded scene splits its pairs between the threads as
the saved one did: doc/reliability.md)."""
import argparse
import os
import sys
import tempfile
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.abspath(os.environ.get('YADE_BUILD_DIR') or os.path.join(REPO, 'build')))


def rssKiB():
    with open('/proc/self/status') as f:
        for line in f:
            if line.startswith('VmRSS:'):
                return int(line.split()[1])
    raise RuntimeError('no VmRSS in /proc/self/status')


def denseScene(nBodies):
    """The lattice of scripts/bench/dense.py with about nBodies spheres (returns the number)."""
    from yade import (O, geom, FrictMat, ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, Bo1_Facet_Aabb,
                      InteractionLoop, Ig2_Sphere_Sphere_ScGeom, Ig2_Facet_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys,
                      Law2_ScGeom_FrictPhys_CundallStrack, NewtonIntegrator)
    from yade.utils import sphere, PWaveTimeStep
    O.reset()
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600, label='mat'))
    r = 0.01
    a = 2 * r * 0.995
    n = max(2, int(round(nBodies ** (1. / 3.))))
    nz = max(2, nBodies // (n * n))

    def half(m):
        return ((m - 1) * a + 2 * r - 0.01 * r) / 2

    def c(m):
        return (m - 1) * a / 2
    O.bodies.append(geom.facetBox((c(n), c(n), c(nz)), (half(n), half(n), half(nz)), wallMask=63))
    O.bodies.append([sphere((i * a, j * a, k * a), r) for k in range(nz) for j in range(n) for i in range(n)])
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Facet_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Facet_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                        [Law2_ScGeom_FrictPhys_CundallStrack()]),
        NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.4),
    ]
    O.dt = .5 * PWaveTimeStep()
    return n * n * nz


def fingerprint():
    """The final state as bytes: pos, vel, angVel, ori, force, torque of every body, by id."""
    import numpy as np
    from yade import O
    a = O.bodies.arrays()
    data = b''.join(np.array(getattr(a, k), dtype=np.float64).tobytes() for k, _ in QUANTITIES)
    del a  # (a live view of pos makes the engine drop its cached positions)
    return data


QUANTITIES = (('pos', 3), ('vel', 3), ('angVel', 3), ('ori', 4), ('force', 3), ('torque', 3))


def deviations(a, b):
    """max|x - y| / max|x| of each quantity of two fingerprints (0: equal)."""
    import numpy as np
    x, y = np.frombuffer(a, dtype=np.float64), np.frombuffer(b, dtype=np.float64)
    n = len(x) // sum(w for _, w in QUANTITIES)
    out, start = {}, 0
    for name, width in QUANTITIES:
        u, v = x[start:start + width * n], y[start:start + width * n]
        start += width * n
        scale = float(np.max(np.abs(u))) if len(u) else 0.
        out[name] = float(np.max(np.abs(u - v))) / scale if scale > 0 else float(np.max(np.abs(u - v), initial=0))
    return out


def slope(samples):
    """Least-squares slope of (step, KiB) samples, in KiB per 10^5 steps."""
    n = len(samples)
    if n < 2:
        return float('nan')
    mx = sum(s for s, _ in samples) / n
    my = sum(v for _, v in samples) / n
    sxx = sum((s - mx) ** 2 for s, _ in samples)
    sxy = sum((s - mx) * (v - my) for s, v in samples)
    return sxy / sxx * 1e5 if sxx > 0 else float('nan')


def interrupted(nBodies, steps, saveEvery, directory, log):
    """The run with saves and reloads; returns (fingerprint, [(step, RSS KiB)], seconds, reloads)."""
    from yade import O
    denseScene(nBodies)
    samples, reloads, done = [(0, rssKiB())], 0, 0
    t0 = time.time()
    while done < steps:
        chunk = min(saveEvery, steps - done)
        O.run(chunk, True)
        done += chunk
        if done < steps:
            k = done // saveEvery
            if k % 2:
                O.saveTmp('soak')
                O.loadTmp('soak')
            else:
                path = os.path.join(directory, 'soak.xml.gz' if k % 4 == 0 else 'soak.yade')
                O.save(path)
                O.load(path)
            reloads += 1
            assert O.iter == done, (O.iter, done)
        samples.append((done, rssKiB()))
        if log and (len(samples) % max(1, (steps // saveEvery) // 20) == 0):
            print('  step %d  RSS %d KiB  %.0f steps/s' % (done, samples[-1][1], done / (time.time() - t0)), flush=True)
    return fingerprint(), samples, time.time() - t0, reloads


def uninterrupted(nBodies, steps):
    from yade import O
    denseScene(nBodies)
    t0 = time.time()
    O.run(steps, True)
    return fingerprint(), time.time() - t0


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--steps', type=float, default=1e6)
    p.add_argument('--save-every', type=float, default=1e4)
    p.add_argument('--bodies', type=int, default=1000)
    p.add_argument('--threads', type=int, default=1)
    p.add_argument('--warmup', type=float, default=0.2, help='fraction of the steps before the slope is fitted')
    p.add_argument('--quiet', action='store_true')
    args = p.parse_args(argv)
    steps, saveEvery = int(args.steps), int(args.save_every)
    if steps < 1 or saveEvery < 1:
        p.error('--steps and --save-every must be at least 1')
    import yade
    from yade import O
    yade.setNumThreads(args.threads)
    with tempfile.TemporaryDirectory(prefix='soak-') as directory:
        a, samples, tA, reloads = interrupted(args.bodies, steps, saveEvery, directory, not args.quiet)
    nSpheres = len(O.bodies) - 12  # (the box's 12 facets)
    contacts = O.interactions.countReal()
    b, tB = uninterrupted(args.bodies, steps)
    after = [(s, v) for s, v in samples if s >= args.warmup * steps]
    rss = [v for _, v in after]
    same = a == b
    print('soak: %d spheres, %d contacts, %d threads, %d steps, %d reloads (every %d steps)' % (nSpheres, contacts, args.threads, steps, reloads, saveEvery))
    print('speed: %.0f steps/s with reloads, %.0f steps/s uninterrupted' % (steps / tA, steps / tB))
    print('RSS after warm-up (%d samples from step %d): %d..%d KiB, slope %.2f KiB per 1e5 steps'
          % (len(after), after[0][0] if after else 0, min(rss or [0]), max(rss or [0]), slope(after)))
    print('reloaded run equals uninterrupted run bit for bit: %s (%d bytes compared)' % ('yes' if same else 'NO', len(a)))
    if not same:
        print('deviation max|x - y| / max|x|: ' + ', '.join('%s %.3g' % kv for kv in deviations(a, b).items()))
    return 0 if same else 1


if __name__ == '__main__':
    sys.exit(main())
