"""Tests of yade.params: readParamsFromTable, yade.params.table, waitIfBatch and the O.tags they set."""

import os
import pathlib
import subprocess
import sys
import textwrap
import warnings

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
LAUNCHER = REPO / "yade"
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(),
                                reason="yade is not built (run bash scripts/setup.sh)")


@pytest.fixture
def params(monkeypatch):
    monkeypatch.delenv("YADE_BATCH", raising=False)
    from yade import params
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # 'Overwriting yade.params.table' between tests
        yield params


def table_module():
    from yade import params
    return params.table


def write_table(tmp_path, text, name="params.txt"):
    p = tmp_path / name
    p.write_text(textwrap.dedent(text).lstrip("\n"))
    return p


def run_script(tmp_path, body, env_extra=None):
    script = tmp_path / "script.py"
    script.write_text(textwrap.dedent(body))
    env = dict(os.environ)
    env.pop("YADE_BATCH", None)
    if env_extra:
        env.update(env_extra)
    return subprocess.run(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", str(script)],
                          capture_output=True, text=True, timeout=120, env=env, cwd=str(tmp_path))


# ------------------------------------------------------------------ defaults (not in a batch)

def test_defaults_path(params):
    from yade import O
    n = params.readParamsFromTable(damping=.2, name="x", nSpheres=100)
    assert n == 0  # nothing read from a table
    from yade.params import table
    assert table is table_module() and sys.modules["yade.params.table"] is table
    assert (table.damping, table.name, table.nSpheres) == (.2, "x", 100)
    assert table.__all__ == ["damping", "name", "nSpheres"]
    assert O.tags["line"] == "l!"
    assert O.tags["params"] == ""
    assert O.tags["defaultParams"] == "damping=0.2,name=x,nSpheres=100"


def test_second_call_replaces_table(params):
    params.readParamsFromTable(a=1)
    first = table_module()
    with pytest.warns(UserWarning, match="Overwriting"):
        params.readParamsFromTable(b=2)
    from yade.params import table
    assert table is not first and table.b == 2 and not hasattr(table, "a")


def test_noTableOk_false_outside_batch(params):
    with pytest.raises(EnvironmentError):
        params.readParamsFromTable(noTableOk=False, a=1)


def test_waitIfBatch_returns_outside_batch(params):
    assert params.waitIfBatch() is None
    assert not params.inBatch()


def test_ids_unique_per_run(tmp_path):
    body = """
        from yade import O
        print('ID', O.tags['id'], O.tags['d.id'])
    """
    ids = set()
    for _ in range(2):
        r = run_script(tmp_path, body)
        assert r.returncode == 0, r.stdout + r.stderr
        line = [l for l in r.stdout.splitlines() if l.startswith("ID ")][0]
        oid, did = line.split()[1:]
        assert oid == did  # no description outside a batch
        ids.add(oid)
    assert len(ids) == 2


def test_defaults_in_launched_script(tmp_path):
    r = run_script(tmp_path, """
        from yade.params import readParamsFromTable, waitIfBatch
        print('RET', readParamsFromTable(damping=.2, nSteps=10))
        from yade.params import table
        print('TABLE', table.damping, table.nSteps)
        print('WAIT', waitIfBatch())  # not in a batch: returns at once
        try:
            damping
            print('GLOBAL yes')
        except NameError:
            print('GLOBAL no')
    """)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "RET 0" in r.stdout and "TABLE 0.2 10" in r.stdout
    assert "WAIT None" in r.stdout
    # as in Yade 2023: the parameters live in yade.params.table only, they are not globals
    assert "GLOBAL no" in r.stdout


def test_utils_exports(tmp_path):
    import yade.utils
    if not hasattr(yade.utils, "readParamsFromTable"):
        pytest.skip("yade.utils does not import readParamsFromTable/waitIfBatch from yade.params yet")
    from yade import params
    assert yade.utils.readParamsFromTable is params.readParamsFromTable
    assert yade.utils.waitIfBatch is params.waitIfBatch
    r = run_script(tmp_path, """
        readParamsFromTable(x=3)
        from yade.params import table
        waitIfBatch()
        print('X', table.x)
    """)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "X 3" in r.stdout


# ------------------------------------------------------------------ reading a table

TABLE = """
    # a parameter table
    description  damping   name    n
    first        .4        'hello' 2**3   # comments are ignored
    second       2*.3      =       1

      # blank lines and comments between lines are fine
    third        =         'bye'   =
"""


def test_table_line_overrides_defaults(params, tmp_path, monkeypatch):
    from yade import O
    tbl = write_table(tmp_path, TABLE)
    monkeypatch.setenv("YADE_BATCH", "%s:3" % tbl)
    assert params.inBatch()
    n = params.readParamsFromTable(damping=.2, name="x", n=0, other=5)
    assert n == 3  # damping, name, n (description is not a parameter)
    from yade.params import table
    assert (table.damping, table.name, table.n, table.other) == (.4, "hello", 8, 5)
    assert not hasattr(table, "description")
    assert table.__all__ == ["damping", "name", "n", "other"]
    assert O.tags["description"] == "first"
    assert O.tags["d.id"] == "first." + O.tags["id"]
    assert O.tags["id.d"] == O.tags["id"] + ".first"
    assert O.tags["line"] == "l3"
    assert O.tags["params"] == "damping=.4,name='hello',n=2**3"
    assert O.tags["defaultParams"] == "other=5"


def test_table_equal_sign_repeats_value_above(params, tmp_path, monkeypatch):
    from yade import O
    tbl = write_table(tmp_path, TABLE)
    monkeypatch.setenv("YADE_BATCH", "%s:4" % tbl)
    params.readParamsFromTable(damping=.2, name="x", n=0)
    t = table_module()
    assert (t.damping, t.name, t.n) == (2 * .3, "hello", 1)
    monkeypatch.setenv("YADE_BATCH", "%s:7" % tbl)
    params.readParamsFromTable(damping=.2, name="x", n=0)
    t = table_module()
    assert (t.damping, t.name, t.n) == (2 * .3, "bye", 1)
    assert O.tags["description"] == "third"
    assert O.tags["params"] == "damping=2*.3,name='bye',n=1"


def test_tableFileLine_argument_and_math_names(params, tmp_path):
    tbl = write_table(tmp_path, """
        a   b        c
        pi  sqrt(2)  [1,2]
    """)
    n = params.readParamsFromTable("%s:2" % tbl, a=0, b=0, c=None, d="dflt")
    t = table_module()
    assert n == 3
    assert t.a == pytest.approx(3.141592653589793) and t.b == pytest.approx(2 ** .5)
    assert t.c == [1, 2] and t.d == "dflt"


def test_description_synthesized(params, tmp_path):
    from yade import O
    tbl = write_table(tmp_path, """
        damping name
        .7 'zz'
    """)
    params.readParamsFromTable("%s:2" % tbl, damping=.2, name="x")
    assert O.tags["description"] == "damping=.7,name=zz"
    assert O.tags["d.id"] == "damping=.7,name=zz." + O.tags["id"]


def test_unknown_column(params, tmp_path):
    tbl = write_table(tmp_path, """
        damping bogus
        .4 3
    """)
    with pytest.raises(NameError, match="bogus"):
        params.readParamsFromTable("%s:2" % tbl, damping=.2)
    assert params.readParamsFromTable("%s:2" % tbl, unknownOk=True, damping=.2) == 2
    assert table_module().bogus == 3


@pytest.mark.parametrize("line", [1, 3, 99])
def test_invalid_line(params, tmp_path, line):
    tbl = write_table(tmp_path, """
        a b
        1 2

    """)
    with pytest.raises(RuntimeError, match="valid line number"):
        params.readParamsFromTable("%s:%d" % (tbl, line), a=0, b=0)


def test_wrong_number_of_values(params, tmp_path):
    tbl = write_table(tmp_path, """
        a b description
        1
    """)
    with pytest.raises(ValueError):
        params.readParamsFromTable("%s:2" % tbl, a=0, b=0)


def test_bad_tableFileLine(params):
    with pytest.raises(ValueError):
        params.readParamsFromTable("no-line-number", a=0)


def test_batch_run_of_launched_script(tmp_path):
    tbl = write_table(tmp_path, TABLE)
    r = run_script(tmp_path, """
        from yade.params import readParamsFromTable, waitIfBatch
        from yade import plot
        print('RET', readParamsFromTable(damping=.2, name='x', n=0))
        from yade.params import table
        O.run(5)
        waitIfBatch()  # blocks until the 5 steps are done
        print('ITER', O.iter)
        print('VALUES', table.damping, table.name, table.n)
        plot.addData(i=O.iter, d=table.damping)
        plot.saveDataTxt(O.tags['d.id'] + '.txt')
        print('DID', O.tags['d.id'])
    """, env_extra={"YADE_BATCH": "%s:4" % tbl.name})
    assert r.returncode == 0, r.stdout + r.stderr
    assert "RET 3" in r.stdout
    assert "ITER 5" in r.stdout
    assert "VALUES 0.6 hello 1" in r.stdout
    did = [l.split()[1] for l in r.stdout.splitlines() if l.startswith("DID ")][0]
    assert did.startswith("second.")
    assert (tmp_path / (did + ".txt")).read_text() == "# d\t\ti\n0.6\t5\n"
