"""Storing and plotting history of simulation variables, as Yade's ``yade.plot``.

Typical use::

    from yade import plot
    plot.plots = {'t': ('Ek', None, 'unbalanced')}   # None: the following go on the right axis
    O.engines += [PyRunner(command='plot.addData(t=O.time, Ek=kineticEnergy(), unbalanced=unbalancedForce())',
                           iterPeriod=100)]
    ...
    plot.plot()                       # live window, or <script>.plot.png when there is no display
    plot.saveDataTxt('data.txt.bz2')  # all columns, bzip2-compressed

* :data:`data` maps each variable name to the list of its values, one per :func:`addData` call;
  a variable missing in a call gets NaN, a new variable is back-filled with NaN.
* :data:`plots` maps each x-variable name to the y-variable names plotted against it; a y entry
  is a name, a ``(name, format)`` pair (matplotlib format such as ``'r-'``), ``None`` (the
  following entries go on an independently scaled right axis) or a callable returning names
  (called at plot time, e.g. ``O.energy.keys``). To plot against the same x variable in several
  subplots, append spaces to its name (``'t'``, ``'t '``, ...): names are stripped.
* :data:`labels` maps variable names to the text shown in axis labels and legends.

matplotlib is imported only when a figure is made; without a usable display (``yade -n``, no
``DISPLAY``) the non-interactive Agg backend is used and :func:`plot` writes a PNG file.
"""
import bz2
import gzip
import math
import numbers
import os
import sys

__all__ = ['data', 'plots', 'labels', 'legendLoc', 'autozoom', 'scientific', 'live', 'liveInterval',
           'componentSeparator', 'addData', 'reset', 'resetData', 'plot', 'saveDataTxt', 'splitData',
           'reverseData']

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


def _fillAxes(ax, x, left, right):
    """Draw the lines of one x variable on ax (and a twin axis for the right side)."""
    n = len(data.get(x, ())) if x in data else max((len(v) for v in data.values()), default=0)
    xs = _column(x, n)
    lines = []
    ax.set_xlabel(_label(x))
    for side, (axis, ys) in enumerate(((ax, left), (None, right))):
        if not ys:
            continue
        if axis is None:
            axis = ax.twinx()
        for y, fmt in ys:
            args = (xs, _column(y, n)) + ((fmt,) if fmt else ())
            line, = axis.plot(*args, label=_label(y))
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
    """Import matplotlib.pyplot; without a display select the Agg backend first."""
    import matplotlib
    if _displayAvailable():
        import matplotlib.pyplot as plt
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
    """Path prefix of the PNG written when nothing can be shown: <script dir>/<script name>."""
    script = sys.argv[0] if sys.argv else ''
    if script and os.path.isfile(script):
        base = os.path.basename(script)
        if base.endswith('.py'):
            base = base[:-3]
        return os.path.join(os.path.dirname(os.path.abspath(script)), base)
    return os.path.join(os.getcwd(), 'yade')


def _savePng(figs):
    base = _figureBase()
    paths = []
    for i, fig in enumerate(figs):
        suffix = '.plot.png' if i == 0 else '.plot.%d.png' % (i + 1)
        path = base + suffix
        try:
            fig.savefig(path)
        except OSError:  # e.g. read-only script directory: use the working directory
            path = os.path.join(os.getcwd(), os.path.basename(base) + suffix)
            fig.savefig(path)
        paths.append(path)
        print('plot: no display available, figure saved to %s' % path)
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


def _startLive(fig):
    if not live:
        return
    try:
        timer = fig.canvas.new_timer(interval=max(1, int(liveInterval * 1000)))
        timer.add_callback(_updateFigure, fig)
        timer.start()
        fig._yadeTimer = timer
    except Exception:
        pass


def createPlots(subPlots=True):
    """Create the matplotlib figure(s) for :data:`plots`; return the list of figures."""
    plt = _pyplot()
    specs = _specs()
    _warnMissing(specs)
    figs = []
    if subPlots or len(specs) <= 1:
        fig = plt.figure()
        fig._yadeLines = []
        rows, cols = _subplotGrid(len(specs))
        for i, (_, x, left, right) in enumerate(specs):
            ax = fig.add_subplot(rows, cols, i + 1)
            fig._yadeLines += _fillAxes(ax, x, left, right)
        figs.append(fig)
    else:
        for _, x, left, right in specs:
            fig = plt.figure()
            ax = fig.add_subplot(1, 1, 1)
            fig._yadeLines = _fillAxes(ax, x, left, right)
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
    ``<script>.plot.png`` in the directory of the running script (``<cwd>/yade.plot.png`` without
    a script; more figures: ``<script>.plot.2.png``, ...), the path is printed, and the figure
    (or list of figures) is returned. No display never raises.
    """
    figs = createPlots(subPlots=subPlots)
    ret = figs[0] if len(figs) == 1 else figs
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
