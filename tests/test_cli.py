"""The CLI through subprocess: outputs, exit codes, JSON that reads back, determinism."""
import json
import os
import subprocess
import sys

import pytest
import sympy

from dhsym.checking.verify import numeric_error
from dhsym.io.library import load


def run(*args, env=None):
    return subprocess.run([sys.executable, "-m", "dhsym.cli", *args], capture_output=True, text=True,
                          env={**os.environ, **(env or {})}, timeout=60)


def test_demo_output():
    result = run("fk", "puma560")
    assert result.returncode == 0 and result.stderr == ""
    assert "px  = c1(a2 c2 + a3 c23 − d4 s23) − d3 s1" in result.stdout
    assert "c23 = cos(θ2 + θ3)" in result.stdout


def test_json_reads_back_with_sympify():
    result = run("fk", "stanford", "--format", "json")
    data = json.loads(result.stdout)
    assert set(data) == {"robot", "convention", "from", "to", "joint_variables", "matrix", "abbreviations"}
    assert (data["from"], data["to"]) == (0, 6)
    matrix = sympy.Matrix(data["matrix"]).applyfunc(sympy.sympify)
    real = {s.name: s for s in load("stanford").fk(raw=True).free_symbols}
    matrix = matrix.subs({sympy.Symbol(n): s for n, s in real.items()})
    assert numeric_error(matrix, load("stanford").fk(raw=True)) < 1e-9
    assert data["abbreviations"]["c1"] == "cos(theta_1)"


def test_from_to_and_inverse():
    forward = json.loads(run("fk", "puma560", "--from", "3", "--to", "6", "--format", "json").stdout)
    backward = json.loads(run("fk", "puma560", "--from", "6", "--to", "3", "--format", "json").stdout)
    assert (forward["from"], backward["from"]) == (3, 6)
    a = sympy.Matrix(forward["matrix"]).applyfunc(sympy.sympify)
    b = sympy.Matrix(backward["matrix"]).applyfunc(sympy.sympify)
    assert numeric_error(a * b, sympy.eye(4)) < 1e-9


def test_tool_frame_is_the_default_end():
    data = json.loads(run("fk", "planar3r", "--format", "json").stdout)
    assert data["to"] == "tool"


@pytest.mark.parametrize("args, message", [
    (("fk", "nope"), "dhsym: error: unknown robot 'nope'; built-in robots are: "),
    (("fk", "planar2r", "--to", "9"), "dhsym: error: no frame 9 in this robot; frames are 0, 1, 2"),
    (("fk",), "dhsym: error: the following arguments are required: ROBOT"),
    (("fk", "missing.yaml"), "dhsym: error: missing.yaml: cannot read file"),
])
def test_user_errors_are_one_line_exit_2(args, message):
    result = run(*args)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and result.stderr.startswith(message)
    assert "Traceback" not in result.stderr


def test_help_at_every_level():
    for args in (("--help",), ("fk", "--help"), ("table", "--help"), ("links", "--help"), ("list", "--help")):
        result = run(*args)
        assert result.returncode == 0 and "usage: dhsym" in result.stdout


def test_list_shows_sources():
    result = run("list")
    assert "puma560" in result.stdout and "source: " in result.stdout


def test_links_and_table():
    links = run("links", "planar2r", "--ascii").stdout
    assert links.count("T") >= 2 and links.isascii()
    table = run("table", "scara_spong").stdout
    assert "d3*" in table and "π" in table


def test_same_output_under_any_hash_seed():
    outputs = {run("fk", "puma560", env={"PYTHONHASHSEED": seed}).stdout for seed in ("0", "1", "12345")}
    assert len(outputs) == 1
    outputs = {run("fk", "scara", "--format", "latex", env={"PYTHONHASHSEED": seed}).stdout for seed in ("0", "7")}
    assert len(outputs) == 1
