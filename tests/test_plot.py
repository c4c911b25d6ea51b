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

def test_plot_headless_writes_png_in_the_current_folder(tmp_path):
    pytest.importorskip("matplotlib")
    sub = tmp_path / "scripts"
    sub.mkdir()
    script = sub / "deposition.py"
    script.write_text(textwrap.dedent("""
        from yade import plot
        plot.plots = {'t': ('a', None, 'b'), 't ': (lambda: ['c'],)}
        for i in range(10):
            plot.addData(t=i, a=i*i, b=-i, c=1)
        fig = plot.plot()
        print('RETURNED', type(fig).__name__)
        plot.plot(subPlots=False)
    """))
    env = dict(os.environ)
    for k in ("DISPLAY", "WAYLAND_DISPLAY", "YADE_BATCH", "MPLBACKEND"):
        env.pop(k, None)
    r = subprocess.run(["/usr/bin/python3", str(LAUNCHER), "-n", "-x", "scripts/deposition.py"],
                       capture_output=True, text=True, timeout=180, env=env, cwd=str(tmp_path))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "Traceback" not in r.stderr
    png = tmp_path / "deposition.plot.png"  # the current folder, not the script's
    assert png.is_file() and png.stat().st_size > 1000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert str(png) in r.stdout  # says where
    assert "RETURNED Figure" in r.stdout
    assert (tmp_path / "deposition.plot.2.png").is_file()  # second figure of subPlots=False
    assert not (sub / "deposition.plot.png").exists()


def test_plot_twin_axes_lines_have_distinct_colors(plot):
    pytest.importorskip("matplotlib")
    from matplotlib.colors import to_rgba
    for i in range(3):
        plot.addData(t=i, a=i, b=2 * i, c=3 * i, d=4 * i)
    plot.plots = {"t": ("a", "b", None, "c", ("d", "k:"))}
    fig = plot.plot(noShow=True)
    left, right = fig.axes
    colors = [to_rgba(l.get_color()) for l in left.get_lines() + right.get_lines()]
    assert len(set(colors)) == 4  # (a twin axis restarts the color cycle unless told otherwise)
    assert colors[3] == to_rgba("k")  # a format's own color is kept


def test_plot_module_import_does_not_load_matplotlib(tmp_path):
    r = run_script(tmp_path, "imp.py", """
        import sys
        from yade import plot
        plot.addData(a=1)
        print('MPL', 'matplotlib' in sys.modules)
    """)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "MPL False" in r.stdout


# ------------------------------------------------------------------ addAutoData

def test_addAutoData_evaluates_plot_names(plot):
    from yade import O
    import yade
    O.reset()
    O.dt = 1e-3
    O.engines = [yade.ForceResetter(), yade.NewtonIntegrator(gravity=(0, 0, -10))]
    O.bodies.append(yade.utils.sphere((0, 0, 0), 1))
    plot.plots = {"O.iter": ("O.time", "O.bodies[0].state.pos", None, "nonexistent_name", "O.tags")}
    try:
        for i in range(3):
            O.step()
            plot.addAutoData()
    finally:
        O.reset()
    assert plot.data["O.iter"] == [1, 2, 3]
    assert plot.data["O.time"] == pytest.approx([0.001, 0.002, 0.003])
    # damped integrator: z = -8e-6, -24e-6, -48e-6 (reference: same positions for this sphere)
    assert plot.data["O.bodies[0].state.pos_z"] == pytest.approx([-8e-6, -2.4e-5, -4.8e-5], rel=1e-12)
    assert "nonexistent_name" not in plot.data and "O.tags" not in plot.data  # left out, with a warning


# ------------------------------------------------------------------ saveGnuplot, savePylab, savePlotSequence

def fill_example(plot):
    plot.plots = {"i": ("a", "b", None, "c"), "t": ("a", ("d", "r--"))}
    for k in range(4):
        plot.addData(i=k, t=k * 0.5, a=k * k, b=1.0 / (k + 1), c=-k, d=k + 0.25)
    plot.labels = {"a": "$A$"}


# The reference's saveGnuplot on the same data (yade-double -n -x on a script doing fill_example and
# plot.saveGnuplot('gp')), from its fourth line on (the third says when it was created).
REFERENCE_GNUPLOT = """\
#
set term wxt 0 persist
set xlabel 'i'
set grid
set datafile missing 'nan'
set ylabel '$A$,b'
set y2label 'c'
set y2tics
plot  "< bzcat gp.data.bz2" using 5:1 title '\u2190 $A$(i)' with lines, "< bzcat gp.data.bz2" using 5:2 title '\u2190 b(i)' with lines, "< bzcat gp.data.bz2" using 5:3 title 'c(i) \u2192' with lines axes x1y2
set term wxt 1 persist
set xlabel 't'
set grid
set datafile missing 'nan'
set ylabel '$A$,d'
plot  "< bzcat gp.data.bz2" using 6:1 title '\u2190 $A$(t)' with lines, "< bzcat gp.data.bz2" using 6:4 title '\u2190 d(t)' with lines
"""

# and its data file (the same as saveDataTxt's)
REFERENCE_GNUPLOT_DATA = """\
# a\t\tb\t\tc\t\td\t\ti\t\tt
0\t1.0\t0\t0.25\t0\t0.0
1\t0.5\t-1\t1.25\t1\t0.5
4\t0.3333333333333333\t-2\t2.25\t2\t1.0
9\t0.25\t-3\t3.25\t3\t1.5
"""


def test_saveGnuplot_as_the_reference(plot, tmp_path):
    fill_example(plot)
    ret = plot.saveGnuplot(str(tmp_path / "gp"))
    assert ret == str(tmp_path / "gp.gnuplot")
    lines = (tmp_path / "gp.gnuplot").read_text(encoding="utf-8").splitlines(keepends=True)
    assert lines[:2] == ["#!/usr/bin/env gnuplot\n", "#\n"] and lines[2].startswith("# created ")
    assert "".join(lines[3:]) == REFERENCE_GNUPLOT
    assert bz2.decompress((tmp_path / "gp.data.bz2").read_bytes()).decode() == REFERENCE_GNUPLOT_DATA


def test_saveGnuplot_options(plot, tmp_path):
    fill_example(plot)
    ret = plot.saveGnuplot(str(tmp_path / "g"), term="png", extension=".png", timestamp=True, comment="hello",
                           title="T", varData=True)
    assert ret.startswith(str(tmp_path / "g_")) and ret.endswith(".gnuplot")
    base = os.path.basename(ret)[:-len(".gnuplot")]
    text = pathlib.Path(ret).read_text(encoding="utf-8")
    assert "# hello\n" in text
    assert 'dataFile="< bzcat %s.data.bz2"\n' % base in text
    assert "set term png; set output '%s.0.png'\n" % base in text
    assert "set title 'T'\n" in text
    assert "plot  dataFile using 5:1" in text
    assert (tmp_path / (base + ".data.bz2")).is_file()


def test_saveGnuplot_script_runs_in_gnuplot(plot, tmp_path):
    import shutil
    if not shutil.which("gnuplot") or not shutil.which("bzcat"):
        pytest.skip("gnuplot is not installed")
    fill_example(plot)
    plot.saveGnuplot(str(tmp_path / "gp"), term="png", extension=".png")
    r = subprocess.run(["gnuplot", "gp.gnuplot"], cwd=str(tmp_path), capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    for i in (0, 1):
        png = tmp_path / ("gp.%d.png" % i)
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_savePylab_script_draws_the_data(plot, tmp_path):
    pytest.importorskip("matplotlib")
    fill_example(plot)
    ret = plot.savePylab(str(tmp_path / "pyl"), title="T")
    assert ret == str(tmp_path / "pyl.py")
    assert bz2.decompress((tmp_path / "pyl.data.bz2").read_bytes()).decode() == REFERENCE_GNUPLOT_DATA
    out = tmp_path / "run"
    out.mkdir()
    r = subprocess.run(["/usr/bin/python3", ret, "fig"], cwd=str(out), capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert (out / "fig.0.png").stat().st_size > 1000 and (out / "fig.1.png").stat().st_size > 1000


def test_savePlotSequence(plot, tmp_path):
    pytest.importorskip("matplotlib")
    plot.plots = {"i": ("a",), "t": ("b", None, "c")}
    for k in range(5):
        plot.addData(i=k, t=k * .1, a=k, b=2 * k, c=3 * k)
    base = str(tmp_path / "seq")
    frames = plot.savePlotSequence(base, stride=2, imgRatio=(4, 3), title="T", titleFrames=2, lastFrames=3)
    # frames of 2, 4 and 5 records (reference: files seq-000.png, seq-001.png, ...)
    assert frames == [base + "-title.png"] * 2 + [base + "-%03d.png" % i for i in range(3)] + [base + "-002.png"] * 3
    for f in set(frames):
        assert pathlib.Path(f).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    import struct
    header = pathlib.Path(base + "-000.png").read_bytes()[16:24]  # (the PNG's IHDR: width, height)
    assert struct.unpack(">II", header) == (400, 300)  # 4 x 3 inches at 100 dpi
    with pytest.raises(ValueError):
        plot.savePlotSequence(base, stride=0)
    plot.resetData()
    with pytest.raises(ValueError):
        plot.savePlotSequence(base)
