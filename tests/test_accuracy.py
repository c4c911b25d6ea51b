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
# the torque-free rotation of an asymmetric top, one case per NewtonIntegrator.rotAlgorithm
ROTATION = {"torque_free_fincham": "Fincham1992", "torque_free_spiral": "delValle2023", "torque_free_omelyan": "Omelyan1998"}
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
    for case in CASES + list(ROTATION):
        mine = [r for r in rows if r["case"] == case]
        assert len(mine) >= 5, case
        for kind in {r["error_kind"] for r in mine}:
            rs = [r for r in mine if r["error_kind"] == kind]
            factors = {float(r["dt_over_critical"]) for r in rs}
            assert len(rs) >= 5 and len(factors) >= 5, (case, kind)
            assert REQUIRED_FACTORS <= factors, (case, kind, factors)
    for r in rows:
        assert r["integrator"] == ROTATION.get(r["case"], "leapfrog")
        err, dt, wall = float(r["error"]), float(r["dt"]), float(r["wall_s"])
        assert math.isfinite(err) and err >= 0, r
        if r["case"] != "settling" and r["error_kind"] != "angular_momentum_rel":   # (exact up to round-off: may be 0)
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
    for case, scheme in ROTATION.items():
        assert "`%s`" % case in md and "rotAlgorithm='%s'" % scheme in md
        assert re.search(r"- Long run: .* largest drift of E .*\n- Cost: [0-9]+ ns per body and step", md)
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


def test_rotation_orders(rows):
    """Fincham1992 (the reference's scheme, the default) is first order in this engine as in the reference, its
    angular momentum exact (its state); SPIRAL's spin third order, the rest second; Omelyan second."""
    def order(case, kind):
        return slope(*series(rows, case, kind))
    for kind in ("angvel_rel", "orientation_rad", "energy_rel"):
        assert order("torque_free_fincham", kind) == pytest.approx(1.0, abs=0.2), kind
        assert order("torque_free_omelyan", kind) == pytest.approx(2.0, abs=0.2), kind
    assert max(series(rows, "torque_free_fincham", "angular_momentum_rel")[1]) < 1e-14
    assert order("torque_free_omelyan", "angular_momentum_rel") == pytest.approx(2.0, abs=0.2)
    assert order("torque_free_spiral", "angvel_rel") == pytest.approx(3.0, abs=0.3)
    for kind in ("orientation_rad", "energy_rel", "angular_momentum_rel"):
        assert order("torque_free_spiral", kind) == pytest.approx(2.0, abs=0.2), kind
    # at the largest step (ω·dt = 0.02 rad), after the run: SPIRAL and Omelyan within 1e-3 rad, Fincham tenths of a radian
    worst = {c: max(series(rows, c, "orientation_rad")[1]) for c in ROTATION}
    assert worst["torque_free_spiral"] < 1e-3 and worst["torque_free_omelyan"] < 1e-3 and worst["torque_free_fincham"] > 0.05


def _suite_module():
    spec = importlib.util.spec_from_file_location("accuracy_suite", str(SUITE))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_elliptic_functions():
    mod = _suite_module()
    assert mod.ellipk(0.5) == pytest.approx(1.8540746773013719, rel=1e-15)   # K(1/2) = Γ(1/4)²/(4·sqrt(π))
    assert mod.ellipk(0.0) == pytest.approx(math.pi / 2, rel=1e-15)
    for m in (0.1, 0.4664, 0.9):
        K = mod.ellipk(m)
        sn, cn, dn, am = mod.ellipj(K, m)
        assert (sn, cn, dn, am) == pytest.approx((1, 0, math.sqrt(1 - m), math.pi / 2), abs=1e-14)
        for u in (0.3, 1.7, -2.9, 11.0):
            sn, cn, dn, _ = mod.ellipj(u, m)
            assert sn * sn + cn * cn == pytest.approx(1, abs=1e-15) and dn * dn + m * sn * sn == pytest.approx(1, abs=1e-15)
            # (sn)' = cn·dn, by a central difference
            h = 1e-5
            assert (mod.ellipj(u + h, m)[0] - mod.ellipj(u - h, m)[0]) / (2 * h) == pytest.approx(cn * dn, abs=1e-9)


def test_free_top_against_rk4():
    """The analytic solution of the suite (spin by Jacobi's functions, orientation by its Euler angles) against
    RK4 on Euler's equations and q' = q·(0, w)/2, step 1e-3 s over 10 s (2.6 periods of the spin)."""
    mod = _suite_module()
    I, w0 = (1., 2., 3.), (1.0, 0.5, 0.9)
    q0 = (0.5907507033036815, 0.21564084004695758, 0.43128168009391515, 0.6469225201408727)
    top = mod.FreeTop(I, w0, q0)

    def f(y):
        q, w = y[:4], y[4:]
        dq = mod.qmul(q, (0.,) + tuple(w))
        return tuple(0.5 * x for x in dq) + ((I[1] - I[2]) * w[1] * w[2] / I[0], (I[2] - I[0]) * w[2] * w[0] / I[1],
                                             (I[0] - I[1]) * w[0] * w[1] / I[2])
    y, h = q0 + w0, 1e-3
    for k in range(10000):
        k1 = f(y)
        k2 = f(tuple(a + .5 * h * b for a, b in zip(y, k1)))
        k3 = f(tuple(a + .5 * h * b for a, b in zip(y, k2)))
        k4 = f(tuple(a + h * b for a, b in zip(y, k3)))
        y = tuple(a + h / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(y, k1, k2, k3, k4))
    assert tuple(top.spin(10.)) == pytest.approx(y[4:], abs=1e-12)
    assert mod.qangle(top.orientation(10.), y[:4]) < 1e-12
    assert tuple(top.spin(0.)) == pytest.approx(w0, abs=1e-15) and mod.qangle(top.orientation(0.), q0) < 1e-15
