"""The `dhsym` process: `python -m dhsym.cli ...` and the installed `dhsym` command call `run()`.

It is `app.main` plus housekeeping that only a whole process should do (tests and notebooks
call `main` in their own process). SymPy's import makes a few hundred thousand objects that
live until the process ends; Python's garbage collector would walk through all of them while
they are imported and again at exit, a quarter of the CPU time of `dhsym fk` (measured by
benchmarks/startup.py). So the collector is off while the modules are imported, and what
exists then is frozen (`gc.freeze`: kept, never walked again) before the command runs and
before the process exits. The command's own work is collected as usual. And SIGTERM and SIGHUP
stop the command the way Ctrl-C does, cleaning up on the way out (see app.Stopped).
"""
import gc
import sys


def run() -> None:
    """Run the command in sys.argv and exit with its status."""
    gc.disable()
    from .app import main, stop_cleanly_on_signals  # SymPy and the dispatcher: objects that live until exit

    gc.freeze()
    gc.enable()
    stop_cleanly_on_signals()
    status = main()
    gc.freeze()  # the final collections need not walk SymPy's objects again
    sys.exit(status)


if __name__ == "__main__":
    run()
