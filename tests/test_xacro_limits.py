"""Hostile .xacro files too big for the corpus (tests/bad_inputs/ has the small ones): each is
refused from a count made as the expansion goes, in one line, long before it could take
gigabytes or hours. The expected lines are exact, so a bound that came too late (after the
text was built) would show as a different message or as the test never ending."""
import pytest
from cli_runner import run_dhsym

pytest.importorskip("xacro", reason="the xacro package expands .xacro files (requirements-dev.txt)")

HEAD = '<?xml version="1.0"?>\n<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
TAIL = ('  <link name="base"/><link name="upper"/>\n  <joint name="shoulder" type="revolute"><parent link="base"/>'
        '<child link="upper"/><axis xyz="0 0 1"/></joint>\n</robot>\n')


def doubling(body: str, levels: int, prelude: str = "") -> str:
    """Macros m1 … m<levels>, each calling the one below twice, around a first macro holding `body`."""
    macros = [prelude, f'  <xacro:macro name="m0">{body}</xacro:macro>\n']
    macros += [f'  <xacro:macro name="m{i}"><xacro:m{i - 1}/><xacro:m{i - 1}/></xacro:macro>\n'
               for i in range(1, levels + 1)]
    return HEAD + "".join(macros) + f"  <xacro:m{levels}/>\n" + TAIL


MEGABYTE = "a" * (1 << 20)


@pytest.mark.slow  # reading and checking a megabyte takes a second or two; the corpus has a small one
@pytest.mark.parametrize("body", [f'<link name="l" note="{MEGABYTE}"/>', f'<link name="l">{MEGABYTE}</link>'],
                         ids=["attribute", "text"])
def test_a_megabyte_doubled_twelve_times_is_refused_by_counting_bytes(body, tmp_path):
    path = tmp_path / "bomb.xacro"
    path.write_text(doubling(body, 12))  # 4 GiB if it were built
    status, stdout, stderr = run_dhsym("import", str(path))
    assert (status, stdout) == (2, "")
    assert stderr == (f"dhsym: error: {path}: the expansion works through more than 16 MiB of text (a macro that "
                      "copies a long text at each level?)\n")


def test_a_text_of_many_dollar_signs_is_refused_before_xacro_reads_it(tmp_path):
    path = tmp_path / "dollars.xacro"
    path.write_text(HEAD + f'  <link name="l">{"$a" * 200_000}</link>\n' + TAIL)  # xacro's lexer: quadratic
    status, _, stderr = run_dhsym("import", str(path))
    assert status == 2
    assert stderr == (f"dhsym: error: {path}: a text of 400,000 characters with 200,000 substitutions is more than a "
                      "robot file needs\n")


@pytest.mark.slow  # xacro's own work up to the bound, a second or two; the corpus has a small one
def test_millions_of_evaluations_are_refused_by_counting_them(tmp_path):
    path = tmp_path / "evaluations.xacro"
    prelude = '  <xacro:property name="p" value="1"/>\n'
    path.write_text(doubling(f'<link name="{"${p}" * 1_250}"/>', 16, prelude))  # 82 million ${p}
    status, _, stderr = run_dhsym("import", str(path))
    assert status == 2
    assert stderr == (f"dhsym: error: {path}: the expansion works out more than 20,000 ${{…}} and $(…) substitutions "
                      "(a macro that repeats one many times?)\n")
