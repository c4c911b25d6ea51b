"""Writing the spheres of the scene to text files (as in Yade's yade.export): text (x y z r per line),
textExt (a choice of formats, read back by yade.ymport.textExt) and textClumps (clump members with
their clump's id, read back by yade.ymport.textClumps)."""
from ._yade import O, _sphereColumns

__all__ = ['text', 'textExt', 'textClumps']

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
