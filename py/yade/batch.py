"""Parametric studies: run one simulation script once per line of a parameter table (``yade-batch``).

    yade-batch [options] TABLE SCRIPT.py

Each selected line of TABLE becomes a job: the launcher next to ``yade-batch`` runs
``yade -n -x -j THREADS --nice NICE SCRIPT.py`` in the current folder with ``YADE_BATCH=TABLE:LINE``
in its environment, so that :func:`yade.params.readParamsFromTable` returns that line's values and
:func:`yade.utils.runningInBatch` / :func:`yade.params.waitIfBatch` know they run in a batch. Its
output goes to a log file named after the script and the line's description (``job.py.first.log``,
``--log``). Jobs run side by side as long as their threads fit in ``-j`` cores. A job that fails, crashes
or is killed does not stop the others; the end of the batch prints a summary (state, exit status and
time per job, the table lines of the failed ones) and the exit status is 1 when a job failed.

While the batch runs, a read-only status page is served over HTTP (``http://localhost:9080``, the next
free port if that one is taken): the jobs, their state and progress, the tail of their logs and the
plots they made (``yade.plot`` figures, saved as PNG next to the logs).

The table format (the same as :func:`yade.params.readParamsFromTable` reads)::

    # comments run from '#' to the end of the line; blank lines are skipped
    damping  nSpheres  !THREADS  description    # first non-blank line: the column names
    .2       100       1         lowDamping     # one simulation per line (numbered as in an editor)
    .4       =         2         highDamping    # '=' repeats the value of the line above

Columns starting with ``!`` are for the batch, not parameters: ``!THREADS`` (or ``!OMP_NUM_THREADS``)
the threads of that job, ``!SCRIPT`` the script (when none is given on the command line), ``!EXEC``
the program to run, ``!COUNT`` the repetitions with ``--timing``. ``doc/batch.md`` has the details.

This module uses the standard library only (it is loaded by ``yade-batch`` without the compiled
engine); the parts a job runs (:func:`startJobReport`) are called by ``yade.params`` and ``yade.plot``.
"""
import argparse
import atexit
import errno
import html
import http.server
import json
import math
import os
import re
import shlex
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.parse

__all__ = ['TableError', 'Table', 'TableLine', 'readTable', 'parseLineSpec', 'Job', 'Batch', 'StatusServer',
           'startStatusServer', 'findLauncher', 'main', 'startJobReport']

BATCH_ENV = 'YADE_BATCH'                  # TABLE:LINE of a job (the reference's name)
PLOT_ENV = 'YADE_BATCH_PLOT'              # where yade.plot saves the job's figure (PNG)
PLOT_PERIOD_ENV = 'YADE_BATCH_PLOT_PERIOD'  # seconds between the figure's updates while the job runs
STATUS_ENV = 'YADE_BATCH_STATUS'          # JSON file where the job reports its progress
DEFAULT_PORT = 9080
DEFAULT_LOG = '$.@.log'
PORT_TRIES = 100

# ====================================================================== the parameter table


class TableError(ValueError):
    """A parameter table that cannot be read, or a line of it that cannot be used."""


class TableLine:
    """One data line of a parameter table: its number (1-based, as in an editor), the raw text and the
    values of the columns as text, with '=' replaced by the value above."""

    def __init__(self, lineNo, text, names, values):
        self.lineNo, self.text, self.names, self.values = lineNo, text, list(names), list(values)

    def items(self):
        return list(zip(self.names, self.values))

    def get(self, name, default=None):
        for n, v in zip(self.names, self.values):
            if n == name:
                return v
        return default

    def params(self):
        """(name, expression) of the simulation's parameters: neither ``description`` nor ``!`` columns."""
        return [(n, v) for n, v in self.items() if n != 'description' and not n.startswith('!')]

    def special(self, key):
        """The value of the batch column ``!key`` (None when the table has no such column)."""
        return self.get('!' + key)

    @property
    def description(self):
        """The ``description`` column, or name=value pairs of the other columns (``!`` and quotes dropped),
        as the reference names a job and as ``O.tags['description']`` holds it."""
        d = self.get('description')
        if d is not None:
            return d
        return synthesizedDescription(self.items())


def synthesizedDescription(items):
    """``a=1,THREADS=2,b=z`` for the columns (name, value), description excluded, quotes removed."""
    text = ','.join('%s=%s' % (n.lstrip('!'), v) for n, v in items if n != 'description')
    return text.replace("'", '').replace('"', '')


class Table:
    """A parsed parameter table: ``names`` (the columns), ``lines`` (line number -> :class:`TableLine`,
    in file order) and ``bad`` (line number -> why that line cannot be used)."""

    def __init__(self, fileName, names, lines, bad):
        self.fileName, self.names, self.lines, self.bad = fileName, names, lines, bad

    def line(self, lineNo):
        """The :class:`TableLine` of that line number, or TableError saying why there is none."""
        if lineNo in self.lines:
            return self.lines[lineNo]
        if lineNo in self.bad:
            raise TableError('%s, line %d: %s' % (self.fileName, lineNo, self.bad[lineNo]))
        raise TableError('%s has no parameter line %d (its parameter lines: %s)'
                         % (self.fileName, lineNo, _lineList(self.lines) or 'none'))


def _lineList(numbers):
    return ', '.join(str(n) for n in numbers)


def stripComment(text):
    i = text.find('#')
    return text if i < 0 else text[:i]


def readTable(fileName):
    """Parse a parameter table file (see the module's documentation); return a :class:`Table`.

    The first non-blank line (comments removed) names the columns; every following non-blank line is
    one simulation. A line with a different number of values, or a '=' with nothing above it, is put
    in ``Table.bad`` with the reason (the batch refuses to run it; other lines are fine)."""
    try:
        with open(fileName, encoding='utf-8', errors='replace') as f:
            rawLines = f.read().splitlines()
    except FileNotFoundError:
        raise TableError('parameter table %s does not exist' % fileName)
    except IsADirectoryError:
        raise TableError('parameter table %s is a directory' % fileName)
    except OSError as e:
        raise TableError('cannot read parameter table %s: %s' % (fileName, e.strerror or e))
    names = None
    lines, bad = {}, {}
    prev = None
    for lineNo, raw in enumerate(rawLines, start=1):
        words = stripComment(raw).split()
        if not words:
            continue
        if names is None:
            names = words
            dup = sorted({w for w in words if words.count(w) > 1})
            if dup:
                raise TableError('%s, line %d: column %s appears more than once' % (fileName, lineNo, ', '.join(dup)))
            continue
        if len(words) != len(names):
            bad[lineNo] = '%d values for %d columns (%s)' % (len(words), len(names), ' '.join(names))
            prev = None  # a malformed line cannot be repeated with '='
            continue
        values, problem = [], None
        for name, w in zip(names, words):
            if w == '=':
                if prev is None:
                    problem = "'=' in column %s has no value above to repeat" % name
                    break
                w = prev[len(values)]
            values.append(w)
        if problem:
            bad[lineNo] = problem
            prev = None
            continue
        prev = values
        lines[lineNo] = TableLine(lineNo, raw, names, values)
    if names is None:
        raise TableError('parameter table %s is empty (no column names)' % fileName)
    return Table(fileName, names, lines, bad)


_LINESPEC = re.compile(r'^\s*(\d+)\s*(?:-\s*(\d+)\s*)?$')


def parseLineSpec(spec):
    """``'2,4-6'`` -> [2, 4, 5, 6] (in the given order, each number once); ValueError on bad syntax."""
    out = []
    if not spec or not spec.strip():
        raise ValueError('empty line list: expected numbers and ranges such as 2,4-6')
    for part in spec.split(','):
        m = _LINESPEC.match(part)
        if not m:
            raise ValueError("bad line list %r: %r is not a line number or a range such as 4-6" % (spec, part.strip()))
        a = int(m.group(1))
        b = int(m.group(2)) if m.group(2) is not None else a
        if b < a:
            raise ValueError('bad line list %r: the range %d-%d goes backwards' % (spec, a, b))
        if a < 1:
            raise ValueError('bad line list %r: line numbers start at 1' % spec)
        for n in range(a, b + 1):
            if n not in out:
                out.append(n)
    return out

# ====================================================================== jobs


def _hms(seconds):
    if seconds is None:
        return '--:--:--'
    seconds = int(max(0, seconds))
    return '%02d:%02d:%02d' % (seconds // 3600, seconds // 60 % 60, seconds % 60)


def _signalName(num):
    try:
        return signal.Signals(num).name
    except ValueError:
        return 'signal %d' % num


def _safeName(text):
    """A text usable inside a file name: no folder separator, no NUL, not empty."""
    text = text.replace('/', '_').replace('\0', '_')
    return text or '_'


class Job:
    """One run of the script: a table line (and a repetition number with ``--timing``)."""

    PENDING, RUNNING, DONE, FAILED, CANCELLED = 'pending', 'running', 'done', 'failed', 'cancelled'

    def __init__(self, index, line, table, script, threads, executable, logPath, repeat=None):
        self.index, self.line, self.table, self.script = index, line, table, script
        self.threads, self.executable, self.logPath, self.repeat = threads, executable, logPath, repeat
        self.description = line.description
        self.plotPath = plotPathForLog(logPath)
        self.statusPath = None
        self.state = Job.PENDING
        self.returncode = None
        self.reason = ''
        self.started = self.finished = None
        self.proc = None
        self.cpus = None
        self.env = {}

    @property
    def name(self):
        """The job's name as the batch prints it: description, [repetition], /threads when more than one."""
        n = self.description
        if self.repeat is not None:
            n += '[%d]' % self.repeat
        if self.threads > 1:
            n += '/%d' % self.threads
        return n

    @property
    def tableLine(self):
        return '%s:%d' % (self.table, self.line.lineNo)

    def command(self, nice):
        exe = self.executable
        prefix = [exe] if os.access(exe, os.X_OK) else [sys.executable, exe]
        cmd = prefix + ['-n', '-x', '-j', str(self.threads)]
        if nice:
            cmd += ['--nice', str(nice)]
        return cmd + [self.script]

    def shellCommand(self, nice):
        """The job as a shell command line (what the batch prints and the page shows)."""
        env = '%s=%s OMP_NUM_THREADS=%d' % (BATCH_ENV, shlex.quote(self.tableLine), self.threads)
        return '%s %s > %s 2>&1' % (env, ' '.join(shlex.quote(c) for c in self.command(nice)), shlex.quote(self.logPath))

    def elapsed(self, now=None):
        if self.started is None:
            return None
        return (self.finished if self.finished is not None else (now or time.time())) - self.started

    def outcome(self):
        """'exit status 0', 'killed by SIGKILL', ... (empty while not finished)."""
        if self.reason:
            return self.reason
        if self.returncode is None:
            return ''
        if self.returncode < 0:
            return 'killed by %s' % _signalName(-self.returncode)
        return 'exit status %d' % self.returncode

    def plotFiles(self):
        """The PNG files the job's yade.plot wrote so far: the first figure, then ``base.2.png``, ..."""
        base = self.plotPath[:-4]
        out = []
        if os.path.isfile(self.plotPath):
            out.append(self.plotPath)
        k = 2
        while k < 100 and os.path.isfile('%s.%d.png' % (base, k)):
            out.append('%s.%d.png' % (base, k))
            k += 1
        return out

    def progress(self):
        """What the job reported last (iter, time, speed, bodies, stopAtIter...), or {}."""
        if not self.statusPath:
            return {}
        try:
            with open(self.statusPath) as f:
                data = json.load(f)
            return data if isinstance(data, dict) else {}
        except (OSError, ValueError):
            return {}


def plotPathForLog(logPath):
    """``job.py.first.log`` -> ``job.py.first.png`` (``.log.N`` -> ``.N.png``; otherwise ``.png`` added)."""
    m = re.match(r'^(.*)\.log(\.\d+)?$', logPath)
    if m:
        return m.group(1) + (m.group(2) or '') + '.png'
    return logPath + '.png'


def logName(fmt, script, lineNo, description):
    """The log file of a job: in *fmt*, ``$`` is the script's name, ``%`` the line number and ``@``
    the description (a ``/`` in it becomes ``_``)."""
    out = []
    for c in fmt:
        if c == '$':
            out.append(os.path.basename(script))
        elif c == '%':
            out.append(str(lineNo))
        elif c == '@':
            out.append(_safeName(description))
        else:
            out.append(c)
    return ''.join(out)


def findLauncher(batchScript):
    """The launcher a batch script runs its jobs with: the file next to it whose name is the batch
    script's without ``-batch`` (``yade-batch`` -> ``yade``, ``yade-fast-batch`` -> ``yade-fast``; the
    name it was called by first, then the name of the file a link points to), else ``yade`` next to it;
    None if there is none."""
    called = os.path.abspath(batchScript)
    real = os.path.realpath(batchScript)
    candidates = []
    for path in (called, real):
        name = os.path.basename(path)
        if name.endswith('-batch'):
            candidates.append(os.path.join(os.path.dirname(path), name[:-len('-batch')]))
    candidates += [os.path.join(os.path.dirname(called), 'yade'), os.path.join(os.path.dirname(real), 'yade')]
    for c in candidates:
        if os.path.isfile(c):
            return c
    return None

# ====================================================================== the batch


class Batch:
    """The jobs of a batch and the loop that runs them on ``cores`` cores."""

    def __init__(self, jobs, cores, nice=10, cpuAffinity=False, plotPeriod=60., out=None, scriptName='',
                 tableName='', statusDir=None):
        self.jobs = jobs
        self.cores = cores
        self.nice = nice
        self.cpuAffinity = cpuAffinity
        self.plotPeriod = plotPeriod
        self.out = out or sys.stdout
        self.scriptName, self.tableName = scriptName, tableName
        self.started = self.finished = None
        self.lock = threading.RLock()
        self.interrupted = False
        self.statusDir = statusDir
        try:
            allowed = sorted(os.sched_getaffinity(0))
        except (AttributeError, OSError):
            allowed = []
        # with no more cores than the process may use, each running job gets CPUs of its own (a job with
        # several threads is bound to them, so that two jobs never pin their threads to the same CPUs)
        self.freeCpus = allowed[:cores] if 0 < cores <= len(allowed) else None
        self.usedCores = 0

    def say(self, text):
        with self.lock:
            try:
                self.out.write(text + '\n')
                self.out.flush()
            except (OSError, ValueError):
                pass

    # -------------------------------------------------------------- states
    def counts(self):
        c = {s: 0 for s in (Job.PENDING, Job.RUNNING, Job.DONE, Job.FAILED, Job.CANCELLED)}
        for j in self.jobs:
            c[j.state] += 1
        return c

    def failed(self):
        return [j for j in self.jobs if j.state in (Job.FAILED, Job.CANCELLED)]

    # -------------------------------------------------------------- running
    def _environment(self, job):
        env = dict(os.environ)
        env[BATCH_ENV] = job.tableLine
        env['OMP_NUM_THREADS'] = str(job.threads)
        env['PYTHONUNBUFFERED'] = '1'  # the log (and the page's tail of it) follows the job
        for k in ('DISPLAY', 'WAYLAND_DISPLAY'):
            env.pop(k, None)
        env[PLOT_ENV] = os.path.abspath(job.plotPath)
        env[PLOT_PERIOD_ENV] = repr(float(self.plotPeriod))
        if job.statusPath:
            env[STATUS_ENV] = job.statusPath
        else:
            env.pop(STATUS_ENV, None)
        if job.threads > 1 and job.cpus is None:
            env['YADE_NO_PINNING'] = '1'  # more jobs than CPUs: let the system place the threads
        env.update(job.env)
        return env

    def _start(self, job):
        job.threads = max(1, job.threads)
        if self.freeCpus is not None:
            job.cpus = self.freeCpus[:job.threads]
            del self.freeCpus[:job.threads]
        self.usedCores += job.threads
        if self.statusDir:
            job.statusPath = os.path.join(self.statusDir, 'job%d.json' % job.index)
        job.started = time.time()
        job.state = Job.RUNNING
        logDir = os.path.dirname(job.logPath)
        try:
            if logDir:
                os.makedirs(logDir, exist_ok=True)
            for stale in [job.plotPath] + job.plotFiles():  # a figure left by an earlier batch is not this job's
                try:
                    os.remove(stale)
                except OSError:
                    pass
            with open(job.logPath, 'wb') as log:
                job.proc = subprocess.Popen(job.command(self.nice), stdin=subprocess.DEVNULL, stdout=log,
                                            stderr=subprocess.STDOUT, env=self._environment(job),
                                            start_new_session=True)
        except OSError as e:
            job.proc = None
            job.reason = 'could not start: %s' % (e.strerror or e)
            try:
                with open(job.logPath, 'a') as log:
                    log.write('yade-batch: %s\n' % job.reason)
            except OSError:
                pass
            self._finish(job, None)
            return
        if job.cpus and (job.threads > 1 or self.cpuAffinity):
            try:
                os.sched_setaffinity(job.proc.pid, job.cpus)
            except OSError:
                pass
        self.say('#%d (%s) started on %s' % (job.index, job.name, time.ctime(job.started)))

    def _finish(self, job, returncode):
        job.finished = time.time()
        job.returncode = returncode
        job.state = Job.DONE if returncode == 0 and not job.reason else Job.FAILED
        if job.cpus is not None and self.freeCpus is not None:
            self.freeCpus = sorted(self.freeCpus + job.cpus)
        self.usedCores -= job.threads
        self._appendSummary(job)
        word = 'done   ' if job.state == Job.DONE else 'FAILED '
        self.say('#%d (%s) %s (%s), duration %s, log %s' % (job.index, job.name, word, job.outcome(),
                                                           _hms(job.elapsed()), job.logPath))

    def _appendSummary(self, job):
        try:
            with open(job.logPath, 'a') as log:
                log.write('\n=================== JOB SUMMARY ================\n')
                log.write('id      : %s\n' % job.description)
                log.write('line    : %s\n' % job.tableLine)
                log.write('status  : %s (%s)\n' % (job.outcome(), 'OK' if job.state == Job.DONE else 'FAILED'))
                log.write('duration: %s\n' % _hms(job.elapsed()))
                log.write('command : %s\n' % job.shellCommand(self.nice))
                log.write('started : %s\n' % (time.ctime(job.started) if job.started else '-'))
                log.write('finished: %s\n' % time.ctime(job.finished))
        except OSError:
            pass

    def _fits(self, job):
        return job.threads <= self.cores - self.usedCores

    def run(self, poll=0.1):
        """Run all pending jobs; return when every job has finished (or the batch was interrupted)."""
        self.started = time.time()
        try:
            while True:
                with self.lock:
                    for job in self.jobs:
                        if job.state == Job.RUNNING and job.proc is not None:
                            rc = job.proc.poll()
                            if rc is not None:
                                self._finish(job, rc)
                    for job in self.jobs:
                        if job.state == Job.PENDING and self._fits(job):
                            self._start(job)
                    if not any(j.state in (Job.PENDING, Job.RUNNING) for j in self.jobs):
                        break
                time.sleep(poll)
        except KeyboardInterrupt:
            try:  # a second Ctrl-C must not leave the jobs running
                previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
            except ValueError:  # (not the main thread)
                previous = None
            try:
                self.interrupt()
            finally:
                if previous is not None:
                    signal.signal(signal.SIGINT, previous)
        self.finished = time.time()

    def interrupt(self):
        """Stop the running jobs (SIGTERM to each job's process group, SIGKILL after 5 s) and cancel the
        pending ones."""
        with self.lock:
            self.interrupted = True
            running = [j for j in self.jobs if j.state == Job.RUNNING and j.proc is not None]
            for j in running:
                _signalGroup(j.proc, signal.SIGTERM)
            deadline = time.time() + 5
            for j in running:
                try:
                    j.proc.wait(max(0.1, deadline - time.time()))
                except subprocess.TimeoutExpired:
                    _signalGroup(j.proc, signal.SIGKILL)
                    j.proc.wait()
                j.reason = 'interrupted (%s)' % ('killed by %s' % _signalName(-j.proc.returncode)
                                                 if j.proc.returncode < 0 else 'exit status %d' % j.proc.returncode)
                self._finish(j, j.proc.returncode)
            for j in self.jobs:
                if j.state == Job.PENDING:
                    j.state = Job.CANCELLED
                    j.reason = 'not run (batch interrupted)'

    # -------------------------------------------------------------- reports
    def summary(self):
        """The lines printed at the end: one per job, then the table lines of the failed jobs."""
        c = self.counts()
        total = (self.finished or time.time()) - (self.started or time.time())
        lines = ['Summary: %d job%s in %s: %d ok, %d failed%s' % (
            len(self.jobs), '' if len(self.jobs) == 1 else 's', _hms(total), c[Job.DONE], c[Job.FAILED],
            ', %d not run' % c[Job.CANCELLED] if c[Job.CANCELLED] else '')]
        wName = max([len(j.name) for j in self.jobs] + [11])
        lines.append('  %-4s %-6s %-*s %-9s %-22s %-9s %s' % ('#', 'line', wName, 'description', 'state', 'exit',
                                                            'time', 'log'))
        for j in self.jobs:
            state = {Job.DONE: 'ok'}.get(j.state, j.state.upper() if j.state != Job.CANCELLED else 'not run')
            lines.append('  %-4d %-6d %-*s %-9s %-22s %-9s %s' % (j.index, j.line.lineNo, wName, j.name, state,
                                                                j.outcome(), _hms(j.elapsed()), j.logPath))
        bad = self.failed()
        if bad:
            lines.append('Failed table lines (%s):' % self.tableName)
            for j in bad:
                lines.append('  line %d (%s): %s  -> %s, log %s' % (j.line.lineNo, j.name, j.line.text.strip(),
                                                                  j.outcome(), j.logPath))
        return lines

    def timingReport(self, command=''):
        """With ``--timing``: per table line, the count, mean, deviation, relative deviation, minimum and
        maximum of the successful jobs' durations, then the line's values."""
        names = None
        byLine = {}
        for j in self.jobs:
            byLine.setdefault(j.line.lineNo, (j.line, []))
            if j.state == Job.DONE:
                byLine[j.line.lineNo][1].append(j.elapsed())
            names = j.line.names
        out = ['## timing data, written %s with arguments' % time.ctime(), '##    %s' % command, '##',
               '## line\tcount\tavg\tdev\trelDev\tmin\tmax\t|\t' + '\t'.join(names or [])]
        for lineNo, (line, ts) in byLine.items():
            if ts:
                avg = sum(ts) / len(ts)
                dev = math.sqrt(sum((t - avg) ** 2 for t in ts) / len(ts))
                nums = '%d\t%.2f\t%.2f\t%.4f\t%.2f\t%.2f' % (len(ts), avg, dev, dev / avg if avg else 0., min(ts), max(ts))
            else:
                nums = '0\tnan\tnan\tnan\tnan\tnan'
            out.append('%d\t%s\t|\t%s' % (lineNo, nums, '\t'.join(line.values)))
        return out

    def snapshot(self):
        """The batch's state as plain data (the page and ``/status.json``)."""
        now = time.time()
        with self.lock:
            jobs = []
            for j in self.jobs:
                jobs.append({'id': j.index, 'line': j.line.lineNo, 'description': j.description, 'name': j.name,
                             'state': j.state, 'outcome': j.outcome(), 'returncode': j.returncode,
                             'threads': j.threads, 'elapsed': j.elapsed(now), 'log': j.logPath,
                             'plots': [os.path.basename(p) for p in j.plotFiles()],
                             'params': j.line.params(), 'progress': j.progress() if j.state == Job.RUNNING else {},
                             'command': j.shellCommand(self.nice)})
            return {'script': self.scriptName, 'table': self.tableName, 'cores': self.cores, 'usedCores': self.usedCores,
                    'started': self.started, 'elapsed': (self.finished or now) - self.started if self.started else 0,
                    'finished': self.finished is not None, 'counts': self.counts(), 'jobs': jobs}


def _signalGroup(proc, sig):
    try:
        os.killpg(proc.pid, sig)
    except OSError:
        try:
            proc.send_signal(sig)
        except OSError:
            pass

# ====================================================================== the status page


def _e(value):
    return html.escape(str(value), quote=True)


def _tail(path, lines=12, maxBytes=16384):
    try:
        with open(path, 'rb') as f:
            f.seek(0, os.SEEK_END)
            size = f.tell()
            f.seek(max(0, size - maxBytes))
            data = f.read()
    except OSError:
        return ''
    text = data.decode('utf-8', errors='replace').replace('\r', '\n')
    return '\n'.join(text.splitlines()[-lines:])


def _progressText(p):
    if not p:
        return ''
    parts = []
    if 'iter' in p:
        s = 'step %s' % p['iter']
        if p.get('stopAtIter') and p['stopAtIter'] > 0:
            s += ' of %s (%.0f %%)' % (p['stopAtIter'], 100. * p['iter'] / p['stopAtIter'])
        parts.append(s)
    if 'time' in p:
        parts.append('t = %.4g s' % p['time'])
    if p.get('running') and p.get('speed') is not None:
        parts.append('%.0f steps/s' % p['speed'])
    if 'bodies' in p:
        parts.append('%s bodies' % p['bodies'])
    return ', '.join(parts)


_STYLE = """body{font-family:sans-serif;margin:1em}table{border-collapse:collapse}
td,th{border:1px solid #999;padding:3px 6px;vertical-align:top;text-align:left}
.pending{background:#eee}.running{background:#ffd}.done{background:#dfd}.failed,.cancelled{background:#fdd}
pre{margin:2px 0;max-width:60em;max-height:14em;overflow:auto;font-size:85%;white-space:pre-wrap}
img{width:320px}"""


def renderPage(batch, refresh=10, host=''):
    """The HTML overview of the batch: every value shown comes through html.escape."""
    s = batch.snapshot()
    c = s['counts']
    title = 'yade-batch: %s with %s' % (s['script'], s['table'])
    out = ['<!DOCTYPE html>', '<html><head><meta charset="utf-8">']
    if refresh and refresh > 0:
        out.append('<meta http-equiv="refresh" content="%d">' % int(refresh))
    out.append('<title>%s</title><style>%s</style></head><body>' % (_e(title), _STYLE))
    out.append('<h1>%s</h1>' % _e(title))
    out.append('<p>%s %s, %s; %d cores, %d in use.</p>' % (
        'Finished after' if s['finished'] else 'Running for', _hms(s['elapsed']),
        _e('started ' + time.ctime(s['started'])) if s['started'] else 'not started',
        s['cores'], s['usedCores']))
    out.append('<p id="counts"><b>%d</b> jobs: %s</p>' % (len(s['jobs']), ', '.join(
        '<span class="%s">%d %s</span>' % (k, v, k) for k, v in c.items() if v or k != Job.CANCELLED)))
    out.append('<table><tr><th>#</th><th>line</th><th>description</th><th>state</th><th>progress</th><th>time</th>'
               '<th>threads</th><th>log</th><th>plots</th></tr>')
    for j in s['jobs']:
        i = j['id']
        state = j['state'] + (' (%s)' % j['outcome'] if j['outcome'] else '')
        params = ' '.join('%s=%s' % (n, v) for n, v in j['params'])
        plots = ''.join('<a href="/jobs/%d/plot/%d"><img src="/jobs/%d/plot/%d" alt="%s"></a>' % (i, k, i, k, _e(p))
                        for k, p in enumerate(j['plots'], start=1))
        out.append('<tr class="%s" id="job%d"><td>%d</td><td>%d</td><td class="description">%s<br><small>%s</small></td>'
                   '<td class="state">%s</td><td>%s</td><td>%s</td><td>%d</td>'
                   '<td><a href="/jobs/%d/log">%s</a><pre>%s</pre></td><td>%s</td></tr>' % (
                       _e(j['state']), i, i, j['line'], _e(j['description']), _e(params), _e(state),
                       _e(_progressText(j['progress'])), _hms(j['elapsed']), j['threads'], i, _e(j['log']),
                       _e(_tail(j['log'])) if j['state'] != Job.PENDING else '', plots))
    out.append('</table>')
    out.append('<p><small>Read-only page of yade-batch (pid %d); <a href="/status.json">status.json</a>.</small></p>'
               % os.getpid())
    out.append('</body></html>')
    return '\n'.join(out)


class _Handler(http.server.BaseHTTPRequestHandler):
    """GET and HEAD of the overview, the jobs' logs and plots, and status.json; nothing else. Files are
    found through the jobs (by number), never through a path from the request."""

    server_version = 'yade-batch'
    sys_version = ''
    protocol_version = 'HTTP/1.0'
    _PATH = re.compile(r'^/jobs/(\d{1,9})/(log|plot/(\d{1,3}))$')

    def version_string(self):
        return 'yade-batch'

    def log_message(self, format, *args):
        pass  # the batch's own output stays readable

    def _hostAllowed(self):
        if not self.server.loopbackOnly:
            return True
        host = (self.headers.get('Host') or '').strip().lower()
        if not host:
            return True
        if host.startswith('['):
            name = host[:host.find(']') + 1] if ']' in host else host
        else:
            name = host.rsplit(':', 1)[0] if ':' in host else host
        return name in ('localhost', '127.0.0.1', '[::1]') or name.startswith('127.')

    def _headers(self, code, ctype, length, extra=()):
        self.send_response(code)
        self.send_header('Content-Type', ctype)
        self.send_header('Content-Length', str(length))
        self.send_header('Cache-Control', 'no-store')
        self.send_header('X-Content-Type-Options', 'nosniff')
        self.send_header('X-Frame-Options', 'DENY')
        self.send_header('Referrer-Policy', 'no-referrer')
        self.send_header('Content-Security-Policy', "default-src 'none'; img-src 'self'; style-src 'unsafe-inline'")
        for k, v in extra:
            self.send_header(k, v)
        self.end_headers()

    def _send(self, code, ctype, body, head, extra=()):
        self._headers(code, ctype, len(body), extra)
        if not head:
            self.wfile.write(body)

    def _error(self, code, text, head, extra=()):
        self._send(code, 'text/plain; charset=utf-8', (text + '\n').encode(), head, extra)

    def _file(self, path, ctype, head):
        try:
            f = open(path, 'rb')
        except OSError:
            return self._error(404, 'not written (yet)', head)
        with f:
            size = os.fstat(f.fileno()).st_size
            self._headers(200, ctype, size)
            if not head:
                remaining = size
                while remaining > 0:
                    chunk = f.read(min(65536, remaining))
                    if not chunk:
                        break
                    self.wfile.write(chunk)
                    remaining -= len(chunk)

    def _serve(self, head):
        if not self._hostAllowed():
            return self._error(403, 'forbidden: this page answers to localhost only', head)
        batch = self.server.batch
        path = urllib.parse.urlsplit(self.path).path
        if path in ('/', '/index.html'):
            body = renderPage(batch, self.server.refresh).encode('utf-8')
            return self._send(200, 'text/html; charset=utf-8', body, head)
        if path == '/status.json':
            return self._send(200, 'application/json', json.dumps(batch.snapshot()).encode('utf-8'), head)
        m = self._PATH.match(path)
        if m:
            i = int(m.group(1))
            if i < len(batch.jobs):
                job = batch.jobs[i]
                if m.group(2) == 'log':
                    return self._file(job.logPath, 'text/plain; charset=utf-8', head)
                k = int(m.group(3))
                plots = job.plotFiles()
                if 1 <= k <= len(plots):
                    return self._file(plots[k - 1], 'image/png', head)
        return self._error(404, 'not found', head)

    def do_GET(self):
        self._serve(False)

    def do_HEAD(self):
        self._serve(True)

    def _readOnly(self):
        self._error(405, 'method not allowed: this page is read-only', False, [('Allow', 'GET, HEAD')])

    do_POST = do_PUT = do_DELETE = do_PATCH = do_OPTIONS = do_TRACE = do_CONNECT = _readOnly


class StatusServer(http.server.ThreadingHTTPServer):
    """The batch's status page (Python's http.server, one thread per request)."""

    daemon_threads = True

    def __init__(self, address, batch, refresh=10):
        self.batch, self.refresh = batch, refresh
        self.loopbackOnly = _isLoopback(address[0])
        if ':' in address[0]:
            self.address_family = socket.AF_INET6
        super().__init__(address, _Handler)


def _isLoopback(address):
    return address in ('localhost', '::1') or address.startswith('127.')


def startStatusServer(batch, address='127.0.0.1', port=DEFAULT_PORT, refresh=10, out=None, tries=PORT_TRIES):
    """Start the page on *address*, on *port* or the next free one (0: any free port); return the
    server (serving in a background thread) or None, saying why, when no port could be had."""
    out = out or sys.stdout
    last = None
    for p in ([0] if port == 0 else range(port, min(port + tries, 65536))):
        try:
            server = StatusServer((address, p), batch, refresh)
        except OSError as e:
            last = e
            if e.errno == errno.EADDRINUSE:
                out.write('yade-batch: port %d is already in use, trying %d\n' % (p, p + 1))
                continue
            break
        threading.Thread(target=server.serve_forever, name='yade-batch-http', daemon=True).start()
        return server
    out.write('yade-batch: no status page (cannot listen on %s port %d%s: %s)\n'
              % (address, port, '' if port == 0 else ' to %d' % min(port + tries - 1, 65535),
                 getattr(last, 'strerror', None) or last))
    return None


def pageAddress(server, address):
    port = server.server_address[1]
    if _isLoopback(address):
        return 'http://localhost:%d' % port
    if address in ('0.0.0.0', '::', ''):
        return 'http://%s:%d' % (socket.gethostname(), port)
    return 'http://%s:%d' % (('[%s]' % address) if ':' in address else address, port)

# ====================================================================== the command line


def _defaultCores():
    try:
        n = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        n = os.cpu_count() or 1
    try:
        omp = int(os.environ.get('OMP_NUM_THREADS', ''))
        if omp > 0:
            n = min(n, omp)
    except ValueError:
        pass
    return max(1, n)


def makeParser(prog='yade-batch', defaultCores=None):
    cores = defaultCores or _defaultCores()
    p = argparse.ArgumentParser(
        prog=prog, usage='%(prog)s [options] TABLE [SCRIPT.py]',
        description='Run SCRIPT.py once per line of the parameter table TABLE (see doc/batch.md), with a '
                    'read-only status page on http://localhost:%d.' % DEFAULT_PORT,
        epilog='Each job runs the launcher (yade -n -x) with %s=TABLE:LINE in its environment, so that '
               'readParamsFromTable() returns that line\'s values. Exit status: 0 when every job succeeded, 1 when '
               'a job failed, 2 on bad arguments, 130 when interrupted.' % BATCH_ENV)
    p.add_argument('table', metavar='TABLE', help='the parameter table')
    p.add_argument('script', metavar='SCRIPT.py', nargs='?',
                   help='the simulation script (may be left out when the table has a !SCRIPT column)')
    p.add_argument('-j', '--jobs', type=int, default=cores, metavar='NUM',
                   help='cores to use in all (the jobs running at once use at most this many threads in all; '
                        'default: %d, the CPUs available, limited by OMP_NUM_THREADS if set)' % cores)
    p.add_argument('--job-threads', type=int, default=1, metavar='NUM',
                   help='threads of each job (default 1); a !THREADS or !OMP_NUM_THREADS column sets them per line')
    p.add_argument('-l', '--lines', metavar='LIST',
                   help='the table lines to run, as numbered in an editor, e.g. 2,4-6 (default: all)')
    p.add_argument('--log', default=DEFAULT_LOG, metavar='FORMAT',
                   help="log file of each job: $ is replaced by the script's name, %% by the line number, @ by the "
                        "description (default: " + DEFAULT_LOG.replace('%', '%%') + ", e.g. job.py.first.log)")
    p.add_argument('--timing', type=int, default=0, metavar='COUNT',
                   help='run each line COUNT times (a !COUNT column overrides it) and print the mean, deviation, '
                        'minimum and maximum of the durations per line')
    p.add_argument('--timing-output', metavar='FILE', help='with --timing, write the durations table to FILE')
    p.add_argument('--nice', type=int, default=10, metavar='NICE', help='niceness added to the jobs (default 10)')
    p.add_argument('--executable', metavar='FILE',
                   help='the program each job runs (default: the yade launcher next to yade-batch); '
                        'a !EXEC column sets it per line')
    p.add_argument('--cpu-affinity', action='store_true',
                   help='bind every job to CPUs of its own (jobs with several threads always are, when -j does '
                        'not exceed the CPUs available)')
    p.add_argument('--dry-run', action='store_true', help='print the jobs and exit without running them')
    p.add_argument('--port', type=int, default=DEFAULT_PORT,
                   help='port of the status page (default %d; the next free one if it is taken; 0: any free port)'
                        % DEFAULT_PORT)
    p.add_argument('--address', default='127.0.0.1',
                   help='address the status page listens on (default 127.0.0.1: this machine only; 0.0.0.0 '
                        'opens it to the network)')
    p.add_argument('--no-http', action='store_true', help='no status page')
    p.add_argument('--http-wait', action='store_true',
                   help='keep serving the status page after the jobs have finished, until Ctrl-C')
    p.add_argument('--refresh', type=float, default=10, metavar='TIME',
                   help='seconds between reloads of the status page in the browser (default 10; 0: never)')
    p.add_argument('--plot-update', type=float, default=60, metavar='TIME',
                   help='seconds between updates of the PNG of a job\'s yade.plot figure while it runs '
                        '(default 60; it is also written by plot.plot() and when the job ends)')
    return p


def _fail(parser, message):
    parser.exit(2, '%s: error: %s\n' % (parser.prog, message))


def _positiveInt(text, what):
    try:
        v = int(text)
    except ValueError:
        raise ValueError('%s must be a whole number, got %r' % (what, text))
    if v < 1:
        raise ValueError('%s must be at least 1, got %d' % (what, v))
    return v


def buildJobs(opts, table, batchScript, parser=None):
    """The jobs of a batch from the parsed options and table (ValueError / TableError on bad input)."""
    if opts.lines:
        numbers = parseLineSpec(opts.lines)
        selected = [table.line(n) for n in numbers]
    else:
        if table.bad:
            n = min(table.bad)
            raise TableError('%s, line %d: %s (use --lines to run the other lines)' % (table.fileName, n, table.bad[n]))
        selected = list(table.lines.values())
    if not selected:
        raise TableError('%s has no parameter lines (only the column names)' % table.fileName)
    launcher = None
    jobs = []
    logs = {}
    for line in selected:
        script = line.special('SCRIPT') or opts.script
        if not script:
            raise ValueError('no script: give SCRIPT.py after the table, or a !SCRIPT column in it')
        if not os.path.isfile(script):
            raise ValueError('script %s does not exist%s' % (script, ' (line %d, !SCRIPT)' % line.lineNo
                                                             if line.special('SCRIPT') else ''))
        threads = opts.job_threads
        t = line.special('THREADS') or line.special('OMP_NUM_THREADS')
        if t is not None:
            threads = _positiveInt(t, '%s line %d: !THREADS' % (table.fileName, line.lineNo))
        if threads > opts.jobs:
            sys.stderr.write('yade-batch: line %d asks for %d threads, more than the %d cores (-j): it gets %d\n'
                             % (line.lineNo, threads, opts.jobs, opts.jobs))
            threads = opts.jobs
        exe = line.special('EXEC') or opts.executable
        if not exe:
            if launcher is None:
                launcher = findLauncher(batchScript)
            if launcher is None:
                raise ValueError('cannot find the yade launcher next to %s; name one with --executable' % batchScript)
            exe = launcher
        elif not os.path.isfile(exe):
            raise ValueError('executable %s does not exist' % exe)
        else:
            exe = os.path.abspath(exe)
        count = opts.timing
        c = line.special('COUNT')
        if c is not None and opts.timing:
            count = _positiveInt(c, '%s line %d: !COUNT' % (table.fileName, line.lineNo))
        repeats = [None] if not opts.timing else list(range(count))
        for r in repeats:
            log = logName(opts.log, script, line.lineNo, line.description)
            if r is not None:
                log += '.%d' % r
            if log in logs:  # two lines with the same description: keep both logs
                log = logName(opts.log, script, line.lineNo, line.description + '.l%d' % line.lineNo)
                if r is not None:
                    log += '.%d' % r
            logs[log] = line.lineNo
            jobs.append(Job(len(jobs), line, table.fileName, script, threads, exe, log, repeat=r))
    return jobs


def main(argv=None, batchScript=None, prog=None, out=None):
    """``yade-batch`` (argv without the program name); return the exit status."""
    out = out or sys.stdout
    batchScript = batchScript or sys.argv[0]
    parser = makeParser(prog or os.path.basename(batchScript) or 'yade-batch')
    opts = parser.parse_args(argv)
    if opts.jobs < 1:
        _fail(parser, '-j/--jobs must be at least 1')
    if opts.job_threads < 1:
        _fail(parser, '--job-threads must be at least 1')
    if opts.timing < 0:
        _fail(parser, '--timing must be at least 1')
    if not (0 <= opts.port <= 65535):
        _fail(parser, '--port must be between 0 and 65535')
    if not any(c in opts.log for c in '$%@'):
        _fail(parser, '--log %s must contain $, %% or @ (else all jobs would write the same log)' % opts.log)
    if opts.table.endswith('.py') and opts.script is None:
        _fail(parser, 'give the parameter table first, then the script (%s looks like a script)' % opts.table)
    try:
        table = readTable(opts.table)
        jobs = buildJobs(opts, table, batchScript, parser)
    except (ValueError, TableError) as e:
        _fail(parser, str(e))

    scripts = sorted({j.script for j in jobs})
    say = lambda text: (out.write(text + '\n'), out.flush())  # noqa: E731
    say('Will run %s with %s, nice %d, on %d core%s.' % (', '.join(scripts), ', '.join(sorted({j.executable for j in jobs})),
                                                        opts.nice, opts.jobs, '' if opts.jobs == 1 else 's'))
    say('Will use table %s, with parameter lines %s.' % (opts.table, _lineList(table.lines)))
    lineNos = []
    for j in jobs:
        if j.line.lineNo not in lineNos:
            lineNos.append(j.line.lineNo)
    say('Will use lines %s.' % ', '.join('%d (%s)' % (n, table.lines[n].description) for n in lineNos))
    say('Jobs:')
    for j in jobs:
        say('   #%d (%s): %s' % (j.index, j.name, j.shellCommand(opts.nice)))
    if opts.dry_run:
        return 0

    import tempfile
    statusDir = tempfile.mkdtemp(prefix='yade-batch-')
    batch = Batch(jobs, opts.jobs, nice=opts.nice, cpuAffinity=opts.cpu_affinity, plotPeriod=opts.plot_update,
                  out=out, scriptName=', '.join(scripts), tableName=opts.table, statusDir=statusDir)
    server = None
    if not opts.no_http:
        server = startStatusServer(batch, opts.address, opts.port, opts.refresh, out=out)
        if server is not None:
            say('%s shows batch summary' % pageAddress(server, opts.address))

    def terminate(signum, frame):
        raise KeyboardInterrupt
    previous = signal.signal(signal.SIGTERM, terminate)
    try:
        batch.run()
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # (the summary is printed whole)
        for line in batch.summary():
            say(line)
        if opts.timing:
            report = batch.timingReport(' '.join(shlex.quote(a) for a in [batchScript] + list(argv or sys.argv[1:])))
            if opts.timing_output:
                with open(opts.timing_output, 'w') as f:
                    f.write('\n'.join(report) + '\n')
                say('Timing data written to %s' % opts.timing_output)
            else:
                for line in report:
                    say(line)
        status = 130 if batch.interrupted else (1 if batch.failed() else 0)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        if server is not None and opts.http_wait and not batch.interrupted:
            say('All jobs finished; %s keeps serving until Ctrl-C.' % pageAddress(server, opts.address))
            try:
                while True:
                    time.sleep(3600)
            except KeyboardInterrupt:
                pass
        say('Bye.')
        return status
    finally:
        signal.signal(signal.SIGTERM, previous)
        signal.signal(signal.SIGINT, signal.default_int_handler)
        if server is not None:
            server.shutdown()
            server.server_close()
        import shutil
        shutil.rmtree(statusDir, ignore_errors=True)

# ====================================================================== inside a job


_report = {'thread': None, 'stop': None}


def _jobState():
    from yade import O  # (only in a job: the engine is loaded there)
    d = {'wall': time.time()}
    for key in ('iter', 'time', 'speed', 'stopAtIter', 'stopAtTime', 'running'):
        try:
            v = getattr(O, key)
            if isinstance(v, float) and not math.isfinite(v):
                v = None
            d[key] = v
        except Exception:
            pass
    try:
        d['bodies'] = len(O.bodies)
    except Exception:
        pass
    return d


def _writeJobState(path):
    try:
        tmp = path + '.tmp'
        with open(tmp, 'w') as f:
            json.dump(_jobState(), f)
        os.replace(tmp, path)
    except Exception:
        pass


def startJobReport(period=None):
    """In a batch job (``YADE_BATCH_STATUS`` set), report the run's progress (step, time, speed, bodies) to
    the batch every *period* seconds from a background thread; does nothing elsewhere or when started
    already. Called by :func:`yade.params.readParamsFromTable`."""
    path = os.environ.get(STATUS_ENV)
    if not path or _report['thread'] is not None:
        return False
    if period is None:
        period = 1.0
    stop = threading.Event()

    def loop():
        while not stop.wait(period):
            _writeJobState(path)

    t = threading.Thread(target=loop, name='yade-batch-report', daemon=True)
    _report.update(thread=t, stop=stop)
    t.start()

    def finish():
        stop.set()
        t.join(2)
        _writeJobState(path)
    atexit.register(finish)
    return True
