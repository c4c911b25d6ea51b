"""Parameters of a (batch) simulation, as in Yade.

A script declares its parameters with their default values::

    readParamsFromTable(damping=.2, nSpheres=100)
    from yade.params import table
    NewtonIntegrator(damping=table.damping)

When the script runs in a batch (``yade-batch``, which sets the ``YADE_BATCH``
environment variable to ``tableFile:lineNumber`` for each job, as the reference does), the values in
that line of the parameter table override the defaults; otherwise the defaults
are used. The values are put in the module ``yade.params.table`` (created anew by
each call of :func:`readParamsFromTable`); they are not made global variables.

Format of the parameter table (a text file)::

    # comments (from '#' to the end of the line) and blank lines are allowed anywhere
    damping  nSpheres  description   # first non-blank line: column names
    .2       100       lowDamping    # each following line: one simulation
    .4       =         highDamping   # '=' repeats the value of the line above

Values are Python expressions (evaluated with the names of the :mod:`math` module
available); the optional ``description`` column is taken as text and names the
run (it is synthesized from the other columns when absent). Columns whose name
starts with ``!`` (``!THREADS``, ``!SCRIPT``...) are for ``yade-batch`` and are not
parameters. ``doc/batch.md`` describes the batch.
"""
import math
import os
import pickle
import sys
import types
import warnings

__all__ = ['readParamsFromTable', 'waitIfBatch', 'inBatch', 'batchTableLine']

_BATCH_ENV = 'YADE_BATCH'


def batchTableLine():
    """The ``tableFile:lineNumber`` of this run when it is part of a batch, else None."""
    return os.environ.get(_BATCH_ENV) or None


def inBatch():
    """Whether this run is part of a batch (the ``YADE_BATCH`` environment variable is set)."""
    return batchTableLine() is not None


def _omega():
    from ._yade import O
    return O


def _evalNamespace():
    ns = {'__builtins__': __builtins__}
    ns.update((k, getattr(math, k)) for k in dir(math) if not k.startswith('_'))
    ns['math'] = math
    return ns


def _setTag(O, key, value):
    try:
        O.tags[key] = value
    except Exception:
        pass


def _paramsModule(mark, values):
    """The module yade.params.<mark>, made anew, holding values (a dict, in order); with mark '' the
    values go into yade.params itself (utils.saveVars, utils.loadVars, readParamsFromTable)."""
    if not mark:
        globals().update(values)
        return sys.modules[__name__]
    name = __name__ + '.' + mark
    if name in sys.modules:
        warnings.warn('Overwriting %s which already exists.' % name)
    mod = types.ModuleType(name)
    for k, v in values.items():
        setattr(mod, k, v)
    mod.__all__ = list(values.keys())
    sys.modules[name] = mod
    globals()[mark] = mod
    return mod


def _makeTableModule(values):
    """Create yade.params.table (a new module) holding values (a dict, in order)."""
    mod = _paramsModule('table', values)
    mod.__doc__ = 'Parameters of this simulation, set by readParamsFromTable.'
    return mod


def readParamsFromTable(tableFileLine=None, noTableOk=True, unknownOk=False, **kw):
    """Read simulation parameters; keyword arguments are the parameters and their default values.

    The parameters are put in the module ``yade.params.table`` (``from yade.params import table``,
    then ``table.name``). Outside a batch the defaults are used; in a batch (``YADE_BATCH`` set to
    ``tableFile:lineNumber`` by ``yade-batch``), or when *tableFileLine* is given, the values of that
    line of the parameter table (line numbers as seen in a text editor) replace the defaults.

    Tags set in ``O.tags``: ``line`` ('l' + the line number, 'l!' outside a batch), ``params``
    ("name1=expr1,name2=expr2" for the parameters read from the table), ``defaultParams``
    ("name=value,..." for the parameters left at their defaults), and in a batch also
    ``description`` (the description column, or synthesized from ``params``),
    ``d.id`` (description + '.' + id) and ``id.d`` (id + '.' + description).

    :param tableFileLine: 'file:line' to read instead of the ``YADE_BATCH`` environment variable.
    :param noTableOk: if False, raise an error when no table is given (not in a batch).
    :param unknownOk: accept (and assign) table columns that have no default value here;
        otherwise such a column raises NameError.
    :return: the number of parameters assigned from the table (0 outside a batch).
    """
    O = _omega()
    if tableFileLine is None:
        tableFileLine = batchTableLine()
    values = {}
    nRead = 0
    if tableFileLine is None:
        if not noTableOk:
            raise EnvironmentError('%s is not defined in the environment' % _BATCH_ENV)
        _setTag(O, 'line', 'l!')
        _setTag(O, 'params', '')
    else:
        fileName, sep, lineStr = str(tableFileLine).rpartition(':')
        if not sep or not fileName:
            raise ValueError("tableFileLine must be 'file:lineNumber', got %r" % tableFileLine)
        try:
            lineNo = int(lineStr)
        except ValueError:
            raise ValueError("tableFileLine must be 'file:lineNumber', got %r" % tableFileLine)
        from .batch import readTable  # (the table format yade-batch reads: one parser for both)
        table = readTable(fileName)
        if lineNo in table.bad:
            raise ValueError('Table %s, line %d: %s' % (fileName, lineNo, table.bad[lineNo]))
        if lineNo not in table.lines:
            raise RuntimeError("Table %s doesn't contain valid line number %d" % (fileName, lineNo))
        line = table.lines[lineNo]
        assigned = []
        for name, expr in line.params():  # (neither description nor the '!' columns of yade-batch)
            if name not in kw and not unknownOk:
                raise NameError("Parameter `%s' has no default value assigned" % name)
            assigned.append((name, expr))
        ns = _evalNamespace()
        for name, expr in assigned:
            try:
                values[name] = eval(expr, ns)
            except Exception as e:
                if hasattr(e, 'add_note'):
                    e.add_note('while evaluating parameter %s=%s (table %s, line %d)' % (name, expr, fileName, lineNo))
                raise
        nRead = len(assigned)
        params = ','.join('%s=%s' % (n, e) for n, e in assigned)
        description = line.description  # (as yade-batch names the job)
        _setTag(O, 'line', 'l%d' % lineNo)
        _setTag(O, 'description', description)
        _setTag(O, 'params', params)
        oid = O.tags['id']
        _setTag(O, 'd.id', description + '.' + oid)
        _setTag(O, 'id.d', oid + '.' + description)
    defaults = [(k, v) for k, v in kw.items() if k not in values]
    _setTag(O, 'defaultParams', ','.join('%s=%s' % (k, v) for k, v in defaults))
    values.update(defaults)
    try:
        _setTag(O, 'pickledPythonVariablesDictionarytable', pickle.dumps(dict(values), protocol=0).decode('latin-1'))
    except Exception:
        pass
    _makeTableModule(values)
    if tableFileLine is not None and inBatch():
        from . import batch  # the job tells yade-batch's status page how far it is
        batch.startJobReport()
    return nRead


def waitIfBatch():
    """In a batch, block until the simulation stops (``O.wait()``); return at once otherwise."""
    if inBatch():
        _omega().wait()
