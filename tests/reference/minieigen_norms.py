# Regenerate: yade -n -x -j1 tests/reference/minieigen_norms.py | grep '^{' > tests/reference/data/minieigen_norms.json
# The Python-visible minieigen reductions (norm, squaredNorm, normalized, normalize, dot) of Vector3 and
# Vector2 on random vectors drawn from a seeded generator (the same draws in both engines; the inputs are
# not stored). A plain Yade script: it runs unchanged in the reference and in this engine.
import json
import random
from yade import Vector2, Vector3


def draws(n, dim, rng):
    return [([rng.uniform(-10, 10) * 10 ** rng.randint(-3, 3) for _ in range(dim)], [rng.uniform(-10, 10) for _ in range(dim)]) for _ in range(n)]


def reductions(cls, pairs):
    out = []
    for v, w in pairs:
        a, b = cls(*v), cls(*w)
        c = cls(*v)
        c.normalize()
        out.append([a.norm(), a.squaredNorm(), list(a.normalized()), list(c), a.dot(b)])
    return out


def run():
    rng = random.Random(7)
    return {'v3': reductions(Vector3, draws(2000, 3, rng)), 'v2': reductions(Vector2, draws(500, 2, rng))}


if __name__ == '__main__':
    print(json.dumps(run()))
