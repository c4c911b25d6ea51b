"""Fixtures shared by the test files that run scenes in this process."""
import os

import pytest

# The suite runs headless: `yade.qt` imported by a test gives the views without a display
# (tests/test_qt_headless.py). The tests of the real views start their own processes under Xvfb.
os.environ.pop("DISPLAY", None)
os.environ.pop("WAYLAND_DISPLAY", None)


@pytest.fixture
def fresh_scene():
    """An empty scene with one thread before the test, and no scene, background run or extra
    thread left behind after it."""
    from yade import O, setNumThreads
    O.pause()
    setNumThreads(1)
    O.reset()
    yield
    O.pause()
    setNumThreads(1)
    O.reset()


# The fuzz harnesses record their case counts (record_property 'fuzz_*'): printed at the end of the
# run, also without -s, so that the CI log shows how many cases each harness ran.
_fuzz_counts = []


def pytest_runtest_logreport(report):
    if report.when == 'call':
        _fuzz_counts.extend((report.nodeid, k, v) for k, v in report.user_properties if k.startswith('fuzz_'))


def pytest_terminal_summary(terminalreporter):
    if _fuzz_counts:
        terminalreporter.section('fuzz harnesses')
        for nodeid, key, value in _fuzz_counts:
            terminalreporter.write_line('%s: %s = %s' % (nodeid.split('::')[0], key, value))
