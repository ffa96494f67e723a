"""The optional extras (pyproject.toml): the core runs without matplotlib, numpy, lxml and xacro, and
a command that needs one that is missing says which extra installs it, in one line, exit status 2.

Each case is a process in which the optional packages cannot be imported (their sys.modules
entries are None, as if they were not installed)."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

OPTIONAL = ("matplotlib", "numpy", "lxml", "xacro")
DATA = Path(__file__).parent / "data"


def without_extras(*args: str, cwd=None) -> subprocess.CompletedProcess:
    probe = ("import sys\n"
             f"for name in {OPTIONAL!r}:\n    sys.modules[name] = None\n"
             "from dhsym.cli.app import main\n"
             f"sys.exit(main({list(args)!r}))")
    return subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=300, cwd=cwd)


def test_the_core_commands_run_without_the_extras(tmp_path):
    for command in (["fk", "puma560"], ["table", "ur5"], ["links", "scara"], ["jacobian", "stanford"],
                    ["ik", "planar2r"], ["latex", "planar2r", "--jacobian", "--ik", "-o", "arm.tex"],
                    ["convert", "puma560", "--to", "standard"], ["check", "spatial3r", "--against", "spatial3r"],
                    ["screws", "planar3r"], ["list"]):
        result = without_extras(*command, cwd=tmp_path)
        assert (result.returncode, result.stderr) == (0, ""), command


@pytest.mark.parametrize("command, extra, missing", [
    (["plot", "planar2r", "-o", "arm.png"], "plot", "matplotlib"),
    (["import", str(DATA / "ur5.urdf")], "urdf", "lxml"),
    (["ik", str(DATA / "numeric" / "offset_wrist_cobot.yaml"), "--numeric"], "plot", "numpy"),
])
def test_a_command_that_needs_a_missing_extra_names_it(command, extra, missing, tmp_path):
    result = without_extras(*command, cwd=tmp_path)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.splitlines() == [
        f"dhsym: error: {missing} is not installed ({_what(missing)}); install it with: pip install 'dhsym[{extra}]'"]
    assert list(tmp_path.iterdir()) == []  # no half-written picture


def _what(missing: str) -> str:
    from dhsym.cli.messages import EXTRAS

    return EXTRAS[missing][0]


def test_the_refusal_of_a_closed_form_names_the_numeric_command_without_numpy(tmp_path):
    robot = str(DATA / "numeric" / "offset_wrist_cobot.yaml")
    result = without_extras("ik", robot, cwd=tmp_path)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.endswith(f"`dhsym ik {robot} --numeric` gives every solution in numbers\n")
