"""Faults injected on purpose (doc/reliability.md lists them with their results):

  * saving: a process killed (SIGKILL) at random moments while it saves (30 times) leaves the previous file
    loadable and whole, and the next save removes the dead process's temporary; a full disk
    (EFBIG from RLIMIT_FSIZE; ENOSPC on a small tmpfs where mounting one is allowed), a missing
    directory and an unwritable one give an OSError naming the file and leave the old file intact;
  * a background run meets O.reset(), O.load(), O.loadTmp(), O.bodies.erase/append/clear,
    O.interactions.erase/clear from the main thread, and errors in a PyRunner or a C++ engine:
    no crash, the error names the engine with its label and the iteration, the simulation is
    paused and consistent (iter, time, bodies) and runs on afterwards.

Each test adds the faults it injects to FAULTS; the last test prints the total."""
import errno
import os
import random
import signal
import subprocess
import sys
import textwrap
import time

import pytest

from yade import (O, ForceResetter, FrictMat, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop,
                  Ig2_Sphere_Sphere_ScGeom, Ip2_FrictMat_FrictMat_FrictPhys, Law2_ScGeom_FrictPhys_CundallStrack,
                  NewtonIntegrator, PyRunner)
from yade.utils import PWaveTimeStep, sphere

pytestmark = pytest.mark.usefixtures("fresh_scene")  # tests/conftest.py

FAULTS = {}


def injected(kind, n=1):
    FAULTS[kind] = FAULTS.get(kind, 0) + n


def temporaries(directory):
    """Files O.save may have left behind (its temporaries are named '.NAME.PID.XXXX')."""
    return sorted(f for f in os.listdir(directory) if f.startswith('.'))


def python(code, *args, timeout=120, **kw):
    return subprocess.run([sys.executable, '-c', textwrap.dedent(code)] + [str(a) for a in args],
                          capture_output=True, text=True, timeout=timeout, **kw)


# ====================================================================== kill -9 while saving

WRITER = r'''
import sys
from yade import O, FrictMat
from yade.utils import sphere
path, n = sys.argv[1], int(sys.argv[2])
O.materials.append(FrictMat(young=1e7, density=2600))
O.bodies.append([sphere((i * .01, (i % 7) * .01, (i % 13) * .01), .004) for i in range(n)])
version = 0
while True:
    O.tags['version'] = str(version)
    O.bodies[n - 1].state.vel = (version, 0, 0)
    O.save(path)
    print(version, flush=True)  # saved: the file holds this version (or a later one)
    version += 1
'''


def killWhenATemporaryAppears(p, directory, before, timeout=20):
    t = time.time()
    while not set(temporaries(directory)) - before and time.time() - t < timeout:
        time.sleep(.0005)
    p.send_signal(signal.SIGKILL)


def test_kill_9_while_saving_leaves_the_previous_file(tmp_path):
    """30 writers each saving a ~2 MB scene in a loop, killed (SIGKILL) after a random delay or as
    soon as the temporary of a save appears (inside the writing): the file always loads and is
    one whole saved version (the last one reported, or the one being renamed)."""
    kills, midWrite, names = 30, 0, ['scene.yade', 'scene.xml.gz', 'scene.yade.bz2']
    rng = random.Random(16)
    n = 2000
    for k in range(kills):
        path = str(tmp_path / names[k % len(names)])
        before = set(temporaries(tmp_path))
        p = subprocess.Popen([sys.executable, '-c', WRITER, path, str(n)], stdout=subprocess.PIPE, text=True)
        first = p.stdout.readline()  # one save done: the file exists
        assert first.strip().isdigit(), first
        if k % 2:
            time.sleep(rng.uniform(0, .1))
            killWhenATemporaryAppears(p, tmp_path, before)
        else:
            time.sleep(rng.uniform(0, .8))
            p.send_signal(signal.SIGKILL)
        out, _ = p.communicate()
        assert p.returncode == -signal.SIGKILL
        lastDone = int(([first] + out.split())[-1])
        if set(temporaries(tmp_path)) - before:
            midWrite += 1  # killed with its temporary there: between mkstemp and rename
        O.load(path)
        version = int(O.tags['version'])
        assert version in (lastDone, lastDone + 1)
        assert len(O.bodies) == n and O.bodies[n - 1].state.vel[0] == version
    injected('SIGKILL while saving', kills)
    assert midWrite >= 5, midWrite  # some kills fell inside the writing
    # the next save of a file removes the temporaries that dead processes left beside it
    for name in names:
        O.save(str(tmp_path / name))
    assert temporaries(tmp_path) == []
    print('\nkill -9 while saving: %d kills, %d with a temporary being written' % (kills, midWrite))


def test_a_living_saver_temporary_is_not_removed(tmp_path):
    """Only the temporaries of processes that no longer exist are removed (another process may be
    saving the same file at this moment)."""
    O.bodies.append(sphere((0, 0, 0), .1))
    alive = tmp_path / ('.f.yade.%d.abcd' % os.getppid())
    alive.write_bytes(b'partial')
    dead = subprocess.Popen([sys.executable, '-c', 'pass'])
    dead.wait()
    orphan = tmp_path / ('.f.yade.%d.efgh' % dead.pid)
    orphan.write_bytes(b'partial')
    other = tmp_path / ('.g.yade.%d.ijkl' % dead.pid)  # another file's: not looked at
    other.write_bytes(b'partial')
    O.save(str(tmp_path / 'f.yade'))
    assert temporaries(tmp_path) == sorted([alive.name, other.name])


# ====================================================================== full disk, bad paths

FULL_DISK = r'''
import os, resource, sys
from yade import O
from yade.utils import sphere
path = sys.argv[1]
O.bodies.append([sphere((i, 0, 0), .4) for i in range(2000)])
old = open(path, 'rb').read()
resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))  # a file may not grow past 4 KiB: EFBIG
try:
    O.save(path)
except OSError as e:
    assert e.errno == 27 and e.filename == path, (e.errno, e.filename)
    assert open(path, 'rb').read() == old
    assert not [f for f in os.listdir(os.path.dirname(path)) if f.startswith('.')]
    print('ERROR', type(e).__name__, e)
'''


def test_file_too_large_gives_an_OSError_naming_the_file(tmp_path):
    path = tmp_path / 'f.yade'
    path.write_bytes(b'previous content')
    r = python(FULL_DISK, path)
    assert r.returncode == 0, r.stderr[-3000:]
    assert "ERROR OSError [Errno 27] File too large: '%s'" % path in r.stdout
    injected('file too large (RLIMIT_FSIZE)')


def test_full_tmpfs_gives_an_OSError_naming_the_file(tmp_path):
    mnt = tmp_path / 'small'
    mnt.mkdir()
    if os.geteuid() != 0 or subprocess.run(['mount', '-t', 'tmpfs', '-o', 'size=64k', 'tmpfs', str(mnt)],
                                           capture_output=True).returncode != 0:
        pytest.skip('mounting a small tmpfs needs root and a system that allows it')
    try:
        path = mnt / 'f.yade'
        O.bodies.append(sphere((0, 0, 0), .1))
        O.save(str(path))
        old = path.read_bytes()
        O.bodies.append([sphere((i, 0, 0), .4) for i in range(2000)])
        with pytest.raises(OSError) as e:
            O.save(str(path))
        assert e.value.errno == errno.ENOSPC and e.value.filename == str(path)
        assert path.read_bytes() == old and temporaries(mnt) == []
        injected('no space left on device (tmpfs)')
    finally:
        subprocess.run(['umount', str(mnt)])


def test_missing_directory_gives_an_OSError_naming_the_file(tmp_path):
    O.bodies.append(sphere((0, 0, 0), .1))
    path = str(tmp_path / 'nonexistent' / 'f.yade')
    with pytest.raises(FileNotFoundError) as e:
        O.save(path)
    assert e.value.filename == path and path in str(e.value)
    injected('missing directory')


UNWRITABLE = r'''
import os, sys
path = sys.argv[1]
from yade import O  # (imported first: the build may not be readable by nobody)
from yade.utils import sphere
if os.geteuid() == 0:
    os.setgid(65534); os.setuid(65534)  # root writes anywhere: save as nobody
O.bodies.append(sphere((0, 0, 0), .1))
try:
    O.save(path)
except PermissionError as e:
    assert e.filename == path, e.filename
    print('ERROR', type(e).__name__, e)
'''


def test_unwritable_directory_gives_a_PermissionError_naming_the_file():
    import shutil
    import tempfile
    top = tempfile.mkdtemp(prefix='yade-faults-')  # (pytest's tmp_path is private to root)
    try:
        os.chmod(top, 0o755)
        d = os.path.join(top, 'readonly')
        os.mkdir(d)
        path = os.path.join(d, 'f.yade')
        with open(path, 'wb') as f:
            f.write(b'previous content')
        os.chmod(d, 0o555)
        r = python(UNWRITABLE, path, cwd='/')
        if os.geteuid() == 0 and 'Operation not permitted' in r.stderr:
            pytest.skip('cannot drop root privileges here')
        assert r.returncode == 0, r.stderr[-3000:]
        assert "ERROR PermissionError [Errno 13] Permission denied: '%s'" % path in r.stdout
        with open(path, 'rb') as f:
            assert f.read() == b'previous content'
        assert temporaries(d) == []
        injected('unwritable directory')
    finally:
        os.chmod(os.path.join(top, 'readonly'), 0o755)
        shutil.rmtree(top)


# ====================================================================== faults during a background run

def dense_scene(n=6):
    """n^3 touching spheres with real contacts: every step does real work."""
    O.materials.append(FrictMat(young=1e7, poisson=.3, frictionAngle=.5, density=2600))
    r = .01
    O.bodies.append([sphere((i * 1.99 * r, j * 1.99 * r, k * 1.99 * r), r)
                     for i in range(n) for j in range(n) for k in range(n)])
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                 [Law2_ScGeom_FrictPhys_CundallStrack()]),
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=.4, label='newton')]
    O.dt = .5 * PWaveTimeStep()


def with_pyrunner():
    """A PyRunner every step: the loop needs the GIL, which the main thread holds while it calls O."""
    O.engines = O.engines + [PyRunner(command='pass', iterPeriod=1, label='idle')]


def start():
    O.run()
    t = time.time()
    while O.iter < 20 and time.time() - t < 30:
        time.sleep(.01)
    assert O.running and O.iter >= 20


def consistent(nBodies):
    """Paused, whole, and steps on: iter and time agree, the bodies and contacts are there."""
    assert not O.running
    it = O.iter
    assert O.time == pytest.approx(it * O.dt, rel=1e-9)
    assert len(O.bodies) == nBodies
    O.step()
    assert O.iter == it + 1
    O.run(5, True)
    assert O.iter == it + 6


@pytest.mark.parametrize('pyrunner', [False, True])
def test_reset_during_a_background_run(pyrunner):
    dense_scene()
    if pyrunner:
        with_pyrunner()
    start()
    O.reset()
    assert not O.running and O.iter == 0 and len(O.bodies) == 0
    injected('O.reset() during a run')


@pytest.mark.parametrize('how', ['file', 'memory'])
def test_load_during_a_background_run(tmp_path, how):
    dense_scene()
    with_pyrunner()
    O.run(10, True)
    path = str(tmp_path / 'f.yade')
    O.save(path) if how == 'file' else O.saveTmp('a')
    start()
    O.load(path) if how == 'file' else O.loadTmp('a')
    assert not O.running and O.iter == 10
    consistent(216)
    injected('O.load()/O.loadTmp() during a run')


@pytest.mark.parametrize('pyrunner', [False, True])
def test_erasing_bodies_during_a_background_run(pyrunner):
    """Each erase waits for the end of a step, erases and lets the run go on."""
    dense_scene()
    if pyrunner:
        with_pyrunner()
    O.stopAtIter = 10 ** 9
    start()
    for i in range(0, 216, 3):
        O.bodies.erase(i)
    assert O.running
    O.pause()
    assert sum(1 for b in O.bodies) == 216 - 72
    assert all(O.bodies[i] is None for i in range(0, 216, 3))
    assert all(i.id1 % 3 and i.id2 % 3 for i in O.interactions)
    consistent(216)
    injected('O.bodies.erase() during a run', 72)


def test_appending_and_clearing_bodies_and_interactions_during_a_background_run():
    dense_scene()
    with_pyrunner()
    O.stopAtIter = 10 ** 9
    start()
    ids = [O.bodies.append(sphere((1 + i * .1, 0, 0), .01)) for i in range(20)]
    assert ids == list(range(216, 236))
    O.interactions.erase(O.interactions.nth(0).id1, O.interactions.nth(0).id2)
    O.interactions.clear()
    assert O.running
    O.bodies.clear()
    O.bodies.append(sphere((0, 0, 0), .01))
    assert O.running
    O.pause()
    consistent(1)
    injected('O.bodies.append/clear, O.interactions.erase/clear during a run', 5)


def test_stop_at_iter_still_holds_after_an_erase_during_the_run():
    dense_scene()
    O.run(200)
    O.bodies.erase(5)
    O.wait()
    assert O.iter == 200
    injected('O.bodies.erase() during a run of n steps')


RAISER = '''
from yade import O
def failOnce():
    if O.iter == 37:
        raise ValueError('injected failure')
'''


def test_exception_in_a_pyrunner_during_a_background_run(capfd):
    import __main__
    exec(RAISER, __main__.__dict__)
    dense_scene()
    O.engines = O.engines + [PyRunner(command='failOnce()', iterPeriod=1, label='checker')]
    O.run()
    t = time.time()
    while O.running and time.time() - t < 30:
        time.sleep(.01)
    # reported at once on stderr with the engine and its label
    err = capfd.readouterr().err
    assert "Simulation stopped by an exception in PyRunner labeled 'checker' at iteration 37" in err
    # paused where it happened: the step that raised is not counted
    assert not O.running and O.iter == 37
    assert O._lastErrorSource == "in PyRunner labeled 'checker' at iteration 37"
    with pytest.raises(ValueError) as e:
        O.wait()
    assert 'PyRunner error.' in str(e.value) and 'injected failure' in str(e.value)
    assert "The simulation stopped on this error in PyRunner labeled 'checker' at iteration 37." in e.value.__notes__
    consistent(216)  # (the command passes again from iteration 38)
    injected('exception in a PyRunner (background run)')


def test_exception_in_a_pyrunner_during_a_blocking_run():
    import __main__
    exec(RAISER, __main__.__dict__)
    dense_scene()
    O.engines = O.engines + [PyRunner(command='failOnce()', iterPeriod=1)]
    with pytest.raises(ValueError) as e:
        O.run(100, True)
    assert "The simulation stopped on this error in PyRunner at iteration 37." in e.value.__notes__
    assert O.iter == 37
    consistent(216)
    injected('exception in a PyRunner (blocking run)')


def test_error_in_a_cpp_engine_during_a_background_run(capfd):
    """The integrator's stability guard (a time step far above the critical one) stops the run."""
    dense_scene()
    O.step()  # (the contacts are there: the lattice flies apart later)
    pos = [tuple(b.state.pos) for b in O.bodies]
    dt = O.dt
    O.dt = 50 * dt
    O.run()
    t = time.time()
    while O.running and time.time() - t < 30:
        time.sleep(.01)
    assert "Simulation stopped by an exception in NewtonIntegrator labeled 'newton' at iteration 1" in capfd.readouterr().err
    assert not O.running and O.iter == 1
    with pytest.raises(RuntimeError, match='critical') as e:
        O.wait()
    assert "The simulation stopped on this error in NewtonIntegrator labeled 'newton' at iteration 1." in e.value.__notes__
    assert [tuple(b.state.pos) for b in O.bodies] == pos  # the guard moved nothing
    O.dt = dt
    consistent(216)
    injected('error in a C++ engine (background run)')


def test_faults_injected():
    total = sum(FAULTS.values())
    print('\nfaults injected: %d' % total)
    for kind, n in sorted(FAULTS.items()):
        print('  %4d  %s' % (n, kind))
    if 'SIGKILL while saving' in FAULTS:  # (the whole file ran)
        assert total >= 100
