"""The one way tests run the dhsym command, as a user would type it.

`run_dhsym(...)` runs it in this process (fast: no interpreter start-up, no SymPy import), with its
own standard input, output and error, a 100-column width and the working folder given;
`run_dhsym_process(...)` runs `python -m dhsym.cli` as a real process, for what only a process
shows: the interpreter's exit status and final flush, closed or full streams, signals,
encodings, what gets imported at start-up. Both return Result(status, stdout, stderr).

>>> result = run_dhsym("table", "planar2r")
>>> result.status, result.stderr, "θ1" in result.stdout
(0, '', True)
>>> run_dhsym("fk", "no_such_robot").status
2
>>> "planar2r" in run_dhsym("list").ok()
True
"""
from __future__ import annotations

import contextlib
import io
import os
import subprocess
import sys
from typing import NamedTuple

COMMAND = [sys.executable, "-m", "dhsym.cli"]  # for the few tests that drive the process themselves (Popen)
WIDTH = {"COLUMNS": "100"}  # not the tester's terminal: outputs are compared as a 100-column terminal shows them


class Result(NamedTuple):
    status: int
    stdout: str
    stderr: str

    def ok(self) -> str:
        """The output of a command that must succeed (status 0; a failure shows its stderr)."""
        assert self.status == 0, self.stderr
        return self.stdout


def run_dhsym(*args, stdin: str = "", cwd=None, env: dict | None = None, **injected) -> Result:
    """`dhsym ARGS` in this process; `injected` goes to cli.main (a test's own `read`, say)."""
    from dhsym.cli import app

    out, err = io.StringIO(), io.StringIO()
    standard_input = io.TextIOWrapper(io.BytesIO(stdin.encode("utf-8")), encoding="utf-8")
    with _environment({**WIDTH, **(env or {})}), contextlib.chdir(cwd or os.getcwd()), _stdin(standard_input), \
            contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = app.main([str(arg) for arg in args], **injected)
        except SystemExit as leaving:  # --help and --version leave through argparse
            status = leaving.code if isinstance(leaving.code, int) else int(leaving.code is not None)
    return Result(status, out.getvalue(), err.getvalue())


def run_dhsym_process(*args, stdin: str | None = None, cwd=None, env: dict | None = None, timeout: float = 120,
                  **options) -> Result:
    """`python -m dhsym.cli ARGS` as a real process. `timeout` is far off: it turns a run that would block
    for ever into a failed test. `options` go to subprocess.run (stdout=a file, preexec_fn, ...); a stream
    redirected there comes back as ''."""
    streams = {"stdout": subprocess.PIPE, "stderr": subprocess.PIPE, **options}
    done = subprocess.run([*COMMAND, *map(str, args)], input=stdin, cwd=cwd, text=True, timeout=timeout,
                          env={**os.environ, "PYTHONIOENCODING": "utf-8", **WIDTH, **(env or {})}, **streams)
    return Result(done.returncode, done.stdout or "", done.stderr or "")


@contextlib.contextmanager
def _environment(values: dict):
    saved = {name: os.environ.get(name) for name in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for name, value in saved.items():
            if value is None:
                os.environ.pop(name, None)
            else:
                os.environ[name] = value


@contextlib.contextmanager
def _stdin(stream):
    saved, sys.stdin = sys.stdin, stream
    try:
        yield
    finally:
        sys.stdin = saved
