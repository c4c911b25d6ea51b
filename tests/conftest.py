"""Fixtures shared by the test files that run scenes in this process."""
import pytest


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
