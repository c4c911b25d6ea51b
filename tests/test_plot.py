"""Tests of yade.plot: recording history (addData), saving it (saveDataTxt) and plotting it."""

import bz2
import gzip
import math
import os
import pathlib
import subprocess
import textwrap

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
LAUNCHER = REPO / "yade"
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(),
                                reason="yade is not built (run bash scripts/setup.sh)")

np = pytest.importorskip("numpy")


@pytest.fixture
def plot():
    from yade import plot
    plot.reset()
    yield plot
    plot.reset()
    try:
        import matplotlib.pyplot as plt
        plt.close("all")
    except ImportError:
        pass


def isnan(v):
    return isinstance(v, float) and math.isnan(v)


def run_script(tmp_path, name, body, env_extra=None):
    script = tmp_path / name
    script.write_text(textwrap.dedent(body))
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    env.pop("WAYLAND_DISPLAY", None)
    env.pop("YADE_BATCH", None)
    env.pop("MPLBACKEND", None)
    if env_extra:
        env.update(env_extra)
    r = subprocess.run(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", str(script)],
                       capture_output=True, text=True, timeout=180, env=env, cwd=str(tmp_path))
    return r


# ------------------------------------------------------------------ addData

def test_addData_rows_and_nan_fill(plot):
    plot.addData(a=1, b=2.5)
    plot.addData(a=3)
    assert plot.data["a"] == [1, 3]
    assert plot.data["b"][0] == 2.5 and isnan(plot.data["b"][1])


def test_addData_new_column_backfilled(plot):
    plot.addData(a=1)
    plot.addData(a=2)
    plot.addData(a=3, c=7)
    assert plot.data["a"] == [1, 2, 3]
    assert len(plot.data["c"]) == 3
    assert isnan(plot.data["c"][0]) and isnan(plot.data["c"][1]) and plot.data["c"][2] == 7


def test_addData_docstring_example(plot):
    plot.addData(a=1)
    plot.addData(b=2)
    plot.addData(a=3, b=4)
    assert repr(plot.data) == "{'a': [1, nan, 3], 'b': [nan, 2, 4]}"


def test_addData_dict_positional(plot):
    plot.addData({"a": 1, "b": 2})
    plot.addData({"a": 3}, b=4)
    assert plot.data == {"a": [1, 3], "b": [2, 4]}


def test_addData_keeps_values_unconverted(plot):
    plot.addData(i=2, f=0.1 + 0.2, n=np.float64(1.5), t=True)
    assert type(plot.data["i"][0]) is int
    assert plot.data["f"][0] == 0.1 + 0.2


def test_addData_vector_components(plot):
    from yade import Vector3, Matrix3
    plot.addData(v=Vector3(1, 2, 3), m=Matrix3(1, 2, 3, 4, 5, 6, 7, 8, 9))
    assert plot.data["v_x"] == [1.0] and plot.data["v_y"] == [2.0] and plot.data["v_z"] == [3.0]
    assert plot.data["m_xy"] == [2.0] and plot.data["m_zx"] == [7.0]
    assert "v" not in plot.data and "m" not in plot.data


def test_addData_rejects_strings_atomically(plot):
    plot.addData(a=1)
    with pytest.raises(ValueError):
        plot.addData(a=2, s="text")
    assert plot.data == {"a": [1]}


def test_reset_and_resetData(plot):
    plot.addData(a=1)
    plot.plots = {"a": ("a",)}
    plot.labels["a"] = "A"
    plot.resetData()
    assert plot.data == {} and plot.labels == {"a": "A"}
    assert plot.plots == {"a": ("a",)}
    plot.addData(a=1)
    plot.reset()
    assert plot.data == {} and plot.plots == {} and plot.labels == {}


# ------------------------------------------------------------------ saveDataTxt

def _fill(plot):
    plot.addData(a=1.5, b=2)
    plot.addData(a=0.1 + 0.2, c=3)
    plot.addData({"a": 4, "d": 1e-20})


EXPECTED = ("# a\t\tb\t\tc\t\td\n"
            "1.5\t2\tnan\tnan\n"
            "0.30000000000000004\tnan\t3\tnan\n"
            "4\tnan\tnan\t1e-20\n")


@pytest.mark.parametrize("suffix,opener", [("", open), (".bz2", bz2.open), (".gz", gzip.open)])
def test_saveDataTxt_format_and_compression(plot, tmp_path, suffix, opener):
    _fill(plot)
    fn = str(tmp_path / ("data.txt" + suffix))
    plot.saveDataTxt(fn)
    if suffix:
        with open(fn, "rb") as f:
            magic = f.read(3)
        assert magic == (b"BZh" if suffix == ".bz2" else b"\x1f\x8b\x08")
    with opener(fn, "rt") as f:
        text = f.read()
    assert text == EXPECTED  # same bytes as the reference Yade writes
    # round trip with numpy (which handles the compression itself)
    arr = np.genfromtxt(fn, names=True)
    assert arr.dtype.names == ("a", "b", "c", "d")
    assert arr["a"].tolist() == [1.5, 0.1 + 0.2, 4.0]
    assert arr["d"][2] == 1e-20 and np.isnan(arr["d"][0])
    raw = np.loadtxt(fn)
    assert raw.shape == (3, 4)
    assert raw[1, 0] == 0.1 + 0.2


def test_saveDataTxt_vars_subset_in_given_order(plot, tmp_path):
    _fill(plot)
    fn = tmp_path / "sub.txt"
    plot.saveDataTxt(str(fn), vars=("c", "a"))
    assert fn.read_text() == "# c\t\ta\nnan\t1.5\n3\t0.30000000000000004\nnan\t4\n"


def test_saveDataTxt_unknown_var(plot, tmp_path):
    _fill(plot)
    with pytest.raises(KeyError):
        plot.saveDataTxt(str(tmp_path / "x.txt"), vars=["a", "nope"])


def test_saveDataTxt_headers(plot, tmp_path):
    plot.addData(a=1)
    fn = tmp_path / "h.txt"
    plot.saveDataTxt(str(fn), headers={"foo": 1, "bar": "x"})
    assert fn.read_text() == "# foo=\t1\n# bar=\tx\n# a\n1\n"


def test_saveDataTxt_empty(plot, tmp_path):
    fn = tmp_path / "e.txt"
    plot.saveDataTxt(str(fn))
    assert fn.read_text() == "# \n"


# ------------------------------------------------------------------ plot (in process, noShow)

def _axes_summary(fig):
    return [(ax.get_xlabel(), ax.get_ylabel(), [l.get_label() for l in ax.get_lines()]) for ax in fig.axes]


def test_plot_noShow_single(plot):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure
    for i in range(5):
        plot.addData(t=i, a=i * i, b=-i)
    plot.plots = {"t": ("a", "b")}
    fig = plot.plot(noShow=True)
    assert isinstance(fig, Figure)
    assert _axes_summary(fig) == [("t", "a, b", ["a", "b"])]
    line = fig.axes[0].get_lines()[0]
    assert list(line.get_xdata()) == [0, 1, 2, 3, 4]
    assert list(line.get_ydata()) == [0, 1, 4, 9, 16]


def test_plot_None_gives_twin_axis(plot):
    pytest.importorskip("matplotlib")
    for i in range(3):
        plot.addData(t=i, a=i, b=10 * i)
    plot.plots = {"t": ("a", None, "b")}
    fig = plot.plot(noShow=True)
    assert len(fig.axes) == 2
    left, right = fig.axes
    assert [l.get_label() for l in left.get_lines()] == ["a"]
    assert [l.get_label() for l in right.get_lines()] == ["b"]
    assert right.get_ylabel() == "b"
    # the right axis shares x with the left one
    assert right.get_shared_x_axes().joined(left, right)


def test_plot_callable_and_fmt_and_labels(plot):
    pytest.importorskip("matplotlib")
    for i in range(3):
        plot.addData(t=i, e1=i, e2=2 * i, tot=3 * i)

    def energyNames():
        return ["e1", "e2"]

    plot.plots = {"t": (energyNames, None, ("tot", "r--"))}
    plot.labels = {"tot": "total energy", "t": "time"}
    fig = plot.plot(noShow=True)
    assert _axes_summary(fig) == [("time", "e1, e2", ["e1", "e2"]), ("", "total energy", ["total energy"])]
    tot = fig.axes[1].get_lines()[0]
    assert tot.get_linestyle() == "--" and tot.get_color() == "r"


def test_plot_callable_evaluated_at_plot_time(plot):
    pytest.importorskip("matplotlib")
    names = []
    plot.plots = {"t": lambda: list(names)}
    plot.addData(t=0, x=1, y=2)
    names.extend(["x", "y"])  # names known only later, as O.energy.keys()
    fig = plot.plot(noShow=True)
    assert [l.get_label() for l in fig.axes[0].get_lines()] == ["x", "y"]


def test_plot_subplots_and_separate_figures(plot):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure
    for i in range(3):
        plot.addData(t=i, a=i, b=i, c=i, x=i)
    plot.plots = {"t": ("a", None, "b"), "t ": ("c",), "x": ("a",)}  # 't ': same x, another subplot
    fig = plot.plot(noShow=True)
    assert isinstance(fig, Figure)
    assert len(fig.axes) == 4  # 3 subplots + 1 twin
    assert [ax.get_xlabel() for ax in fig.axes] == ["t", "", "t", "x"]
    figs = plot.plot(noShow=True, subPlots=False)
    assert isinstance(figs, list) and len(figs) == 3
    assert [len(f.axes) for f in figs] == [2, 1, 1]


def test_plot_missing_column_is_nan(plot, capsys):
    pytest.importorskip("matplotlib")
    plot.addData(t=1, a=2)
    plot.plots = {"t": ("a", "missing")}
    fig = plot.plot(noShow=True)
    lines = fig.axes[0].get_lines()
    assert np.isnan(lines[1].get_ydata()).all()
    assert "missing" in capsys.readouterr().out
    assert "missing" not in plot.data


def test_plot_without_data(plot):
    pytest.importorskip("matplotlib")
    plot.plots = {"t": ("a",)}
    fig = plot.plot(noShow=True)
    assert len(fig.axes) == 1


# ------------------------------------------------------------------ plot() headless, via the launcher

def test_plot_headless_writes_png_beside_script(tmp_path):
    pytest.importorskip("matplotlib")
    sub = tmp_path / "scripts"
    sub.mkdir()
    r = run_script(sub, "deposition.py", """
        from yade import plot
        plot.plots = {'t': ('a', None, 'b'), 't ': (lambda: ['c'],)}
        for i in range(10):
            plot.addData(t=i, a=i*i, b=-i, c=1)
        fig = plot.plot()
        print('RETURNED', type(fig).__name__)
        plot.plot(subPlots=False)
    """)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "Traceback" not in r.stderr
    png = sub / "deposition.plot.png"
    assert png.is_file() and png.stat().st_size > 1000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert str(png) in r.stdout  # says where
    assert "RETURNED Figure" in r.stdout
    assert (sub / "deposition.plot.2.png").is_file()  # second figure of subPlots=False
    assert not (tmp_path / "deposition.plot.png").exists()


def test_plot_module_import_does_not_load_matplotlib(tmp_path):
    r = run_script(tmp_path, "imp.py", """
        import sys
        from yade import plot
        plot.addData(a=1)
        print('MPL', 'matplotlib' in sys.modules)
    """)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "MPL False" in r.stdout
