"""The accuracy suite (./yade --accuracy DIR, scripts/accuracy/accuracy.py).

The full suite takes a few seconds, so it is run once, through the launcher, into a temporary
directory; the tests check the three files it writes and the convergence orders they report.
"""
import csv
import importlib.util
import math
import os
import pathlib
import re
import struct
import subprocess
import time
import zlib

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
LAUNCHER = REPO / "yade"
SUITE = REPO / "scripts" / "accuracy" / "accuracy.py"
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(),
                                reason="yade is not built (run bash scripts/setup.sh)")

COLUMNS = ["case", "integrator", "dt", "dt_over_critical", "steps", "wall_s", "error", "error_kind"]
CASES = ["free_fall", "elastic_impact", "settling", "sliding"]
REQUIRED_FACTORS = {0.05, 0.1, 0.2, 0.4, 0.8}


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    out = tmp_path_factory.mktemp("accuracy")
    env = dict(os.environ)
    env.pop("OMP_NUM_THREADS", None)
    t0 = time.time()
    r = subprocess.run(["/usr/bin/python3", str(LAUNCHER), "--accuracy", str(out)], capture_output=True,
                       text=True, timeout=600, env=env, cwd=str(REPO))
    elapsed = time.time() - t0
    return out, r, elapsed


@pytest.fixture(scope="module")
def rows(suite):
    out, r, _ = suite
    assert r.returncode == 0, r.stdout + r.stderr
    with open(out / "accuracy.csv", newline="") as fh:
        return list(csv.DictReader(fh))


def series(rows, case, kind):
    rs = sorted((r for r in rows if r["case"] == case and r["error_kind"] == kind), key=lambda r: float(r["dt"]))
    return [float(r["dt"]) for r in rs], [float(r["error"]) for r in rs]


def slope(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def test_runs_successfully_and_fast(suite):
    out, r, elapsed = suite
    assert r.returncode == 0, r.stdout + r.stderr
    for name in ("accuracy.csv", "accuracy.md", "accuracy.png"):
        assert (out / name).is_file() and (out / name).stat().st_size > 0, name
    assert "total" in r.stdout
    assert elapsed < 180, "the suite must finish in under 3 minutes (took %.1f s)" % elapsed


def test_csv_columns_and_rows(rows):
    assert rows
    for c in COLUMNS:
        assert c in rows[0], c
    for case in CASES:
        mine = [r for r in rows if r["case"] == case]
        assert len(mine) >= 5, case
        for kind in {r["error_kind"] for r in mine}:
            rs = [r for r in mine if r["error_kind"] == kind]
            factors = {float(r["dt_over_critical"]) for r in rs}
            assert len(rs) >= 5 and len(factors) >= 5, (case, kind)
            assert REQUIRED_FACTORS <= factors, (case, kind, factors)
    for r in rows:
        assert r["integrator"] == "leapfrog"
        err, dt, wall = float(r["error"]), float(r["dt"]), float(r["wall_s"])
        assert math.isfinite(err) and err >= 0, r
        if r["case"] != "settling":      # settling is exact up to round-off (may be 0)
            assert err > 0, r
        assert dt > 0 and wall >= 0 and int(r["steps"]) > 0, r
        # dt is the stated fraction of PWaveTimeStep (the same sphere in every case)
        assert dt / float(r["dt_over_critical"]) == pytest.approx(
            float(rows[0]["dt"]) / float(rows[0]["dt_over_critical"]), rel=1e-5)


def test_free_fall_order(rows):
    dts, errs = series(rows, "free_fall", "position_rel")
    assert slope(dts, errs) == pytest.approx(1.0, abs=0.3)


def test_impact_orders(rows):
    dts, errs = series(rows, "elastic_impact", "contact_duration_rel")
    assert slope(dts, errs) == pytest.approx(2.0, abs=0.5)
    dts, errs = series(rows, "elastic_impact", "rebound_velocity_rel")
    assert slope(dts, errs) == pytest.approx(2.0, abs=0.5)
    dts, errs = series(rows, "elastic_impact", "contact_duration_steps_rel")
    assert slope(dts, errs) == pytest.approx(1.0, abs=0.5)
    # the errors are small where they should be: below 2 % up to 0.8·PWaveTimeStep
    assert max(errs) < 0.2
    assert max(series(rows, "elastic_impact", "contact_duration_rel")[1]) < 0.02


def test_sliding_order_and_settling_roundoff(rows):
    dts, errs = series(rows, "sliding", "stopping_distance_rel")
    assert slope(dts, errs) == pytest.approx(1.0, abs=0.3)
    dts, errs = series(rows, "settling", "static_overlap_rel")
    assert max(errs) < 1e-9    # converged to the exact static overlap m·g/Kn, round-off only


def test_errors_match_the_analysis(rows):
    # where the analysis of the scheme gives the error in closed form, the measurement agrees
    for r in rows:
        if r.get("predicted_error"):
            assert float(r["error"]) == pytest.approx(float(r["predicted_error"]), rel=1e-3), r


def test_markdown(suite, rows):
    out, _, _ = suite
    md = (out / "accuracy.md").read_text()
    for case in CASES:
        assert "`%s`" % case in md
    assert md.count("| dt/dt_crit |") >= len(CASES)        # a table per case
    assert "## Reading" in md
    assert "measured order" in md and "theoretical order" in md
    if not any(r["case"] == "torque_free_rotation" for r in rows):
        assert "torque_free_rotation" in md
        assert "not available: no aspherical integrator yet" in md
    # the summary reports the orders the csv gives
    m = re.search(r"\| free_fall \| position_rel \| leapfrog \| ([-0-9.]+) \| 1 \|", md)
    assert m and float(m.group(1)) == pytest.approx(1.0, abs=0.3)
    m = re.search(r"\| elastic_impact \| contact_duration_rel \| leapfrog \| ([-0-9.]+) \| 2 \|", md)
    assert m and float(m.group(1)) == pytest.approx(2.0, abs=0.5)


def test_png_is_valid(suite):
    out, _, _ = suite
    data = (out / "accuracy.png").read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    length, kind = struct.unpack(">I4s", data[8:16])
    assert kind == b"IHDR" and length == 13
    w, h = struct.unpack(">II", data[16:24])
    assert w >= 400 and h >= 300
    assert struct.unpack(">I", data[29:33])[0] == zlib.crc32(data[12:29]) & 0xffffffff
    assert data.rstrip(b"\0")[-8:-4] == b"IEND"


def test_fit_order_ignores_roundoff_points():
    spec = importlib.util.spec_from_file_location("accuracy_suite", str(SUITE))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    dts = [1e-3 * 2 ** k for k in range(6)]
    o, n = mod.fit_order(dts, [3 * d * d for d in dts], [1e-16] * 6)
    assert n == 6 and o == pytest.approx(2.0, abs=1e-12)
    # points at the round-off floor are left out; with fewer than 3 left there is no order
    o, n = mod.fit_order(dts, [1e-15, 1e-15, 5e-15] + [d for d in dts[3:]], [1e-15] * 6)
    assert n == 3 and o == pytest.approx(1.0, abs=1e-12)
    assert mod.fit_order(dts, [1e-16] * 6, [1e-16] * 6) == (None, 0)
