"""The reference's Qt GUI module (qt.View(), qt.Controller(), ...). This engine has no GUI yet: importing
it raises ImportError, as the reference's does when it runs without a display (`-n`)."""
raise ImportError("yade.qt: this build has no Qt GUI yet (the 3D view and controller come in a later version); "
                  "run the script without its qt lines, or guard them with `if not opts.nogui:` "
                  "(the reference raises ImportError here too when started with -n)")
