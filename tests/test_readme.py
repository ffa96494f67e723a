"""The README's console examples are real: each `$ dhsym ...` block is today's output."""
import re
import shlex
from pathlib import Path

import pytest
from cli_runner import run_dhsym

README = (Path(__file__).parent.parent / "README.md").read_text(encoding="utf-8")
EXAMPLES = re.findall(r"```console\n\$ dhsym ([^\n]*)\n(.*?)```", README, re.DOTALL)


def test_there_are_examples():
    assert len(EXAMPLES) >= 3


@pytest.mark.parametrize("command, shown", EXAMPLES, ids=[c for c, _ in EXAMPLES])
def test_example_output_is_current(command, shown):
    assert run_dhsym(*shlex.split(command)).ok() == shown  # at 100 columns, not the tester's terminal
