"""The controller window (manual: "Controller"): run, pause and step; the iteration, virtual and real time;
dt, editable, with the time stepper's state; the script's name; save and load; a display tab with the
renderer's switches; a field for Python commands, run in the script's namespace.

It reads the scene four times a second (O.iter, O.time, O.dt: no pause of a running simulation) and acts
only through O, so that what it does is what a script would do.
"""
import time

from PyQt5 import QtCore, QtWidgets

from yade import _yade


class ControllerWindow(QtWidgets.QWidget):
    refreshMs = 250

    def __init__(self, renderer, openView):
        super().__init__()
        self.setWindowTitle('Yade')
        self.renderer = renderer
        self.openView = openView
        self.started = time.time()
        tabs = QtWidgets.QTabWidget()
        tabs.addTab(self._simulationTab(), 'Simulation')
        tabs.addTab(self._displayTab(), 'Display')
        tabs.addTab(self._pythonTab(), 'Python')
        layout = QtWidgets.QVBoxLayout(self)
        layout.addWidget(tabs)
        self.timer = QtCore.QTimer(self)
        self.timer.timeout.connect(self.refresh)
        self.timer.start(self.refreshMs)
        self.refresh()

    # --- the simulation tab
    def _simulationTab(self):
        w = QtWidgets.QWidget()
        form = QtWidgets.QFormLayout(w)
        import yade.runtime
        self.scriptLabel = QtWidgets.QLabel(str(yade.runtime.opts.script or '(none)'))
        self.iterLabel, self.virtLabel, self.realLabel = QtWidgets.QLabel(), QtWidgets.QLabel(), QtWidgets.QLabel()
        self.dtEdit = QtWidgets.QLineEdit()
        self.dtEdit.returnPressed.connect(self.applyDt)
        self.dtState = QtWidgets.QLabel()
        self.message = QtWidgets.QLabel()
        self.message.setWordWrap(True)
        form.addRow('script', self.scriptLabel)
        form.addRow('iteration', self.iterLabel)
        form.addRow('virtual time', self.virtLabel)
        form.addRow('real time', self.realLabel)
        dtRow = QtWidgets.QHBoxLayout()
        dtRow.addWidget(self.dtEdit)
        dtRow.addWidget(self.dtState)
        form.addRow('Δt', dtRow)
        buttons = QtWidgets.QHBoxLayout()
        self.runButton = QtWidgets.QPushButton('Run')
        self.runButton.clicked.connect(self.runOrPause)
        step = QtWidgets.QPushButton('Step')
        step.clicked.connect(self.step)
        buttons.addWidget(self.runButton)
        buttons.addWidget(step)
        form.addRow(buttons)
        files = QtWidgets.QHBoxLayout()
        for label, slot in (('Save...', self.saveDialog), ('Load...', self.loadDialog), ('3D view', self.openView),
                            ('Inspect', self.inspect)):
            b = QtWidgets.QPushButton(label)
            b.clicked.connect(slot)
            files.addWidget(b)
        form.addRow(files)
        form.addRow(self.message)
        return w

    def refresh(self):
        O = _yade.O
        self.iterLabel.setText('#%d' % O.iter)
        self.virtLabel.setText('%.6g s' % O.time)
        s = int(time.time() - self.started)
        self.realLabel.setText('%02d:%02d:%02d' % (s // 3600, s // 60 % 60, s % 60))
        if not self.dtEdit.hasFocus():
            self.dtEdit.setText('%.6g' % O.dt)
        self.dtState.setText('(time stepper)' if O.dynDt else '(fixed)')
        self.runButton.setText('Pause' if O.running else 'Run')

    def _act(self, what):
        try:
            what()
            self.message.setText('')
            return True
        except Exception as e:
            self.message.setText('%s: %s' % (type(e).__name__, e))
            return False

    def runOrPause(self):
        O = _yade.O
        self._act(O.pause if O.running else O.run)
        self.refresh()

    def step(self):
        O = _yade.O
        if not O.running:
            self._act(O.step)
        self.refresh()

    def applyDt(self):
        """Sets O.dt from the field; a bad value is refused with its message and the old one shown again."""
        text = self.dtEdit.text()

        def apply():
            _yade.O.dt = float(text)
        if not self._act(apply):
            self.dtEdit.setText('%.6g' % _yade.O.dt)
        self.refresh()

    def saveDialog(self):
        name, _ = QtWidgets.QFileDialog.getSaveFileName(self, 'Save the simulation', '', 'Yade (*.yade *.yade.gz *.xml)')
        if name:
            self._act(lambda: _yade.O.save(name))

    def loadDialog(self):
        name, _ = QtWidgets.QFileDialog.getOpenFileName(self, 'Load a simulation', '', 'Yade (*.yade *.yade.gz *.yade.bz2 *.yade.zst *.xml)')
        if name:
            self._act(lambda: _yade.O.load(name))

    def inspect(self):
        from yade import qt
        qt.Inspector()

    # --- the display tab: the renderer's switches, from its declaration
    def _displayTab(self):
        w = QtWidgets.QWidget()
        layout = QtWidgets.QVBoxLayout(w)
        self.switches = {}
        for name, value in self.renderer.dict().items():
            if isinstance(value, bool):
                box = QtWidgets.QCheckBox(name)
                box.setChecked(value)
                box.toggled.connect(lambda on, name=name: self.setSwitch(name, on))
                self.switches[name] = box
                layout.addWidget(box)
        layout.addStretch()
        return w

    def setSwitch(self, name, on):
        setattr(self.renderer, name, bool(on))
        from yade import qt
        for v in qt.views():
            v._update()

    # --- the Python tab
    def _pythonTab(self):
        w = QtWidgets.QWidget()
        layout = QtWidgets.QVBoxLayout(w)
        self.command = QtWidgets.QLineEdit()
        self.command.setPlaceholderText('a Python command, e.g. O.bodies[0].state.vel = (0, 0, 1)')
        self.command.returnPressed.connect(self.runCommand)
        self.output = QtWidgets.QLabel()
        self.output.setWordWrap(True)
        layout.addWidget(self.command)
        layout.addWidget(self.output)
        layout.addStretch()
        return w

    def runCommand(self, text=None):
        """Runs a command in the script's namespace (__main__); shows its value or its error."""
        import __main__
        text = self.command.text() if text is None else text
        ns = __main__.__dict__
        try:
            try:
                result = repr(eval(text, ns))
            except SyntaxError:
                exec(text, ns)
                result = ''
        except Exception as e:
            result = '%s: %s' % (type(e).__name__, e)
        self.output.setText(result)
        return result
