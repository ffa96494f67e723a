"""Bounded work: past its budget a simplification gives back the raw product with one warning.

The slow case is a simplifier strategy that never finishes, injected through
Chain(simplifier=...). Only the first test measures time (the one budget check the issue asks
for); the others check what happens, not how fast.
"""
import signal
import time
import warnings

import pytest

from dhsym import Chain, DHRow, real_symbol
from dhsym.cli import app as cli
from dhsym.core.budget import SimplificationTimeout, time_budget, within
from dhsym.io.library import read

BUDGET = 0.5  # seconds
MARGIN = 3.0  # seconds allowed on top of the budget: returning the raw product on a busy CI machine


def never_finishes(steps, joint_variables):
    """A strategy stuck in a search that keeps growing."""
    work = []
    while True:
        work.append(len(work))


def two_link_rows():
    t1, t2, l1, l2 = (real_symbol(name) for name in ("theta_1", "theta_2", "l_1", "l_2"))
    return [DHRow.revolute(t1, a=l1), DHRow.revolute(t2, a=l2)]


def test_over_budget_gives_the_raw_product_with_a_warning_in_time():
    slow = Chain(two_link_rows(), "standard", simplifier=never_finishes, timeout=BUDGET)
    with pytest.warns(SimplificationTimeout, match=r"^simplification took longer than 0.5 s; showing the "
                                                   r"unsimplified product$"):
        started = time.monotonic()
        result = slow.fk()
        elapsed = time.monotonic() - started
    assert elapsed < BUDGET + MARGIN
    assert result == Chain(two_link_rows(), "standard").fk(raw=True)


def test_the_cli_prints_the_raw_result_and_one_warning_line(capsys):
    expected = _cli(["fk", "planar2r", "--raw"], capsys)
    robot = read("planar2r")
    chain = robot.chain
    robot.chain = Chain(chain.rows, chain.convention, chain.base, chain.tool, simplifier=never_finishes,
                        name=chain.name)
    status, stdout, stderr = _cli(["fk", "planar2r", "--timeout", "0.2"], capsys, read=lambda name: robot)
    assert status == 0 and stdout == expected[1]
    assert stderr == "dhsym: warning: simplification took longer than 0.2 s; showing the unsimplified product\n"


def test_a_command_that_cannot_finish_stops_with_one_error_line(capsys, monkeypatch):
    def reading_forever(name):
        never_finishes(None, None)
    monkeypatch.setattr(cli, "COMMAND_BUDGET_FLOOR", 0)  # the factor alone, so the test is quick
    status, stdout, stderr = _cli(["fk", "planar2r", "--timeout", "0.1"], capsys, read=reading_forever)
    assert (status, stdout) == (2, "")
    assert stderr.startswith("dhsym: error: planar2r: gave up after 0.5 s; the result is too large")
    assert stderr.count("\n") == 1


def test_a_tiny_timeout_still_prints_the_raw_product(capsys):
    expected = _cli(["fk", "puma560", "--raw"], capsys)[1]
    status, stdout, stderr = _cli(["fk", "puma560", "--timeout", "0.0001"], capsys)
    assert (status, stdout) == (0, expected)
    assert stderr == "dhsym: warning: simplification took longer than 0.0001 s; showing the unsimplified product\n"


class OuterDeadline(BaseException):
    pass


def test_an_outer_deadline_is_not_swallowed_by_the_simplification_fallback():
    patient = Chain(two_link_rows(), "standard", simplifier=never_finishes, timeout=30)
    with pytest.raises(OuterDeadline):
        with time_budget(0.2, OuterDeadline):
            patient.fk()


def test_a_simplification_budget_gives_the_outer_timer_back():
    quick = Chain(two_link_rows(), "standard", simplifier=never_finishes, timeout=0.2)
    with pytest.raises(OuterDeadline):
        with time_budget(1.5, OuterDeadline):
            with pytest.warns(SimplificationTimeout):
                quick.fk()
            give_up = time.monotonic() + 10
            while time.monotonic() < give_up:
                time.sleep(0.01)
            pytest.fail("the outer deadline was lost")


def test_no_budget_arms_no_timer_and_a_negative_one_is_refused():
    with time_budget(None):
        assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
    with pytest.raises(ValueError):
        with time_budget(-1):
            pass


def _cli(argv, capsys, **injected):
    status = cli.main(argv, **injected)
    stdout, stderr = capsys.readouterr()
    return status, stdout, stderr


def test_an_outer_budget_of_the_same_kind_is_not_taken_for_the_simplifications_own():
    """A determinant's budget runs out while a transform simplifies: the transform must not fall
    back to its raw product (that was the fallback of a budget that had not run out)."""
    patient = Chain(two_link_rows(), "standard", simplifier=never_finishes, timeout=30)
    with warnings.catch_warnings():
        warnings.simplefilter("error", SimplificationTimeout)
        assert within(0.2, patient.fk, lambda: "outer fallback") == "outer fallback"


def test_within_gives_the_result_or_the_fallback():
    assert within(None, lambda: 1, lambda: 2) == 1
    assert within(0.05, lambda: never_finishes(None, None), lambda: 2) == 2
