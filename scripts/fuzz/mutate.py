"""Mutations of saved scenes (doc/file-format.md), for scripts/fuzz/fuzz_loader.py.

An XML file is decoded into the same tree of nodes the C++ reader builds (tag, attributes, text,
children), mutated at the level of that tree (numbers, versions, tags, classes, ids, counts,
duplicated or removed children), encoded again (XML, or the binary tree of format version 1,
which the reader still reads). A binary file (the block format) is cut into its blocks, whose
payloads are damaged, dropped, duplicated or swapped, and whose checksums are then made right, so
that the damage reaches the checks of the content. Either is then possibly damaged byte by
byte (truncation, bit flips, inserted or removed bytes) and compressed (gzip, bzip2), and the
compressed stream itself possibly damaged. Everything is drawn from one random.Random, so a case
is replayed from its seed.

No import of yade: this module only handles bytes.
"""
import bz2
import gzip
import random
import xml.etree.ElementTree as ET

import struct
import zlib

BINARY_MAGIC = b'YADE-CLONE-BINARY\n'  # the tree (format version 1)
BLOCKS_MAGIC = b'YADE-CLONE-BLOCKS\n'  # the block format (version 2)
XML_HEADER = b'<?xml version="1.0" encoding="UTF-8"?>\n'

# Values that break readers: integer limits, non-finite and extreme floats, junk.
SPECIAL_NUMBERS = ['2147483647', '2147483648', '-2147483649', '4294967296', str(2 ** 63), str(2 ** 63 - 1),
                   str(-2 ** 63), str(2 ** 64), '-1', '-2', '0', '-0', 'nan', '-nan', 'inf', '-inf', '1e308',
                   '-1e308', '1e309', '5e-324', '1e-320', '0.5', '1.5', '99999999999999999999999999', '',
                   '0x10', '1e', '--1', '1 2', '1,5', 'nan(0x1)', 'infinity', '9e15', '9e16']
HUGE_COUNTS = [2 ** 31, 2 ** 32, 2 ** 63, 2 ** 64 - 1, 10 ** 6, 10 ** 9]


class Node:
    """One node of a saved scene: tag, attributes (name -> str), text, children."""
    __slots__ = ('tag', 'attrs', 'text', 'children', 'countOverride')

    def __init__(self, tag, attrs=None, text='', children=None):
        self.tag, self.attrs, self.text = tag, dict(attrs or {}), text
        self.children = list(children or [])
        self.countOverride = None  # (attributes, children) counts written instead of the real ones

    def copy(self):
        n = Node(self.tag, self.attrs, self.text, [c.copy() for c in self.children])
        n.countOverride = self.countOverride
        return n

    def walk(self, parent=None):
        """Every (node, parent) pair, depth first."""
        yield self, parent
        for c in self.children:
            yield from c.walk(self)


# ------------------------------------------------------------------ the two encodings

def _readSize(data, pos):
    v, shift = 0, 0
    while True:
        byte = data[pos]
        pos += 1
        v |= (byte & 0x7f) << shift
        shift += 7
        if not byte & 0x80:
            return v, pos


def _readString(data, pos):
    n, pos = _readSize(data, pos)
    return data[pos:pos + n], pos + n


def _text(b):
    return b.decode('utf-8', 'surrogateescape')


def _bytes(s):
    return s.encode('utf-8', 'surrogateescape')


def fromBinary(data):
    def node(pos):
        tag, pos = _readString(data, pos)
        na, pos = _readSize(data, pos)
        attrs = {}
        for _ in range(na):
            k, pos = _readString(data, pos)
            v, pos = _readString(data, pos)
            attrs[_text(k)] = _text(v)
        text, pos = _readString(data, pos)
        nc, pos = _readSize(data, pos)
        children = []
        for _ in range(nc):
            c, pos = node(pos)
            children.append(c)
        return Node(_text(tag), attrs, _text(text), children), pos
    root, _ = node(len(BINARY_MAGIC))
    return root


def _putSize(out, v):
    while True:
        byte = v & 0x7f
        v >>= 7
        out.append(byte | (0x80 if v else 0))
        if not v:
            return


def _putString(out, s):
    b = _bytes(s)
    _putSize(out, len(b))
    out += b


def toBinary(root):
    out = bytearray(BINARY_MAGIC)

    def node(n):
        _putString(out, n.tag)
        na, nc = n.countOverride or (len(n.attrs), len(n.children))
        _putSize(out, na)
        for k in sorted(n.attrs):
            _putString(out, k)
            _putString(out, n.attrs[k])
        _putString(out, n.text)
        _putSize(out, nc)
        for c in n.children:
            node(c)
    node(root)
    return bytes(out)


def fromXml(data):
    def convert(e):
        return Node(e.tag, e.attrib, e.text or '' if len(e) == 0 else '', [convert(c) for c in e])
    return convert(ET.fromstring(data))


def _escape(s):
    return s.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;').replace('"', '&quot;')


def toXml(root):
    out = [XML_HEADER.decode()]

    def node(n, depth):
        attrs = ''.join(' %s="%s"' % (k, _escape(n.attrs[k])) for k in sorted(n.attrs))
        if not n.text and not n.children:
            out.append('%s<%s%s/>\n' % (' ' * depth, n.tag, attrs))
            return
        out.append('%s<%s%s>%s' % (' ' * depth, n.tag, attrs, _escape(n.text)))
        if n.children:
            out.append('\n')
            for c in n.children:
                node(c, depth + 1)
            out.append(' ' * depth)
        out.append('</%s>\n' % n.tag)
    node(root, 0)
    return _bytes(''.join(out))


def decode(data):
    """(tree, 'binary' or 'xml') of an uncompressed saved scene."""
    if data.startswith(BINARY_MAGIC):
        return fromBinary(data), 'binary'
    return fromXml(data), 'xml'


_decoded = {}


def decodedCopy(data):
    """decode(data), parsed once per seed and copied (copying is faster than parsing)."""
    if data not in _decoded:
        _decoded[data] = decode(data)
    root, encoding = _decoded[data]
    return root.copy(), encoding


def encode(root, encoding):
    return toBinary(root) if encoding == 'binary' else toXml(root)


# ------------------------------------------------------------------ mutations of the tree

def _numberSlots(root):
    """(node, attribute name or None for the text) of every value that holds numbers."""
    slots = []
    for n, _ in root.walk():
        for k, v in n.attrs.items():
            if k not in ('name', 'class') and _hasNumber(v):
                slots.append((n, k))
        if _hasNumber(n.text):
            slots.append((n, None))
    return slots


def _hasNumber(s):
    return any(c.isdigit() for c in s[:40]) or 'nan' in s or 'inf' in s


def _get(n, k):
    return n.text if k is None else n.attrs[k]


def _set(n, k, v):
    if k is None:
        n.text = v
    else:
        n.attrs[k] = v


def replaceNumber(rng, root):
    slots = _numberSlots(root)
    if not slots:
        return 'no number'
    n, k = rng.choice(slots)
    tokens = _get(n, k).split(' ')
    i = rng.randrange(len(tokens))
    tokens[i] = rng.choice(SPECIAL_NUMBERS)
    _set(n, k, ' '.join(tokens))
    return 'number <%s %s>[%d]=%s' % (n.tag, k or 'text', i, tokens[i])


def wrongVersion(rng, root):
    v = rng.choice(['0', '2', '-1', '1000000', 'x', '', '1.5', str(2 ** 63), ' 1', None])
    if v is None:
        root.attrs.pop('formatVersion', None)
    else:
        root.attrs['formatVersion'] = v
    return 'formatVersion=%r' % v


TAGS = ['yade', 'scene', 'obj', 'ref', 'null', 'a', 'tags', 'tag', 'energy', 'term', 'materials', 'bodies',
        'interactions', 'engines', 'permanentForces', 'f', 's', 'x']


def renameTag(rng, root):
    nodes = [n for n, _ in root.walk()]
    n = rng.choice(nodes)
    old, n.tag = n.tag, rng.choice(TAGS)
    return 'tag <%s> -> <%s>' % (old, n.tag)


def swapTags(rng, root):
    nodes = [n for n, _ in root.walk()]
    a, b = rng.choice(nodes), rng.choice(nodes)
    a.tag, b.tag = b.tag, a.tag
    return 'swapped <%s> <%s>' % (a.tag, b.tag)


def _withChildren(root):
    return [n for n, _ in root.walk() if n.children]


def deleteChild(rng, root):
    parents = _withChildren(root)
    if not parents:
        return 'no children'
    p = rng.choice(parents)
    c = p.children.pop(rng.randrange(len(p.children)))
    return 'deleted <%s> from <%s>' % (c.tag, p.tag)


def duplicateChild(rng, root):
    """A child copied among its siblings: duplicated bodies, interactions, ids, attributes."""
    parents = _withChildren(root)
    if not parents:
        return 'no children'
    p = rng.choice(parents)
    c = rng.choice(p.children)
    p.children.insert(rng.randrange(len(p.children) + 1), c.copy())
    return 'duplicated <%s> in <%s>' % (c.tag, p.tag)


def moveChild(rng, root):
    parents = _withChildren(root)
    if not parents:
        return 'no children'
    p = rng.choice(parents)
    c = p.children.pop(rng.randrange(len(p.children)))
    inside = {id(n) for n, _ in c.walk()}  # (not into itself: the tree must stay a tree)
    q = rng.choice([n for n, _ in root.walk() if id(n) not in inside])
    q.children.insert(rng.randrange(len(q.children) + 1), c)
    return 'moved <%s> from <%s> to <%s>' % (c.tag, p.tag, q.tag)


def swapSiblings(rng, root):
    parents = _withChildren(root)
    if not parents:
        return 'no children'
    p = rng.choice(parents)
    i, j = rng.randrange(len(p.children)), rng.randrange(len(p.children))
    p.children[i], p.children[j] = p.children[j], p.children[i]
    return 'swapped children %d %d of <%s>' % (i, j, p.tag)


def changeClass(rng, root):
    objs = [n for n, _ in root.walk() if 'class' in n.attrs]
    if not objs:
        return 'no object'
    names = sorted({n.attrs['class'] for n in objs}) + ['NoSuchClass', '', 'Serializable', 'Functor', 'Engine', 'Shape']
    n = rng.choice(objs)
    old, n.attrs['class'] = n.attrs['class'], rng.choice(names)
    return 'class %s -> %s' % (old, n.attrs['class'])


def changeId(rng, root):
    """An object id or a reference changed: dangling, forward or duplicated references."""
    nodes = [n for n, _ in root.walk() if 'id' in n.attrs]
    if not nodes:
        return 'no id'
    ids = [n.attrs['id'] for n in nodes]
    n = rng.choice(nodes)
    n.attrs['id'] = rng.choice(ids + ['-1', str(2 ** 31), str(2 ** 63), 'x', ''])
    return 'id of <%s> -> %s' % (n.tag, n.attrs['id'])


def changeAttrName(rng, root):
    named = [n for n, _ in root.walk() if 'name' in n.attrs and n.tag == 'a']
    if not named:
        return 'no attribute'
    n = rng.choice(named)
    other = rng.choice(named).attrs['name']
    old, n.attrs['name'] = n.attrs['name'], rng.choice([other, 'noSuchAttribute', ''])
    return 'attribute %s -> %s' % (old, n.attrs['name'])


def dropAttr(rng, root):
    nodes = [n for n, _ in root.walk() if n.attrs]
    if not nodes:
        return 'no attributes'
    n = rng.choice(nodes)
    k = rng.choice(sorted(n.attrs))
    del n.attrs[k]
    return 'dropped %s of <%s>' % (k, n.tag)


def changeText(rng, root):
    nodes = [n for n, _ in root.walk()]
    n = rng.choice(nodes)
    n.text = rng.choice(['', ' ', 'x', '\x00', '\udcff\udcfe', 'a' * 1000, '1 ' * 50, '<obj/>', '&amp;', '\n'])
    return 'text of <%s> replaced' % n.tag


def changeCount(rng, root):
    """A wrong count of numbers in a vector, or (binary) a wrong count of attributes or children."""
    slots = _numberSlots(root)
    if slots and rng.random() < .5:
        n, k = rng.choice(slots)
        tokens = _get(n, k).split()
        if tokens and rng.random() < .5:
            tokens.pop(rng.randrange(len(tokens)))
        else:
            tokens.insert(rng.randrange(len(tokens) + 1), rng.choice(SPECIAL_NUMBERS[:12]))
        _set(n, k, ' '.join(tokens))
        return 'count of numbers in <%s %s>' % (n.tag, k or 'text')
    n = rng.choice([n for n, _ in root.walk()])
    na, nc = len(n.attrs), len(n.children)
    if rng.random() < .5:
        na = rng.choice(HUGE_COUNTS + [na + 1, max(na - 1, 0)])
    else:
        nc = rng.choice(HUGE_COUNTS + [nc + 1, max(nc - 1, 0)])
    n.countOverride = (na, nc)
    return 'counts of <%s> written as %d attributes, %d children' % (n.tag, na, nc)


def nestDeep(rng, root):
    """A chain of nested children (depth limits of the readers)."""
    n = rng.choice([n for n, _ in root.walk()])
    depth = rng.choice([10, 63, 64, 65, 200])
    chain = Node('obj', {'class': 'Body', 'id': '999999'})
    cur = chain
    for _ in range(depth):
        child = Node(rng.choice(['a', 'obj', 'x']), {'name': 'shape'})
        cur.children.append(child)
        cur = child
    n.children.append(chain)
    return 'nested %d deep under <%s>' % (depth, n.tag)


TREE_MUTATIONS = [replaceNumber, replaceNumber, replaceNumber, wrongVersion, renameTag, swapTags, deleteChild,
                  duplicateChild, duplicateChild, moveChild, swapSiblings, changeClass, changeId, changeAttrName,
                  dropAttr, changeText, changeCount, changeCount, nestDeep]


# ------------------------------------------------------------------ mutations of bytes

def truncate(rng, data):
    cut = rng.randrange(len(data) + 1) if data else 0
    return data[:cut], 'truncated at %d of %d' % (cut, len(data))


def flipBits(rng, data):
    if not data:
        return data, 'nothing to flip'
    b = bytearray(data)
    k = rng.choice([1, 1, 2, 8])
    for _ in range(k):
        i = rng.randrange(len(b))
        b[i] ^= 1 << rng.randrange(8)
    return bytes(b), '%d bit(s) flipped' % k


def insertBytes(rng, data):
    i = rng.randrange(len(data) + 1)
    junk = bytes(rng.randrange(256) for _ in range(rng.choice([1, 2, 7, 100])))
    return data[:i] + junk + data[i:], '%d bytes inserted at %d' % (len(junk), i)


def deleteBytes(rng, data):
    if not data:
        return data, 'nothing to delete'
    i = rng.randrange(len(data))
    n = rng.choice([1, 2, 7, 100])
    return data[:i] + data[i + n:], '%d bytes deleted at %d' % (n, i)


def duplicateBytes(rng, data):
    if not data:
        return data, 'nothing to duplicate'
    i = rng.randrange(len(data))
    n = rng.choice([1, 16, 256])
    return data[:i + n] + data[i:i + n] + data[i + n:], '%d bytes repeated at %d' % (n, i)


BYTE_MUTATIONS = [truncate, flipBits, flipBits, insertBytes, deleteBytes, duplicateBytes]


# ------------------------------------------------------------------ mutations of blocks

def splitBlocks(data):
    """[(type, payload)] of a file in the block format (up to where it stops making sense)."""
    out, i = [], len(BLOCKS_MAGIC)
    while i + 16 <= len(data):
        kind, n, _ = struct.unpack_from('<4sQI', data, i)
        out.append((kind, data[i + 16:i + 16 + n]))
        i += 16 + n
    return out


def joinBlocks(blocks):
    return BLOCKS_MAGIC + b''.join(struct.pack('<4sQI', k, len(p), zlib.crc32(p)) + p for k, p in blocks)


SPECIAL_REALS = [float('nan'), float('inf'), -float('inf'), -1.0, 0.0, -0.0, 1e308, 5e-324, 2.0 ** 31, -2.0 ** 63]
SPECIAL_WORDS = [0, 1, 2 ** 31 - 1, 2 ** 31, 2 ** 32 - 1, 4096, 4097, 65536]


def damagePayload(rng, blocks):
    i = rng.randrange(len(blocks))
    kind, payload = blocks[i]
    if not payload:
        return 'block %d (%s) empty, left' % (i, kind.decode('latin-1'))
    choice = rng.randrange(4)
    if choice == 0 and len(payload) >= 8:  # a number: a special real where one may be
        at = rng.randrange(len(payload) - 7)
        payload = payload[:at] + struct.pack('<d', rng.choice(SPECIAL_REALS)) + payload[at + 8:]
        what = 'special real at %d' % at
    elif choice == 1 and len(payload) >= 4:  # a count, an id, a size
        at = rng.randrange(len(payload) - 3)
        payload = payload[:at] + struct.pack('<I', rng.choice(SPECIAL_WORDS)) + payload[at + 4:]
        what = 'special word at %d' % at
    elif choice == 2:  # one byte
        at = rng.randrange(len(payload))
        payload = payload[:at] + bytes([rng.randrange(256)]) + payload[at + 1:]
        what = 'byte at %d' % at
    else:
        payload, what = rng.choice(BYTE_MUTATIONS)(rng, payload)
    blocks[i] = (kind, payload)
    return 'block %d (%s): %s' % (i, kind.decode('latin-1'), what)


def reorderBlocks(rng, blocks):
    i, j = rng.randrange(len(blocks)), rng.randrange(len(blocks))
    choice = rng.randrange(4)
    if choice == 0:
        del blocks[i]
        return 'block %d dropped' % i
    if choice == 1:
        blocks.insert(j, blocks[i])
        return 'block %d repeated at %d' % (i, j)
    if choice == 2:
        blocks[i], blocks[j] = blocks[j], blocks[i]
        return 'blocks %d and %d swapped' % (i, j)
    kind, payload = blocks[i]
    blocks[i] = (rng.choice([b'HEAD', b'TABL', b'ROWS', b'LIST', b'PAIR', b'POOL', b'CONT', b'PERM', b'END ', b'XXXX']), payload)
    return 'block %d (%s) given the type %s' % (i, kind.decode('latin-1'), blocks[i][0].decode('latin-1'))


# The kinds of attributes (AttrKind, lib/serialization/Attr.hpp, in its order): bytes of a value in a
# column, 0 for the kinds of variable length.
KIND_NAMES = ['Bool', 'Int', 'Long', 'Real', 'String', 'Vector2r', 'Vector2i', 'Vector3r', 'Vector3i', 'Vector6r',
              'Matrix3r', 'Quaternionr', 'IntVector', 'RealVector', 'StringVector', 'Vector3rVector', 'Ptr', 'PtrVector',
              'Vector6i', 'Vector2rVector', 'QuaternionrVector']
KIND_WIDTH = [1, 4, 8, 8, 0, 16, 8, 24, 12, 48, 72, 32, 0, 0, 0, 0, 8, 0, 24, 0, 0]
_ITEM_WIDTH = {'IntVector': 4, 'RealVector': 8, 'Vector3rVector': 24, 'PtrVector': 8, 'Vector2rVector': 16, 'QuaternionrVector': 32}


def _skipVariable(p, i, kind):
    name = KIND_NAMES[kind]
    if name == 'String':
        return _readString(p, i)[1]
    n, i = _readSize(p, i)
    if name == 'StringVector':
        for _ in range(n):
            i = _readString(p, i)[1]
        return i
    return i + n * _ITEM_WIDTH[name]


def editColumn(data, cls, attr, value):
    """A file in the block format with the value of attribute attr of the first object of class cls
    (in its first rows block) replaced by `value`, bytes as the column holds one row (for a column
    with one value for all the rows: that value), checksums right. Returns (bytes, kind name)."""
    blocks = splitBlocks(data)
    tables = {}
    for b, (kind, p) in enumerate(blocks):
        if kind == b'TABL':
            key, i = _readSize(p, 0)
            name, i = _readString(p, i)
            n, i = _readSize(p, i)
            schema = []
            for _ in range(n):
                a, i = _readString(p, i)
                schema.append((a.decode(), p[i]))
                i += 1
            tables[key] = (name.decode(), schema)
        elif kind == b'ROWS':
            key, i = _readSize(p, 0)
            _, i = _readSize(p, i)
            n, i = _readSize(p, i)
            name, schema = tables[key]
            if name != cls:
                continue
            for a, k in schema:
                mode, start = p[i], i + 1
                w = KIND_WIDTH[k]
                if w:
                    end, i = start + w, start + (w if mode == 1 else n * w)
                else:
                    end = _skipVariable(p, start, k)
                    i = start
                    for _ in range(n):
                        i = _skipVariable(p, i, k)
                if a == attr:
                    blocks[b] = (kind, p[:start] + value + p[end:])
                    return joinBlocks(blocks), KIND_NAMES[k]
    raise LookupError('%s.%s not in the file' % (cls, attr))


def mutateBlocks(rng, data):
    """(bytes, description): blocks damaged, their checksums right."""
    blocks = splitBlocks(data)
    steps = [(damagePayload if rng.random() < .75 else reorderBlocks)(rng, blocks) for _ in range(rng.choice([1, 1, 2]))]
    return joinBlocks(blocks), '; '.join(steps)


def compress(rng, data):
    """(bytes, file name suffix, description): uncompressed, gzip or bzip2."""
    kind = rng.choice(['', '', '.gz', '.bz2'])
    if kind == '.gz':
        data = gzip.compress(data, compresslevel=rng.choice([1, 9]))
    elif kind == '.bz2':
        data = bz2.compress(data, compresslevel=rng.choice([1, 9]))
    return data, kind, kind or 'uncompressed'


# ------------------------------------------------------------------ a whole case

def whole(rng, seeds):
    """Cases that are not mutations of a seed: empty, random, headers alone, nested compression."""
    kind = rng.randrange(9)
    if kind == 0:
        return b'', 'empty file'
    if kind == 1:
        return bytes(rng.randrange(256) for _ in range(rng.choice([1, 17, 1000]))), 'random bytes'
    if kind == 2:
        return rng.choice([BINARY_MAGIC, BLOCKS_MAGIC]) + bytes(rng.randrange(256) for _ in range(rng.choice([0, 1, 5, 16, 100]))), 'binary magic + random'
    if kind == 3:
        return XML_HEADER + rng.choice([b'', b'<', b'<yade', b'<yade/>', b'<yade formatVersion="1"/>',
                                        b'<yade formatVersion="1"><scene/></yade>', b'\xff\xfe']), 'XML header + fragment'
    if kind == 4:
        return gzip.compress(rng.choice([b'', b'x', BINARY_MAGIC])), 'gzip of nothing useful'
    if kind == 5:
        return bz2.compress(rng.choice([b'', b'x', XML_HEADER])), 'bzip2 of nothing useful'
    if kind == 6:
        return gzip.compress(gzip.compress(rng.choice(seeds))), 'gzip of gzip'
    if kind == 7:
        return rng.choice([b'\x1f\x8b', b'BZh', b'BZh9', b'\x1f\x8b\x08\x00']), 'compression magic alone'
    return rng.choice(seeds) + rng.choice([b'\x00', b' ', b'\n<x/>', BINARY_MAGIC, b'END ' + bytes(12)]), 'trailing bytes after a valid scene'


def makeCase(rng, seeds):
    """(bytes, file name suffix, description) of one fuzz case, from seeds (valid saved scenes,
    uncompressed) and rng."""
    if rng.random() < .06:
        data, what = whole(rng, seeds)
        return data, rng.choice(['', '.gz', '.bz2', '.xml']), what
    seed = rng.choice(seeds)
    steps = []
    if seed.startswith(BLOCKS_MAGIC):
        data = seed
        if rng.random() < .75:  # damage the blocks under right checksums: gets into the scene reader
            data, what = mutateBlocks(rng, data)
            steps.append(what)
    elif rng.random() < .75:  # mutate the tree: gets past the byte-level checks into the scene reader
        root, encoding = decodedCopy(seed)
        if rng.random() < .3:
            encoding = 'binary' if encoding == 'xml' else 'xml'
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            steps.append(rng.choice(TREE_MUTATIONS)(rng, root))
        data = encode(root, encoding)
    else:
        data = seed
    if rng.random() < .3:  # damage the bytes
        for _ in range(rng.choice([1, 1, 2])):
            data, what = rng.choice(BYTE_MUTATIONS)(rng, data)
            steps.append(what)
    data, suffix, what = compress(rng, data)
    steps.append(what)
    if suffix and rng.random() < .3:  # damage the compressed stream
        data, what = rng.choice(BYTE_MUTATIONS)(rng, data)
        steps.append('compressed stream: ' + what)
    return data, suffix, '; '.join(steps)


def caseRng(seed, k):
    """The random generator of case k of a run with this seed (cases replay one by one)."""
    return random.Random('%d:%d' % (seed, k))
