# Dense random packings (pack.randomPeriPack, pack.randomDensePack): a plain Yade script that runs
# unchanged in the reference Yade and in this engine; it prints one JSON line of the packings'
# statistics, which tests/test_pack_dense.py compares. Regenerate its data file (in tests/reference/):
#   yade -n -x -j1 pack_dense.py 2>/dev/null | grep '^PACKDENSE ' | sed 's/^PACKDENSE //' > data/pack_dense.json
import json
import math

RUN = __name__ == '__main__'  # (before the star import, which sets __name__ in the reference)

from yade import *
from yade import pack, utils


def stats(sp, volume):
    """number, radii (mean, spread, extremes), solid fraction of volume, periodicity and cell"""
    rs = [r for c, r in sp]
    n = len(rs)
    m = sum(rs) / n
    return dict(n=n, rMean=m, rStd=math.sqrt(sum((r - m) ** 2 for r in rs) / n), rMin=min(rs), rMax=max(rs),
                fill=sum(4 / 3. * math.pi * r ** 3 for r in rs) / volume, periodic=sp.isPeriodic, cell=list(sp.cellSize))


def cellVolume(sp):
    return sp.cellSize[0] * sp.cellSize[1] * sp.cellSize[2]


def scenes():
    out = {}
    O.bodies.append(utils.sphere((5, 5, 5), 1))  # the user's scene, which must be left as it was
    O.engines = [ForceResetter()]
    O.dt = 1.234e-3
    for seed in (1, 2):
        sp = pack.randomPeriPack(radius=.1, initSize=Vector3(1, 1, 1), seed=seed)
        out['peri%d' % seed] = stats(sp, cellVolume(sp))
    sp = pack.randomPeriPack(radius=.07, initSize=Vector3(1, 1, 1), rRelFuzz=.3, seed=3)
    out['periFuzz'] = stats(sp, cellVolume(sp))
    sp = pack.randomDensePack(pack.inAlignedBox((0, 0, 0), (1, 1, 1)), radius=.05, spheresInCell=300, returnSpherePack=True, seed=1)
    out['denseBoxPeri'] = stats(sp, 1.)
    sp = pack.randomDensePack(pack.inSphere((0, 0, 0), .5), radius=.04, rRelFuzz=.3, spheresInCell=300, returnSpherePack=True, seed=1)
    out['denseSpherePeri'] = stats(sp, 4 / 3. * math.pi * .5 ** 3)
    sp = pack.randomDensePack(pack.inAlignedBox((0, 0, 0), (1, 1, 1)), radius=.08, returnSpherePack=True, seed=1)
    out['denseBoxAperiodic'] = stats(sp, 1.)
    out['userScene'] = [len(O.bodies), len(O.engines), O.dt, O.periodic]
    return out


if RUN:
    print('PACKDENSE', json.dumps(scenes()))
