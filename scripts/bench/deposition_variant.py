# Feature-cost variant of the deposition benchmark: the unchanged scene with ONE optional feature on.
#
#     ./yade -n -x -j1 scripts/bench/deposition_variant.py VARIANT [N] [STEPS] [SETTLE]
#     yade   -n -x -j1 scripts/bench/deposition_variant.py VARIANT [N] [STEPS] [SETTLE]   (reference)
#
# VARIANT is one of
#     energy    O.trackEnergy = True
#     pyrunner  a PyRunner(command='pass', iterPeriod=100) appended to O.engines
#     wall      Bo1_Wall_Aabb in the collider and Ig2_Wall_Sphere_ScGeom in the InteractionLoop
#               (unused: the scene holds no Wall)
#     plain     nothing changed (the scene itself; for checking the wrapper adds no cost)
#
# The scene (deposition.py next to this file, or $BENCH_SCENE) is read, the variant's lines are
# inserted just before its "O.dt = ..." line (after O.engines is set, before any step), and the
# result is executed here, so that everything else (sizes, timing, the printed line) is the
# scene's own. Only plain Yade names are used: it runs in the reference too.
import os
import sys

VARIANTS = {
    'plain': "",
    'energy': "O.trackEnergy = True\n",
    'pyrunner': "O.engines = O.engines + [PyRunner(command='pass', iterPeriod=100)]\n",
    'wall': (
        "_bc = [e for e in O.engines if isinstance(e, InsertionSortCollider)][0]\n"
        "_bc.boundDispatcher.functors = list(_bc.boundDispatcher.functors) + [Bo1_Wall_Aabb()]\n"
        "_il = [e for e in O.engines if isinstance(e, InteractionLoop)][0]\n"
        "_il.geomDispatcher.functors = list(_il.geomDispatcher.functors) + [Ig2_Wall_Sphere_ScGeom()]\n"
    ),
}

_args = [a for a in sys.argv[1:] if not a.startswith('-')]
if not _args or _args[0] not in VARIANTS:
    raise SystemExit("usage: deposition_variant.py {%s} [N] [STEPS] [SETTLE]" % ",".join(sorted(VARIANTS)))
_variant = _args[0]
# sys.argv[0], not __file__: the reference's launcher runs scripts with __file__ set to itself
_scene = os.environ.get('BENCH_SCENE') or os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), 'deposition.py')
with open(_scene) as _f:
    _lines = _f.read().splitlines(True)
_at = [k for k, l in enumerate(_lines) if l.lstrip().startswith('O.dt') and '=' in l]
if not _at:
    raise SystemExit("deposition_variant.py: no 'O.dt = ...' line in %s to insert the variant before" % _scene)
_lines[_at[0]:_at[0]] = [VARIANTS[_variant]]
# the scene sees the same arguments as when run directly (the variant name removed)
_rest = sys.argv[1:]
_rest.remove(_variant)
sys.argv = [_scene] + _rest
exec(compile(''.join(_lines), _scene, 'exec'), globals())
