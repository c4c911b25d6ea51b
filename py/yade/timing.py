"""Per-engine wall time: set ``O.timingEnabled=True``, run, then ``timing.stats()``.

Each engine accumulates ``execTime`` [ns] and ``execCount`` while O.timingEnabled is on (one clock
read before and after each engine run; nothing when it is off). InteractionLoop's time includes
its Ig2, Ip2 and Law2 functors.
"""

from yade import O


def _engineName(e):
    return e.label if e.label else type(e).__name__


def reset():
    """Zero execTime and execCount of every engine in O.engines."""
    for e in O.engines:
        e.execTime = 0
        e.execCount = 0


def runtime():
    """The engines' total measured time [ns]: the sum of execTime over O.engines (as in the reference)."""
    return sum(e.execTime for e in O.engines)


def stats(out=None):
    """Print a table (engine, runs, total time, time per run, share of the total); returns it as a
    list of (name, execCount, execTime [ns]) tuples."""
    import sys
    out = out or sys.stdout
    rows = [(_engineName(e), e.execCount, e.execTime) for e in O.engines]
    total = sum(r[2] for r in rows)
    if not O.timingEnabled and total == 0:
        out.write("timing: O.timingEnabled is False, nothing was measured\n")
    out.write("%-40s %10s %14s %12s %8s\n" % ("Name", "Count", "Time [us]", "per run [us]", "share"))
    for name, count, ns in rows:
        out.write("%-40s %10d %14.0f %12.2f %7.1f%%\n"
                  % (name, count, ns / 1e3, ns / 1e3 / count if count else 0, 100.0 * ns / total if total else 0))
    out.write("%-40s %10s %14.0f\n" % ("TOTAL", "", total / 1e3))
    return rows
