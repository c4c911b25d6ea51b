#!/usr/bin/python3
"""Run the installed reference Yade's own regression tests (yade/tests/*.py of its Python package)
against this build and print, per test module, how many tests ran, passed, failed and errored.

    YADE_BUILD_DIR=build /usr/bin/python3 scripts/reference_tests.py [module ...]

The reference's test folder is found at run time (nothing of it is copied here); without an
installed reference the script says so and exits 0. Each module runs in its own Python process with
this build first on PYTHONPATH, from a scratch directory; the modules' own imports of their helper
modules (testMathHelper) are found in the reference's folder. Exit status: 0 always (a report)."""
import glob
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_MODULES = ['dummyTest', 'wrapper', 'core', 'pbc', 'clump', 'cohesive-chain', 'engines', 'utilsModule', 'libVersions',
                   'testMinieigenHP', 'testMath', 'enumTest', 'ymport-foamfiles']

# Run inside the child: load one test file by path, run its tests, print the counts as JSON.
CHILD = r'''
import importlib.util, io, json, sys, unittest
path, name, out = sys.argv[1], sys.argv[2], sys.argv[3]
counts = {"run": 0, "failures": 0, "errors": 0, "skipped": 0, "note": ""}
try:
    spec = importlib.util.spec_from_file_location(name.replace("-", "_"), path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    suite = unittest.defaultTestLoader.loadTestsFromModule(mod)
    stream = io.StringIO()
    r = unittest.TextTestRunner(stream=stream, verbosity=2).run(suite)
    counts.update(run=r.testsRun, failures=len(r.failures), errors=len(r.errors), skipped=len(r.skipped))
    sys.stderr.write(stream.getvalue())
except BaseException as e:
    counts.update(errors=1, note="import failed: %s: %s" % (type(e).__name__, str(e).splitlines()[0] if str(e) else ""))
open(out, "w").write(json.dumps(counts))  # (a file: a test module may take over stdout)
'''


def referenceTestDir():
    """The tests folder of the installed reference's Python package, or None."""
    for pattern in ('/usr/lib/x86_64-linux-gnu/yade*/py/yade/tests', '/usr/lib/*/yade*/py/yade/tests', '/usr/lib/yade*/py/yade/tests',
                    '/usr/local/lib/yade*/py/yade/tests'):
        for d in sorted(glob.glob(pattern)):
            if os.path.isfile(os.path.join(d, 'dummyTest.py')):
                return d
    return None


def runModule(testDir, name, buildDir, timeout=600):
    path = os.path.join(testDir, name + '.py')
    if not os.path.isfile(path):
        return {'run': 0, 'failures': 0, 'errors': 0, 'skipped': 0, 'note': 'not in the reference'}, ''
    env = dict(os.environ)
    env['PYTHONPATH'] = os.pathsep.join([buildDir, testDir] + ([env['PYTHONPATH']] if env.get('PYTHONPATH') else []))
    env['YADE_BUILD_DIR'] = buildDir
    env.setdefault('OMP_NUM_THREADS', '1')
    with tempfile.TemporaryDirectory() as scratch:
        try:
            out = os.path.join(scratch, 'counts.json')
            p = subprocess.run([sys.executable, '-c', CHILD, path, name, out], cwd=scratch, env=env, capture_output=True, text=True,
                               timeout=timeout)
        except subprocess.TimeoutExpired:
            return {'run': 0, 'failures': 0, 'errors': 1, 'skipped': 0, 'note': 'timed out after %d s' % timeout}, ''
        if os.path.isfile(out):
            with open(out) as f:
                return json.load(f), p.stderr
    tail = (p.stderr.strip().splitlines() or ['(no output)'])[-1]
    return {'run': 0, 'failures': 0, 'errors': 1, 'skipped': 0, 'note': 'crashed (exit %d): %s' % (p.returncode, tail[:100])}, p.stderr


def main(argv):
    verbose = '-v' in argv
    modules = [a for a in argv if not a.startswith('-')] or DEFAULT_MODULES
    buildDir = os.path.abspath(os.environ.get('YADE_BUILD_DIR', os.path.join(ROOT, 'build')))
    testDir = referenceTestDir()
    if testDir is None:
        print('reference_tests: no installed reference Yade found (its yade/tests folder); nothing to run')
        return 0
    print('reference tests from %s, run against %s\n' % (testDir, buildDir))
    print('%-18s %5s %6s %6s %6s  %s' % ('module', 'run', 'passed', 'failed', 'errors', 'note'))
    total = dict(run=0, passed=0, failures=0, errors=0)
    for name in modules:
        c, log = runModule(testDir, name, buildDir)
        passed = max(0, c['run'] - c['failures'] - c['errors'] - c['skipped'])
        print('%-18s %5d %6d %6d %6d  %s' % (name, c['run'], passed, c['failures'], c['errors'], c['note']))
        if verbose and log:
            print('\n'.join('    ' + l for l in log.splitlines() if ' ... ' in l or l.startswith(('FAIL:', 'ERROR:'))))
        total['run'] += c['run']
        total['passed'] += passed
        total['failures'] += c['failures']
        total['errors'] += c['errors']
    print('%-18s %5d %6d %6d %6d' % ('total', total['run'], total['passed'], total['failures'], total['errors']))
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
