"""Reading bodies from files (as in Yade's yade.ymport): spheres from text files (text, textExt),
facets from text files (textFacets), from STL surfaces (stl, ASCII or binary), MEDIT meshes (gmsh), I-DEAS universal
files (unv) and OpenFOAM meshes (blockMeshDict, polyMesh). Each function
returns a list of bodies to give to O.bodies.append(), except textClumps, which adds its clumps itself."""
import math
import struct

from ._yade import O, Quaternion, Vector3
from . import utils

__all__ = ['text', 'textExt', 'textClumps', 'textFacets', 'stl', 'gmsh', 'unv', 'blockMeshDict', 'polyMesh']


class ImportFormatError(ValueError):
    """A file or format that cannot be read."""


def _rows(filename):
    """(line number, list of fields) of the lines of a text file that are neither empty nor comments
    (starting with #); also the format named by a '#format <name>' line, if any."""
    rows, fileFormat = [], None
    with open(filename) as f:
        for n, line in enumerate(f, 1):
            fields = line.split()
            if not fields:
                continue
            if fields[0].startswith('#'):
                if fields[0] == '#format' and len(fields) > 1:
                    fileFormat = fields[1]
                continue
            rows.append((n, fields))
    return rows, fileFormat


def _numbers(filename, n, fields, count, what, kind=float, exact=False):
    """The first `count` fields of line n as numbers of type `kind` (all of them and exactly `count` if `exact`)."""
    if len(fields) < count or (exact and len(fields) != count):
        raise ImportFormatError('%s:%d: %s needs %s%d columns, the line has %d'
                                % (filename, n, what, 'exactly ' if exact else '', count, len(fields)))
    try:
        return [kind(x) for x in fields[:count]]
    except ValueError as e:
        raise ImportFormatError('%s:%d: %s' % (filename, n, e))


_sphereFormats = ('x_y_z_r', 'x_y_z_r_matId', 'x_y_z_r_attrs')


def textExt(filename, format='x_y_z_r', shift=Vector3.Zero, scale=1.0, attrs=None, **kw):
    """Spheres from a text file written by export.textExt: columns x y z r, then (format
    'x_y_z_r_matId') the index of the material in O.materials, or ('x_y_z_r_attrs') more columns,
    appended to the list `attrs` as strings, one list per sphere. Each sphere is
    utils.sphere(shift + scale·(x, y, z), scale·r, **kw). Lines starting with # are skipped."""
    if format not in _sphereFormats:
        raise ImportFormatError('ymport.textExt: unknown format %r; use one of %s' % (format, ', '.join(_sphereFormats)))
    shift = Vector3(shift)
    rows, _ = _rows(filename)
    ret = []
    for n, fields in rows:
        x, y, z, r = _numbers(filename, n, fields, 4, 'a sphere')
        kwi = dict(kw)
        if format == 'x_y_z_r_matId':
            if len(fields) < 5:
                raise ImportFormatError('%s:%d: format x_y_z_r_matId needs 5 columns, the line has %d' % (filename, n, len(fields)))
            kwi['material'] = int(fields[4])
        elif format == 'x_y_z_r_attrs' and attrs is not None:
            attrs.append(fields[4:])
        ret.append(utils.sphere(shift + scale * Vector3(x, y, z), scale * r, **kwi))
    return ret


def text(filename, shift=Vector3.Zero, scale=1.0, **kw):
    """Spheres from a text file of lines 'x y z r' (textExt with format 'x_y_z_r')."""
    return textExt(filename, format='x_y_z_r', shift=shift, scale=scale, **kw)


def textClumps(fileName, shift=Vector3.Zero, discretization=0, orientation=Quaternion.Identity, scale=1.0, **kw):
    """Clumps from a text file of lines 'x y z r clumpId' (as export.textClumps writes them): each run
    of consecutive lines with the same clumpId becomes one clump, added to the simulation by
    O.bodies.appendClumped(spheres, discretization=discretization), the spheres made by
    utils.sphere(shift + orientation·(scale·(x, y, z)), scale·r, **kw). Lines starting with # are
    skipped. Returns the list of what appendClumped returned: [(clumpId, [memberIds]), ...]."""
    if not hasattr(O.bodies, 'appendClumped'):
        raise NotImplementedError('ymport.textClumps: this build has no O.bodies.appendClumped yet, so clumps cannot be made')
    if not isinstance(orientation, Quaternion):
        raise TypeError('ymport.textClumps: orientation must be a Quaternion, got %s' % type(orientation).__name__)
    shift = Vector3(shift)
    groups, last = [], None
    for n, fields in _rows(fileName)[0]:
        if len(fields) < 5:
            raise ImportFormatError('%s:%d: a clump member needs 5 columns (x y z r clumpId), the line has %d' % (fileName, n, len(fields)))
        x, y, z, r, clump = _numbers(fileName, n, fields, 5, 'a clump member')
        if not groups or clump != last:
            groups.append([])
        groups[-1].append((Vector3(x, y, z), r))
        last = clump
    return [O.bodies.appendClumped([utils.sphere(shift + orientation * (scale * c), scale * r, **kw) for c, r in g],
                                   discretization=discretization) for g in groups]


_facetFormats = ('x1_y1_z1_x2_y2_z2_x3_y3_z3', 'x1_y1_z1_x2_y2_z2_x3_y3_z3_matId', 'id_x1_y1_z1_x2_y2_z2_x3_y3_z3_matId',
                 'x1_y1_z1_x2_y2_z2_x3_y3_z3_attrs')


def textFacets(filename, format='x1_y1_z1_x2_y2_z2_x3_y3_z3', shift=Vector3.Zero, scale=1.0, attrs=None, **kw):
    """Facets from a text file, one triangle per line: the 9 coordinates of its vertices, with
    (formats ..._matId) the index of the material in O.materials last, (id_..._matId) an id first
    (ignored), or (..._attrs) more columns, appended to `attrs` as strings. Each facet is
    utils.facet([shift + scale·vertex, ...], **kw). Lines starting with # are skipped."""
    if format not in _facetFormats:
        raise ImportFormatError('ymport.textFacets: unknown format %r; use one of %s' % (format, ', '.join(_facetFormats)))
    shift = Vector3(shift)
    rows, _ = _rows(filename)
    ret = []
    for n, fields in rows:
        kwi = dict(kw)
        if format.startswith('id_'):
            fields = fields[1:]
        c = _numbers(filename, n, fields, 9, 'a facet')
        if format.endswith('_matId'):
            if len(fields) < 10:
                raise ImportFormatError('%s:%d: format %s needs the material index after the 9 coordinates' % (filename, n, format))
            kwi['material'] = int(fields[9])
        elif format.endswith('_attrs') and attrs is not None:
            attrs.append(fields[9:])
        ret.append(utils.facet([shift + scale * Vector3(c[3 * i], c[3 * i + 1], c[3 * i + 2]) for i in range(3)], **kwi))
    return ret


def _stlTriangles(filename):
    """The triangles (3 tuples of 3 floats) of an ASCII or binary STL file. The coordinates are single precision, as
    STL's are (and as the reference reads ASCII files too: 4.097997188568115 becomes 4.0979971885681152)."""
    with open(filename, 'rb') as f:
        data = f.read()
    if len(data) >= 84:
        count = struct.unpack_from('<I', data, 80)[0]
        if len(data) == 84 + 50 * count:  # a binary file: 80-byte header, count, 50 bytes per triangle
            tris = []
            for i in range(count):
                v = struct.unpack_from('<12f', data, 84 + 50 * i)
                tris.append((v[3:6], v[6:9], v[9:12]))
            return tris
    words = data.decode('ascii', errors='replace').split()
    if not words or words[0].lower() != 'solid':
        raise ImportFormatError('%s: neither an ASCII STL file (starting with "solid") nor a binary one (80-byte header, '
                                'triangle count, 50 bytes per triangle)' % filename)
    verts = []
    for i, w in enumerate(words):
        if w.lower() == 'vertex':
            try:
                verts.append(struct.unpack('<3f', struct.pack('<3f', *(float(x) for x in words[i + 1:i + 4]))))
            except ValueError as e:
                raise ImportFormatError('%s: bad vertex: %s' % (filename, e))
    if len(verts) % 3:
        raise ImportFormatError('%s: %d vertices, not a whole number of triangles' % (filename, len(verts)))
    return [tuple(verts[i:i + 3]) for i in range(0, len(verts), 3)]


def stl(file, dynamic=None, fixed=True, wire=True, color=None, highlight=False, noBound=False, material=-1, scale=1.0,
        shift=Vector3.Zero):
    """Facets of the triangles of an STL surface (ASCII or binary): utils.facet of
    shift + scale·vertex for each triangle, with the given display, mask and material options.
    Degenerate triangles (zero area) are skipped."""
    shift = Vector3(shift)
    ret = []
    for tri in _stlTriangles(file):
        vs = [shift + scale * Vector3(v) for v in tri]
        if (vs[1] - vs[0]).cross(vs[2] - vs[0]).norm() == 0:
            continue
        ret.append(utils.facet(vs, dynamic=dynamic, fixed=fixed, wire=wire, color=color, highlight=highlight, noBound=noBound,
                               material=material))
    return ret


def gmsh(meshfile='file.mesh', shift=Vector3.Zero, scale=1.0, orientation=Quaternion.Identity, **kw):
    """Facets of the triangles of a mesh in the MEDIT text format (.mesh, as GMSH writes it): the
    'Vertices' section (count, then 'x y z ref' lines) and the 'Triangles' section (count, then
    'i j k ref' lines, 1-based vertex numbers); each vertex becomes shift + orientation·(scale·v).
    Extra keywords go to utils.facet."""
    with open(meshfile) as f:
        words = f.read().split()
    shift, q = Vector3(shift), Quaternion(orientation)

    def section(name, width):
        if name not in words:
            raise ImportFormatError('%s: no %s section (not a MEDIT .mesh file?)' % (meshfile, name))
        i = words.index(name)
        try:
            n = int(words[i + 1])
            rows = [words[i + 2 + width * k:i + 2 + width * (k + 1)] for k in range(n)]
            if n and len(rows[-1]) < width:
                raise IndexError
            return rows
        except (ValueError, IndexError):
            raise ImportFormatError('%s: the %s section is cut short or not numbers' % (meshfile, name))

    try:
        vertices = [shift + q * (scale * Vector3(*[float(x) for x in row[:3]])) for row in section('Vertices', 4)]
        triangles = [[int(x) - 1 for x in row[:3]] for row in section('Triangles', 4)]
    except ValueError as e:
        raise ImportFormatError('%s: %s' % (meshfile, e))
    for t in triangles:
        if min(t) < 0 or max(t) >= len(vertices):
            raise ImportFormatError('%s: a triangle refers to vertex %d, there are %d' % (meshfile, max(t) + 1, len(vertices)))
    return [utils.facet([vertices[i] for i in t], **kw) for t in triangles]


# I-DEAS universal files (.unv): datasets, each between two lines '-1', its number on the line after the first.
_UNV_BEAMS = (11, 21, 22, 23, 24, 31, 32)  # FE descriptors (rods, beams, pipes) whose element has a beam record
_UNV_TRIANGLE = 41  # plane stress linear triangle: the one element the reference makes facets of
_UNV_FACES = frozenset(d for t in range(40, 100, 10) for d in range(t + 1, t + 7))  # 2D elements: 41-46, ..., 91-96


def _unvDatasets(fileName):
    """[(dataset number, line of its opening -1, [(line number, fields), ...] of its non-empty lines)] of a .unv file."""
    with open(fileName, errors='replace') as f:
        lines = f.read().splitlines()
    if not any(line.strip() for line in lines):
        raise ImportFormatError('%s: empty file, no UNV dataset in it' % fileName)
    datasets, i = [], 0
    while i < len(lines):
        if not lines[i].strip():
            i += 1
            continue
        if lines[i].split() != ['-1']:
            raise ImportFormatError('%s:%d: expected the line -1 that opens a dataset, got %r'
                                    % (fileName, i + 1, lines[i].strip()[:60]))
        start = i + 1
        head = lines[i + 1].split() if i + 1 < len(lines) else []
        if not head or head == ['-1']:
            raise ImportFormatError('%s:%d: a dataset opened by -1 has no dataset number on the next line' % (fileName, start))
        try:
            number = int(head[0])
        except ValueError:
            raise ImportFormatError('%s:%d: the dataset number %r is not an integer' % (fileName, start + 1, head[0]))
        body, k = [], i + 2
        while k < len(lines) and lines[k].split() != ['-1']:
            if lines[k].strip():
                body.append((k + 1, lines[k].split()))
            k += 1
        if k >= len(lines):
            raise ImportFormatError('%s:%d: dataset %d is not closed by a line -1 (the file is cut short?)'
                                    % (fileName, start, number))
        datasets.append((number, start, body))
        i = k + 1
    return datasets


def unv(fileName, shift=(0, 0, 0), scale=1.0, returnConnectivityTable=False, **kw):
    r"""Import geometry from unv file, return list of created facets.

    :param string fileName: name of unv file
    :param (float,float,float)|Vector3 shift: (X,Y,Z) parameter moves the specimen.
    :param float scale: factor scales the given data.
    :param \*\*kw: (unused keyword arguments) is passed to :yref:`yade.utils.facet`
    :param bool returnConnectivityTable: if True, apart from facets returns also nodes (list of (x,y,z) nodes
        coordinates) and elements (list of (id1,id2,id3) element nodes ids). If False (default), returns only facets

    unv files are mainly used for FEM analyses (OOFEM, Abaqus); they can be created e.g. with Salome. Read here: the
    nodes of every dataset 2411 (in the file's order, shift + scale·(x, y, z); Fortran 'D' exponents accepted) and
    the elements of every dataset 2412; each linear triangle of FE descriptor 41 (plane stress, what Salome writes)
    becomes utils.facet of its 3 nodes in their order, and (id1, id2, id3) are indices into the list of nodes. As in
    the reference, other elements are skipped: other triangles (e.g. 91, thin shell, as gmsh writes them),
    quadrilaterals (44, 94), beams, solids; skipped 2D elements give a RuntimeWarning. Other datasets (units 164,
    coordinate systems 2420, groups 2467, ...) are skipped.

    Unlike the reference, an element's nodes are found by their labels (the reference takes label - 1 as an index,
    which is right only for nodes numbered 1, 2, 3... in order), the elements after a skipped one are read (the
    reference loses some: the two triangles after one skipped 2D or solid element, in the files tried), 'D'
    exponents are read (a ValueError there), and a bad file raises ImportFormatError (a ValueError) naming the file
    and line, before any facet is made: an empty file or one that is not UNV (an empty list there), a dataset
    without its opening or closing -1 line (read anyway there when at the file's start or end), a field that is not
    a number or a coordinate that is not finite, a node label defined twice, an element referring to a node no
    dataset 2411 defines (an IndexError there, or node 0 taken as the last one), a record with too few or too many
    fields, a triangle with other than 3 nodes (the first 3 there), with a node twice or of zero area."""
    datasets = _unvDatasets(fileName)
    shift = Vector3(shift)
    coords, index = [], {}  # the nodes' coordinates as in the file; node label -> index in coords
    for number, _, body in datasets:
        if number != 2411:
            continue
        if len(body) % 2:
            raise ImportFormatError('%s:%d: dataset 2411 ends with a node record without its coordinates line'
                                    % (fileName, body[-1][0]))
        for (n1, f1), (n2, f2) in zip(body[0::2], body[1::2]):
            label = _numbers(fileName, n1, f1, 4, "a node's record (label, coordinate systems, color)", int, True)[0]
            if label in index:
                raise ImportFormatError('%s:%d: node %d is defined twice' % (fileName, n1, label))
            xyz = _numbers(fileName, n2, [x.replace('D', 'E').replace('d', 'e') for x in f2], 3, "a node's coordinates",
                           float, True)
            if not all(math.isfinite(x) for x in xyz):
                raise ImportFormatError("%s:%d: node %d's coordinates are not finite" % (fileName, n2, label))
            index[label] = len(coords)
            coords.append(Vector3(*xyz))
    triangles, skipped = [], {}  # [(i1, i2, i3)] indices in coords; skipped 2D elements: FE descriptor -> count
    for number, _, body in datasets:
        if number != 2412:
            continue
        r = 0
        while r < len(body):
            n, f = body[r]
            label, kind, _, _, _, count = _numbers(fileName, n, f, 6, 'an element record (label, FE descriptor, physical and '
                                                   'material properties, color, number of nodes)', int, True)
            if count < 1:
                raise ImportFormatError('%s:%d: element %d has %d nodes' % (fileName, n, label, count))
            r += 1
            if kind in _UNV_BEAMS:  # the beam record: orientation node, end releases
                if r >= len(body):
                    raise ImportFormatError('%s:%d: element %d (a beam) has no beam record after it' % (fileName, n, label))
                _numbers(fileName, body[r][0], body[r][1], 3, 'the beam record of element %d' % label, int, True)
                r += 1
            labels = []
            while len(labels) < count:
                if r >= len(body):
                    raise ImportFormatError('%s:%d: element %d has %d nodes, the dataset ends after %d'
                                            % (fileName, n, label, count, len(labels)))
                nr, fr = body[r]
                for x in _numbers(fileName, nr, fr, len(fr), 'a line of node labels', int):
                    if x not in index:
                        raise ImportFormatError('%s:%d: element %d refers to node %d, which no dataset 2411 defines'
                                                % (fileName, nr, label, x))
                    labels.append(x)
                r += 1
            if len(labels) != count:
                raise ImportFormatError('%s:%d: element %d has %d nodes, its node lines list %d'
                                        % (fileName, n, label, count, len(labels)))
            if kind == _UNV_TRIANGLE:
                if count != 3:
                    raise ImportFormatError('%s:%d: element %d, a linear triangle (FE descriptor 41), has %d nodes, not 3'
                                            % (fileName, n, label, count))
                ids = tuple(index[x] for x in labels)
                v = [coords[i] for i in ids]
                if len(set(labels)) < 3 or (v[1] - v[0]).cross(v[2] - v[0]).norm() == 0:
                    raise ImportFormatError('%s:%d: element %d is a triangle of zero area (nodes %s)'
                                            % (fileName, n, label, ' '.join(str(x) for x in labels)))
                triangles.append(ids)
            elif kind in _UNV_FACES:
                skipped[kind] = skipped.get(kind, 0) + 1
    if skipped:
        import warnings
        what = ', '.join('%d element%s of FE descriptor %d' % (c, 's' if c > 1 else '', d) for d, c in sorted(skipped.items()))
        warnings.warn('ymport.unv: %s: skipped %s: as in the reference, only linear triangles of FE descriptor 41 become '
                      'facets' % (fileName, what), RuntimeWarning, stacklevel=2)
    nodes = [shift + scale * v for v in coords]
    facets = [utils.facet([nodes[i] for i in t], **kw) for t in triangles]
    if returnConnectivityTable:
        return facets, [tuple(v) for v in nodes], triangles
    return facets


# OpenFOAM dictionaries: comments removed, then tokens, with '(' ')' '{' '}' ';' as tokens of their own.
def _foamTokens(path):
    import re
    with open(path) as f:
        text = f.read()
    text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
    text = re.sub(r'//[^\n]*', ' ', text)
    return re.findall(r'[(){};]|[^\s(){};]+', text)


def _foamList(tokens, i, path):
    """The nested list starting at tokens[i] == '(' (an optional count before it is skipped), and the
    index after its ')'; numbers are floats, a 'N(' prefix (faces of polyMesh) is dropped."""
    if tokens[i] != '(':
        raise ImportFormatError('%s: expected "(" at token %d, got %r' % (path, i, tokens[i]))
    out, i = [], i + 1
    while i < len(tokens) and tokens[i] != ')':
        if tokens[i] == '(':
            item, i = _foamList(tokens, i, path)
            out.append(item)
        else:
            t = tokens[i]
            if i + 1 < len(tokens) and tokens[i + 1] == '(' and t.isdigit():
                i += 1  # (the number of items of the list that follows)
                continue
            try:
                out.append(float(t))
            except ValueError:
                out.append(t)
            i += 1
    if i >= len(tokens):
        raise ImportFormatError('%s: a list is not closed' % path)
    return out, i + 1


def _foamEntry(tokens, key, path):
    """The list after `key` (skipping a count), at the top level of the file."""
    for i, t in enumerate(tokens):
        if t == key:
            j = i + 1
            while j < len(tokens) and tokens[j] != '(':
                j += 1
            if j < len(tokens):
                return _foamList(tokens, j, path)[0]
    raise ImportFormatError('%s: no "%s" entry' % (path, key))


def _wantedPatch(kind, patchasWall, emptyasWall):
    return kind == 'wall' or (kind == 'patch' and patchasWall) or (kind == 'empty' and emptyasWall)


def blockMeshDict(path, patchasWall=True, emptyasWall=True, **kw):
    """Facets of the boundary faces of an OpenFOAM blockMeshDict (its 'vertices', scaled by
    'convertToMeters' or 'scale', and the faces of its 'boundary' patches): two facets per
    quadrilateral (v0 v1 v2, v2 v3 v0). Patches of type wall always, 'patch' ones if patchasWall,
    'empty' ones if emptyasWall. Extra keywords go to utils.facet."""
    tokens = _foamTokens(path)
    factor = 1.0
    for key in ('convertToMeters', 'scale'):
        if key in tokens:
            factor = float(tokens[tokens.index(key) + 1])
    vertices = [factor * Vector3(*v) for v in _foamEntry(tokens, 'vertices', path)]
    ret = []
    i = tokens.index('boundary') if 'boundary' in tokens else -1
    if i < 0:
        raise ImportFormatError('%s: no "boundary" entry' % path)
    if tokens[i + 1] != '(':
        raise ImportFormatError('%s: "boundary" is not followed by a list' % path)
    # boundary ( name { type X; faces ( (a b c d) ... ); } ... ): walk the tokens of each patch
    j = i + 2
    while j < len(tokens) and tokens[j] != ')':
        name = tokens[j]
        if tokens[j + 1] != '{':
            raise ImportFormatError('%s: patch %r has no {...} block' % (path, name))
        k, kind, faces = j + 2, None, []
        while tokens[k] != '}':
            if tokens[k] == 'type':
                kind = tokens[k + 1]
            if tokens[k] == 'faces':
                faces, k = _foamList(tokens, k + 1, path)
                continue
            k += 1
        if _wantedPatch(kind, patchasWall, emptyasWall):
            for f in faces:
                v = [vertices[int(x)] for x in f]
                for t in range(1, len(v) - 1):  # (v0 v1 v2), (v2 v3 v0) for a quadrilateral
                    ret.append(utils.facet((v[0], v[t], v[t + 1]) if t == 1 else (v[t], v[t + 1], v[0]), **kw))
        j = k + 1
    return ret


def polyMesh(path, patchasWall=True, emptyasWall=True, **kw):
    """Facets of the boundary faces of an OpenFOAM polyMesh directory (files points, faces and
    boundary): each face of n vertices becomes n facets around its center. Patches of type wall
    always, 'patch' ones if patchasWall, 'empty' ones if emptyasWall. Extra keywords go to utils.facet."""
    import os
    pt = _foamTokens(os.path.join(path, 'points'))
    ft = _foamTokens(os.path.join(path, 'faces'))
    bt = _foamTokens(os.path.join(path, 'boundary'))

    def body(tokens, what):
        """The main list of a polyMesh file: the first '(' after the FoamFile header's '}'."""
        start = tokens.index('}') + 1 if 'FoamFile' in tokens else 0
        j = start
        while j < len(tokens) and tokens[j] != '(':
            j += 1
        if j >= len(tokens):
            raise ImportFormatError('%s: no list in the %s file' % (path, what))
        return _foamList(tokens, j, path)[0]

    points = [Vector3(*p) for p in body(pt, 'points')]
    faces = body(ft, 'faces')
    ret = []
    bl = body(bt, 'boundary')
    # bl is [name, '{', 'type', kind, ';', ..., 'nFaces', n, ';', 'startFace', s, ';', '}', ...]
    k = 0
    while k < len(bl):
        if bl[k] == '{':
            end = bl.index('}', k)
            block = bl[k + 1:end]
            info = {block[m]: block[m + 1] for m in range(len(block) - 1) if isinstance(block[m], str) and block[m] in ('type', 'nFaces', 'startFace')}
            if _wantedPatch(info.get('type'), patchasWall, emptyasWall):
                start, n = int(info['startFace']), int(info['nFaces'])
                for f in faces[start:start + n]:
                    v = [points[int(x)] for x in f]
                    c = sum(v, Vector3.Zero) / len(v)
                    for t in range(len(v)):
                        ret.append(utils.facet((v[t], v[(t + 1) % len(v)], c), **kw))
            k = end + 1
        else:
            k += 1
    return ret
