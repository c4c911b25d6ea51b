# The screenshot of doc/gui.md and the README: tutorial 02 (gravity deposition) after 6 000 steps, in the 3D view
# and the controller. Run from the repository's root, with a display (or under Xvfb):
#   xvfb-run -a -s "-screen 0 1280x800x24" env PYTHONPATH=build /usr/bin/python3 scripts/gui_screenshot.py [out.png]
import os, sys, time
from yade import *
out = sys.argv[1:]
sys.argv = ['02-gravity-deposition.py']
exec(open('examples/tutorial/02-gravity-deposition.py').read())
sys.argv[1:] = out
from yade import qt
from PyQt5 import QtWidgets
qt.Renderer().bgColor = (0.2, 0.2, 0.2)
v = qt.View()
v.viewDir = (-0.6, 1, -0.45); v.upVector = (0, 0, 1); v.center()
import yade.runtime
yade.runtime.opts.script = 'examples/tutorial/02-gravity-deposition.py'
c = qt.Controller()
O.run(6000, True)
v.center(); c.refresh()
qt._processEvents(); time.sleep(0.3); qt._processEvents()
from PyQt5 import QtGui
view, ctrl = v._widget.grabFramebuffer(), c.grab()
img = QtGui.QImage(view.width() + 10 + ctrl.width(), max(view.height(), ctrl.height()), QtGui.QImage.Format_RGB32)
img.fill(QtGui.QColor(255, 255, 255))
p = QtGui.QPainter(img)
p.drawImage(0, 0, view)
p.drawPixmap(view.width() + 10, 0, ctrl)
p.end()
img.save(sys.argv[1] if len(sys.argv) > 1 else 'doc/images/gui-gravity-deposition.png')
print('saved', img.width(), img.height(), O.iter)
