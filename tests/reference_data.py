"""What the tests that compare with the reference share: a script of tests/reference/ imported as a module (its
scene functions), the reference's output stored beside it (tests/reference/data/), and the numbers of nested
results in one flat list."""
import importlib.util
import json
import os

REFERENCE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'reference')


def scenes_and_data(script, data):
    """tests/reference/<script> as a module, and tests/reference/data/<data> (JSON) as stored from the reference."""
    spec = importlib.util.spec_from_file_location(os.path.splitext(script)[0] + '_scenes', os.path.join(REFERENCE_DIR, script))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    with open(os.path.join(REFERENCE_DIR, 'data', data)) as f:
        return module, json.load(f)


def flat(x):
    """The numbers of nested dicts (in key order) and lists, in one list."""
    if isinstance(x, dict):
        return [v for k in sorted(x) for v in flat(x[k])]
    if isinstance(x, list):
        return [v for y in x for v in flat(y)]
    return [x]
