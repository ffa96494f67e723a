"""Hostile and malformed input: every file in tests/bad_inputs/ gives exactly its expected lines.

Each case NAME has NAME.expected (the exact stderr, one line per message; empty when the input
is accepted silently), usually an input NAME.yaml, and optionally NAME.args (the command line,
one argument per line, `{file}` standing for NAME.yaml; the default is `fk NAME.yaml`).
An expected line with an error means exit status 2 and nothing on stdout; warnings alone
mean exit status 0 and a result on stdout. Several inputs try to run code that would create
a file named CANARY; the tests check that it never appears.

Most cases run in-process (tests/cli_runner.py, fast); a handful run through a real subprocess,
to check what a user sees: no traceback, the exit status, the streams.
"""
import os
import re
import shutil
import stat
import subprocess
from pathlib import Path

import pytest
from cli_runner import run_dhsym, run_dhsym_process

from dhsym.cli import app as cli
from dhsym.errors import UserError
from dhsym.io.library import builtin_names
from dhsym.io.output import write_atomic
from dhsym.io.yamlsafe import MAX_FILE_BYTES, MAX_YAML_NODES

CORPUS = Path(__file__).parent / "bad_inputs"
CASES = sorted(path.stem for path in CORPUS.glob("*.expected"))
# seconds each: a macro that doubles to its bound, 3,000 tool steps multiplied out
SLOW_CASES = ["cli_fk_3000_tool_steps", "xacro_doubling_macro"]
THROUGH_SUBPROCESS = ["yaml_python_object_apply", "expr_import", "warn_twist_90"]
CANARY = "CANARY"


def command_line(name: str) -> list[str]:
    args_file = CORPUS / f"{name}.args"
    args = args_file.read_text(encoding="utf-8").splitlines() if args_file.exists() else ["fk", "{file}"]
    return [arg.replace("{file}", f"{name}.yaml") for arg in args]


def expected_lines(name: str) -> list[str]:
    text = (CORPUS / f"{name}.expected").read_text(encoding="utf-8")
    return text.replace("{builtin_names}", ", ".join(builtin_names())).splitlines()


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    """A copy of the corpus to run in, so that a canary would land where we look for it."""
    folder = tmp_path_factory.mktemp("bad_inputs")
    for path in CORPUS.iterdir():
        shutil.copy(path, folder / path.name)
    before = sorted(os.listdir(folder))
    yield folder
    assert sorted(os.listdir(folder)) == before  # nothing created, nothing removed, anywhere in the run


def check_outcome(name: str, status: int, stdout: str, stderr: str) -> None:
    lines = expected_lines(name)
    assert stderr.splitlines() == lines
    assert "Traceback" not in stderr
    if any(line.startswith("dhsym: error: ") for line in lines):
        assert status == 2 and stdout == "" and len(lines) == 1
        if (CORPUS / f"{name}.yaml").exists() and not name.startswith("cli_"):  # the file's content is at fault
            assert re.match(rf"dhsym: error: {re.escape(name)}\.yaml:\d+:\d+: \S", lines[0])
    else:
        assert all(line.startswith("dhsym: warning: ") for line in lines)
        assert status == 0 and stdout.strip()


def test_the_corpus_is_big_and_complete():
    inputs = list(CORPUS.glob("*.yaml"))
    assert len(inputs) >= 40
    for path in inputs:
        assert (CORPUS / f"{path.stem}.expected").exists(), path.name
    assert sum(CANARY in path.read_bytes().decode("utf-8", "replace") for path in inputs) >= 12


@pytest.mark.parametrize("name", [pytest.param(name, marks=pytest.mark.slow) if name in SLOW_CASES else name
                                  for name in CASES])
def test_case_in_process(name, workdir):
    check_outcome(name, *run_dhsym(*command_line(name), cwd=workdir))
    assert not (workdir / CANARY).exists()


@pytest.mark.slow
@pytest.mark.parametrize("name", THROUGH_SUBPROCESS)
def test_case_through_subprocess(name, workdir):
    check_outcome(name, *run_dhsym_process(*command_line(name), cwd=workdir))
    assert not (workdir / CANARY).exists()


def test_a_file_over_the_size_limit_is_refused_without_reading_it_all(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    Path("huge.yaml").write_bytes(b"notes: " + b"x" * MAX_FILE_BYTES + b"\n")
    assert run_dhsym("fk", "huge.yaml") == (
        2, "", "dhsym: error: huge.yaml:1:1: file is larger than 1 MiB, the limit for robot files\n")


@pytest.mark.slow
def test_too_many_yaml_values_are_refused(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    Path("wide.yaml").write_text("convention: standard\nnotes: [" + "1, " * MAX_YAML_NODES + "1]\n")
    status, stdout, stderr = run_dhsym("fk", "wide.yaml")
    assert (status, stdout) == (2, "")
    assert re.fullmatch(r"dhsym: error: wide\.yaml:2:\d+: more than 20000 YAML values; this is not a robot file\n",
                        stderr)


def test_an_internal_bug_asks_for_a_report_and_exits_70():
    def broken(name):
        raise KeyError("a bug")
    status, stdout, stderr = run_dhsym("fk", "planar2r", read=broken)
    assert status == 70 and stdout == ""
    assert stderr == ("dhsym: internal error: KeyError: 'a bug' (a bug in dhsym, not a mistake in your input; please "
                      "report it on the dhsym issue tracker with the command and the robot file)\n")


def test_a_closed_pipe_is_one_error_line():
    def reader_left(name):
        raise BrokenPipeError()
    status, stdout, stderr = run_dhsym("fk", "planar2r", read=reader_left)
    assert (status, stdout) == (cli.EXIT_BROKEN_PIPE, "")
    assert stderr.startswith("dhsym: error: standard output was closed by its reader") and stderr.count("\n") == 1


@pytest.mark.slow
def test_an_ascii_terminal_gets_advice_not_a_traceback():
    result = run_dhsym_process("fk", "planar2r", env={"PYTHONIOENCODING": "ascii"})
    assert result.status == 2 and result.stdout == ""
    assert result.stderr == "dhsym: error: the output cannot be written as ascii; use --ascii, or set " \
                            "PYTHONIOENCODING=utf-8\n"


def test_messages_stay_on_one_line_whatever_the_file_is_called(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    Path("two\nlines.yaml").write_text("convention: standard\njoints: []\n")
    status, _, stderr = run_dhsym("fk", "two\nlines.yaml")
    assert status == 2
    assert stderr == "dhsym: error: two\\nlines.yaml:2:9: joints is empty; a robot needs at least one joint\n"


# --- Nothing lost: output files are written atomically and never over an input.

def test_refuses_to_overwrite_the_input_by_any_name(tmp_path):
    robot = tmp_path / "arm.yaml"
    robot.write_text("convention: standard\n")
    (tmp_path / "link.yaml").symlink_to(robot)
    os.link(robot, tmp_path / "hard.yaml")
    for target in ("arm.yaml", "link.yaml", "hard.yaml", "./sub/../arm.yaml"):
        (tmp_path / "sub").mkdir(exist_ok=True)
        with pytest.raises(UserError, match="refusing to overwrite the input file"):
            write_atomic(tmp_path / target, "oops", inputs=[str(robot)])
    assert robot.read_text() == "convention: standard\n"


def test_a_failed_write_keeps_the_old_file_and_leaves_no_temporary(tmp_path):
    target = tmp_path / "T.tex"
    target.write_text("old")
    with pytest.raises(UnicodeEncodeError):
        write_atomic(target, "new \ud800 text")  # a lone surrogate cannot be encoded: fails mid-write
    assert target.read_text() == "old"
    assert os.listdir(tmp_path) == ["T.tex"]


def test_a_new_file_gets_ordinary_permissions(tmp_path):
    mask = os.umask(0o022)
    try:
        write_atomic(tmp_path / "new.txt", "x")
    finally:
        os.umask(mask)
    assert stat.S_IMODE((tmp_path / "new.txt").stat().st_mode) == 0o644


def test_a_missing_folder_is_a_user_error(tmp_path):
    with pytest.raises(UserError, match="does not exist"):
        write_atomic(tmp_path / "nowhere" / "T.tex", "x")


needs_fifo = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes need a POSIX system")


@pytest.mark.slow
@needs_fifo
def test_a_named_pipe_nobody_writes_is_refused_at_once_not_waited_for(tmp_path):
    os.mkfifo(tmp_path / "robot.yaml")
    result = run_dhsym_process("fk", "robot.yaml", cwd=tmp_path)
    assert result.status == 2 and result.stdout == ""
    assert result.stderr.startswith("dhsym: error: robot.yaml: is a named pipe that no program writes to")
    assert result.stderr.count("\n") == 1 and "- to read standard input" in result.stderr


@pytest.mark.slow
@needs_fifo
def test_a_named_pipe_nobody_reads_is_refused_as_output_and_no_file_appears(tmp_path):
    os.mkfifo(tmp_path / "T.tex")
    result = run_dhsym_process("latex", "planar2r", "-o", "T.tex", cwd=tmp_path)
    assert result.status == 2 and result.stdout == ""
    assert result.stderr == ("dhsym: error: T.tex: is a named pipe that no program reads, and dhsym does not wait "
                             "for one; start the reader first, or write to a file\n")
    assert stat.S_ISFIFO((tmp_path / "T.tex").stat().st_mode) and os.listdir(tmp_path) == ["T.tex"]


@needs_fifo
def test_a_named_pipe_with_a_reader_gets_the_output(tmp_path):
    os.mkfifo(tmp_path / "T.tex")
    reader = subprocess.Popen(["cat", "T.tex"], cwd=tmp_path, stdout=subprocess.PIPE, text=True)
    handle = os.open(tmp_path / "T.tex", os.O_WRONLY)  # waits until cat has opened its end
    try:
        write_atomic(tmp_path / "T.tex", "written through the pipe")
    finally:
        os.close(handle)
    assert reader.communicate(timeout=120)[0] == "written through the pipe"


@pytest.mark.slow
def test_a_socket_is_neither_a_robot_file_nor_an_output(tmp_path, monkeypatch):
    socket = pytest.importorskip("socket")
    if not hasattr(socket, "AF_UNIX"):
        pytest.skip("no Unix sockets here")
    monkeypatch.chdir(tmp_path)  # a short relative name: socket paths are limited to about 100 bytes
    server = socket.socket(socket.AF_UNIX)
    server.bind("robot.sock")
    try:
        result = run_dhsym_process("fk", "robot.sock", cwd=tmp_path)
        assert result.status == 2 and result.stderr == "dhsym: error: robot.sock: is a socket, not a robot file\n"
        with pytest.raises(UserError, match="^robot.sock: is a socket, not a file to write to$"):
            write_atomic("robot.sock", "x")
    finally:
        server.close()


@pytest.mark.slow
def test_devices_and_standard_input_still_work(tmp_path):
    robot = (Path(__file__).parents[1] / "dhsym" / "robots" / "planar2r.yaml").read_text(encoding="utf-8")
    assert run_dhsym_process("latex", "planar2r", "-o", os.devnull, cwd=tmp_path).status == 0
    full = (run_dhsym_process("latex", "planar2r", "-o", "/dev/full", cwd=tmp_path) if Path("/dev/full").exists()
            else None)
    assert full is None or full.stderr == "dhsym: error: /dev/full: cannot write file: No space left on device\n"
    piped = run_dhsym_process("fk", "-", cwd=tmp_path, stdin=robot)
    assert piped.status == 0 and "a_{1}" not in piped.stdout and "c12" in piped.stdout
