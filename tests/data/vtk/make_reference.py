"""Writes the reference files of this folder with the reference Yade (2023.02a here), run from the
repository root:  yade -n -x tests/data/vtk/make_reference.py
The files are the reference's own output for the exports of scenes.EXPORTS."""
import os
import sys

here = os.path.dirname(os.path.abspath('tests/data/vtk/make_reference.py'))
sys.path.insert(0, here)
import scenes  # noqa: E402
from yade import export  # noqa: E402

scenes.runExports(export, here)
print('written:', sorted(f for f in os.listdir(here) if f.endswith('.vtk')))
sys.exit(0)
