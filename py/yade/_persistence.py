"""O.save, O.load and O.reload: files in the binary or XML format of doc/file-format.md,
gzip-, bzip2- or zstd-compressed when the name ends in .gz / .bz2 / .zst. The scene is streamed
to and from the file by the C++ core (compressed as it goes), never held whole in memory."""
import os
import tempfile

from ._yade import Omega, FileFormatError

_lastFile = [None]
_UMASK = os.umask(0)  # read once (os.umask can only be read by setting it)
os.umask(_UMASK)


def save(self, fileName, quiet=False):
    """Save the scene: XML if the name contains 'xml', binary otherwise; compressed for .gz/.bz2/.zst.
    The file is written to a temporary beside the target, flushed to the disk and renamed, so a
    failure (a full disk, a process killed half-way) leaves the previous file as it was; an error
    is an OSError that names the file."""
    fileName = os.fspath(fileName)
    xml = 'xml' in os.path.basename(fileName)
    directory = os.path.dirname(os.path.abspath(fileName))
    prefix = '.' + os.path.basename(fileName) + '.'
    try:
        _removeOrphans(directory, prefix)
        fd, tmp = tempfile.mkstemp(prefix=prefix + '%d.' % os.getpid(), dir=directory)
    except OSError as e:
        raise OSError(e.errno, e.strerror, fileName) from None
    try:
        with os.fdopen(fd, 'wb') as f:
            self._saveToFd(f.fileno(), xml, fileName)
            os.fsync(f.fileno())  # the content is on the disk before the name points to it
        os.chmod(tmp, 0o666 & ~_UMASK)  # mkstemp makes it private; give the usual permissions
        os.replace(tmp, fileName)
        _syncDirectory(directory)
    except BaseException as e:
        if os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(e, OSError) and e.errno is not None and e.filename is None:
            raise OSError(e.errno, e.strerror, fileName) from None  # (a write error names no file)
        raise
    _lastFile[0] = fileName


def _syncDirectory(directory):
    """Flush the directory entry of a renamed file to the disk (where the system allows it)."""
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _removeOrphans(directory, prefix):
    """Remove the temporaries of saves of this file by processes that no longer exist (killed
    while saving: the previous file is intact, the temporary is garbage)."""
    for name in os.listdir(directory):
        if not name.startswith(prefix):
            continue
        pid = name[len(prefix):].split('.', 1)[0]
        if not pid.isdigit() or int(pid) == os.getpid():
            continue
        try:
            os.kill(int(pid), 0)
        except ProcessLookupError:  # (PermissionError: it exists, under another user)
            try:
                os.unlink(os.path.join(directory, name))
            except OSError:
                pass
        except OSError:
            pass


def load(self, fileName, quiet=False):
    """Load a scene saved by O.save; the format and compression are detected from the content.
    A missing, truncated or corrupt file raises and leaves the current scene as it was.
    ``:memory:<mark>`` names the scene saved by O.saveTmp(mark)."""
    fileName = os.fspath(fileName)
    if fileName.startswith(_MEMORY):
        loadTmp(self, fileName[len(_MEMORY):])
        return
    with open(fileName, 'rb') as f:
        try:
            self._loadFromFd(f.fileno())
        except FileFormatError as e:
            raise FileFormatError('%s: %s' % (fileName, e)) from None
        except OSError as e:
            if e.filename is None:
                raise OSError(e.errno, e.strerror, fileName) from None  # (a read error names no file)
            raise
    _lastFile[0] = fileName


def reload(self, quiet=False):
    """Load again the file last saved or loaded."""
    if _lastFile[0] is None:
        raise RuntimeError('O.reload(): no file has been saved or loaded yet')
    load(self, _lastFile[0], quiet)


_MEMORY = ':memory:'
_saveTmp, _loadTmp = Omega.saveTmp, Omega.loadTmp


def saveTmp(self, mark='', quiet=False):
    """Save the scene in memory under a slot name (O.filename becomes ':memory:<mark>')."""
    _saveTmp(self, mark)
    _lastFile[0] = _MEMORY + mark


def loadTmp(self, mark='', quiet=False):
    """Load the scene saved by O.saveTmp(mark) (O.filename becomes ':memory:<mark>')."""
    _loadTmp(self, mark)
    _lastFile[0] = _MEMORY + mark


Omega.saveTmp = saveTmp
Omega.loadTmp = loadTmp
Omega.save = save
Omega.load = load
Omega.reload = reload
Omega.filename = property(lambda self: _lastFile[0],
                          doc='The file the simulation was last saved to or loaded from (None if none yet)')


def sceneToString(self):
    """The whole scene as bytes (the binary format of O.save); O.stringToScene reads it back."""
    return self._toBytes(False)


def stringToScene(self, data, mark=''):
    """Replace the scene by one from O.sceneToString (bytes; str is taken as XML text)."""
    if isinstance(data, str):
        data = data.encode('utf-8')
    self._fromBytes(data)


def tmpToFile(self, fileName, mark=''):
    """Write the simulation saved by O.saveTmp(mark) to fileName as XML."""
    with open(os.fspath(fileName), 'w', encoding='utf-8') as f:
        f.write(self.tmpToString(mark))


_tmpDir = [None]
_tmpCount = [0]


def tmpFilename(self):
    """A new file name in a private temporary folder, removed (with its files) when the program ends."""
    if _tmpDir[0] is None:
        import atexit
        import shutil
        _tmpDir[0] = tempfile.mkdtemp(prefix='yade-')
        atexit.register(shutil.rmtree, _tmpDir[0], True)
    _tmpCount[0] += 1
    return os.path.join(_tmpDir[0], 'tmp-%d' % _tmpCount[0])


Omega.sceneToString = sceneToString
Omega.stringToScene = stringToScene
Omega.tmpToFile = tmpToFile
Omega.tmpFilename = tmpFilename
