"""The inspector (manual: "Inspector"): a tree of the engines, bodies, interactions and the cell on the left,
the attributes of what is chosen on the right, each from its declaration (dict()), so that no class needs
GUI code of its own. A writable attribute is edited by typing a Python expression (evaluated with the
names of `from yade import *`); a bad value is refused with its message and the old one kept. Objects held
by an attribute (a body's shape, an engine's functors) open as children of the tree.

Scripts and tests drive it as a user would: `select(obj)`, `setAttribute(name, text)` (None when it was
set, else the error's message), `value(name)`.
"""
from PyQt5 import QtCore, QtWidgets

import yade
from yade import _yade


def _label(obj):
    label = getattr(obj, 'label', '')
    return '%s%s' % (type(obj).__name__, ' "%s"' % label if label else '')


class InspectorWindow(QtWidgets.QWidget):
    maxBodiesListed = 1000  # the tree lists this many; the id field reaches any body

    def __init__(self):
        super().__init__()
        self.setWindowTitle('Yade inspector')
        self.obj = None
        self.tree = QtWidgets.QTreeWidget()
        self.tree.setHeaderLabels(['object'])
        self.tree.itemClicked.connect(lambda item, col: self.select(item.data(0, QtCore.Qt.UserRole)))
        self.table = QtWidgets.QTableWidget(0, 2)
        self.table.setHorizontalHeaderLabels(['attribute', 'value'])
        self.table.horizontalHeader().setStretchLastSection(True)
        self.table.itemChanged.connect(self._edited)
        self.bodyId = QtWidgets.QSpinBox()
        self.bodyId.setRange(0, 2**31 - 1)
        self.bodyId.setPrefix('body #')
        self.bodyId.editingFinished.connect(lambda: self.showBody(self.bodyId.value()))
        self.message = QtWidgets.QLabel()
        self.message.setWordWrap(True)
        left = QtWidgets.QWidget()
        lv = QtWidgets.QVBoxLayout(left)
        lv.addWidget(self.tree)
        lv.addWidget(self.bodyId)
        refresh = QtWidgets.QPushButton('Refresh')
        refresh.clicked.connect(self.rebuild)
        lv.addWidget(refresh)
        right = QtWidgets.QWidget()
        rv = QtWidgets.QVBoxLayout(right)
        rv.addWidget(self.table)
        rv.addWidget(self.message)
        split = QtWidgets.QSplitter()
        split.addWidget(left)
        split.addWidget(right)
        QtWidgets.QVBoxLayout(self).addWidget(split)
        self.resize(700, 500)
        self._filling = False
        self.rebuild()

    # --- the tree
    def _item(self, parent, text, obj):
        item = QtWidgets.QTreeWidgetItem(parent, [text])
        item.setData(0, QtCore.Qt.UserRole, obj)
        return item

    def rebuild(self):
        O = _yade.O
        self.tree.clear()
        engines = self._item(self.tree, 'Engines', None)
        for e in O.engines:
            self._item(engines, _label(e), e)
        bodies = self._item(self.tree, 'Bodies (%d)' % len(O.bodies), None)
        for i, b in enumerate(O.bodies):
            if i >= self.maxBodiesListed:
                self._item(bodies, '... (the id field below reaches the others)', None)
                break
            if b is not None:
                self._item(bodies, '#%d %s' % (b.id, type(b.shape).__name__ if b.shape is not None else ''), b)
        intrs = self._item(self.tree, 'Interactions (%d)' % O.interactions.countReal(), None)
        for k, i in enumerate(O.interactions):
            if k >= self.maxBodiesListed:
                self._item(intrs, '...', None)
                break
            self._item(intrs, '#%d + #%d' % (i.id1, i.id2), i)
        if O.periodic:
            self._item(self.tree, 'Cell', O.cell)
        engines.setExpanded(True)

    # --- the attributes
    def select(self, obj):
        """Shows the attributes of obj (any object with dict(), e.g. an engine, a body, its shape, O.cell)."""
        if obj is None:
            return
        self.obj = obj
        self.message.setText(_label(obj))
        self._fill()

    def showBody(self, bodyId):
        O = _yade.O
        if 0 <= bodyId < len(O.bodies) and O.bodies[bodyId] is not None:
            self.bodyId.setValue(bodyId)
            self.select(O.bodies[bodyId])

    def _attributes(self):
        d = self.obj.dict() if hasattr(self.obj, 'dict') else {}
        if isinstance(self.obj, yade.Body):  # its parts, as the reference's inspector shows them
            d = dict(d, shape=self.obj.shape, state=self.obj.state, material=self.obj.material, bound=self.obj.bound)
        return d

    def _fill(self):
        self._filling = True
        try:
            attrs = self._attributes()
            self.table.setRowCount(len(attrs))
            for row, (name, value) in enumerate(attrs.items()):
                key = QtWidgets.QTableWidgetItem(name)
                key.setFlags(key.flags() & ~QtCore.Qt.ItemIsEditable)
                val = QtWidgets.QTableWidgetItem(self._show(value))
                if isinstance(value, yade.Serializable) or (isinstance(value, list) and value and isinstance(value[0], yade.Serializable)):
                    val.setFlags(val.flags() & ~QtCore.Qt.ItemIsEditable)
                self.table.setItem(row, 0, key)
                self.table.setItem(row, 1, val)
        finally:
            self._filling = False

    @staticmethod
    def _show(value):
        if isinstance(value, yade.Serializable):
            return '[%s]' % _label(value)
        if isinstance(value, list) and value and isinstance(value[0], yade.Serializable):
            return '[%s]' % ', '.join(_label(v) for v in value)
        return repr(value)

    def _edited(self, item):
        if self._filling or item.column() != 1:
            return
        name = self.table.item(item.row(), 0).text()
        error = self.setAttribute(name, item.text())
        if error:
            self._fill()  # the old value back
            self.message.setText(error)

    def setAttribute(self, name, text):
        """Sets attribute `name` of the shown object from a Python expression; None when set, else the error's
        message (the attribute then keeps its old value, as the class's checks leave it)."""
        ns = dict(vars(yade))
        try:
            value = eval(text, ns)
            setattr(self.obj, name, value)
        except Exception as e:
            return '%s: %s' % (type(e).__name__, e)
        self._fill()
        self.message.setText('%s.%s = %s' % (_label(self.obj), name, text))
        return None

    def value(self, name):
        """The value of attribute `name` of the shown object, as the table shows it."""
        for row in range(self.table.rowCount()):
            if self.table.item(row, 0).text() == name:
                return self.table.item(row, 1).text()
        raise KeyError(name)
