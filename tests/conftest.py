"""Fixtures shared by the test files that run scenes in this process."""
import pytest


@pytest.fixture
def fresh_scene():
    """An empty scene before the test, and no scene or background run left behind after it."""
    from yade import O
    O.pause()
    O.reset()
    yield
    O.pause()
    O.reset()
