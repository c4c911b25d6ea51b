"""Runs fuzz cases in child processes, so that a crash (a signal) or a hang is seen and named.

The parent splits the cases into chunks and starts one worker process per chunk (the same script
with --worker). Before each case the worker writes the case's number into a progress file; if the
worker dies, the parent reads that number, records the case as a crash (with the signal), and goes
on with a new worker from the next case. The worker prints one JSON line at the end: its counts
per outcome and its failures. Outcomes whose name starts with 'FAIL' are failures.

No import of yade here: the parent only starts and watches processes.
"""
import argparse
import collections
import json
import os
import signal
import subprocess
import sys
import tempfile
import time


def parseArgs(description, defaultCases):
    p = argparse.ArgumentParser(description=description)
    p.add_argument('--cases', type=int, default=defaultCases, help='number of cases (default %(default)s)')
    p.add_argument('--seed', type=int, default=7, help='seed of the run: case k of seed S is always the same')
    p.add_argument('--first', type=int, default=0, help='number of the first case')
    p.add_argument('--chunk', type=int, default=1000, help='cases per worker process')
    p.add_argument('--timeout', type=float, default=60, help='seconds a case may take before it counts as a hang')
    p.add_argument('--replay', type=int, default=None, metavar='K', help='run case K alone, in this process, verbosely')
    p.add_argument('--verbose', action='store_true', help='print every case')
    p.add_argument('--json', default=None, metavar='FILE', help='also write the summary to FILE as JSON')
    p.add_argument('--worker', action='store_true', help=argparse.SUPPRESS)
    p.add_argument('--progress', default=None, help=argparse.SUPPRESS)
    return p.parse_args()


class Progress:
    """The number of the case a worker is running, in a file the parent reads after a crash."""

    def __init__(self, path):
        self.fd = os.open(path, os.O_WRONLY | os.O_CREAT) if path else None

    def mark(self, k):
        if self.fd is not None:
            os.pwrite(self.fd, b'%-20d\n' % k, 0)


def runCases(runOne, first, count, progress, verbose, timeout):
    """Worker loop: runOne(k) -> (outcome, description, detail) for k in [first, first+count). A case
    that takes more than timeout seconds ends the worker (faulthandler prints the stacks, exit status 1)."""
    import faulthandler
    counts = collections.Counter()
    failures = []
    for k in range(first, first + count):
        progress.mark(k)
        faulthandler.dump_traceback_later(timeout, exit=True)
        outcome, description, detail = runOne(k)
        counts[outcome] += 1
        if verbose:
            print('case %d: %s | %s | %s' % (k, outcome, description, detail), flush=True)
        if outcome.startswith('FAIL'):
            failures.append({'case': k, 'outcome': outcome, 'description': description, 'detail': detail})
    faulthandler.cancel_dump_traceback_later()
    progress.mark(first + count)
    return {'counts': dict(counts), 'failures': failures}


def _describe(script, seed, k):
    """The description of case k, got from a fresh process (the crashed one cannot tell)."""
    try:
        r = subprocess.run([sys.executable, script, '--seed', str(seed), '--replay', str(k), '--describe'],
                           capture_output=True, text=True, timeout=60)
        return r.stdout.strip().splitlines()[-1] if r.stdout.strip() else ''
    except (subprocess.SubprocessError, OSError):
        return ''


def parent(script, args, name):
    """Runs args.cases cases in chunks of worker processes; prints the counts; returns the summary."""
    counts = collections.Counter()
    failures = []
    start = time.time()
    k, end = args.first, args.first + args.cases
    with tempfile.TemporaryDirectory(prefix='fuzz-') as tmp:
        progressFile = os.path.join(tmp, 'progress')
        while k < end:
            n = min(args.chunk, end - k)
            cmd = [sys.executable, script, '--worker', '--seed', str(args.seed), '--first', str(k), '--cases', str(n),
                   '--timeout', str(args.timeout), '--progress', progressFile] + (['--verbose'] if args.verbose else [])
            if os.path.exists(progressFile):
                os.unlink(progressFile)
            try:
                r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                   timeout=args.timeout * n + 120)  # (the worker's own watchdog comes first)
                rc, out, err = r.returncode, r.stdout, r.stderr
            except subprocess.TimeoutExpired as e:
                rc, out, err = None, e.stdout or '', e.stderr or ''
                out = out.decode() if isinstance(out, bytes) else out
                err = err.decode() if isinstance(err, bytes) else err
            if args.verbose:
                sys.stdout.write(''.join(l + '\n' for l in out.splitlines() if not l.startswith('{')))
            if rc == 0 and out.strip():
                result = json.loads(out.strip().splitlines()[-1])
                counts.update(result['counts'])
                failures += result['failures']
                k += n
                continue
            # the worker crashed, hung or failed to start: the case it was running is a failure
            try:
                with open(progressFile) as f:
                    bad = int(f.read().split()[0])
            except (OSError, ValueError, IndexError):
                bad = k
            if bad >= k + n:  # (died after its last case: e.g. at exit)
                bad = k + n - 1
            if rc is None or (rc == 1 and 'Timeout (' in err):
                outcome = 'FAIL hang (over %g s)' % args.timeout
            elif rc < 0:
                outcome = 'FAIL crash (%s)' % signal.Signals(-rc).name
            else:
                outcome = 'FAIL worker exit status %d' % rc
            counts[outcome] += 1
            # cases of the chunk before the bad one ran fine, but their counts died with the worker:
            # run them again (they are deterministic) by restarting at k only if bad == k
            if bad > k:
                counts.update(_rerun(script, args, k, bad - k, tmp))
            failures.append({'case': bad, 'outcome': outcome, 'description': _describe(script, args.seed, bad),
                             'detail': ' / '.join(err.strip().splitlines()[-6:])})
            k = bad + 1
    elapsed = time.time() - start
    summary = {'harness': name, 'seed': args.seed, 'first': args.first, 'cases': args.cases,
               'seconds': round(elapsed, 1), 'counts': dict(sorted(counts.items())), 'failures': failures}
    report(summary)
    return summary


def _rerun(script, args, first, n, tmp):
    cmd = [sys.executable, script, '--worker', '--seed', str(args.seed), '--first', str(first), '--cases', str(n),
           '--timeout', str(args.timeout), '--progress', os.path.join(tmp, 'progress2')]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=args.timeout * n + 120)
    if r.returncode == 0 and r.stdout.strip():
        return json.loads(r.stdout.strip().splitlines()[-1])['counts']
    return {'FAIL rerun of cases %d..%d' % (first, first + n - 1): 1}


def report(summary):
    counts = summary['counts']
    total = sum(counts.values())
    print('%s: %d cases (seed %d, cases %d..%d) in %.1f s' % (summary['harness'], total, summary['seed'],
          summary['first'], summary['first'] + summary['cases'] - 1, summary['seconds']))
    for outcome, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])):
        print('  %7d  %s' % (n, outcome))
    for f in summary['failures']:
        print('  FAILED case %d (replay: --seed %d --replay %d): %s | %s | %s' % (
            f['case'], summary['seed'], f['case'], f['outcome'], f['description'], f['detail']))
    print('  failures: %d' % len(summary['failures']), flush=True)


def main(script, name, defaultCases, runOneFactory):
    """Entry point of a harness. runOneFactory(seed, describeOnly=False) -> runOne, and runOne(k) ->
    (outcome, description, detail); the factory is only called in a worker or for --replay, so
    yade is only imported there."""
    if '--describe' in sys.argv:  # (used by the parent after a crash: print the case's description)
        sys.argv.remove('--describe')
        args = parseArgs(name, defaultCases)
        print(runOneFactory(args.seed, describeOnly=True)(args.replay)[1])
        return 0
    args = parseArgs(name, defaultCases)
    import faulthandler
    faulthandler.enable()  # a crash prints the Python stack (to the worker's stderr)
    if args.replay is not None:
        faulthandler.dump_traceback_later(args.timeout, exit=True)  # a hang too
        outcome, description, detail = runOneFactory(args.seed)(args.replay)
        print('case %d: %s\n  %s\n  %s' % (args.replay, outcome, description, detail))
        return 1 if outcome.startswith('FAIL') else 0
    if args.worker:
        runOne = runOneFactory(args.seed)
        result = runCases(runOne, args.first, args.cases, Progress(args.progress), args.verbose, args.timeout)
        sys.stdout.flush()
        print(json.dumps(result), flush=True)
        return 0
    summary = parent(script, args, name)
    if args.json:
        with open(args.json, 'w') as f:
            json.dump(summary, f, indent=1)
    return 1 if summary['failures'] else 0
