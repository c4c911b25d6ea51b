#!/usr/bin/python3
"""Runs doc/getting-started.md's code blocks in a temporary folder, as a reader would, and makes the page's
pictures from what they wrote: doc/images/getting-started-plot.png (the deposition's plot, as the engine
saved it) and doc/images/getting-started-vtk.png (rendered from the run's last VTK files with VTK's own
Python module, under Xvfb when there is no display).

    python3 scripts/getting_started_pictures.py [--keep FOLDER]

tests/test_getting_started.py runs the same blocks (blocks() and runPage() below) and checks their output.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, 'doc', 'getting-started.md')
IMAGES = os.path.join(ROOT, 'doc', 'images')


def blocks(path=PAGE):
    """The page's code blocks in order, as (kind, text): kind 'file' for a block whose first line is
    '# name.ext' (saved under that name), 'command' for a sh block."""
    out = []
    for lang, text in re.findall(r'```(\w*)\n(.*?)```', open(path).read(), re.S):
        first = text.splitlines()[0]
        if re.fullmatch(r'# [\w.-]+\.\w+', first.strip()):
            out.append(('file', text))
        elif lang == 'sh':
            out.append(('command', text.strip()))
        else:
            raise ValueError('%s: a code block that is neither a file (# name.ext) nor a sh command: %r' % (path, text[:60]))
    return out


def fileName(text):
    return text.splitlines()[0][2:].strip()


def runPage(folder, skipFirstCommand=True, timeout=600):
    """Writes the page's files in `folder` and runs its commands there (./yade and ./yade-batch are this
    repository's), in order; the first command (the set-up, which the README's first command is) is left out.
    Returns [(command, CompletedProcess)]."""
    results = []
    commands = 0
    env = dict(os.environ)
    env.pop('DISPLAY', None)
    for kind, text in blocks():
        if kind == 'file':
            with open(os.path.join(folder, fileName(text)), 'w') as f:
                f.write(text)
            continue
        commands += 1
        if commands == 1 and skipFirstCommand:
            continue
        cmd = re.sub(r'(^|\s)\./(yade(-batch)?)\b', lambda m: m.group(1) + os.path.join(ROOT, m.group(2)), text)
        r = subprocess.run(['bash', '-c', cmd], cwd=folder, capture_output=True, text=True, timeout=timeout, env=env)
        results.append((text, r))
    return results


def renderVtk(folder, png):
    """The last spheres and force chains the deposition wrote, drawn with VTK into png."""
    import vtk

    def last(kind, ext):
        files = glob.glob(os.path.join(folder, 'vtk', 'deposition-%s.*.%s' % (kind, ext)))
        return max(files, key=lambda f: int(f.rsplit('.', 2)[1]))

    def surfaceActor(source, color):
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        mapper.ScalarVisibilityOff()
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*color)
        return actor

    def reader(cls, path):
        r = cls()
        r.SetFileName(path)
        r.Update()
        return r

    spheres = reader(vtk.vtkXMLUnstructuredGridReader, last('spheres', 'vtu')).GetOutput()
    spheres.GetPointData().SetActiveScalars('radii')
    ball = vtk.vtkSphereSource()
    ball.SetThetaResolution(16)
    ball.SetPhiResolution(12)
    ball.SetRadius(1)
    glyphs = vtk.vtkGlyph3D()
    glyphs.SetInputData(spheres)
    glyphs.SetSourceConnection(ball.GetOutputPort())
    glyphs.SetScaleModeToScaleByScalar()
    glyphs.SetColorModeToColorByScale()
    glyphs.Update()
    speed = spheres.GetPointData().GetArray('linVelLen')
    sphereActor = surfaceActor(glyphs, (.55, .7, .9))
    sphereActor.GetProperty().SetOpacity(.25)

    chains = reader(vtk.vtkXMLPolyDataReader, last('intrs', 'vtp')).GetOutput()
    forces = chains.GetCellData().GetArray('forceN')
    fmax = forces.GetRange()[1] or 1.
    toPoints = vtk.vtkCellDataToPointData()
    toPoints.SetInputData(chains)
    toPoints.Update()
    pts = toPoints.GetOutput()
    pts.GetPointData().SetActiveScalars('forceN')
    tubes = vtk.vtkTubeFilter()
    tubes.SetInputData(pts)
    tubes.SetNumberOfSides(8)
    tubes.SetRadius(.002)
    tubes.SetVaryRadiusToVaryRadiusByAbsoluteScalar()
    tubes.SetRadiusFactor(1)
    # radius in proportion to the force: 0.012 for the largest
    scale = vtk.vtkArrayCalculator()
    scale.SetInputData(pts)
    scale.AddScalarArrayName('forceN')
    scale.SetFunction('0.001+0.011*forceN/%r' % fmax)
    scale.SetResultArrayName('tubeRadius')
    scale.Update()
    scaled = scale.GetOutput()
    scaled.GetPointData().SetActiveScalars('tubeRadius')
    tubes.SetInputData(scaled)
    tubeActor = surfaceActor(tubes, (.8, .1, .1))

    box = reader(vtk.vtkXMLUnstructuredGridReader, last('facets', 'vtu')).GetOutput()
    boxMapper = vtk.vtkDataSetMapper()
    boxMapper.SetInputData(box)
    boxActor = vtk.vtkActor()
    boxActor.SetMapper(boxMapper)
    boxActor.GetProperty().SetRepresentationToWireframe()
    boxActor.GetProperty().SetColor(.3, .3, .3)

    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    for a in (boxActor, sphereActor, tubeActor):
        ren.AddActor(a)
    text = vtk.vtkTextActor()
    text.SetInput('%d spheres (light blue), %d contacts (red, thickness ~ normal force, max %.3g N); max speed %.2g m/s'
                  % (spheres.GetNumberOfPoints(), chains.GetNumberOfCells(), fmax, speed.GetRange()[1]))
    text.GetTextProperty().SetColor(0, 0, 0)
    text.GetTextProperty().SetFontSize(14)
    text.SetPosition(10, 10)
    ren.AddActor2D(text)
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(.5, .5, .2)
    cam.SetPosition(2.2, -1.4, 1.6)
    cam.SetViewUp(0, 0, 1)
    ren.ResetCamera()
    cam.Zoom(1.05)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(900, 700)
    win.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.Update()
    w = vtk.vtkPNGWriter()
    w.SetFileName(png)
    w.SetInputConnection(grab.GetOutputPort())
    w.Write()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--keep', help='run in this folder (kept) instead of a temporary one')
    p.add_argument('--render-only', metavar='FOLDER', help='only render the picture from a folder the page ran in')
    args = p.parse_args()
    if not os.environ.get('DISPLAY') and shutil.which('xvfb-run') and not os.environ.get('_GS_XVFB'):
        env = dict(os.environ, _GS_XVFB='1')
        sys.exit(subprocess.call(['xvfb-run', '-a', '-s', '-screen 0 1280x1024x24', sys.executable] + sys.argv, env=env))
    folder = args.render_only or args.keep or tempfile.mkdtemp(prefix='getting-started-')
    os.makedirs(folder, exist_ok=True)
    if not args.render_only:
        for cmd, r in runPage(folder):
            print('$ %s  (exit %d)' % (cmd, r.returncode))
            print('\n'.join(r.stdout.splitlines()[-3:]))
            if r.returncode != 0:
                print(r.stderr[-3000:], file=sys.stderr)
                return 1
    os.makedirs(IMAGES, exist_ok=True)
    shutil.copy(os.path.join(folder, 'deposition.png'), os.path.join(IMAGES, 'getting-started-plot.png'))
    renderVtk(folder, os.path.join(IMAGES, 'getting-started-vtk.png'))
    print('wrote doc/images/getting-started-plot.png and doc/images/getting-started-vtk.png (from %s)' % folder)
    if not args.keep and not args.render_only:
        shutil.rmtree(folder)
    return 0


if __name__ == '__main__':
    sys.exit(main())
