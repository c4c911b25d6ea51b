"""Writing the scene to files (as in Yade's yade.export): text (x y z r per line), textExt (a choice
of formats, read back by yade.ymport.textExt), textClumps (clump members with their clump's id, read
back by yade.ymport.textClumps) and VTKExporter (one-off snapshots in VTK's legacy ASCII format, for
ParaView: spheres, facets, interactions, contact points, the periodic cell)."""
import numbers
import os
import sys
import warnings

from ._yade import O, _sphereColumns


class _LazyNumpy:
    """numpy, imported at its first use (the launcher imports NumPy lazily: a script that never uses it starts faster)."""

    def __getattr__(self, name):
        import numpy as np
        return getattr(np, name)


numpy = _LazyNumpy()


__all__ = ['text', 'textExt', 'textClumps', 'VTKExporter']

_formats = ('x_y_z_r', 'x_y_z_r_matId', 'x_y_z_r_attrs')


class ExportFormatError(ValueError, RuntimeError):
    """An unknown format name (a RuntimeError too, as the reference raises)."""


def _g(x):
    return '%g' % x


def _attrColumns(value):
    """The numbers written for one attribute: a scalar, or the components of a vector or a matrix."""
    try:
        return [_g(float(value))]
    except TypeError:
        pass
    try:
        flat = [v for row in value for v in (row if hasattr(row, '__len__') else [row])]
    except TypeError:
        raise TypeError('export.textExt: attribute value %r is neither a number nor a vector/matrix' % (value,))
    return [_g(float(v)) for v in flat]


def textExt(filename, format='x_y_z_r', comment='', mask=-1, attrs=[]):
    """Write the spheres (other bodies are skipped; with mask, only those whose mask shares a bit
    with it) to `filename`, one line per sphere, numbers separated by tabs as C's %g prints them.
    The first line is '#format <format>', then '# <comment>' if given. Formats: 'x_y_z_r',
    'x_y_z_r_matId' (the index of the material in O.materials), 'x_y_z_r_attrs' (then the values of
    the Python expressions `attrs`, evaluated with b the body, e.g. 'b.state.vel'; the comment line
    starts with the column names x y z r). Returns the number of spheres written."""
    if format not in _formats:
        raise ExportFormatError("export.textExt: unknown format %r; use one of %s" % (format, ', '.join(_formats)))
    if isinstance(attrs, str):
        raise TypeError('export.textExt: attrs must be a list of expressions (str), not one str')
    ids, pos, radius, matId = _sphereColumns(mask)
    lines = ['#format ' + format + '\n']
    if format == 'x_y_z_r_attrs':
        lines.append('# x y z r ' + comment + '\n')
    elif comment:
        lines.append('# ' + comment + '\n')
    codes = [compile(a, '<export.textExt attrs>', 'eval') for a in attrs] if format == 'x_y_z_r_attrs' else []
    for i in range(len(ids)):
        cols = [_g(pos[i, 0]), _g(pos[i, 1]), _g(pos[i, 2]), _g(radius[i])]
        if format == 'x_y_z_r_matId':
            cols.append('%d' % matId[i])
        elif codes:
            b = O.bodies[int(ids[i])]
            for c in codes:
                cols += _attrColumns(eval(c, {'b': b, 'O': O}))
        lines.append('\t'.join(cols) + '\n')
    with open(filename, 'w') as f:
        f.writelines(lines)
    return len(ids)


def text(filename, mask=-1):
    """Write the spheres as lines 'x y z r' (textExt's format 'x_y_z_r'); returns their number."""
    return textExt(filename, format='x_y_z_r', mask=mask)


def textClumps(filename, format='x_y_z_r_clumpId', comment='', mask=-1):
    """Write the spherical members of the clumps (whose mask shares a bit with `mask`; other bodies
    are skipped) to `filename`, clump after clump by increasing clump id, one line 'x y z r clumpId'
    per member (tab-separated, C's %g), the id being the clump body's. The first line is
    '#format x_y_z_r_clumpId', then '# <comment>' if given; ymport.textClumps reads it back.
    Returns (number of clumps in the scene, number of spheres written), as the reference does."""
    if format != 'x_y_z_r_clumpId':
        raise ExportFormatError("export.textClumps: unknown format %r; the only one is 'x_y_z_r_clumpId'" % (format,))
    ids, pos, radius, _ = _sphereColumns(mask)
    members = {}  # clump id -> rows of its members
    for i in range(len(ids)):
        b = O.bodies[int(ids[i])]
        if b.isClumpMember:
            members.setdefault(b.clumpId, []).append(i)
    lines = ['#format x_y_z_r_clumpId\n'] + (['# ' + comment + '\n'] if comment else [])
    for c in sorted(members):
        lines += ['\t'.join([_g(pos[i, 0]), _g(pos[i, 1]), _g(pos[i, 2]), _g(radius[i]), '%d' % c]) + '\n' for i in members[c]]
    with open(filename, 'w') as f:
        f.writelines(lines)
    return sum(1 for b in O.bodies if b.isClump), sum(len(m) for m in members.values())


# ---------------------------------------------------------------------------------------------------
# VTKExporter: VTK legacy ASCII files (https://vtk.org/wp-content/uploads/2015/04/file-formats.pdf)


def _reraise(exc, message):
    """Raise `message` as an exception of exc's type (so that `except AttributeError` still catches a
    failing attribute), chained to exc; a RuntimeError where that type cannot take one message."""
    try:
        new = type(exc)(message)
    except Exception:
        new = RuntimeError(message)
    raise new from exc


def _lines1(values):
    return ''.join('%g\n' % x for x in values.tolist())


def _rows(values):
    return ''.join(' '.join('%g' % x for x in row) + '\n' for row in values.tolist())


_KINDS = {(): 'SCALARS', (3,): 'VECTORS', (3, 3): 'TENSORS'}
_KIND_WORDS = {'SCALARS': 'a number', 'VECTORS': 'a 3-vector', 'TENSORS': 'a 3x3 matrix'}


def _numbers(value):
    """value as a float array of shape (), (3,) or (3,3); None if it is none of them."""
    if value is None or isinstance(value, (str, bytes)):
        return None
    try:
        a = numpy.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None
    return a if a.shape in _KINDS else None


def _block(kind, name, values):
    """One data array: SCALARS (with its lookup table), VECTORS, or TENSORS (3 rows and a blank line
    each, as the reference writes them)."""
    if kind == 'SCALARS':
        return 'SCALARS %s double 1\nLOOKUP_TABLE default\n' % name + _lines1(values)
    if kind == 'VECTORS':
        return 'VECTORS %s double\n' % name + _rows(values)
    return 'TENSORS %s double\n' % name + ''.join(_rows(t) + '\n' for t in values)


_yadeNames = None


def _namespace(frame):
    """The globals in which `what` expressions run: yade's names (Vector3, Matrix3, O, utils...), then
    the names of the code that called the exporter (so that its own functions and variables work)."""
    global _yadeNames
    if _yadeNames is None:
        import yade
        _yadeNames = {k: getattr(yade, k) for k in dir(yade) if not k.startswith('_')}
    ns = dict(_yadeNames)
    ns.update(frame.f_globals)
    if frame.f_locals is not frame.f_globals:
        ns.update(frame.f_locals)
    return ns


def _evalArrays(method, what, ns, items, label):
    """Evaluate every expression of `what` (name -> Python expression) for each item (a dict of the
    local names: b, i...), before anything is written. Returns the data arrays as text blocks.
    label(k) names item k in error messages."""
    if not what:
        return []
    if not hasattr(what, 'items'):
        raise TypeError('VTKExporter.%s: what must be a dict name -> expression, not %r' % (method, what))
    blocks = []
    for name, expr in what.items():
        if not isinstance(name, str) or not name or name.split() != [name]:
            raise ValueError('VTKExporter.%s: %r cannot name a VTK array (a non-empty word without spaces)' % (method, name))
        if not isinstance(expr, str):
            raise TypeError('VTKExporter.%s: what[%r] must be a Python expression as a str, not %r' % (method, name, expr))
        try:
            code = compile(expr, '<VTKExporter what[%r]>' % name, 'eval')
        except SyntaxError as e:
            raise SyntaxError('VTKExporter.%s: what[%r] = %r is not a Python expression: %s' % (method, name, expr, e.msg)) from e
        values, kind = [], None
        for k, loc in enumerate(items):
            ns.update(loc)  # as globals, so that a comprehension in the expression sees b (or i) too
            try:
                v = eval(code, ns)
            except Exception as e:
                _reraise(e, 'VTKExporter.%s: what[%r] = %r failed for %s: %s: %s' % (method, name, expr, label(k), type(e).__name__, e))
            a = _numbers(v)
            if a is None:
                raise TypeError('VTKExporter.%s: what[%r] = %r gives %r for %s: only a number, a 3-vector or a 3x3 matrix can be '
                                'written' % (method, name, expr, v, label(k)))
            if kind is None:
                kind = _KINDS[a.shape]
            elif _KINDS[a.shape] != kind:
                raise TypeError('VTKExporter.%s: what[%r] = %r gives %s for %s but %s for %s' % (
                    method, name, expr, _KIND_WORDS[_KINDS[a.shape]], label(k), _KIND_WORDS[kind], label(0)))
            values.append(a)
        blocks.append(_block(kind, name, numpy.array(values, dtype=float)))
    return blocks


def _isAll(method, ids):
    if isinstance(ids, str):
        if ids != 'all':
            raise ValueError("VTKExporter.%s: ids must be 'all' or a list, not %r" % (method, ids))
        return True
    return False


def _bodies(method, ids, shape, stacklevel=3):
    """The bodies of `ids` (a list of ids) whose shape is a `shape`; others are skipped with a warning
    (as the reference does); an id with no body raises IndexError."""
    try:
        ids = list(ids)
    except TypeError:
        raise TypeError("VTKExporter.%s: ids must be 'all' or a list of body ids, not %r" % (method, ids)) from None
    n = len(O.bodies)
    out = []
    for i in ids:
        if not isinstance(i, numbers.Integral) or isinstance(i, bool):
            raise TypeError('VTKExporter.%s: body id %r is not an integer' % (method, i))
        b = O.bodies[int(i)] if 0 <= i < n else None
        if b is None:
            raise IndexError('VTKExporter.%s: no body with id %r (%s)' % (
                method, i, 'ids go from 0 to %d' % (n - 1) if n else 'the scene has no bodies'))
        if not isinstance(b.shape, shape):
            warnings.warn('VTKExporter.%s: body %d is not of type %s: skipped' % (method, i, shape), RuntimeWarning, stacklevel=stacklevel)
            continue
        out.append(b)
    return out


def _header(comment, dataset='POLYDATA'):
    return '# vtk DataFile Version 3.0.\n%s\nASCII\n\nDATASET %s\n' % (str(comment).replace('\r', ' ').replace('\n', ' '), dataset)


def _facetCorners(bodies):
    """The corners of the facets in world coordinates, 3 rows per facet."""
    pts = []
    for b in bodies:
        p, q = b.state.pos, b.state.ori
        pts += [tuple(p + q * v) for v in b.shape.vertices]
    return numpy.array(pts, dtype=float).reshape(-1, 3)


class VTKExporter(object):
    """Write snapshots of the scene to `VTK simple legacy files
    <https://vtk.org/wp-content/uploads/2015/04/file-formats.pdf>`_ (ASCII; ParaView opens them),
    one file per call: spheres, facets, interactions, contact points, the periodic cell. For output
    at every n steps, put a PyRunner with command='vtkExporter.exportSpheres()' in O.engines, or
    use VTKRecorder.

    :param str baseName: the files are named baseName-spheres-00000003.vtk, baseName-facets-...,
        baseName-intrs-..., baseName-cps-... (contact points), baseName-periCell-...
    :param int startSnap: the first number of each kind of file (spheresSnapCount, facetsSnapCount,
        intrsSnapCount, contactPointsSnapCount, polyhedraSnapCount, PotentialBlocksSnapCount start
        at it and count the files written of each kind).

    `what` arguments are dicts name -> Python expression (a str), evaluated with ``b`` the body (or
    ``i`` the interaction), with yade's names and the names of the calling code: a number gives a
    SCALARS array, a 3-vector a VECTORS array, a 3x3 matrix a TENSORS array, e.g.
    ``what=dict(vel='b.state.vel', dist='b.state.pos.norm()')``. Everything is evaluated before the
    file is written: an expression that fails raises its error naming the expression and the body,
    and no file is written."""

    def __init__(self, baseName, startSnap=0):
        self.spheresSnapCount = startSnap
        self.facetsSnapCount = startSnap
        self.intrsSnapCount = startSnap
        self.polyhedraSnapCount = startSnap
        self.PotentialBlocksSnapCount = startSnap
        self.contactPointsSnapCount = startSnap
        self.baseName = baseName

    def _write(self, kind, numLabel, counter, text):
        fileName = '%s-%s-%08d.vtk' % (self.baseName, kind, numLabel if numLabel is not None else counter)
        tmp = fileName + '.part'
        try:
            with open(tmp, 'w') as f:
                f.write(text)
            os.replace(tmp, fileName)
        except BaseException:
            if os.path.exists(tmp):
                os.remove(tmp)
            raise
        return fileName

    def exportSpheres(self, ids='all', what={}, comment='comment', numLabel=None, useRef=False):
        """Write the spheres (positions, radii as the array ``radius``) and the arrays of `what`.

        :param ids: 'all' (every sphere, clump members included), or a list of body ids (bodies that
            are not spheres are skipped with a warning)
        :param dict what: name -> expression of ``b``, e.g. ``dict(v='b.state.vel')``
        :param str comment: the file's comment line
        :param int numLabel: the file's number; if None, spheresSnapCount (which counts the files)
        :param bool useRef: write the bodies' reference positions (state.refPos) instead of positions"""
        from .wrapper import Sphere
        ns = _namespace(sys._getframe(1))
        if _isAll('exportSpheres', ids):
            sid, pos, radius, _ = _sphereColumns(-1)
            bodies = [O.bodies[int(i)] for i in sid] if (what or useRef) else None
        else:
            bodies = _bodies('exportSpheres', ids, Sphere)
            sid = [b.id for b in bodies]
            arrays = O.bodies.arrays()
            pos, radius = arrays.pos[sid], arrays.radius[sid]
        n = len(sid)
        if n == 0:
            warnings.warn('VTKExporter.exportSpheres: no spheres to export, no file written', RuntimeWarning, stacklevel=2)
            return
        if useRef:
            pos = numpy.array([tuple(b.state.refPos) for b in bodies], dtype=float)
        blocks = _evalArrays('exportSpheres', what, ns, [{'b': b} for b in bodies] if what else [], lambda k: 'body %d' % bodies[k].id)
        text = (_header(comment) + 'POINTS %d double\n' % n + _rows(numpy.asarray(pos, dtype=float))
                + '\nPOINT_DATA %d\n' % n + _block('SCALARS', 'radius', numpy.asarray(radius, dtype=float))
                + ''.join('\n' + blk for blk in blocks))
        self._write('spheres', numLabel, self.spheresSnapCount, text)
        self.spheresSnapCount += 1

    def _facets(self, method, ids):
        from .wrapper import Facet
        if _isAll(method, ids):
            return [b for b in O.bodies if b is not None and isinstance(b.shape, Facet)]
        return _bodies(method, ids, Facet, stacklevel=4)

    def exportFacets(self, ids='all', what={}, comment='comment', numLabel=None):
        """Write the facets as triangles (3 points per facet, in world coordinates: a corner shared by
        several facets is written once per facet) and the arrays of `what` (one value per facet).

        :param ids: 'all' or a list of body ids (bodies that are not facets are skipped with a warning)
        :param dict what: name -> expression of ``b``, e.g. ``dict(n='b.shape.normal')``
        :param int numLabel: the file's number; if None, facetsSnapCount"""
        ns = _namespace(sys._getframe(1))
        bodies = self._facets('exportFacets', ids)
        n = len(bodies)
        if n == 0:
            warnings.warn('VTKExporter.exportFacets: no facets to export, no file written', RuntimeWarning, stacklevel=2)
            return
        blocks = _evalArrays('exportFacets', what, ns, [{'b': b} for b in bodies] if what else [], lambda k: 'body %d' % bodies[k].id)
        text = (_header(comment) + 'POINTS %d double\n' % (3 * n) + _rows(_facetCorners(bodies))
                + '\nPOLYGONS %d %d\n' % (n, 4 * n) + ''.join('3 %d %d %d\n' % (3 * k, 3 * k + 1, 3 * k + 2) for k in range(n)))
        if blocks:
            text += '\nCELL_DATA %d\n' % n + '\n'.join(blocks)
        self._write('facets', numLabel, self.facetsSnapCount, text)
        self.facetsSnapCount += 1

    def exportFacetsAsMesh(self, ids='all', connectivityTable=None, what={}, comment='comment', numLabel=None):
        """Write the facets as one mesh: each node once, the triangles as lists of node numbers.

        :param connectivityTable: the 3 node numbers (0, 1, ...) of each facet, in the order of the
            facets written (those of ids); a node takes the coordinates of the corner that names it.
            If None, corners with exactly the same coordinates are one node.
        Other parameters as exportFacets (same file name and counter)."""
        ns = _namespace(sys._getframe(1))
        bodies = self._facets('exportFacetsAsMesh', ids)
        n = len(bodies)
        if n == 0:
            warnings.warn('VTKExporter.exportFacetsAsMesh: no facets to export, no file written', RuntimeWarning, stacklevel=2)
            return
        corners = _facetCorners(bodies)
        if connectivityTable is None:
            index, nodes, table = {}, [], []
            for c in corners.tolist():
                key = tuple(c)
                if key not in index:
                    index[key] = len(nodes)
                    nodes.append(c)
                table.append(index[key])
            nodes = numpy.array(nodes, dtype=float)
            table = numpy.array(table, dtype=int).reshape(-1, 3)
        else:
            try:
                table = numpy.array([[int(j) for j in row] for row in connectivityTable], dtype=int)
            except (TypeError, ValueError) as e:
                raise TypeError('VTKExporter.exportFacetsAsMesh: connectivityTable must be a list of 3 node numbers per facet (%s)' % e) from None
            if table.shape != (n, 3):
                raise ValueError('VTKExporter.exportFacetsAsMesh: connectivityTable has the shape %s for %d facets: it needs one row of 3 '
                                 'node numbers per facet' % (table.shape, n))
            if table.min() < 0:
                raise ValueError('VTKExporter.exportFacetsAsMesh: connectivityTable has a negative node number')
            nodes = numpy.full((table.max() + 1, 3), numpy.nan)
            flat = table.reshape(-1)
            scale = max(1.0, float(numpy.abs(corners).max()))
            for k in range(len(flat)):
                j = flat[k]
                if numpy.isnan(nodes[j, 0]):
                    nodes[j] = corners[k]
                elif numpy.abs(nodes[j] - corners[k]).max() > 1e-9 * scale:
                    raise ValueError('VTKExporter.exportFacetsAsMesh: node %d is corner %d of body %d, at %s, and also a corner at %s: the '
                                     'connectivityTable does not match the facets' % (j, k % 3, bodies[k // 3].id, tuple(corners[k]), tuple(nodes[j])))
            unused = numpy.flatnonzero(numpy.isnan(nodes[:, 0]))
            if len(unused):
                raise ValueError('VTKExporter.exportFacetsAsMesh: node %d is a corner of no facet in connectivityTable' % unused[0])
        blocks = _evalArrays('exportFacetsAsMesh', what, ns, [{'b': b} for b in bodies] if what else [], lambda k: 'body %d' % bodies[k].id)
        text = (_header(comment) + 'POINTS %d double\n' % len(nodes) + _rows(nodes)
                + '\nPOLYGONS %d %d\n' % (n, 4 * n) + ''.join('3 %d %d %d\n' % tuple(row) for row in table.tolist()))
        if blocks:
            text += '\nCELL_DATA %d\n' % n + '\n'.join(blocks)
        self._write('facets', numLabel, self.facetsSnapCount, text)
        self.facetsSnapCount += 1

    def _interactions(self, method, ids, objects):
        """(id1, id2, cellDist (n x 3, of body 2's image seen from body 1), interactions or None,
        contact points or None) of the real interactions of ids; objects: the Interaction objects are
        needed."""
        if _isAll(method, ids):
            arrays = O.interactions.arrays()
            if len(arrays['id1']) == O.interactions.countReal():  # all are ScGeom + NormShearPhys: NumPy arrays
                id1, id2 = numpy.array(arrays['id1'], dtype=int), numpy.array(arrays['id2'], dtype=int)
                cellDist = numpy.array(arrays['cellDist'], dtype=float) if O.periodic else numpy.zeros((len(id1), 3))
                cps = numpy.array(arrays['contactPoint'], dtype=float).reshape(-1, 3)
                intrs = [O.interactions[a, b] for a, b in zip(id1.tolist(), id2.tolist())] if objects else None
                return id1, id2, cellDist, intrs, cps
            intrs = [i for i in O.interactions if i.isReal]
            pairs = [(i.id1, i.id2, i) for i in intrs]
        else:
            try:
                ids = list(ids)
            except TypeError:
                raise TypeError("VTKExporter.%s: ids must be 'all' or a list of (id1, id2) pairs, not %r" % (method, ids)) from None
            pairs = []
            for p in ids:
                try:
                    a, b = p
                    if not all(isinstance(x, numbers.Integral) and not isinstance(x, bool) for x in (a, b)):
                        raise TypeError
                except (TypeError, ValueError):
                    raise TypeError('VTKExporter.%s: %r is not an (id1, id2) pair of body ids' % (method, p)) from None
                try:
                    i = O.interactions[int(a), int(b)]
                except IndexError as e:
                    raise IndexError('VTKExporter.%s: no interaction between bodies %d and %d (%s)' % (method, a, b, e)) from None
                if not i.isReal:
                    raise IndexError('VTKExporter.%s: the interaction between bodies %d and %d is not real (the bodies are only near '
                                     'each other)' % (method, a, b))
                pairs.append((int(a), int(b), i))
        id1 = numpy.array([p[0] for p in pairs], dtype=int)
        id2 = numpy.array([p[1] for p in pairs], dtype=int)
        # body 2's image is pos2 + hSize*cellDist for the interaction's own order; a pair given the other
        # way round (body 2 first) has the opposite shift
        cellDist = numpy.array([tuple(i.cellDist) if a == i.id1 else tuple(-x for x in i.cellDist) for a, b, i in pairs],
                               dtype=float).reshape(-1, 3)
        intrs = [p[2] for p in pairs]
        return id1, id2, cellDist, intrs, None

    def exportInteractions(self, ids='all', what={}, verticesWhat={}, comment='comment', numLabel=None, useRef=False):
        """Write the real interactions as lines (2 points per interaction: the centres of its two
        bodies, written once per interaction; in a periodic scene the second is the image of body 2
        that touches body 1, so that each line has the contact's length), the arrays of `what` (one
        value per line, evaluated with ``i`` the interaction) and those of `verticesWhat` (one value
        per point, evaluated with ``b`` that point's body, ``b1`` and ``b2`` the line's two bodies and
        ``i`` the interaction).

        :param ids: 'all' or a list of (id1, id2) pairs (the line goes from id1 to id2); a pair with
            no real interaction raises IndexError
        :param dict what: e.g. ``dict(fn='i.phys.normalForce.norm()')``
        :param dict verticesWhat: e.g. ``dict(r='b.shape.radius')``
        :param int numLabel: the file's number; if None, intrsSnapCount
        :param bool useRef: the bodies' reference positions (state.refPos) instead of positions"""
        ns = _namespace(sys._getframe(1))
        id1, id2, cellDist, intrs, _ = self._interactions('exportInteractions', ids, bool(what or verticesWhat))
        n = len(id1)
        if n == 0:
            warnings.warn('VTKExporter.exportInteractions: no interactions to export, no file written', RuntimeWarning, stacklevel=2)
            return
        if useRef:
            ref = {int(j): tuple(O.bodies[int(j)].state.refPos) for j in set(id1.tolist()) | set(id2.tolist())}
            p1 = numpy.array([ref[j] for j in id1.tolist()], dtype=float)
            p2 = numpy.array([ref[j] for j in id2.tolist()], dtype=float)
        else:
            pos = O.bodies.arrays().pos
            p1, p2 = numpy.array(pos[id1], dtype=float), numpy.array(pos[id2], dtype=float)
        if O.periodic:
            p2 += cellDist.dot(numpy.asarray(O.cell.hSize, dtype=float).T)
        points = numpy.empty((2 * n, 3))
        points[0::2], points[1::2] = p1, p2

        def pairName(k):
            return 'interaction (%d, %d)' % (id1[k], id2[k])
        cellBlocks = _evalArrays('exportInteractions', what, ns, [{'i': i} for i in intrs] if what else [], pairName)
        pointBlocks = []
        if verticesWhat:
            items = []
            for k, i in enumerate(intrs):
                b1, b2 = O.bodies[int(id1[k])], O.bodies[int(id2[k])]
                items += [{'b': b1, 'b1': b1, 'b2': b2, 'i': i}, {'b': b2, 'b1': b1, 'b2': b2, 'i': i}]
            pointBlocks = _evalArrays('exportInteractions', verticesWhat, ns, items,
                                      lambda k: 'body %d of %s' % ((id1, id2)[k % 2][k // 2], pairName(k // 2)))
        text = (_header(comment) + 'POINTS %d double\n' % (2 * n) + _rows(points)
                + 'LINES %d %d\n' % (n, 3 * n) + ''.join('2 %d %d\n' % (2 * k, 2 * k + 1) for k in range(n)))
        if cellBlocks:
            text += '\nCELL_DATA %d\n' % n + ''.join('\n' + blk for blk in cellBlocks)
        if pointBlocks:
            text += '\nPOINT_DATA %d\n' % (2 * n) + ''.join('\n' + blk for blk in pointBlocks)
        self._write('intrs', numLabel, self.intrsSnapCount, text)
        self.intrsSnapCount += 1

    def exportContactPoints(self, ids='all', what={}, useRef={}, comment='comment', numLabel=None):
        """Write the contact points (i.geom.contactPoint) of the real interactions and the arrays of
        `what` (evaluated with ``i`` the interaction).

        :param ids: 'all' or a list of (id1, id2) pairs, as exportInteractions
        :param dict what: e.g. ``dict(fn='i.phys.normalForce')``
        :param useRef: accepted for the reference's signature; unused (a contact point has no
            reference position)
        :param int numLabel: the file's number; if None, contactPointsSnapCount"""
        ns = _namespace(sys._getframe(1))
        id1, id2, _, intrs, cps = self._interactions('exportContactPoints', ids, True)
        n = len(id1)
        if n == 0:
            warnings.warn('VTKExporter.exportContactPoints: no interactions to export, no file written', RuntimeWarning, stacklevel=2)
            return

        def pairName(k):
            return 'interaction (%d, %d)' % (id1[k], id2[k])
        if cps is None:
            pts = []
            for k, i in enumerate(intrs):
                try:
                    pts.append(tuple(i.geom.contactPoint))
                except AttributeError as e:
                    raise AttributeError('VTKExporter.exportContactPoints: %s has no contact point (%s)' % (pairName(k), e)) from None
            cps = numpy.array(pts, dtype=float).reshape(-1, 3)
        blocks = _evalArrays('exportContactPoints', what, ns, [{'i': i} for i in intrs] if what else [], pairName)
        text = _header(comment) + 'POINTS %d double\n' % n + _rows(cps)
        if blocks:
            text += '\nPOINT_DATA %d\n' % n + ''.join('\n' + blk for blk in blocks)
        self._write('cps', numLabel, self.contactPointsSnapCount, text)
        self.contactPointsSnapCount += 1

    def exportPeriodicCell(self, comment='comment', numLabel=None):
        """Write the periodic cell as one hexahedron (its 8 corners O.cell.hSize*(x,y,z), x, y, z in
        {0,1}). As the reference, the file's number is intrsSnapCount when numLabel is None (the cell
        has no counter of its own, and no counter changes). In a scene that is not periodic: a
        warning, and no file."""
        if not O.periodic:
            warnings.warn('VTKExporter.exportPeriodicCell: the scene is not periodic, no file written', RuntimeWarning, stacklevel=2)
            return
        h = numpy.asarray(O.cell.hSize, dtype=float)
        corners = numpy.array([(0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1), (0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)], dtype=float)
        text = (_header(comment, 'UNSTRUCTURED_GRID') + 'POINTS 8 double\n' + _rows(corners.dot(h.T))
                + '\nCELLS 1 9\n8 0 1 2 3 4 5 6 7\n\nCELL_TYPES 1\n12\n')
        self._write('periCell', numLabel, self.intrsSnapCount, text)

    def exportPolyhedra(self, ids='all', what={}, comment='comment', numLabel=None, useRef=False):
        """Not available: this engine has no Polyhedra shape (raises NotImplementedError)."""
        raise NotImplementedError('VTKExporter.exportPolyhedra: this engine has no Polyhedra shape, so no polyhedra to export')

    def exportPotentialBlocks(self, ids='all', what={}, comment='comment', numLabel=None, useRef=False):
        """Not available: this engine has no PotentialBlock shape (raises NotImplementedError)."""
        raise NotImplementedError('VTKExporter.exportPotentialBlocks: this engine has no PotentialBlock shape, so no potential blocks to export')
