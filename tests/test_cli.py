"""The CLI as a user runs it: outputs, exit codes, JSON that reads back, determinism, numbers
and angles as written, output that fits its width, and faults that are not bugs.

Most tests run the command in this process (tests/cli_runner.py: the same `main`, its own
streams, 100 columns); a real process where only one shows it: the demo, the hash seed, no
terminal and no $COLUMNS, a full disk, a closed or abandoned standard output."""
import json
import os
import re
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

import pytest
import sympy
from cli_runner import COMMAND, run_dhsym_process
from cli_runner import run_dhsym as run

from dhsym import load
from dhsym.checking.verify import numeric_error

UR5_PUBLISHED = """\
name: UR5 (published numbers)
convention: standard
joints:
  - {joint: R, alpha: pi/2,  a: 0,        d: 0.089159, theta: theta_1}
  - {joint: R, alpha: 0,     a: -0.425,   d: 0,        theta: theta_2}
  - {joint: R, alpha: 0,     a: -0.39225, d: 0,        theta: theta_3}
  - {joint: R, alpha: pi/2,  a: 0,        d: 0.10915,  theta: theta_4}
  - {joint: R, alpha: -pi/2, a: 0,        d: 0.09465,  theta: theta_5}
  - {joint: R, alpha: 0,     a: 0,        d: 0.0823,   theta: theta_6}
"""
OFFSET_ARM = """\
name: arm with offsets
convention: standard
joints:
  - {joint: R, alpha: 0,   a: l_1, d: 0, theta: theta_1}
  - {joint: R, alpha: 0,   a: l_2, d: 0, theta: theta_2 - pi/4}
  - {joint: R, alpha: 0.3, a: 0,   d: 0, theta: theta_3 - pi/2}
"""


@pytest.fixture
def robot_file(tmp_path):
    def write(text, name="arm.yaml"):
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return str(path)
    return write


@pytest.mark.slow
def test_demo_output():
    result = run_dhsym_process("fk", "puma560")
    assert result.status == 0 and result.stderr == ""
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
    (("fk", "planar2r", "--to", "9"), "dhsym: error: --to: no frame 9 in this robot; frames are 0, 1, 2"),
    (("fk",), "dhsym: error: the following arguments are required: ROBOT"),
    (("fk", "missing.yaml"), "dhsym: error: missing.yaml: cannot read file"),
])
def test_user_errors_are_one_line_exit_2(args, message):
    result = run(*args)
    assert result.status == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and result.stderr.startswith(message)
    assert "Traceback" not in result.stderr


def test_help_at_every_level():
    for args in (("--help",), ("fk", "--help"), ("table", "--help"), ("links", "--help"), ("list", "--help")):
        result = run(*args)
        assert result.status == 0 and "usage: dhsym" in result.stdout


def test_version_is_the_installed_package_s():
    pyproject = (Path(__file__).parent.parent / "pyproject.toml").read_text()
    written = re.search(r'^version = "(.+)"', pyproject, re.M).group(1)
    assert run("--version") == (0, f"dhsym {written}\n", "")
    assert run("--version", "fk", "puma560") == (0, f"dhsym {written}\n", "")  # as --help: nothing else is done


def test_list_shows_sources():
    result = run("list")
    assert "puma560" in result.stdout and "source: " in result.stdout


def test_links_and_table():
    links = run("links", "planar2r", "--ascii").stdout
    assert links.count("T") >= 2 and links.isascii()
    table = run("table", "scara_spong").stdout
    assert "d3*" in table and "π" in table


@pytest.mark.slow
def test_same_output_under_any_hash_seed():
    outputs = {run_dhsym_process("fk", "puma560", env={"PYTHONHASHSEED": seed}).stdout for seed in ("0", "1", "12345")}
    assert len(outputs) == 1
    outputs = {run_dhsym_process("fk", "scara", "--format", "latex", env={"PYTHONHASHSEED": seed}).stdout
               for seed in ("0", "7")}
    assert len(outputs) == 1


# --- numbers and angles as written ------------------------------------------------------------

def test_decimals_print_as_decimals_everywhere(robot_file):
    path = robot_file(UR5_PUBLISHED)
    text = run("fk", path).stdout
    assert "pz  = 0.089159 − 0.425 s2 − 0.39225 s23 − 0.09465 c234 − 0.0823 s234 s5\n" in text
    assert "px  = −c1(0.425 c2 + 0.39225 c23 + 0.0823 c234 s5 − 0.09465 s234) + s1(0.10915 + 0.0823 c5)\n" in text
    table = run("table", path).stdout
    assert "1 │ θ1* │ 0.089159 │ 0        │ π/2\n" in table and "│ −0.39225 │" in table
    latex = run("fk", path, "--format", "latex").stdout
    assert "0.089159 - 0.425 s_{2} - 0.39225 s_{23}" in latex and "\\frac" not in latex
    data = json.loads(run("fk", path, "--format", "json").stdout)
    assert data["matrix"][2][3] == ("-0.425*sin(theta_2) - 0.0823*sin(theta_5)*sin(theta_2 + theta_3 + theta_4) - "
                                    "0.39225*sin(theta_2 + theta_3) - 0.09465*cos(theta_2 + theta_3 + theta_4) + "
                                    "0.089159")
    assert json.loads(run("table", path, "--format", "json").stdout)["rows"][0]["d"] == "0.089159"


@pytest.mark.slow
def test_a_factored_determinant_keeps_the_decimals_as_written(robot_file):
    text = run("jacobian", robot_file(UR5_PUBLISHED)).stdout
    assert "det J = −0.16670625 s3 s5(0.425 c2 + 0.39225 c23 − 0.09465 s234)\n" in text
    assert "  0.425 c2 + 0.39225 c23 − 0.09465 s234 = 0: shoulder" in text


def test_control_characters_in_names_are_escaped_in_every_output(robot_file):
    path = robot_file('name: "arm\\e[31mRED\\x9b"\nsource: "a\\u202eb"\nconvention: standard\n'
                      "joints:\n  - {joint: R, alpha: 0, a: l_1, d: 0, theta: theta_1}\n")
    for command in (["table"], ["fk"], ["jacobian"], ["screws"], ["fk", "--format", "json"], ["latex"],
                    ["latex", "--document", "article"], ["check", "--against", path]):
        result = run(command[0], path, *command[1:])
        assert result.status == 0 and result.stdout, command
        assert not any(ch not in "\n\t" and not ch.isprintable() for ch in result.stdout), command
    assert run("table", path).stdout.startswith("arm\\x1b[31mRED\\x9b: DH table")
    assert json.loads(run("fk", path, "--format", "json").stdout)["robot"] == "arm\x1b[31mRED\x9b"


def test_sums_and_products_of_decimals_stay_decimals(robot_file):
    path = robot_file(UR5_PUBLISHED.replace("a: -0.39225, d: 0,        theta: theta_3",
                                            "a: -0.39225, d: 0,        theta: theta_3, var: theta_3")
                      .replace("alpha: 0,     a: -0.39225", "alpha: pi,    a: -0.39225"))
    assert "pz  = 0.089159 − 0.425 s2" in run("fk", path).stdout
    sums = robot_file("convention: standard\njoints:\n  - {joint: R, alpha: 0, a: 0.425, d: 0, theta: q}\n"
                      "tool: [{Tx: 0.39225}, {Tz: 0.333*0.5}]\n", "sums.yaml")
    data = json.loads(run("fk", sums, "--format", "json").stdout)
    assert data["matrix"][0][3] == "0.81725*cos(q)" and data["matrix"][2][3] == "0.1665"
    assert sympy.sympify(data["matrix"][2][3], rational=True) == sympy.Rational(333, 2000)


def test_fractions_and_multiples_of_pi_print_as_written(robot_file):
    path = robot_file("convention: standard\njoints:\n  - {joint: R, alpha: pi/3, a: l_1/2, d: 0.5, theta: q}\n")
    table = run("table", path).stdout
    assert "1 │ q* │ 0.5 │ l1/2 │ π/3\n" in table
    assert "⎢ 0    √3/2    0.5          0.5       ⎥" in run("fk", path).stdout  # cos(π/3) next to d: 0.5


def test_an_offset_keeps_its_angle_as_written(robot_file):
    path = robot_file(OFFSET_ARM)
    text = run("fk", path).stdout
    assert "⎡ s123    c123 cos(0.3)   −c123 sin(0.3)   l1 c1 + l2 c12 ⎤" in text
    assert "c12 = cos(θ1 + θ2 − π/4), s12 = sin(θ1 + θ2 − π/4)" in text
    assert "sin(π/4" not in text and "+ π/4" not in text
    table = run("table", path).stdout
    assert "2 │ θ2* − π/4 │ 0  │ l2 │ 0\n" in table and "3 │ θ3* − π/2 │ 0  │ 0  │ 0.3\n" in table
    latex = run("fk", path, "--format", "latex").stdout
    assert "c_{12} &= \\cos(\\theta_{1} + \\theta_{2} - \\frac{\\pi}{4})" in latex
    data = json.loads(run("fk", path, "--format", "json").stdout)
    assert data["matrix"][0][3] == "l_1*cos(theta_1) + l_2*cos(theta_1 + theta_2 - pi/4)"
    assert data["abbreviations"]["c12"] == "cos(theta_1 + theta_2 - pi/4)"
    real = {s.name: s for s in load_file(path).fk().free_symbols}
    matrix = sympy.Matrix([[sympy.sympify(e, locals=real, rational=True) for e in row] for row in data["matrix"]])
    assert numeric_error(matrix, load_file(path).fk(raw=True)) < 1e-9


def load_file(path):
    from readers import load_robot_file
    return load_robot_file(path)


def test_a_function_of_anything_but_a_symbol_is_bracketed(robot_file):
    path = robot_file("convention: standard\njoints:\n  - {joint: R, alpha: alpha/2, a: 0, d: 0, theta: q}\n"
                      "  - {joint: R, alpha: beta, a: 0, d: 0, theta: r}\n")
    text = run("links", path).stdout
    assert "cos(α/2)" in text and "cos β" in text and "cos α/2" not in text


# --- output that fits ---------------------------------------------------------------------------

@pytest.mark.parametrize("columns", ["60", "80", "100"])
def test_text_follows_columns_and_breaks_long_elements(columns):
    for robot in ("puma560", "iiwa7", "stanford", "finger_rrr"):
        text = run("fk", robot, env={"COLUMNS": columns}).stdout
        assert max(len(line.replace("\u0305", "")) for line in text.splitlines()[1:]) <= int(columns), (robot, text)


def test_a_long_element_breaks_before_a_top_level_sign_with_a_hanging_indent():
    lines = run("fk", "iiwa7", "--width", "100").stdout.splitlines()
    start = lines.index(next(line for line in lines if line.startswith("r11 = ")))
    assert lines[start:start + 3] == [
        "r11 = c1(c2{c3[c4(c5 c6 c7 − s5 s7) + s4 s6 c7] − s3(c5 s7 + s5 c6 c7)}",
        "          − s2[c4 s6 c7 − s4(c5 c6 c7 − s5 s7)])",
        "        − s1{c3(c5 s7 + s5 c6 c7) + s3[c4(c5 c6 c7 − s5 s7) + s4 s6 c7]}"]


@pytest.mark.slow
def test_the_textbook_forms_print_unchanged_at_the_default_width():
    text = run_dhsym_process("fk", "puma560", env={"COLUMNS": ""}).stdout  # no terminal, no COLUMNS: 100
    assert "r11 = c1[c23(c4 c5 c6 − s4 s6) − s23 s5 c6] + s1(c4 s6 + s4 c5 c6)\n" in text


@pytest.mark.parametrize("width", ["0", "-5", "39"])
def test_a_width_below_the_minimum_is_refused(width):
    result = run("fk", "puma560", f"--width={width}")
    assert result.status == 2 and result.stdout == ""
    assert result.stderr == (f"dhsym: error: argument --width: the width must be at least 40 columns, not {width} "
                             f"(see 'dhsym fk --help')\n")


def test_ascii_modified_tables_keep_i_minus_1():
    table = run("table", "puma560", "--ascii").stdout
    assert "i | alpha(i-1) | a(i-1) | d(i) | theta(i)\n" in table
    assert "T_i = Rx(alpha(i-1)) Tx(a(i-1)) Rz(theta(i)) Tz(d(i))" in table and table.isascii()


# --- standard input, limits and faults that are not bugs ----------------------------------------

@pytest.mark.slow
def test_every_robot_command_reads_the_robot_file_from_standard_input(robot_file, tmp_path):
    path = robot_file(OFFSET_ARM)
    for command in (["fk"], ["links"], ["table"], ["latex", "--document", "snippet"]):
        from_file, from_stdin = run(*command[:1], path, *command[1:]), run(*command[:1], "-", *command[1:],
                                                                           stdin=OFFSET_ARM)
        assert from_stdin.status == 0 and from_stdin.stdout.replace("<stdin>", path) == from_file.stdout
    picture = run("plot", "-", "--set", "l_1=1", "l_2=0.5", "-o", str(tmp_path / "arm.png"), stdin=OFFSET_ARM)
    assert picture.status == 0 and (tmp_path / "arm.png").read_bytes()[:4] == b"\x89PNG"
    broken = run("fk", "-", stdin="convention: standard\njoints: [{joint: R, alpha: pi2, a: 0, d: 0, theta: q}]\n")
    assert broken.stderr == ("dhsym: warning: <stdin>:2:28: joint row 1 alpha: 'pi2' is a new symbol, not π; "
                             "did you mean pi/2?\n")


@pytest.mark.slow
def test_the_ur5_determinant_does_not_depend_on_the_machine():
    """Factored or not is decided by counting terms, not by a time budget (it used to say "not
    computed" on a loaded machine)."""
    result = run("jacobian", "ur5")
    assert result.status == 0
    assert "not computed" not in result.stdout and "s5" in result.stdout.split("det")[-1]


def test_a_result_too_large_to_print_is_refused_within_seconds(robot_file):
    rows = "".join(f"  - {{joint: R, alpha: alpha_{i}, a: a_{i}, d: d_{i}, theta: theta_{i}}}\n" for i in range(1, 25))
    path = robot_file("name: general\nconvention: standard\njoints:\n" + rows)
    result = run("fk", path)  # refused by the estimate (the message below), not by a budget after minutes
    assert result.status == 2 and result.stdout == ""
    assert result.stderr == (f"dhsym: error: {path}: 0T24 would take about 1.2 trillion characters, too large to "
                             f"print or read; ask for part of the chain with --from/--to (--from 0 --to 8 fits), or "
                             f"print the link matrices with 'dhsym links'\n")
    assert run("fk", path, "--from", "0", "--to", "3").status == 0


@pytest.mark.slow
@pytest.mark.skipif(not (os.path.exists("/dev/full") and stat.S_ISCHR(os.stat("/dev/full").st_mode)),
                    reason="needs /dev/full")
def test_a_full_disk_is_an_error_not_a_bug():
    for command in (["fk", "puma560"], ["table", "puma560"], ["fk", "iiwa7", "--format", "json"]):
        with open("/dev/full", "w") as full:
            result = run_dhsym_process(*command, stdout=full)
        assert (result.status, result.stderr) == (2, "dhsym: error: cannot write the output: No space left on "
                                                         "device\n"), command
    result = run_dhsym_process("latex", "planar2r", "-o", "/dev/full")
    assert (result.status, result.stderr) == (2, "dhsym: error: /dev/full: cannot write file: No space left on "
                                                     "device\n")
    assert stat.S_ISCHR(os.stat("/dev/full").st_mode)  # written to, never replaced by a regular file


@pytest.mark.slow
def test_a_closed_standard_output_or_pipe_is_not_a_bug():
    closed = run_dhsym_process("fk", "puma560", stdout=subprocess.DEVNULL, close_fds=True,
                               preexec_fn=lambda: os.close(1))
    assert (closed.status, closed.stderr) == (2, "dhsym: error: standard output is closed; there is nowhere "
                                                     "to write the result\n")
    reader = subprocess.Popen([*COMMAND, "links", "iiwa7"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    reader.stdout.close()  # the reader leaves before anything is written, like `| head -0`
    assert reader.wait(timeout=60) == 141
    assert reader.stderr.read() == ("dhsym: error: standard output was closed by its reader before all of the output "
                                    "was written (a pipe into head?); the output is incomplete\n").encode()


# dhsym's own entry point, with the write's fsync held up: the signal comes while the temporary file exists
PAUSED_WRITE = ("import os, sys, time; sync = os.fsync; os.fsync = lambda fd: (time.sleep(120), sync(fd)); "
                "sys.argv = ['dhsym', 'convert', 'planar2r', '--to', 'modified', '-o', 'out.yaml']; "
                "from dhsym.cli.__main__ import run; run()")


@pytest.mark.slow
@pytest.mark.parametrize("signal_name, old", [("SIGTERM", None), ("SIGHUP", "old contents\n"), ("SIGINT", None)])
def test_a_signal_during_an_output_write_leaves_no_temporary_file(tmp_path, signal_name, old):
    """Stopped by SIGTERM or SIGHUP (kill, a closed terminal) as by Ctrl-C: the old file or none,
    no .out.yaml.XXXX.tmp beside it, one line and the status a shell gives a tool stopped so."""
    if old is not None:
        (tmp_path / "out.yaml").write_text(old)
    process = subprocess.Popen([sys.executable, "-c", PAUSED_WRITE], cwd=tmp_path, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    for _ in range(1200):  # until the temporary file exists (at most a minute)
        if any(path.name.endswith(".tmp") for path in tmp_path.iterdir()) or process.poll() is not None:
            break
        time.sleep(0.05)
    number = getattr(signal, signal_name)
    process.send_signal(number)
    stdout, stderr = process.communicate(timeout=60)
    expected = (130, "dhsym: interrupted\n") if signal_name == "SIGINT" else (128 + number,
                                                                               f"dhsym: stopped by {signal_name}\n")
    assert (process.returncode, stderr) == expected
    assert [path.name for path in tmp_path.iterdir()] == ([] if old is None else ["out.yaml"])
    if old is not None:
        assert (tmp_path / "out.yaml").read_text() == old


def test_an_unwritable_output_path_is_one_error_line(tmp_path):
    result = run("latex", "planar2r", "-o", str(tmp_path / "missing" / "arm.tex"))
    assert (result.status, result.stdout) == (2, "")
    assert result.stderr == f"dhsym: error: {tmp_path / 'missing' / 'arm.tex'}: folder " \
                            f"'{tmp_path / 'missing'}' does not exist\n"
    folder = tmp_path / "folder.tex"
    folder.mkdir()
    result = run("latex", "planar2r", "-o", str(folder))
    assert result.status == 2 and result.stderr.startswith(f"dhsym: error: {folder}: cannot write file: ")
