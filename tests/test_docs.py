"""Every example in README.md and docs/*.md is run, so that none can go stale.

What a page shows, and how it is checked (blocks run in page order, in a scratch folder per page
that sees the repository's `docs/` and `tests/`, with COLUMNS=100):

- ```console: `$ dhsym ARGS` followed by its output (standard error, then standard output, as a
  terminal shows them: dhsym warns before it prints, and an error leaves no output). The command
  runs as `python -m dhsym.cli ARGS` does (`dhsym.cli.main` inside this process, which is what
  `python -m dhsym.cli` calls; one README example also runs as a real process), and the output must
  be exactly what is shown. The exit status must be 0 unless the next line is `$ echo $?` followed
  by the status. `< FILE` and `> FILE` redirect as a shell does. A built-in robot's file is shown as
  `.../dhsym/robots/NAME.yaml`: where dhsym is installed differs from machine to machine.
- ```sh: a list of commands without output. Lines `dhsym ...` run and must exit with status 0;
  `make TARGET` must name a Makefile target and `pip install '.[EXTRA]'` an extra of pyproject.toml.
- ```python: run in order in one namespace per page. `>>>` lines (with `...` continuations) are
  compared with the output below them as doctest does (`<BLANKLINE>` for an empty line; an
  exception as `Traceback (most recent call last):` and its last line); a block without prompts
  must not raise.
- ```yaml: a robot file; it must load (```yaml refused: it must be refused with a UserError).
  ```yaml file=NAME also writes it as NAME for the commands after it; ```yaml shows=PATH is a copy of
  the repository's file PATH and must stay one.
- ```text: shown, not run (measurements, pictures of the layout).

Relative links must point at files that exist, and the README stays a five-minute read.

When outputs change on purpose, regenerate the pages and review the diff:

    DHSYM_UPDATE_DOCS=1 python -m pytest tests/test_docs.py && git diff README.md docs/
"""
from __future__ import annotations

import contextlib
import io
import os
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from cli_runner import run_dhsym

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = Path(__import__("dhsym").__file__).resolve().parent
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
UPDATE = os.environ.get("DHSYM_UPDATE_DOCS") == "1"
COLUMNS = "100"  # the shown outputs are 100 columns wide, whatever the tester's terminal
SHELL_WORDS = ("make", "pip", "git", "cd", "python", "python3", "pdflatex", "jupyter", "source", ".")
FENCE = re.compile(r"^( *)```(\S*)(.*)$")


@dataclass
class Block:
    """A fenced code block: its info string and its lines, with where they sit in the page."""
    kind: str
    options: str
    indent: str
    start: int  # index of the first line inside the fence
    lines: list[str] = field(default_factory=list)
    replacement: list[str] | None = None  # the block's new lines in update mode

    @property
    def text(self) -> str:
        return "".join(line + "\n" for line in self.lines)

    def option(self, name: str) -> str | None:
        found = re.search(rf"\b{name}=(\S+)", self.options)
        return found.group(1) if found else None


def blocks(page: Path) -> list[Block]:
    """The fenced blocks of a markdown page, dedented by their fence's indentation."""
    found, current = [], None
    for number, line in enumerate(page.read_text(encoding="utf-8").split("\n")):
        fence = FENCE.match(line)
        if current is None and fence:
            current = Block(fence.group(2), fence.group(3).strip(), fence.group(1), number + 1)
        elif current is not None and fence and not fence.group(2) and not fence.group(3).strip():
            found.append(current)
            current = None
        elif current is not None:
            current.lines.append(line[len(current.indent):] if line.startswith(current.indent) else line.lstrip())
    assert current is None, f"{page.name}: a code block is not closed"
    return found


def run_console(block: Block, where: str) -> list[str]:
    """Run a console session; returns its lines with today's outputs (for update mode)."""
    sessions, current = [], None
    for line in block.lines:
        if line.startswith("$ "):
            current = [line[2:], []]
            sessions.append(current)
        else:
            assert current is not None, f"{where}: a console block starts with `$ command`"
            current[1].append(line)
    rewritten, status, previous = [], None, ""
    for command, shown in sessions:
        words = shlex.split(command)
        if words == ["echo", "$?"]:
            assert status is not None, f"{where}: `echo $?` follows no dhsym command"
            output, status = f"{status}\n", None
        else:
            assert words[0] == "dhsym", f"{where}: only `dhsym ...` and `echo $?` run in a console block: {command}"
            if status not in (None, 0):
                raise AssertionError(f"{where}: `{previous}` exited with status {status}; show it with `$ echo $?`")
            output, status = run_command(words[1:])
            previous = command
        expected = "".join(line + "\n" for line in shown)
        if not UPDATE:
            assert output == expected, f"{where}: `{command}` prints something else today " \
                                       f"(DHSYM_UPDATE_DOCS=1 rewrites the page)"
        rewritten += ["$ " + command, *output.splitlines()]
    if status not in (None, 0):
        raise AssertionError(f"{where}: `{previous}` exited with status {status}; show it with `$ echo $?`")
    return rewritten


def run_command(words: list[str]) -> tuple[str, int]:
    """One dhsym command line with optional `< FILE` and `> FILE` at its end: what a terminal shows
    (warnings and errors come before any output: dhsym reads and checks before it prints), and the status."""
    stdin, target = "", None
    while len(words) >= 2 and words[-2] in ("<", ">"):
        if words[-2] == "<":
            stdin = Path(words[-1]).read_text(encoding="utf-8")
        else:
            target = Path(words[-1])
        words = words[:-2]
    result = run_dhsym(*words, stdin=stdin)
    stderr = result.stderr.replace(str(PACKAGE) + os.sep, ".../dhsym/")
    if target is not None:
        target.write_text(result.stdout, encoding="utf-8")
        return stderr, result.status
    return stderr + result.stdout, result.status


def run_sh(block: Block, where: str, makefile: str, pyproject: str) -> None:
    for line in block.lines:
        command = line.split("#")[0].strip()
        if not command:
            continue
        words = shlex.split(command)
        while "=" in words[0] and words[0].split("=")[0].isidentifier():  # VAR=value before a command
            words = words[1:]
        if words[0] == "dhsym":
            output, status = run_command(words[1:])
            assert status == 0, f"{where}: `{command}` exited with status {status}:\n{output}"
        elif words[0] == "make":
            for target in words[1:]:
                assert re.search(rf"^{re.escape(target)}:", makefile, re.M), f"{where}: no make target {target}"
        elif words[:2] == ["pip", "install"]:
            for extra in re.findall(r"\[([\w,-]+)\]", command):
                for name in extra.split(","):
                    assert re.search(rf"^{name} = \[", pyproject, re.M), f"{where}: pyproject.toml has no extra {name}"
        else:
            assert words[0] in SHELL_WORDS, f"{where}: a sh block runs dhsym, make, pip and shell basics: {command}"


def run_python(block: Block, where: str, namespace: dict) -> list[str]:
    """Run a python block in the page's namespace; returns its lines with today's outputs."""
    if not any(line.startswith(">>>") for line in block.lines):
        exec(compile(block.text, where, "exec"), namespace)
        return block.lines
    examples, current = [], None
    for line in block.lines:
        if line.startswith(">>>"):
            current = [[line[4:]], [], line]
            examples.append(current)
        elif line.startswith("...") and current is not None and not current[1]:
            current[0].append(line[4:])
            current[2] += "\n" + line
        elif current is not None and line.strip():
            current[1].append(line)
        else:
            current = None
    rewritten = []
    for source, shown, prompt in examples:
        got = io.StringIO()
        with contextlib.redirect_stdout(got):
            try:
                exec(compile("\n".join(source) + "\n", where, "single"), namespace)
            except Exception as error:  # shown as doctest shows it: the header and the last line
                kind = type(error)
                name = kind.__qualname__ if kind.__module__ == "builtins" else f"{kind.__module__}.{kind.__qualname__}"
                print(f"Traceback (most recent call last):\n{name}: {error}")
        printed = got.getvalue().rstrip("\n")
        output = [line.rstrip() or "<BLANKLINE>" for line in printed.split("\n")] if printed else []
        if not UPDATE:
            assert output == [line.rstrip() for line in shown], \
                f"{where}: `{source[0]}` gives\n" + "\n".join(output) + "\n(DHSYM_UPDATE_DOCS=1 rewrites the page)"
        rewritten += [*prompt.split("\n"), *output]
    return rewritten


def load_yaml(block: Block, where: str) -> None:
    import dhsym

    shown_file = block.option("shows")
    if shown_file:  # a copy of a file in the repository, which must stay the same
        text = (ROOT / shown_file).read_text(encoding="utf-8")
        if UPDATE:
            block.replacement = text.splitlines()
        assert UPDATE or block.text == text, f"{where}: the block is not what {shown_file} holds"
        dhsym.load(str(ROOT / shown_file))
        return
    name = Path(block.option("file") or "robot.yaml")
    name.write_text(block.text, encoding="utf-8")
    try:
        dhsym.load(str(name))
    except dhsym.UserError as error:
        assert "refused" in block.options.split(), f"{where}: the robot file does not load: {error}"
    else:
        assert "refused" not in block.options.split(), f"{where}: the file marked `refused` loads"
    if not block.option("file"):
        name.unlink()


def write_back(page: Path, found: list[Block]) -> None:
    lines = page.read_text(encoding="utf-8").split("\n")
    for block in reversed(found):
        if block.replacement is not None and block.replacement != block.lines:
            end = block.start + len(block.lines)
            lines[block.start:end] = [block.indent + line if line else line for line in block.replacement]
    page.write_text("\n".join(lines), encoding="utf-8")


@pytest.fixture
def sandbox(tmp_path, monkeypatch):
    """A scratch folder that sees the repository's examples, as the pages' commands expect."""
    for name in ("docs", "tests"):
        (tmp_path / name).symlink_to(ROOT / name)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("COLUMNS", COLUMNS)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    return tmp_path


@pytest.mark.parametrize("page", PAGES, ids=[p.name for p in PAGES])
def test_every_example_on_the_page_is_current(page, sandbox):
    makefile = (ROOT / "Makefile").read_text(encoding="utf-8")
    pyproject = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    namespace: dict = {"__name__": "__docs__"}
    found = blocks(page)
    for block in found:
        where = f"{page.relative_to(ROOT)}:{block.start}"
        if block.kind == "console":
            block.replacement = run_console(block, where)
        elif block.kind == "sh":
            run_sh(block, where, makefile, pyproject)
        elif block.kind == "python":
            block.replacement = run_python(block, where, namespace)
        elif block.kind == "yaml":
            load_yaml(block, where)
        else:
            assert block.kind == "text", f"{where}: say what the block is: console, sh, python, yaml or text"
    if UPDATE:
        write_back(page, found)


def anchors(page: Path) -> set[str]:
    """The anchors GitHub gives a page's headings: lower case, punctuation dropped, spaces as hyphens."""
    headings = re.findall(r"^#+ (.+)$", re.sub(r"^```.*?^```", "", page.read_text(encoding="utf-8"), flags=re.M | re.S),
                          re.M)
    return {re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-") for heading in headings}


@pytest.mark.parametrize("page", PAGES, ids=[p.name for p in PAGES])
def test_relative_links_point_at_files_and_headings(page):
    text = page.read_text(encoding="utf-8")
    for target, anchor in re.findall(r"\]\(([^)#\s]*)(?:#([^)\s]*))?\)", text):
        if re.match(r"[a-z]+:", target):
            continue
        linked = (page.parent / target) if target else page
        assert linked.exists(), f"{page.name}: the link {target} points at nothing"
        if anchor:
            assert anchor in anchors(linked), f"{page.name}: {target} has no heading #{anchor}"


def test_the_readme_is_a_five_minute_read():
    """Short, with the examples a newcomer runs first, and a way on to every page in docs/."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(readme.splitlines()) <= 260
    assert len(re.findall(r"^\$ dhsym ", readme, re.M)) >= 5
    for page in PAGES[1:]:
        assert f"docs/{page.name}" in readme, f"the README does not lead to docs/{page.name}"


def test_the_readme_example_runs_as_a_process_too():
    """The examples run inside this process; the first one also runs the way a user runs it."""
    readme = next(b for b in blocks(ROOT / "README.md") if b.kind == "console")
    command, *shown = readme.lines
    result = subprocess.run([sys.executable, "-m", "dhsym.cli", *shlex.split(command[2:])[1:]], capture_output=True,
                            text=True, timeout=120, cwd=ROOT, env={**os.environ, "COLUMNS": COLUMNS})
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == "".join(line + "\n" for line in shown)
