"""Storing and plotting history of simulation variables, as Yade's ``yade.plot``.

Typical use::

    from yade import plot
    plot.plots = {'t': ('Ek', None, 'unbalanced')}   # None: the following go on the right axis
    O.engines += [PyRunner(command='plot.addData(t=O.time, Ek=kineticEnergy(), unbalanced=unbalancedForce())',
                           iterPeriod=100)]
    ...
    plot.plot()                       # live window, or ./<script>.plot.png when there is no display
    plot.saveDataTxt('data.txt.bz2')  # all columns, bzip2-compressed
    plot.saveGnuplot('history')       # history.gnuplot + history.data.bz2, for gnuplot

* :data:`data` maps each variable name to the list of its values, one per :func:`addData` call;
  a variable missing in a call gets NaN, a new variable is back-filled with NaN.
* :data:`plots` maps each x-variable name to the y-variable names plotted against it; a y entry
  is a name, a ``(name, format)`` pair (matplotlib format such as ``'r-'``), ``None`` (the
  following entries go on an independently scaled right axis) or a callable returning names
  (called at plot time, e.g. ``O.energy.keys``). To plot against the same x variable in several
  subplots, append spaces to its name (``'t'``, ``'t '``, ...): names are stripped.
* :data:`labels` maps variable names to the text shown in axis labels and legends.

matplotlib is imported only when a figure is made; without a usable display (``yade -n``, no
``DISPLAY``) the non-interactive Agg backend is used and :func:`plot` writes a PNG file in the
current folder.

Other outputs: :func:`saveGnuplot` (a gnuplot script and its data), :func:`savePylab` (a
standalone Python script and its data), :func:`savePlotSequence` (PNG frames of the plots as the
data grow, for a movie). :func:`addAutoData` records the variables of :data:`plots`, each name
being evaluated as a Python expression.
"""
import bz2
import gzip
import math
import numbers
import os
import sys
import time

__all__ = ['data', 'plots', 'labels', 'legendLoc', 'autozoom', 'scientific', 'live', 'liveInterval',
           'componentSeparator', 'addData', 'addAutoData', 'reset', 'resetData', 'plot', 'saveDataTxt',
           'saveGnuplot', 'savePylab', 'savePlotSequence', 'splitData', 'reverseData']

nan = float('nan')

data = {}
"Recorded data: variable name -> list of values (all lists have the same length)."
plots = {}
"What to plot: x-variable name -> sequence of y entries (see the module documentation)."
labels = {}
"Text used in axis labels and legends instead of variable names (name -> label)."
legendLoc = ('upper left', 'upper right')
"Location of the legend of the left and right axes (matplotlib ``loc`` values)."
autozoom = True
"Rescale the axes when a live plot is updated."
scientific = True
"Use scientific notation for large/small tick labels."
live = True
"Update a figure shown on screen periodically while it is open."
liveInterval = 1.
"Seconds between updates of a live figure."
componentSeparator = '_'
"Separator between a variable name and the component suffix for vector/matrix values (``v_x``)."

_vectorTypes = None


def _componentTypes():
    """(type, suffixes) for the vector and matrix types whose values addData splits in components."""
    global _vectorTypes
    if _vectorTypes is None:
        xyz = 'xyz'
        table = [('Vector2', [(i, xyz[i]) for i in range(2)]),
                 ('Vector2i', [(i, xyz[i]) for i in range(2)]),
                 ('Vector3', [(i, xyz[i]) for i in range(3)]),
                 ('Vector3i', [(i, xyz[i]) for i in range(3)]),
                 ('Matrix3', [((i, j), xyz[i] + xyz[j]) for i in range(3) for j in range(3)])]
        found = []
        try:
            from . import _yade
        except ImportError:
            _yade = None
        for name, suffixes in table:
            t = getattr(_yade, name, None)
            if isinstance(t, type):
                found.append((t, suffixes))
        _vectorTypes = found
    return _vectorTypes


def _isNumber(v):
    if isinstance(v, (str, bytes)):
        return False
    if isinstance(v, numbers.Number):
        return True
    if hasattr(v, '__len__') or hasattr(v, '__iter__'):
        return getattr(v, 'shape', None) == ()  # a 0-d numpy array is a number
    return hasattr(v, '__float__')


def _expand(name, value, out):
    for t, suffixes in _componentTypes():
        if isinstance(value, t):
            for idx, suf in suffixes:
                out[name + componentSeparator + suf] = value[idx]
            return
    if not _isNumber(value):
        raise ValueError('plot.addData given unhandled sequence type (%s=%r is a %s, must be number or '
                         'Vector2/Vector3/Matrix3)' % (name, value, type(value).__name__))
    out[name] = value


def addData(*d_in, **kw):
    """Append one record to :data:`data`: ``addData(name1=value1, name2=value2, ...)``.

    Dictionaries may also be given as positional arguments (``addData({'a': 1}, b=2)``).
    Variables not given in this call get NaN; a variable seen for the first time is back-filled
    with NaN for the earlier records, so all columns keep the same length. Vector2, Vector3 and
    Matrix3 values are stored as one column per component (``v_x``, ``v_y``, ``v_z``; ``m_xx``, ...).
    Strings and other sequences raise ValueError (and nothing is added).

    >>> from yade import plot
    >>> plot.resetData()
    >>> plot.addData(a=1)
    >>> plot.addData(b=2)
    >>> plot.addData(a=3, b=4)
    >>> plot.data
    {'a': [1, nan, 3], 'b': [nan, 2, 4]}
    """
    given = {}
    for d in d_in:
        if not isinstance(d, dict):
            raise TypeError('plot.addData: positional arguments must be dicts, not %s' % type(d).__name__)
        given.update(d)
    given.update(kw)
    row = {}
    for name, value in given.items():
        if not isinstance(name, str):
            raise TypeError('plot.addData: variable names must be strings, got %r' % (name,))
        _expand(name, value, row)
    n = max((len(v) for v in data.values()), default=0)
    for name in row:
        if name not in data:
            data[name] = [nan] * n
    for name, col in data.items():
        # a column shorter than the others (edited by hand) is padded first
        if len(col) < n:
            col.extend([nan] * (n - len(col)))
        col.append(row.get(name, nan))
    if _batch['path']:
        _batchUpdate()


_autoNamespace = {}


def _evalNamespace():
    """Globals for addAutoData: yade's names, then the running script's (__main__) on top."""
    if not _autoNamespace:
        import yade
        _autoNamespace.update({k: getattr(yade, k) for k in dir(yade) if not k.startswith('_')})
        try:
            from yade import utils
            _autoNamespace.update({k: getattr(utils, k) for k in dir(utils) if not k.startswith('_')})
        except ImportError:
            pass
    ns = dict(_autoNamespace)
    main = sys.modules.get('__main__')
    if main is not None:
        ns.update(vars(main))
    return ns


def _plotNames():
    """The variable names of :data:`plots` (x names, then y names), each once, in order."""
    names = []
    for _, x, left, right in _specs():
        for name in [x] + [y for y, _ in left + right]:
            if name not in names:
                names.append(name)
    return names


def addAutoData():
    """Append one record holding every variable of :data:`plots`, each name evaluated as a Python
    expression (``plot.plots = {'O.iter': ('O.time', 'unbalancedForce()')}``) in the running
    script's namespace (with yade's names); a name whose evaluation raises is left out of the
    record (NaN) with a warning."""
    ns = _evalNamespace()
    record = {}
    for name in _plotNames():
        try:
            record[name] = eval(name, ns)
        except Exception as e:
            print('plot.addAutoData: cannot evaluate %r (%s: %s); left out' % (name, type(e).__name__, e))
    bad = []
    for name, value in record.items():  # (a value addData would refuse is left out too)
        try:
            _expand(name, value, {})
        except ValueError:
            bad.append(name)
            print('plot.addAutoData: %r is a %s, not a number; left out' % (name, type(value).__name__))
    for name in bad:
        del record[name]
    addData(record)


def resetData():
    """Clear all recorded data; keep :data:`plots` and :data:`labels`."""
    data.clear()


def reset():
    """Reset all plot-related variables: :data:`data`, :data:`plots` and :data:`labels`."""
    data.clear()
    plots.clear()
    labels.clear()


def splitData():
    """Make the next record start a new line segment: add a record of NaN in all columns."""
    if data:
        addData({name: nan for name in data})


def reverseData():
    """Reverse the order of the records in all columns."""
    for col in data.values():
        col.reverse()


def _open(fileName, mode):
    if fileName.endswith('.bz2'):
        return bz2.open(fileName, mode + 't')
    if fileName.endswith('.gz'):
        return gzip.open(fileName, mode + 't')
    return open(fileName, mode)


def saveDataTxt(fileName, vars=None, headers=None):
    """Save :data:`data` to a text file, compressed with bzip2/gzip when *fileName* ends in .bz2/.gz.

    The file starts with ``# key=<TAB>value`` lines for the items of *headers* (a dict; optional),
    then the line ``# name1<TAB><TAB>name2 ...`` naming the columns, then one line per record with
    the values separated by tabs (written with ``str``, full precision; ``nan`` for missing values).
    The result can be read with ``numpy.genfromtxt(fileName, names=True)`` or ``numpy.loadtxt``.

    :param vars: names of the variables to save, in that order (default: all, sorted by name).
    :param headers: dict of extra information written as comments at the top of the file.
    """
    if vars is None:
        vars = sorted(data.keys())
    elif isinstance(vars, str):
        vars = [vars]
    else:
        vars = list(vars)
    missing = [v for v in vars if v not in data]
    if missing:
        raise KeyError(missing[0] if len(missing) == 1 else missing)
    n = min((len(data[v]) for v in vars), default=0)
    with _open(fileName, 'w') as f:
        if headers:
            for k, v in headers.items():
                f.write('# %s=\t%s\n' % (k, v))
        f.write('# ' + '\t\t'.join(vars) + '\n')
        cols = [data[v] for v in vars]
        for i in range(n):
            f.write('\t'.join(str(c[i]) for c in cols) + '\n')


def _stamped(baseName, timestamp):
    import time
    return baseName + time.strftime('_%Y%m%d_%H:%M') if timestamp else baseName


def _createdLine():
    import time
    return 'created %s (%s)' % (time.asctime(), time.strftime('%Y%m%d_%H:%M'))


def _gnuplotString(text):
    return "'" + str(text).replace("'", "''") + "'"  # (two quotes stand for one in a gnuplot '...' string)


def saveGnuplot(baseName, term='wxt', extension=None, timestamp=False, comment=None, title=None, varData=False):
    """Write a gnuplot script drawing :data:`plots`, and the data it reads.

    The data go to ``<baseName>.data.bz2`` (as :func:`saveDataTxt`, all variables sorted by name:
    column *k* is the *k*-th name), the script to ``<baseName>.gnuplot``, which reads the data
    file by its name alone: run gnuplot in their folder (``gnuplot -persist name.gnuplot``). One
    plot per x variable, the variables after ``None`` on the right axis (y2).

    :param term: gnuplot terminal (``wxt``, ``x11``, ``png``, ``pdfcairo``...).
    :param extension: when given (``'.png'``), each plot is written to ``<baseName>.<i><extension>``
        instead of a window.
    :param timestamp: append ``_YYYYmmdd_HH:MM`` to *baseName*.
    :param comment: a line written as a comment at the top of the script.
    :param title: title of every plot.
    :param varData: name the data source once, in a gnuplot variable ``dataFile``.
    :return: the name of the gnuplot script.
    """
    baseName = _stamped(os.fspath(baseName), timestamp)
    vars = sorted(data.keys())
    saveDataTxt(baseName + '.data.bz2', vars)
    column = {name: i + 1 for i, name in enumerate(vars)}
    dataName = os.path.basename(baseName) + '.data.bz2'
    source = '"< bzcat %s"' % dataName
    out = ['#!/usr/bin/env gnuplot', '#', '# ' + _createdLine(), '#']
    if comment:
        out.append('# ' + str(comment).replace('\n', ' '))
    if varData:
        out.append('dataFile=%s' % source)
        source = 'dataFile'
    if extension and not extension.startswith('.'):
        extension = '.' + extension
    specs = _specs()
    _warnMissing(specs)
    for i, (_, x, left, right) in enumerate(specs):
        if x not in column:
            continue
        if extension:
            out.append("set term %s; set output %s" % (term, _gnuplotString(os.path.basename(baseName) + '.%d%s' % (i, extension))))
        else:
            out.append('set term %s %d persist' % (term, i))
        out += ['set xlabel %s' % _gnuplotString(_label(x)), 'set grid', "set datafile missing 'nan'"]
        if title:
            out.append('set title %s' % _gnuplotString(title))
        left = [(y, f) for y, f in left if y in column]
        right = [(y, f) for y, f in right if y in column]
        if left:
            out.append('set ylabel %s' % _gnuplotString(','.join(_label(y) for y, _ in left)))
        if right:
            out += ['set y2label %s' % _gnuplotString(','.join(_label(y) for y, _ in right)), 'set y2tics']
        curves = ['%s using %d:%d title %s with lines' % (source, column[x], column[y], _gnuplotString('\u2190 %s(%s)' % (_label(y), _label(x))))
                  for y, _ in left]
        curves += ['%s using %d:%d title %s with lines axes x1y2' % (source, column[x], column[y], _gnuplotString('%s(%s) \u2192' % (_label(y), _label(x))))
                   for y, _ in right]
        if curves:
            out.append('plot  ' + ', '.join(curves))
    with open(baseName + '.gnuplot', 'w', encoding='utf-8') as f:
        f.write('\n'.join(out) + '\n')
    return baseName + '.gnuplot'


def savePylab(baseName, timestamp=False, title=None):
    """Write a standalone Python script drawing :data:`plots` with matplotlib, and its data.

    The data go to ``<baseName>.data.bz2`` (as :func:`saveDataTxt`), the script to
    ``<baseName>.py``; it reads the data file from its own folder and shows the figures (or, run
    as ``python3 <baseName>.py out``, writes ``out.0.png``, ``out.1.png``, ...). It needs only
    numpy and matplotlib.

    :return: the name of the script.
    """
    baseName = _stamped(os.fspath(baseName), timestamp)
    vars = sorted(data.keys())
    saveDataTxt(baseName + '.data.bz2', vars)
    figures = []
    for _, x, left, right in _specs():
        figures.append((x, [(y, f) for y, f in left], [(y, f) for y, f in right]))
    labelsUsed = {name: _label(name) for name in vars}
    script = """#!/usr/bin/env python3
# %(created)s by yade.plot.savePylab: the plots of %(base)s.data.bz2
import os, sys
import numpy
import matplotlib
if len(sys.argv) > 1:
    matplotlib.use('Agg')
import matplotlib.pyplot as plt

names = %(names)r
labels = %(labels)r
figures = %(figures)r  # (x, left [(y, format)], right [(y, format)])
title = %(title)r
columns = numpy.loadtxt(os.path.join(os.path.dirname(os.path.abspath(__file__)), %(dataName)r), ndmin=2)
data = {name: columns[:, i] for i, name in enumerate(names)}
for i, (x, left, right) in enumerate(figures):
    fig, ax = plt.subplots()
    ax.set_xlabel(labels.get(x, x))
    k = 0
    for side, ys in enumerate((left, right)):
        if not ys:
            continue
        axis = ax if side == 0 else ax.twinx()
        for y, fmt in ys:
            if x in data and y in data:
                axis.plot(data[x], data[y], *([fmt] if fmt else []), label=labels.get(y, y), **({} if fmt else {'color': 'C%%d' %% (k %% 10)}))
            k += 1
        axis.set_ylabel(', '.join(labels.get(y, y) for y, _ in ys))
        axis.legend(loc='upper left' if side == 0 else 'upper right')
    if title:
        ax.set_title(title)
    if len(sys.argv) > 1:
        fig.savefig('%%s.%%d.png' %% (sys.argv[1], i))
if len(sys.argv) <= 1:
    plt.show()
""" % {'created': _createdLine(), 'base': os.path.basename(baseName), 'names': vars, 'labels': labelsUsed,
       'figures': figures, 'title': title, 'dataName': os.path.basename(baseName) + '.data.bz2'}
    with open(baseName + '.py', 'w', encoding='utf-8') as f:
        f.write(script)
    return baseName + '.py'


def savePlotSequence(fileBase, stride=1, imgRatio=(5, 7), title=None, titleFrames=20, lastFrames=30):
    """Save the plots as they looked while the data grew, one PNG per *stride* records
    (``<fileBase>-000.png``, ``-001.png``, ...; the last frame has all the records), e.g. to make
    a movie of them. Each figure is *imgRatio* (width, height) inches.

    :param title: when given, a first frame ``<fileBase>-title.png`` showing this text.
    :return: the list of frame files in movie order: the title frame *titleFrames* times, the
        frames, then the last frame repeated *lastFrames* times (so that they stay on screen).
    """
    if stride < 1:
        raise ValueError('plot.savePlotSequence: stride must be at least 1 (got %r)' % (stride,))
    fileBase = os.fspath(fileBase)
    n = _rowCount()
    if n == 0 or not plots:
        raise ValueError('plot.savePlotSequence: nothing to plot (plot.plots or plot.data is empty)')
    ends = list(range(stride, n, stride)) + [n]
    plt = _pyplot()
    frames = []
    for i, rows in enumerate(ends):
        figs = createPlots(subPlots=True, rows=rows)
        fig = figs[0]
        fig.set_size_inches(*imgRatio)
        path = '%s-%03d.png' % (fileBase, i)
        fig.savefig(path)
        plt.close(fig)
        frames.append(path)
    out = []
    if title:
        fig = plt.figure(figsize=imgRatio)
        fig.text(.5, .5, str(title), ha='center', va='center', wrap=True, fontsize='xx-large')
        path = '%s-title.png' % fileBase
        fig.savefig(path)
        plt.close(fig)
        out += [path] * titleFrames
    return out + frames + [frames[-1]] * lastFrames


# ---------------------------------------------------------------------------------------------
# plotting

def _label(name):
    return str(labels.get(name, name))


def _entries(spec, out):
    """Flatten one y specification into out: (name, fmt) pairs and None for the axis switch."""
    if spec is None:
        out.append(None)
    elif isinstance(spec, str):
        out.append((spec, None))
    elif isinstance(spec, dict):
        out.extend((str(k), v) for k, v in spec.items())
    elif isinstance(spec, (tuple, list)) and len(spec) == 2 and isinstance(spec[0], str) \
            and (spec[1] is None or isinstance(spec[1], str)):
        out.append((spec[0], spec[1]))
    elif callable(spec):
        got = spec()
        if isinstance(got, str):
            got = [got]
        for e in got:
            _entries(e, out)
    else:
        try:
            items = list(spec)
        except TypeError:
            raise TypeError('plot.plots: invalid y entry %r (a name, (name, format), None or a callable '
                            'returning names)' % (spec,))
        for e in items:
            _entries(e, out)


def _yAxes(ys):
    """Split the y specification of one x variable into (left, right) lists of (name, fmt)."""
    if isinstance(ys, str) or callable(ys) or ys is None:
        ys = [ys]
    flat = []
    for e in ys:
        _entries(e, flat)
    left, right = [], []
    cur = left
    for e in flat:
        if e is None:
            cur = right
        else:
            cur.append((e[0].strip(), e[1]))
    return left, right


def _column(name, n):
    import numpy
    col = data.get(name)
    if col is None:
        return numpy.full(n, nan)
    try:
        return numpy.array(col[:n], dtype=float)
    except (TypeError, ValueError):
        return numpy.array([float(v) if _isNumber(v) else nan for v in col[:n]], dtype=float)


def _specs():
    """[(x name as given, x name, left, right)] for every entry of plots."""
    out = []
    for xKey, ys in plots.items():
        left, right = _yAxes(ys)
        out.append((xKey, str(xKey).strip(), left, right))
    return out


def _warnMissing(specs):
    if not data:
        return
    names = []
    for _, x, left, right in specs:
        for name in [x] + [y for y, _ in left + right]:
            if name not in data and name not in names:
                names.append(name)
    if names:
        print('Missing columns in plot.data, plotted as NaN: ', ', '.join(names))


def _fmtHasColor(fmt):
    """Whether a matplotlib format string such as 'r--' or 'C3o' names a color."""
    try:
        from matplotlib.axes._base import _process_plot_format
        return _process_plot_format(fmt)[2] is not None
    except Exception:  # (a private helper: fall back to the one-letter colors)
        return any(c in 'bgrcmykw' for c in fmt)


def _fillAxes(ax, x, left, right, rows=None):
    """Draw the lines of one x variable on ax (and a twin axis for the right side), at most rows
    records. Lines without a color of their own take the colors of the cycle in turn, across both
    axes (a twin axis would otherwise start the cycle again, drawing its first line in the color
    of the left axis' first)."""
    n = len(data.get(x, ())) if x in data else max((len(v) for v in data.values()), default=0)
    if rows is not None:
        n = min(n, rows)
    xs = _column(x, n)
    lines = []
    ax.set_xlabel(_label(x))
    k = 0
    for side, (axis, ys) in enumerate(((ax, left), (None, right))):
        if not ys:
            continue
        if axis is None:
            axis = ax.twinx()
        for y, fmt in ys:
            args = (xs, _column(y, n)) + ((fmt,) if fmt else ())
            kw = {} if fmt and _fmtHasColor(fmt) else {'color': 'C%d' % (k % 10)}
            k += 1
            line, = axis.plot(*args, label=_label(y), **kw)
            lines.append((line, x, y))
        axis.set_ylabel(', '.join(_label(y) for y, _ in ys))
        try:
            axis.legend(loc=legendLoc[side])
        except Exception:
            pass
        if scientific:
            try:
                axis.ticklabel_format(style='sci', scilimits=(-3, 4), axis='both')
            except Exception:
                pass  # non-scalar (e.g. log) formatters
    return lines


def _subplotGrid(n):
    rows = int(math.ceil(math.sqrt(n))) if n else 1
    cols = int(math.ceil(n / rows)) if n else 1
    return rows, cols


def _displayAvailable():
    if sys.platform.startswith(('linux', 'freebsd', 'openbsd', 'netbsd', 'sunos')):
        return bool(os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY'))
    return True


_NON_INTERACTIVE = ('agg', 'cairo', 'pdf', 'pgf', 'ps', 'svg', 'template')


def _pyplot():
    """Import matplotlib.pyplot; without a display select the Agg backend first; with the GUI's windows
    (yade.qt) Qt5Agg, unless a backend was chosen already (MPLBACKEND, an earlier import)."""
    import matplotlib
    if _displayAvailable():
        from yade import qt
        useQt = qt.noView == '' and not os.environ.get('MPLBACKEND')  # the figures in the windows' Qt loop, as the reference's
        if useQt and 'matplotlib.pyplot' not in sys.modules:
            qt._application()
            matplotlib.use('Qt5Agg')
        import matplotlib.pyplot as plt
        if useQt and 'qt' not in str(matplotlib.get_backend()).lower() and not plt.get_fignums():
            try:  # (a script imported pyplot first: its default backend cannot run beside Qt's loop)
                qt._application()
                plt.switch_backend('Qt5Agg')
            except Exception:
                pass
    elif 'matplotlib.pyplot' not in sys.modules:
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
    else:
        import matplotlib.pyplot as plt
        if _interactiveBackend():  # chosen before, but there is no display to use it
            try:
                plt.switch_backend('Agg')
            except Exception:
                pass
    return plt


def _interactiveBackend():
    import matplotlib
    b = str(matplotlib.get_backend()).lower()
    if b in _NON_INTERACTIVE or 'inline' in b:
        return False
    return True


def _figureBase():
    """Path prefix of the PNG written when nothing can be shown: <current folder>/<script name>
    (<current folder>/yade without a script)."""
    script = sys.argv[0] if sys.argv else ''
    base = 'yade'
    if script and os.path.isfile(script):
        base = os.path.basename(script)
        if base.endswith('.py'):
            base = base[:-3]
    return os.path.join(os.getcwd(), base)


def _savePng(figs):
    base = _figureBase()
    paths = []
    for i, fig in enumerate(figs):
        suffix = '.plot.png' if i == 0 else '.plot.%d.png' % (i + 1)
        path = base + suffix
        if _batch['path']:  # a yade-batch job: the PNG named after the job, that the status page shows
            path = _batch['path'] if i == 0 else '%s.%d.png' % (_batch['path'][:-4], i + 1)
        try:
            fig.savefig(path)
        except OSError:  # e.g. a read-only current folder: the temporary folder
            import tempfile
            path = os.path.join(tempfile.gettempdir(), os.path.basename(base) + suffix)
            fig.savefig(path)
        paths.append(path)
        if path not in _batch['said']:
            print('plot: no display available, figure saved to %s' % path)
            if _batch['path']:
                _batch['said'].add(path)  # (not again at each update of the job's figure)
    if _batch['path']:
        _batch['saved'], _batch['rows'] = time.time(), _rowCount()
    return paths


def _updateFigure(fig):
    """Refresh the lines of a live figure from data."""
    for line, x, y in getattr(fig, '_yadeLines', ()):
        n = len(data.get(x, ()))
        line.set_data(_column(x, n), _column(y, n))
    if autozoom:
        for ax in fig.axes:
            ax.relim()
            ax.autoscale_view()
    fig.canvas.draw_idle()


_liveFigures = []


def _startLive(fig):
    if not live:
        return
    try:
        timer = fig.canvas.new_timer(interval=max(1, int(liveInterval * 1000)))
        timer.add_callback(_updateFigure, fig)
        timer.start()
        fig._yadeTimer = timer
        _liveFigures.append(fig)
        import yade.qt  # noqa: F401  (O.run(n, True) and O.wait() then give the figures their turn: _pumpLive)
    except Exception:
        pass


def _pumpLive():
    """Lets the live figures update and answer the mouse (their timers fire) while the main thread waits for
    a run (yade.qt._whileWaiting); False when none is open."""
    if not _liveFigures:
        return False
    import matplotlib.pyplot as plt
    for fig in list(_liveFigures):
        try:
            if not plt.fignum_exists(fig.number):
                _liveFigures.remove(fig)
                continue
            fig.canvas.flush_events()
        except Exception:
            _liveFigures.remove(fig)
    return bool(_liveFigures)


def createPlots(subPlots=True, rows=None):
    """Create the matplotlib figure(s) for :data:`plots` (with the first *rows* records only, if
    given); return the list of figures."""
    plt = _pyplot()
    specs = _specs()
    _warnMissing(specs)
    figs = []
    if subPlots or len(specs) <= 1:
        fig = plt.figure()
        fig._yadeLines = []
        gridRows, gridCols = _subplotGrid(len(specs))
        for i, (_, x, left, right) in enumerate(specs):
            ax = fig.add_subplot(gridRows, gridCols, i + 1)
            fig._yadeLines += _fillAxes(ax, x, left, right, rows)
        figs.append(fig)
    else:
        for _, x, left, right in specs:
            fig = plt.figure()
            ax = fig.add_subplot(1, 1, 1)
            fig._yadeLines = _fillAxes(ax, x, left, right, rows)
            figs.append(fig)
    for fig in figs:
        try:
            fig.tight_layout()
        except Exception:
            pass
    return figs


def plot(noShow=False, subPlots=True):
    """Plot :data:`plots` (one subplot per x variable, or one figure each if *subPlots* is False).

    With *noShow*, return the figure (a list of figures when there are several) without showing it;
    ``plot.plot(noShow=True).savefig('file.pdf')`` saves it. Otherwise the figure is shown in a
    window that is updated live when a display and an interactive matplotlib backend are available
    (returns None); when not (``yade -n``, no ``DISPLAY``), it is written to
    ``<script>.plot.png`` in the current folder (``yade.plot.png`` without a script; more figures:
    ``<script>.plot.2.png``, ...), the path is printed, and the figure (or list of figures) is
    returned. No display never raises.
    """
    figs = createPlots(subPlots=subPlots)
    ret = figs[0] if len(figs) == 1 else figs
    _batch['subPlots'] = subPlots
    if noShow:
        return ret
    plt = _pyplot()
    if _displayAvailable() and _interactiveBackend():
        try:
            plt.ion()
            for fig in figs:
                fig.show()
                _startLive(fig)
            plt.show(block=False)
            try:
                plt.pause(0.001)
            except Exception:
                pass
            return None
        except Exception as e:  # no usable GUI after all: fall back to a file
            print('plot: cannot show the figure (%s)' % e)
    _savePng(figs)
    for fig in figs:
        try:
            plt.close(fig)  # the Figure object stays usable (savefig) but pyplot forgets it
        except Exception:
            pass
    _redrawAtExit(subPlots)
    return ret


_atExit = {'subPlots': None, 'registered': False, 'rows': None}


def _redrawAtExit(subPlots):
    """Without a display the PNG is written when plot() is called, usually before the run; it
    is written again with all the data when the program ends (if data were added since)."""
    import atexit
    _atExit['subPlots'] = subPlots
    _atExit['rows'] = _rowCount()
    if not _atExit['registered']:
        atexit.register(_finalPng)
        _atExit['registered'] = True


def _rowCount():
    return max((len(v) for v in data.values()), default=0)


def _finalPng():
    if _batch['path']:
        return  # (_batchFinal writes the job's figure)
    if _atExit['subPlots'] is None or _rowCount() == _atExit['rows'] or not plots:
        return
    try:
        plt = _pyplot()
        figs = createPlots(subPlots=_atExit['subPlots'])
        _savePng(figs)
        for fig in figs:
            plt.close(fig)
    except Exception as e:  # never fail at exit because of a plot
        print('plot: could not write the final figure (%s)' % e)


# ---------------------------------------------------------------- in a yade-batch job
# yade-batch names the PNG of each job's figure (YADE_BATCH_PLOT, e.g. /dir/job.py.first.png) and shows it
# on its status page: plot() writes it there instead of <script>.plot.png, it is updated every
# YADE_BATCH_PLOT_PERIOD seconds while data are added, and written when the job ends (also when the
# script never called plot(), as long as plots and data are set).
_batch = {'path': os.environ.get('YADE_BATCH_PLOT') or None, 'period': 60., 'saved': None, 'rows': 0,
          'said': set(), 'subPlots': True, 'busy': False}
try:
    _batch['period'] = float(os.environ.get('YADE_BATCH_PLOT_PERIOD', 60.))
except ValueError:
    pass


def _batchWrite():
    if not plots or not _rowCount() or _batch['busy']:
        return
    _batch['busy'] = True
    try:
        plt = _pyplot()
        figs = createPlots(subPlots=_batch['subPlots'])
        _savePng(figs)
        for fig in figs:
            plt.close(fig)
    except Exception as e:  # a figure must never break the job
        print('plot: could not write the figure for yade-batch (%s)' % e)
    finally:
        _batch['busy'] = False


def _batchUpdate():
    if _batch['period'] <= 0 or not plots:
        return
    now = time.time()
    if _batch['saved'] is None:
        _batch['saved'] = now  # the first update comes one period after the first data
    elif now - _batch['saved'] >= _batch['period']:
        _batchWrite()


def _batchFinal():
    if _rowCount() != _batch['rows']:
        _batchWrite()


if _batch['path']:
    import atexit
    atexit.register(_batchFinal)
