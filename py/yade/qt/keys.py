"""The prompt's keys for the windows, as the manual's: F12 the controller, F11 a 3D view, F10 both, F8 the plot
(yade.plot.plot()). Installed by the launcher at the IPython prompt when the windows can open."""


def install(shell=None):
    """Adds the keys to the IPython shell's prompt; False when that prompt has no key bindings to add to."""
    try:
        shell = shell or get_ipython()  # noqa: F821  (defined by IPython)
        bindings = shell.pt_app.key_bindings
        add = bindings.add
    except Exception:
        return False
    from yade import qt

    def both():
        qt.Controller()
        qt.View()

    def plot():
        from yade import plot as p
        p.plot()
    for key, action in (('f12', qt.Controller), ('f11', qt.View), ('f10', both), ('f8', plot)):
        add(key)(lambda event, action=action: action())
    return True
