"""Kept for scripts that do `from yade._customConverters import *` (as in Yade): conversions between
Python sequences and the engine's vectors and lists are built into the compiled module, so this
module has nothing to export."""
__all__ = []
