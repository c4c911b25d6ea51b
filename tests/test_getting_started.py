"""doc/getting-started.md, run as a reader would: its code blocks are taken from the page (so the page
cannot drift), its files written and its commands run in a temporary folder (scripts/getting_started_pictures.py
runPage), and what they print and write is checked: the deposition comes to rest, its plot and VTK series are
there, and the three-line batch runs its jobs with the table's damping."""
import os
import pathlib
import sys

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPO / 'scripts'))
import getting_started_pictures as page  # noqa: E402


@pytest.fixture(scope='module')
def ran(tmp_path_factory):
    folder = tmp_path_factory.mktemp('getting-started')
    return folder, {cmd: r for cmd, r in page.runPage(str(folder))}


def table(path):
    lines = pathlib.Path(path).read_text().splitlines()
    names = lines[0][2:].split()
    return names, np.array([[float(x) for x in l.split()] for l in lines[1:] if l.strip()])


def test_the_install_block_is_the_readmes_first_command():
    first = [text for kind, text in page.blocks() if kind == 'command'][0]
    readme = (REPO / 'README.md').read_text().split('```')[1].strip().splitlines()
    assert first == readme[0]


def test_every_block_is_a_file_or_a_command_and_every_command_ran(ran):
    folder, results = ran
    kinds = [k for k, _ in page.blocks()]
    assert kinds.count('file') == 2 and kinds.count('command') == 4
    assert len(results) == 3
    for cmd, r in results.items():
        assert r.returncode == 0, (cmd, r.stdout[-2000:], r.stderr[-2000:])
        assert 'Traceback' not in r.stderr, r.stderr


def test_the_deposition_comes_to_rest(ran):
    folder, results = ran
    out = results['./yade -n -x deposition.py'].stdout
    line = [l for l in out.splitlines() if l.startswith('deposition: ')]
    assert len(line) == 1, out
    words = line[0].split()
    assert int(words[1]) > 500  # spheres
    assert float(words[5]) < 0.01  # the unbalanced force at the end
    names, data = table(folder / 'deposition.txt')
    assert names == ['Ek', 't', 'unbalanced']
    ek = data[:, 0]
    assert len(ek) == 199 and ek[-1] < 1e-4 * ek.max()
    assert (folder / 'deposition.png').read_bytes()[:8] == b'\x89PNG\r\n\x1a\n'


def test_the_vtk_series_is_listed(ran):
    folder, results = ran
    listing = results['ls vtk/'].stdout.split()
    for kind, ext in (('spheres', 'vtu'), ('facets', 'vtu'), ('intrs', 'vtp')):
        assert 'deposition-%s.pvd' % kind in listing
        assert len([f for f in listing if f.startswith('deposition-%s.' % kind) and f.endswith(ext)]) == 20
    vtk = pytest.importorskip('vtk')
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(str(folder / 'vtk' / 'deposition-spheres.19000.vtu'))
    r.Update()
    out = results['./yade -n -x deposition.py'].stdout
    assert r.GetOutput().GetNumberOfPoints() == int(out.split('deposition: ')[1].split()[0])


def test_the_batch_runs_three_jobs_with_the_tables_damping(ran):
    """Each job reads its line's damping: before the spheres touch anything they fall with Cundall's damping
    at g·(1 - damping) (the force and the velocity point the same way), so the first recorded kinetic
    energies are in the ratio (1 - damping)² from job to job."""
    folder, results = ran
    r = results['./yade-batch -j 2 deposition.table deposition.py']
    assert 'http://localhost:' in r.stdout
    assert '3 ok, 0 failed' in r.stdout
    first = {}
    for name in ('low', 'medium', 'high'):
        assert (folder / ('deposition.py.%s.log' % name)).exists()
        names, data = table(folder / ('deposition-%s.txt' % name))
        first[name] = data[0, 0]
    for a, b, da, db in (('low', 'high', .05, .5), ('medium', 'high', .2, .5)):
        assert first[a] / first[b] == pytest.approx(((1 - da) / (1 - db)) ** 2, rel=5e-3)
