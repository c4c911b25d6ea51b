"""The math types (as in Yade's yade.minieigenHP): vectors, matrices and quaternions of Real with the
minieigen API (Vector3(1, 2, 3).norm(), Quaternion(axis, angle), Matrix3.Identity, ...)."""
from . import _yade

__all__ = [n for n in ('Vector2', 'Vector2i', 'Vector3', 'Vector3i', 'Vector4', 'Vector6', 'Vector6i', 'Matrix3', 'Matrix6', 'Quaternion',
                       'AlignedBox2', 'AlignedBox3', 'VectorX', 'MatrixX') if hasattr(_yade, n)]
globals().update({n: getattr(_yade, n) for n in __all__})

# The precision levels (as Yade's minieigenHP.HP1, HP2...): Real is a double here, so there is one, HP1.
import types as _types

HP1 = _types.ModuleType('yade.minieigenHP.HP1', 'The math types at precision level 1 (double): the same as yade.minieigenHP.')
HP1.__dict__.update({n: globals()[n] for n in __all__})
