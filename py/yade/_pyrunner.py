"""The error a PyRunner's command raises, as the reference reports it: an exception that is a
RuntimeError whose message is

    PyRunner error.

    COMMAND: '<command>'

    ERROR:
    <the error's message>

    STACK TRACE:
    <the traceback, its lines separated by blank lines>

and, where Python allows it, also of the original class (a ZeroDivisionError stays one, so
`except ZeroDivisionError` still catches it); the original is its __cause__. KeyboardInterrupt,
SystemExit and other exceptions that are not Exceptions pass through unchanged."""
import traceback

_classes = {}


def _errorClass(original):
    if original not in _classes:
        def text(self):
            return self.args[0] if self.args else ''
        try:  # the original class and RuntimeError (impossible for classes with their own layout, e.g. NameError)
            cls = original if issubclass(original, RuntimeError) else type(original.__name__, (original, RuntimeError), {'__str__': text})
            cls.__qualname__ = original.__qualname__
            cls.__module__ = original.__module__
        except TypeError:
            cls = RuntimeError
        _classes[original] = cls
    return _classes[original]


def wrapped(command, error, trace=None):
    """The exception to raise for `error` (with traceback `trace`), raised by the PyRunner command
    `command` (None: raise the error itself)."""
    if not isinstance(error, Exception):
        return None
    if trace is not None and error.__traceback__ is None:
        error.__traceback__ = trace
    stack = '\n'.join(traceback.format_exception(type(error), error, error.__traceback__))
    message = "PyRunner error.\n\nCOMMAND: %r\n\nERROR:\n%s\n\nSTACK TRACE:\n%s" % (command, error, stack)
    try:
        new = _errorClass(type(error))(message)
    except Exception:
        new = RuntimeError(message)
    new.__cause__ = error
    return new
