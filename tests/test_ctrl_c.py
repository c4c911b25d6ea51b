"""Ctrl-C (SIGINT) stops a blocking run at the end of the current step and raises KeyboardInterrupt.

(Beyond the reference: there a blocking O.run(n, True) or O.wait() ignores SIGINT.) Each test runs
`./yade -n -x script.py` in a subprocess, waits until the script says it started, sends SIGINT and
checks that the launcher exits within a few seconds with status 1, a KeyboardInterrupt traceback
on stderr, and that the simulation stopped between two steps (what a PyRunner counted agrees with
O.iter, and O.iter no longer moves).
"""

import os
import pathlib
import re
import signal
import subprocess
import textwrap
import time

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
LAUNCHER = REPO / "yade"
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(), reason="yade is not built (run bash scripts/setup.sh)")


def terminal_sigint():
    """In the child: SIGINT as a program started from a terminal has it (default). A shell starts its
    background jobs (`cmd &`, as a CI runner may start this suite) with SIGINT ignored, and Python,
    like any program, then keeps it ignored: no Ctrl-C reaches such a job."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)

# A PyRunner counts its calls; the first O.run(10, True) measures the offset between O.iter and
# the count (the runner does not run at iteration 0); the script prints START, then blocks.
PROLOGUE = """
    import sys, time
    calls = [0]
    def count():
        calls[0] += 1
    O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -10)), PyRunner(command='count()', iterPeriod=1)]
    O.bodies.append(sphere((0, 0, 0), 1))
    O.dt = 1e-4
    O.run(10, True)
    offset = O.iter - calls[0]
    def report():
        it = O.iter
        time.sleep(0.3)
        print('STOPPED iter=%d calls=%d offset=%d running=%s later=%d' % (it, calls[0], offset, O.running, O.iter), flush=True)
"""


def interrupt(tmp_path, body, delay=1.0):
    script = tmp_path / "long.py"
    script.write_text(textwrap.dedent(PROLOGUE) + textwrap.dedent(body))
    env = dict(os.environ, YADE_BUILD_DIR=str(BUILD))
    p = subprocess.Popen(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", str(script)], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env, cwd=str(tmp_path), preexec_fn=terminal_sigint)
    try:
        deadline = time.time() + 120
        line = ""
        while "START" not in line and time.time() < deadline:
            line = p.stdout.readline()
            if not line and p.poll() is not None:
                break
        assert "START" in line, p.stderr.read()
        time.sleep(delay)
        sent = time.time()
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
        return p.returncode, time.time() - sent, out, err
    finally:
        if p.poll() is None:
            p.kill()
            p.communicate()


def check_interrupted(rc, took, out, err):
    """The script exited with status 1 within 5 s, with KeyboardInterrupt, between two steps."""
    assert rc == 1, out + err
    assert took < 5
    assert "KeyboardInterrupt" in err
    check_stopped_between_steps(out)


def check_stopped_between_steps(out):
    m = re.search(r"STOPPED iter=(\d+) calls=(\d+) offset=(-?\d+) running=(\w+) later=(\d+)", out)
    assert m, out
    it, calls, offset, running, later = int(m[1]), int(m[2]), int(m[3]), m[4], int(m[5])
    assert it > 10  # it did run
    assert it - calls == offset  # the step in progress was completed (its PyRunner ran)
    assert running == "False" and later == it  # and nothing runs afterwards


def test_sigint_stops_blocking_run(tmp_path):
    rc, took, out, err = interrupt(tmp_path, """
        print('START', flush=True)
        try:
            O.run(10**9, True)
        except KeyboardInterrupt:
            report()
            raise
    """)
    check_interrupted(rc, took, out, err)


def test_sigint_stops_wait(tmp_path):
    rc, took, out, err = interrupt(tmp_path, """
        O.run()
        print('START', flush=True)
        try:
            O.wait()
        except KeyboardInterrupt:
            report()
            raise
    """)
    check_interrupted(rc, took, out, err)


def test_sigint_in_a_long_script_stops_the_background_run(tmp_path):
    # a Python loop while the simulation runs in the background: the launcher pauses the run
    rc, took, out, err = interrupt(tmp_path, """
        import atexit
        atexit.register(report)
        O.run()
        print('START', flush=True)
        while True:
            time.sleep(0.01)
    """)
    check_interrupted(rc, took, out, err)


def test_run_can_continue_after_interrupt(tmp_path):
    # the KeyboardInterrupt is caught by the script: the simulation is paused and may be resumed
    rc, took, out, err = interrupt(tmp_path, """
        print('START', flush=True)
        try:
            O.run(10**9, True)
        except KeyboardInterrupt:
            it = O.iter
            O.run(5, True)
            print('RESUMED', O.iter - it, O.iter - calls[0] == offset, flush=True)
    """)
    assert rc == 0, out + err
    assert "RESUMED 5 True" in out


def test_sigint_stops_a_saved_simulation_run_by_the_launcher(tmp_path):
    # ./yade -n -x sim.yade.gz runs the saved simulation until it stops: here, until Ctrl-C
    maker = tmp_path / "make.py"
    maker.write_text(textwrap.dedent("""
        O.engines = [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -10))]
        O.bodies.append(sphere((0, 0, 0), 1))
        O.dt = 1e-4
        O.save('sim.yade.gz')
    """))
    env = dict(os.environ, YADE_BUILD_DIR=str(BUILD))
    r = subprocess.run(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", str(maker)], capture_output=True, text=True,
                       env=env, cwd=str(tmp_path), timeout=120)
    assert r.returncode == 0, r.stderr
    p = subprocess.Popen(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", "sim.yade.gz"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, env=env, cwd=str(tmp_path), preexec_fn=terminal_sigint)
    try:
        assert "Running simulation sim.yade.gz" in p.stdout.readline()
        time.sleep(1.0)
        sent = time.time()
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
        assert time.time() - sent < 5
        assert p.returncode == 1 and "KeyboardInterrupt" in err
    finally:
        if p.poll() is None:
            p.kill()
            p.communicate()
