"""Bounded work, decided by measuring the work, never the clock.

Whether a transform is built, a determinant factored or a proof by algebra tried is decided
from estimates made before the work (sizes, counts of terms), so the answer is the same on any
machine under any load. A time limit (--timeout) stays only as a safety net; these tests check
what happens when it fires and that everything works where the platform has no timer (Windows).
No test here measures time.
"""
import importlib
import signal
import time

import pytest
from cli_runner import run_dhsym

import dhsym
from dhsym import Chain, DHRow, real_symbol
from dhsym.cli import options
from dhsym.core import chain as chain_module
from dhsym.core.budget import BudgetExceeded, CommandTooSlow, time_budget
from dhsym.errors import UserError

determinant_module = importlib.import_module("dhsym.velocity.determinant")  # not the function of that name


def never_finishes(*args):
    """A computation stuck in a search that keeps growing."""
    work = []
    while True:
        work.append(len(work))


def general_rows(n):
    rows = []
    for i in range(1, n + 1):
        t, d, a, alpha = (real_symbol(f"{name}_{i}") for name in ("theta", "d", "a", "alpha"))
        rows.append(DHRow.revolute(t, d=d, a=a, alpha=alpha))
    return rows


def test_a_transform_too_large_to_build_is_refused_from_its_estimate():
    chain = Chain(general_rows(24), "standard")
    with pytest.raises(UserError, match=r"^0T24 would have about [\d,]+ expression nodes, more than the "
                                        r"2,000,000 that dhsym works out; ask for a shorter part of the chain$"):
        chain.fk()
    assert chain.transform(0, 3).shape == (4, 4)  # a part of it is worked out as usual


def test_the_work_limit_is_a_size_not_a_time(monkeypatch):
    chain = Chain(general_rows(3), "standard")
    monkeypatch.setattr(chain_module, "MAX_WORK_NODES", 100)
    with pytest.raises(UserError, match=r"would have about 900 expression nodes, more than the 100"):
        chain.fk()


@pytest.mark.slow
def test_whether_a_determinant_is_factored_is_decided_by_counting_terms(monkeypatch):
    """The UR5's determinant in frame 4, where J is shortest, has at most 336 terms written out
    (Leibniz's formula), in either convention."""
    assert dhsym.load("ur5").determinant().value is not None
    monkeypatch.setattr(determinant_module, "FACTOR_MAX_TERMS", 335)
    result = dhsym.load("ur5").determinant()
    assert result.value is None and result.factors == []
    assert result.note == ("the axes of joints 4–6 do not meet in a point, and the full 6×6 determinant would "
                           "expand to about 336 terms even in frame 4, where J is shortest; that is more than the "
                           "335 that dhsym factors: not computed.")


def test_the_safety_net_stops_a_command_with_one_line_that_says_what_it_is(monkeypatch):
    monkeypatch.setattr(options, "SAFETY_NET_SECONDS", 0.2)  # the default limit, as if 600 s had passed
    status, stdout, stderr = run_dhsym("fk", "planar2r", read=never_finishes)
    assert (status, stdout) == (2, "")
    assert stderr == ("dhsym: error: planar2r: stopped by the safety net after 0.2 s (--timeout); no normal input "
                      "takes this long, and the size estimates did not foresee it; please report the robot file on "
                      "the dhsym issue tracker\n")


def test_a_limit_the_user_set_too_short_is_said_to_be_too_short():
    status, stdout, stderr = run_dhsym("fk", "puma560", "--timeout", "1e-7", read=never_finishes)
    assert (status, stdout) == (2, "")
    assert stderr == ("dhsym: error: puma560: stopped after 1e-07 s, the limit set with --timeout, before the work "
                      "was done; that limit is too short for this command: give a longer one, or leave --timeout out "
                      "(the default, 600 s, is a safety net far above any normal case)\n")


def test_without_an_interval_timer_commands_still_work(monkeypatch):
    """Windows has no signal.setitimer: the estimates alone bound the work, and nothing exits 70."""
    expected = run_dhsym("jacobian", "planar2r")
    monkeypatch.delattr(signal, "setitimer")
    assert run_dhsym("jacobian", "planar2r") == expected
    status, stdout, stderr = run_dhsym("fk", "general.yaml", read=lambda name: _general_robot(24))
    assert status == 2 and "too large to print or read" in stderr
    with time_budget(0.01, CommandTooSlow):  # no timer: no limit, no error
        time.sleep(0.05)


def _general_robot(n):
    from readers import load_robot_text

    rows = "".join(f"  - {{joint: R, alpha: alpha_{i}, a: a_{i}, d: d_{i}, theta: theta_{i}}}\n"
                   for i in range(1, n + 1))
    return load_robot_text(f"convention: standard\njoints:\n{rows}", "general.yaml")


class OuterDeadline(BaseException):
    pass


def test_an_inner_budget_gives_the_outer_timer_back():
    with pytest.raises(OuterDeadline):
        with time_budget(1.5, OuterDeadline):
            with time_budget(60):
                pass
            give_up = time.monotonic() + 10
            while time.monotonic() < give_up:
                time.sleep(0.01)
            pytest.fail("the outer deadline was lost")


def test_an_outer_timer_that_fires_first_stays_in_charge():
    with pytest.raises(OuterDeadline):
        with time_budget(0.2, OuterDeadline):
            with time_budget(30):
                never_finishes()


def test_no_budget_arms_no_timer_and_a_negative_one_is_refused():
    with time_budget(None):
        assert signal.getitimer(signal.ITIMER_REAL) == (0.0, 0.0)
    with pytest.raises(ValueError):
        with time_budget(-1):
            pass
    with pytest.raises(BudgetExceeded):
        with time_budget(0.05):
            never_finishes()
