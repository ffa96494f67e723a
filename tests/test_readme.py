"""The README's console examples are real: each `$ dhsym ...` block is today's output."""
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

README = (Path(__file__).parent.parent / "README.md").read_text(encoding="utf-8")
EXAMPLES = re.findall(r"```console\n\$ dhsym ([^\n]*)\n(.*?)```", README, re.DOTALL)


def test_there_are_examples():
    assert len(EXAMPLES) >= 3


@pytest.mark.parametrize("command, shown", EXAMPLES, ids=[c for c, _ in EXAMPLES])
def test_example_output_is_current(command, shown):
    result = subprocess.run([sys.executable, "-m", "dhsym.cli", *shlex.split(command)], capture_output=True,
                            text=True, timeout=60, env={**os.environ, "COLUMNS": "100"})  # not the tester's terminal
    assert result.returncode == 0
    assert result.stdout == shown
