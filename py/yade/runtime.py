"""How this process was started (the reference's yade.runtime): `opts`, the launcher's options as scripts
read them (opts.nogui, opts.threads, opts.stdperformance...), `argv` and `hasDisplay` (False: no GUI here).
The launcher sets them; from plain python3 they keep these defaults."""
import argparse
import sys

opts = argparse.Namespace(nogui=True, threads=1, exitAfter=False, script=None, args=[], test=False, performance=False,
                          quickperformance=False, stdperformance=None, nice=None, version=False, cores=None, verbosity=None)
argv = list(sys.argv)
hasDisplay = False
