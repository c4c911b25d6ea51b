"""The launcher as cmake/Install.cmake and the Debian package install it (<prefix>/bin/yade-fast): a
copy with no source tree next to it takes the 'yade' package from <prefix>/lib/yade-fast, else from
sys.path (here PYTHONPATH names the build), and says that --test needs the source tree."""

import os
import pathlib
import shutil
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(),
                                reason="yade is not built (run bash scripts/setup.sh)")


def run_copy(tmp_path, *args, pythonpath=True, env_extra=None):
    bindir = tmp_path / "bin"
    bindir.mkdir(exist_ok=True)
    launcher = bindir / "yade-fast"
    shutil.copy(REPO / "yade", launcher)
    env = dict(os.environ)
    env.pop("YADE_BUILD_DIR", None)
    env.pop("OMP_NUM_THREADS", None)
    if pythonpath:
        env["PYTHONPATH"] = str(BUILD)
    else:
        env.pop("PYTHONPATH", None)
    env.update(env_extra or {})
    return subprocess.run(["/usr/bin/python3", str(launcher), *map(str, args)], capture_output=True,
                          text=True, timeout=120, env=env, cwd=str(tmp_path))


def test_installed_copy_runs_a_script_from_sys_path(tmp_path):
    script = tmp_path / "s.py"
    script.write_text("O.bodies.append(sphere((0, 0, 0), 1))\nO.run(3, True)\nprint('iter', O.iter, yade.__file__)\n")
    r = run_copy(tmp_path, "-n", "-x", script)
    assert r.returncode == 0, r.stderr
    assert "iter 3 " + str(BUILD / "yade") in r.stdout


def test_installed_copy_prefers_its_private_package(tmp_path):
    """<prefix>/lib/yade-fast/yade comes first, before a 'yade' on sys.path (Debian's python3-yade in
    /usr/lib/python3/dist-packages, here a stub on PYTHONPATH)."""
    (tmp_path / "lib" / "yade-fast").mkdir(parents=True)
    (tmp_path / "lib" / "yade-fast" / "yade").symlink_to(BUILD / "yade")
    stub = tmp_path / "other" / "yade"
    stub.mkdir(parents=True)
    (stub / "__init__.py").write_text("raise ImportError('the other yade was imported')\n")
    script = tmp_path / "s.py"
    script.write_text("print('from', yade.__file__)\n")
    r = run_copy(tmp_path, "-n", "-x", script, pythonpath=False, env_extra={"PYTHONPATH": str(stub.parent)})
    assert r.returncode == 0, r.stderr
    assert "from " + str(tmp_path / "lib" / "yade-fast" / "yade" / "__init__.py") in r.stdout


def test_installed_copy_names_itself_and_refuses_test(tmp_path):
    r = run_copy(tmp_path, "-h")
    assert r.returncode == 0 and r.stdout.startswith("usage: yade-fast "), r.stdout
    r = run_copy(tmp_path, "--test")
    assert r.returncode == 2 and "need the source tree" in r.stderr


def test_installed_copy_without_package(tmp_path):
    r = run_copy(tmp_path, "-n", "-x", pythonpath=False)
    if r.returncode == 0:
        pytest.skip("a yade package is installed for /usr/bin/python3")
    assert r.returncode == 2 and "not installed" in r.stderr, r.stderr


@pytest.mark.skipif(not (REPO / "yade-batch").is_file(), reason="no yade-batch")
def test_installed_batch_copy_uses_the_private_package(tmp_path):
    """yade-fast-batch beside yade-fast, the package in <prefix>/lib/yade-fast and another 'yade' first on
    sys.path (as Debian's python3-yade): the batch module and the jobs' engine come from the private one."""
    bindir = tmp_path / "bin"
    bindir.mkdir()
    shutil.copy(REPO / "yade", bindir / "yade-fast")
    shutil.copy(REPO / "yade-batch", bindir / "yade-fast-batch")
    (tmp_path / "lib" / "yade-fast").mkdir(parents=True)
    (tmp_path / "lib" / "yade-fast" / "yade").symlink_to(BUILD / "yade")
    stub = tmp_path / "other" / "yade"
    stub.mkdir(parents=True)
    (stub / "__init__.py").write_text("raise ImportError('the other yade was imported')\n")
    (tmp_path / "s.py").write_text("readParamsFromTable(a=0)\nfrom yade.params import table\nprint('A', table.a, yade.__file__)\n")
    (tmp_path / "t.table").write_text("a\n7\n")
    env = dict(os.environ)
    env.pop("YADE_BUILD_DIR", None)
    env.pop("OMP_NUM_THREADS", None)
    env["PYTHONPATH"] = str(stub.parent)
    r = subprocess.run(["/usr/bin/python3", str(bindir / "yade-fast-batch"), "--no-http", "-j", "1", "t.table", "s.py"],
                       capture_output=True, text=True, timeout=120, env=env, cwd=str(tmp_path))
    assert r.returncode == 0, r.stdout + r.stderr
    log = (tmp_path / "s.py.a=7.log").read_text()
    assert "A 7 " + str(tmp_path / "lib" / "yade-fast" / "yade" / "__init__.py") in log, log
