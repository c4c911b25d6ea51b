"""yade-batch (py/yade/batch.py): the parameter table, the jobs it runs with the launcher, their logs
and exit statuses, the summary, and the read-only status page fetched with a real HTTP client while
a batch runs.

The main test runs a real batch of three jobs (one failing on purpose) that wait for a file the test
creates once it has seen them running on the page, so it needs no fixed delays. The batch of the
oedometric tutorial (examples/tutorial/03-oedometric-test.table: three simulations of 7-11 s each, about
20 s on two cores) is the slowest test here."""
import http.client
import io
import json
import os
import pathlib
import re
import shutil
import signal
import socket
import subprocess
import textwrap
import time
import urllib.request

import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
BATCH = REPO / "yade-batch"
BUILD = pathlib.Path(os.environ.get("YADE_BUILD_DIR") or REPO / "build")

pytestmark = pytest.mark.skipif(not (BUILD / "yade").is_dir(),
                                reason="yade is not built (run bash scripts/setup.sh)")


@pytest.fixture(scope="module")
def batch():
    """The module py/yade/batch.py (from the build: `yade.batch`)."""
    from yade import batch as mod
    return mod


def free_port(count=1):
    """A port p such that p ... p+count-1 are free on 127.0.0.1 now."""
    for _ in range(50):
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            p = s.getsockname()[1]
        if p + count > 65535:
            continue
        try:
            socks = []
            for k in range(count):
                t = socket.socket()
                socks.append(t)
                t.bind(("127.0.0.1", p + k))
            return p
        except OSError:
            continue
        finally:
            for t in socks:
                t.close()
    pytest.skip("no free port range")


def env():
    e = dict(os.environ)
    e.setdefault("YADE_BUILD_DIR", str(BUILD))
    e.pop("DISPLAY", None)
    e.pop("YADE_BATCH", None)
    return e


def write(path, text):
    path.write_text(textwrap.dedent(text).lstrip("\n"))
    return path


def run_batch(cwd, *args, timeout=120):
    return subprocess.run(["/usr/bin/python3", str(BATCH), *map(str, args)], capture_output=True, text=True,
                          timeout=timeout, env=env(), cwd=str(cwd))


def wait_for(predicate, timeout, what, proc=None):
    deadline = time.time() + timeout
    while time.time() < deadline:
        value = predicate()
        if value:
            return value
        if proc is not None and proc.poll() is not None:
            break
        time.sleep(0.1)
    raise AssertionError("timed out waiting for " + what)


def get(port, path, method="GET", host=None):
    """(status, headers, body) of a request sent as is (no normalisation of the path)."""
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    try:
        c.putrequest(method, path, skip_host=host is not None)
        if host is not None:
            c.putheader("Host", host)
        c.endheaders()
        r = c.getresponse()
        return r.status, dict(r.getheaders()), r.read()
    finally:
        c.close()


def status_json(port):
    with urllib.request.urlopen("http://localhost:%d/status.json" % port, timeout=10) as r:
        return json.loads(r.read().decode())


def page(port):
    with urllib.request.urlopen("http://localhost:%d/" % port, timeout=10) as r:
        assert r.status == 200 and r.headers["Content-Type"].startswith("text/html")
        return r.read().decode()

# ====================================================================== a real batch with its page


XSS = "<script>alert(1)</script>"

JOB = """
import os, time
readParamsFromTable(n=1, fail=0)
from yade.params import table
from yade import plot
print('PARAMS', table.n, table.fail, runningInBatch(), O.tags['line'], O.tags['description'])
O.bodies.append(sphere((0, 0, 0), .1))
O.dt = 1e-4
plot.plots = {'i': ('z',)}
O.engines = O.engines + [PyRunner(command='plot.addData(i=O.iter, z=O.bodies[0].state.pos[2])', iterPeriod=1)]
O.run(10 * table.n, True)
plot.plot()
print('READY', O.iter, flush=True)
for k in range(1200):  # until the test has looked at the page (at most 60 s)
    if os.path.exists('go'):
        break
    time.sleep(.05)
if table.fail:
    raise RuntimeError('failing on purpose at line ' + O.tags['line'])
print('END', O.iter)
"""

TABLE = """
# three jobs; the second fails on purpose
n   fail  description
3   0     first
=   1     second       # '=': n is 3 again
5   0     %s
""" % XSS


@pytest.fixture(scope="module")
def real_batch(tmp_path_factory):
    """Runs the three-job batch with --http-wait; yields (dir, port, pages seen while running, pages after,
    result) once the batch has been stopped with Ctrl-C."""
    d = tmp_path_factory.mktemp("batch")
    write(d / "job.py", JOB)
    write(d / "jobs.table", TABLE)
    port = free_port()
    out = open(d / "out.txt", "w")
    proc = subprocess.Popen(["/usr/bin/python3", str(BATCH), "-j", "3", "--port", str(port), "--http-wait",
                             "--refresh", "2", "jobs.table", "job.py"], stdout=out, stderr=subprocess.STDOUT,
                            env=env(), cwd=str(d))
    seen = {}
    try:
        # (the port printed: another program may have taken the free one in the meantime)
        port = int(wait_for(lambda: re.search(r"http://localhost:(\d+) shows batch summary", (d / "out.txt").read_text()),
                            60, "the page's address", proc).group(1))

        def all_ready():
            try:
                s = status_json(port)
            except (OSError, ValueError):
                return None
            logs = [d / j["log"] for j in s["jobs"]]
            if all(j["state"] == "running" for j in s["jobs"]) and \
                    all(p.is_file() and "READY" in p.read_text() for p in logs) and \
                    [j["progress"].get("iter") for j in s["jobs"]] == [30, 30, 50]:  # (reported each second)
                return s
        seen["status"] = wait_for(all_ready, 90, "three running jobs on the page", proc)
        seen["page"] = page(port)
        seen["log_running"] = get(port, "/jobs/1/log")
        (d / "go").write_text("")
        after = {}
        after["status"] = wait_for(lambda: (lambda s: s if s["finished"] else None)(status_json(port)), 90,
                                   "the end of the jobs", proc)
        wait_for(lambda: "keeps serving" in (d / "out.txt").read_text(), 30, "--http-wait", proc)
        after["page"] = page(port)
        after["log"] = get(port, "/jobs/1/log")
        after["head"] = get(port, "/jobs/1/log", method="HEAD")
        after["plot"] = get(port, "/jobs/0/plot/1")
        after["probes"] = {p: get(port, p)[0] for p in (
            "/../../etc/passwd", "/jobs/0/../../../../etc/passwd", "/jobs/0/log/../../../etc/passwd",
            "/%2e%2e/%2e%2e/etc/passwd", "/jobs/0/..%2f..%2fjob.py", "/job.py", "/jobs.table",
            "/jobs/7/log", "/jobs/-1/log", "/jobs/0/plot/0", "/jobs/0/plot/9", "//etc/passwd",
            "/jobs/0/log%00.png")}
        after["post"] = get(port, "/", method="POST")
        after["delete"] = get(port, "/jobs/0/log", method="DELETE")
        after["evil_host"] = get(port, "/", host="evil.example:%d" % port)
        after["local_host"] = get(port, "/", host="localhost:%d" % port)
        proc.send_signal(signal.SIGINT)
        rc = proc.wait(30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        out.close()
    yield d, port, seen, after, rc, (d / "out.txt").read_text()


def test_page_lists_the_running_jobs(real_batch):
    d, port, seen, after, rc, out = real_batch
    s = seen["status"]
    assert [j["state"] for j in s["jobs"]] == ["running"] * 3
    assert [j["line"] for j in s["jobs"]] == [3, 4, 5]
    assert [j["description"] for j in s["jobs"]] == ["first", "second", XSS]
    html = seen["page"]
    for i in range(3):
        assert 'id="job%d"' % i in html and 'href="/jobs/%d/log"' % i in html
    assert html.count('<tr class="running"') == 3
    assert "3 running" in html
    assert len(re.findall(r"<td>step (30|50), t = [0-9.e+-]+ s, 1 bodies</td>", html)) == 3  # progress reported
    # the tail of each log is on the page
    assert "READY" in html
    code, headers, body = seen["log_running"]
    assert code == 200 and b"PARAMS 3 1 True l4 second" in body


def test_page_shows_final_states_and_the_failed_log(real_batch):
    d, port, seen, after, rc, out = real_batch
    s = after["status"]
    assert [j["state"] for j in s["jobs"]] == ["done", "failed", "done"]
    assert [j["returncode"] for j in s["jobs"]] == [0, 1, 0]
    html = after["page"]
    assert '<tr class="done" id="job0"' in html and '<tr class="failed" id="job1"' in html
    assert '<tr class="done" id="job2"' in html
    assert "failed (exit status 1)" in html
    assert "2 done" in html and "1 failed" in html
    code, headers, body = after["log"]
    assert code == 200 and headers["Content-Type"].startswith("text/plain")
    assert headers["X-Content-Type-Options"] == "nosniff"
    assert b"RuntimeError: failing on purpose at line l4" in body
    assert b"JOB SUMMARY" in body and b"exit status 1 (FAILED)" in body
    assert body == (d / "job.py.second.log").read_bytes()
    code, headers, body = after["head"]
    assert code == 200 and body == b"" and int(headers["Content-Length"]) == (d / "job.py.second.log").stat().st_size


def test_description_is_escaped(real_batch):
    d, port, seen, after, rc, out = real_batch
    for html in (seen["page"], after["page"]):
        assert XSS not in html
        assert "&lt;script&gt;alert(1)&lt;/script&gt;" in html
        assert "<script" not in html.lower()
    # the file name keeps the description, a '/' made harmless
    assert (d / "job.py.<script>alert(1)<_script>.log").is_file()
    assert "default-src 'none'" in after["local_host"][1]["Content-Security-Policy"]


def test_plots_are_served(real_batch):
    d, port, seen, after, rc, out = real_batch
    code, headers, body = after["plot"]
    assert code == 200 and headers["Content-Type"] == "image/png"
    assert body[:8] == b"\x89PNG\r\n\x1a\n"
    assert body == (d / "job.py.first.png").read_bytes()
    assert 'src="/jobs/0/plot/1"' in after["page"]
    assert not (d / "job.plot.png").exists()  # each job's figure has its own name


def test_page_is_read_only_and_serves_nothing_else(real_batch):
    d, port, seen, after, rc, out = real_batch
    assert after["probes"] == {p: 404 for p in after["probes"]}
    assert after["post"][0] == 405 and after["post"][1]["Allow"] == "GET, HEAD"
    assert after["delete"][0] == 405
    assert (d / "job.py.first.log").is_file()
    assert after["evil_host"][0] == 403  # a page bound to 127.0.0.1 answers to localhost only
    assert after["local_host"][0] == 200
    assert "askforstop" not in after["page"].lower() and "<form" not in after["page"].lower()


def test_jobs_read_their_table_line(real_batch):
    d, port, seen, after, rc, out = real_batch
    logs = {name: (d / ("job.py.%s.log" % name)).read_text() for name in ("first", "second", "<script>alert(1)<_script>")}
    assert "PARAMS 3 0 True l3 first" in logs["first"]
    assert "PARAMS 3 1 True l4 second" in logs["second"]
    assert "PARAMS 5 0 True l5 %s" % XSS in logs["<script>alert(1)<_script>"]
    assert "END 30" in logs["first"] and "END 50" in logs["<script>alert(1)<_script>"]
    assert "END" not in logs["second"]


def test_exit_status_and_summary(real_batch):
    d, port, seen, after, rc, out = real_batch
    assert rc == 1, out  # one job failed (also after --http-wait ended by Ctrl-C)
    assert "http://localhost:%d shows batch summary" % port in out
    assert "#1 (second) FAILED  (exit status 1)" in out
    assert "Summary: 3 jobs in" in out and "2 ok, 1 failed" in out
    summary = out[out.index("Summary:"):].splitlines()
    assert [l.split()[:4] for l in summary[2:5]] == [["0", "3", "first", "ok"], ["1", "4", "second", "FAILED"],
                                                     ["2", "5", XSS, "ok"]]
    assert "exit status 1" in summary[3] and "job.py.second.log" in summary[3]
    summary = "\n".join(summary)
    assert "line 4 (second): =   1     second       # '=': n is 3 again  -> exit status 1" in summary
    assert "Bye." in out

# ====================================================================== other batches (fast ones)


def test_port_in_use_takes_the_next_one_and_bang_columns(tmp_path):
    """A taken port: a message and the next port. !THREADS sets the job's threads; '!' columns are not
    parameters; the description synthesized by the batch is the one the job's O.tags hold."""
    write(tmp_path / "s.py", """
        import os
        readParamsFromTable(a=0)
        from yade.params import table
        print('A', table.a, os.environ['OMP_NUM_THREADS'], O.tags['description'], O.tags['params'])
    """)
    write(tmp_path / "t.table", """
        a      !THREADS
        'x_y'  2
    """)
    port = free_port(2)
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", port))
        busy.listen(1)
        r = run_batch(tmp_path, "-j", "2", "--port", port, "t.table", "s.py")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "port %d is already in use, trying %d" % (port, port + 1) in r.stdout
    assert "http://localhost:%d shows batch summary" % (port + 1) in r.stdout
    assert "Traceback" not in r.stdout + r.stderr
    log = (tmp_path / "s.py.a=x_y,THREADS=2.log").read_text()
    assert "A x_y 2 a=x_y,THREADS=2 a='x_y'" in log
    assert "#0 (a=x_y,THREADS=2/2) started" in r.stdout


def test_killed_job_does_not_stop_the_batch(tmp_path):
    write(tmp_path / "s.py", """
        import os, signal
        readParamsFromTable(k=0)
        from yade.params import table
        if table.k == 1:
            os.kill(os.getpid(), signal.SIGKILL)
        print('SURVIVED', table.k)
    """)
    write(tmp_path / "t.table", """
        k description
        0 zero
        1 crash
        2 two
    """)
    r = run_batch(tmp_path, "-j", "1", "--no-http", "t.table", "s.py")
    assert r.returncode == 1, r.stdout + r.stderr
    assert "#1 (crash) FAILED  (killed by SIGKILL)" in r.stdout
    assert "line 3 (crash): 1 crash  -> killed by SIGKILL" in r.stdout
    assert "SURVIVED 0" in (tmp_path / "s.py.zero.log").read_text()
    assert "SURVIVED 2" in (tmp_path / "s.py.two.log").read_text()  # the job after the crash ran
    assert "killed by SIGKILL (FAILED)" in (tmp_path / "s.py.crash.log").read_text()


def test_lines_log_format_and_timing(tmp_path):
    write(tmp_path / "s.py", """
        readParamsFromTable(v=0)
        from yade.params import table
        print('V', table.v)
    """)
    write(tmp_path / "t.table", """
        v
        10
        20
        30
        40
    """)
    r = run_batch(tmp_path, "--lines", "4,2", "--log", "logs/@-%.out", "--timing", "2", "--no-http", "t.table", "s.py")
    assert r.returncode == 0, r.stdout + r.stderr
    logs = sorted(p.name for p in (tmp_path / "logs").iterdir())
    assert logs == ["v=10-2.out.0", "v=10-2.out.1", "v=30-4.out.0", "v=30-4.out.1"]
    assert "V 30" in (tmp_path / "logs" / "v=30-4.out.1").read_text()
    assert "Will use lines 4 (v=30), 2 (v=10)." in r.stdout
    rows = [l.split("\t") for l in r.stdout.splitlines() if l[:1].isdigit()]
    assert [(row[0], row[1]) for row in rows] == [("4", "2"), ("2", "2")]
    assert rows[0][-1] == "30"


def test_dry_run(tmp_path):
    write(tmp_path / "s.py", "print(1)\n")
    write(tmp_path / "t.table", """
        a description
        1 one
        2 two
    """)
    r = run_batch(tmp_path, "--dry-run", "--job-threads", "2", "-j", "4", "t.table", "s.py")
    assert r.returncode == 0, r.stderr
    assert "#0 (one/2): YADE_BATCH=t.table:2 OMP_NUM_THREADS=2 " in r.stdout
    assert "-n -x -j 2 --nice 10 s.py > s.py.one.log 2>&1" in r.stdout
    assert "#1 (two/2)" in r.stdout
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.py", "t.table"]


@pytest.mark.parametrize("args,message", [
    (["missing.table", "s.py"], "parameter table missing.table does not exist"),
    (["--lines", "2", "t.table", "nothere.py"], "script nothere.py does not exist"),
    (["--lines", "2", "t.table"], "no script: give SCRIPT.py after the table"),
    (["--lines", "2,x", "t.table", "s.py"], "'x' is not a line number or a range"),
    (["--lines", "5-3", "t.table", "s.py"], "the range 5-3 goes backwards"),
    (["--lines", "1", "t.table", "s.py"], "t.table has no parameter line 1 (its parameter lines: 2, 3, 5)"),
    (["--lines", "9", "t.table", "s.py"], "has no parameter line 9"),
    (["--lines", "4", "t.table", "s.py"], "t.table, line 4: 1 values for 2 columns (a description)"),
    (["t.table", "s.py"], "t.table, line 4: 1 values for 2 columns (a description) (use --lines"),
    (["--log", "x.log", "t.table", "s.py"], "must contain $, % or @"),
    (["-j", "0", "t.table", "s.py"], "-j/--jobs must be at least 1"),
    (["s.py"], "give the parameter table first"),
    (["empty.table", "s.py"], "parameter table empty.table is empty"),
    (["--lines", "2", "--executable", "nope", "t.table", "s.py"], "executable nope does not exist"),
])
def test_bad_input_is_refused_clearly(tmp_path, args, message):
    write(tmp_path / "s.py", "print(1)\n")
    write(tmp_path / "t.table", """
        a description
        1 one
        2 two
        oops
        3 three
    """)
    write(tmp_path / "empty.table", "# nothing\n")
    r = run_batch(tmp_path, *args, timeout=60)
    assert r.returncode == 2, r.stdout + r.stderr
    assert message in r.stderr, r.stderr
    assert "Traceback" not in r.stderr
    assert not list(tmp_path.glob("*.log"))

# ====================================================================== the module's parts


TABLE_TEXT = """
# a comment line
   # an indented one
damping  n   !THREADS  description
.2       10  1         low      # trailing comment

.4       =   =         high
.6       20  2         =
"""


def test_read_table(batch, tmp_path):
    t = batch.readTable(str(write(tmp_path / "t.table", TABLE_TEXT)))
    assert t.names == ["damping", "n", "!THREADS", "description"]
    assert list(t.lines) == [4, 6, 7] and not t.bad
    low, high, third = t.lines[4], t.lines[6], t.lines[7]
    assert low.values == [".2", "10", "1", "low"] and low.description == "low"
    assert high.values == [".4", "10", "1", "high"]
    assert third.values == [".6", "20", "2", "high"]  # '=' in the description column too
    assert third.params() == [("damping", ".6"), ("n", "20")]
    assert third.special("THREADS") == "2" and third.special("SCRIPT") is None
    assert "trailing comment" in low.text


def test_read_table_bad_lines_and_synthesized_description(batch, tmp_path):
    t = batch.readTable(str(write(tmp_path / "t.table", """
        a      b
        =      1
        1      2 3
        'q'    =
        "s"    'u'
    """)))
    assert t.bad == {2: "'=' in column a has no value above to repeat", 3: "3 values for 2 columns (a b)",
                     4: "'=' in column b has no value above to repeat"}  # ('=' right after a bad line)
    assert t.lines[5].description == "a=s,b=u"
    with pytest.raises(batch.TableError, match="line 3: 3 values"):
        t.line(3)
    with pytest.raises(batch.TableError, match="has no parameter line 1 "):
        t.line(1)
    with pytest.raises(batch.TableError, match="column a appears more than once"):
        batch.readTable(str(write(tmp_path / "d.table", "a a\n1 2\n")))


def test_line_spec(batch):
    assert batch.parseLineSpec("2,4-6") == [2, 4, 5, 6]
    assert batch.parseLineSpec(" 7 , 3-3,2-3 ") == [7, 3, 2]
    for bad in ("", "a", "2,,3", "3-", "-3", "0", "4-2", "1.5"):
        with pytest.raises(ValueError):
            batch.parseLineSpec(bad)


def test_log_and_plot_names(batch):
    assert batch.logName("$.@.log", "dir/job.py", 4, "second") == "job.py.second.log"
    assert batch.logName("$.%.log", "job.py", 4, "second") == "job.py.4.log"
    assert batch.logName("logs/@", "job.py", 4, "a/b") == "logs/a_b"
    assert batch.plotPathForLog("job.py.second.log") == "job.py.second.png"
    assert batch.plotPathForLog("job.py.second.log.3") == "job.py.second.3.png"
    assert batch.plotPathForLog("x.out") == "x.out.png"


def test_find_launcher(batch, tmp_path):
    for name in ("yade-fast-batch", "yade-fast", "yade"):
        (tmp_path / name).write_text("#!/bin/sh\n")
    assert batch.findLauncher(str(tmp_path / "yade-fast-batch")) == str(tmp_path / "yade-fast")
    (tmp_path / "yade-fast").unlink()
    assert batch.findLauncher(str(tmp_path / "yade-fast-batch")) == str(tmp_path / "yade")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "yade-double").write_text("")
    (tmp_path / "sub" / "yade-double-batch").write_text("")
    os.symlink(tmp_path / "sub" / "yade-double-batch", tmp_path / "sub" / "yade-batch")
    # called through a link whose own sibling does not exist: the sibling of the file it points to
    assert batch.findLauncher(str(tmp_path / "sub" / "yade-batch")) == str(tmp_path / "sub" / "yade-double")
    assert batch.findLauncher(str(REPO / "yade-batch")) == str(REPO / "yade")


def test_read_params_skips_bang_columns(tmp_path):
    from yade import O, params
    import warnings
    tbl = write(tmp_path / "t.table", """
        a  !THREADS  b
        1  2         'z'
    """)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert params.readParamsFromTable("%s:2" % tbl, a=0, b="") == 2
    assert (params.table.a, params.table.b) == (1, "z")
    assert O.tags["description"] == "a=1,THREADS=2,b=z" and O.tags["params"] == "a=1,b='z'"


def test_running_in_batch_follows_yade_batch(monkeypatch):
    from yade import utils, params
    monkeypatch.delenv("YADE_BATCH", raising=False)
    monkeypatch.setenv("PARAM_TABLE", "t.table:2")  # (the reference ignores it too)
    assert not utils.runningInBatch() and not params.inBatch()
    monkeypatch.setenv("YADE_BATCH", "t.table:2")
    assert utils.runningInBatch() and params.inBatch()


def test_page_escapes_logs_and_file_names(batch, tmp_path):
    """In-process: a batch whose log and description hold HTML, served on a free port."""
    log = tmp_path / "a<b>.log"
    log.write_text("<img src=x onerror=alert(2)>\n& done\n")
    line = batch.TableLine(2, "x", ["description"], ['"><script>alert(3)</script>'])
    job = batch.Job(0, line, "t<1>.table", "s.py", 1, "/bin/true", str(log))
    job.state, job.started, job.finished, job.returncode = batch.Job.FAILED, time.time() - 2, time.time(), 3
    b = batch.Batch([job], 1, scriptName="<i>s.py</i>", tableName="t<1>.table", out=io.StringIO())
    b.started = time.time() - 5
    server = batch.startStatusServer(b, "127.0.0.1", 0)
    try:
        port = server.server_address[1]
        html = page(port)
        for raw in ("<img src=x", "<script>", "<i>s.py", "t<1>", 'a<b>.log"'):
            assert raw not in html
        for escaped in ("&lt;img src=x onerror=alert(2)&gt;", "&amp; done", "&quot;&gt;&lt;script&gt;alert(3)",
                        "&lt;i&gt;s.py&lt;/i&gt;", "t&lt;1&gt;.table", "a&lt;b&gt;.log"):
            assert escaped in html
        assert "failed (exit status 3)" in html
        code, headers, body = get(port, "/jobs/0/log")
        assert code == 200 and body.startswith(b"<img") and headers["Content-Type"] == "text/plain; charset=utf-8"
        assert get(port, "/jobs/0/plot/1")[0] == 404  # no figure written
    finally:
        server.shutdown()
        server.server_close()


def test_status_server_refuses_a_taken_range(batch):
    """When every port tried is taken: a message and no page (the batch runs without it)."""
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen(1)
        port = busy.getsockname()[1]
        out = io.StringIO()
        assert batch.startStatusServer(object(), "127.0.0.1", port, out=out, tries=1) is None
    assert "port %d is already in use" % port in out.getvalue() and "no status page" in out.getvalue()

# ====================================================================== the tutorial's table


def test_oedometric_tutorial_runs_as_a_batch(tmp_path):
    tut = REPO / "examples" / "tutorial"
    for name in ("03-oedometric-test.py", "03-oedometric-test.table"):
        (tmp_path / name).write_bytes((tut / name).read_bytes())
    t0 = time.time()
    r = run_batch(tmp_path, "-j", "2", "--port", free_port(), "03-oedometric-test.table", "03-oedometric-test.py",
                  timeout=900)
    assert r.returncode == 0, r.stdout + r.stderr
    print("tutorial batch: %.1f s" % (time.time() - t0))
    for desc in ("r05-load1e6", "r05-load2e6", "r06-load1e6"):
        log = (tmp_path / ("03-oedometric-test.py.%s.log" % desc)).read_text()
        assert "exit status 0 (OK)" in log
        png = tmp_path / ("03-oedometric-test.py.%s.png" % desc)
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        data = list(tmp_path.glob(desc + ".*.txt"))  # plot.saveDataTxt(O.tags['d.id'] + '.txt')
        assert len(data) == 1, data
        rows = [l.split() for l in data[0].read_text().splitlines()[1:] if l.strip()]
        assert len(rows) > 10


def test_plot_png_of_a_batch_job(tmp_path):
    """In a job (YADE_BATCH_PLOT set by the batch), yade.plot writes the figure under the job's name: every
    YADE_BATCH_PLOT_PERIOD seconds while data come, and at the end, also without plot.plot()."""
    png = tmp_path / "job.py.first.png"
    write(tmp_path / "job.py", """
        import os, time
        from yade import plot
        plot.plots = {'i': ('v',)}
        plot.addData(i=0, v=0)
        time.sleep(.3)
        plot.addData(i=1, v=1)  # a period after the first data: the figure is written
        print('DURING', os.path.exists(%r))
        os.remove(%r)
        plot.addData(i=2, v=4)  # (at the end: written again, with all the data)
    """ % (str(png), str(png)))
    e = env()
    e.update({"YADE_BATCH_PLOT": str(png), "YADE_BATCH_PLOT_PERIOD": "0.2"})
    r = subprocess.run(["/usr/bin/python3", str(REPO / "yade"), "-n", "-x", "job.py"], capture_output=True, text=True,
                       timeout=120, env=e, cwd=str(tmp_path))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "DURING True" in r.stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert r.stdout.count("figure saved to") == 1  # said once, not at every update
    assert not (tmp_path / "job.plot.png").exists()


def test_ctrl_c_stops_the_jobs(tmp_path):
    """Ctrl-C (SIGINT) to the batch stops its running jobs (they run in sessions of their own, so the batch
    signals them), cancels the pending ones, prints the summary and exits with 130."""
    write(tmp_path / "s.py", """
        import os, time
        readParamsFromTable(k=0)
        open('pid', 'a').write('%d\\n' % os.getpid())
        time.sleep(120)
    """)
    write(tmp_path / "t.table", """
        k
        1
        2
    """)
    out = open(tmp_path / "out.txt", "w")
    proc = subprocess.Popen(["/usr/bin/python3", str(BATCH), "-j", "1", "--no-http", "t.table", "s.py"], stdout=out,
                            stderr=subprocess.STDOUT, env=env(), cwd=str(tmp_path))
    try:
        pid = int(wait_for(lambda: (tmp_path / "pid").is_file() and (tmp_path / "pid").read_text().strip(), 60,
                           "the first job", proc))
        proc.send_signal(signal.SIGINT)
        rc = proc.wait(30)
    finally:
        if proc.poll() is None:
            proc.kill()
        out.close()
    text = (tmp_path / "out.txt").read_text()
    assert rc == 130, text
    assert "interrupted (killed by SIGTERM)" in text and "1 not run" in text
    assert "Traceback" not in text
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)


def test_same_description_keeps_both_logs(tmp_path):
    write(tmp_path / "s.py", "print(1)\n")
    write(tmp_path / "t.table", """
        a description
        1 same
        2 same
    """)
    r = run_batch(tmp_path, "--dry-run", "t.table", "s.py")
    assert r.returncode == 0, r.stderr
    assert "> s.py.same.log 2>&1" in r.stdout and "> s.py.same.l3.log 2>&1" in r.stdout


def test_help():
    r = subprocess.run(["/usr/bin/python3", str(BATCH), "--help"], capture_output=True, text=True, timeout=60, env=env())
    assert r.returncode == 0 and r.stdout.startswith("usage: yade-batch [options] TABLE [SCRIPT.py]"), r.stderr
    assert "(default: $.@.log, e.g. job.py.first.log)" in r.stdout and "--http-wait" in r.stdout


def test_installed_copy_runs_its_own_launcher(tmp_path):
    """As the Debian package installs them: yade-fast-batch next to yade-fast, no source tree, the 'yade'
    package from sys.path; the jobs run yade-fast."""
    bindir = tmp_path / "bin"
    bindir.mkdir()
    shutil.copy(REPO / "yade", bindir / "yade-fast")
    shutil.copy(BATCH, bindir / "yade-fast-batch")
    write(tmp_path / "s.py", """
        readParamsFromTable(a=0)
        from yade.params import table
        print('A', table.a, yade.__file__)
    """)
    write(tmp_path / "t.table", "a\n7\n")
    e = env()
    e.pop("YADE_BUILD_DIR", None)
    e["PYTHONPATH"] = str(BUILD)
    r = subprocess.run(["/usr/bin/python3", str(bindir / "yade-fast-batch"), "--no-http", "t.table", "s.py"],
                       capture_output=True, text=True, timeout=120, env=e, cwd=str(tmp_path))
    assert r.returncode == 0, r.stdout + r.stderr
    assert "Will run s.py with %s," % (bindir / "yade-fast") in r.stdout
    assert "A 7 " + str(BUILD / "yade") in (tmp_path / "s.py.a=7.log").read_text()
    r = subprocess.run(["/usr/bin/python3", str(bindir / "yade-fast-batch"), "-h"], capture_output=True, text=True,
                       timeout=60, env=e)
    assert r.stdout.startswith("usage: yade-fast-batch "), r.stdout + r.stderr
