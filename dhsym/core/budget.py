"""Time budgets: one per simplification, so a huge chain prints its raw product instead of
hanging, and one for a whole command, so that nothing (printing included) runs for hours.

>>> with time_budget(5):
...     pass
>>> with time_budget(0.05, CommandTooSlow):
...     while True:
...         pass
Traceback (most recent call last):
dhsym.core.budget.CommandTooSlow

Budgets nest. `within` runs a computation and falls back only when its own time is up; an
outer budget that runs out inside passes through to whoever set it:

>>> within(5, lambda: "done", lambda: "fallback")
'done'
"""
from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager
from typing import Callable, TypeVar

Result = TypeVar("Result")


class BudgetExceeded(BaseException):
    """Raised inside the budgeted block when time is up (a BaseException so that no
    `except Exception` inside SymPy can swallow it)."""


class CommandTooSlow(BaseException):
    """Raised when a whole command is over its budget; a separate class, so that the
    simplification fallback (which catches BudgetExceeded) cannot swallow it."""


class SimplificationTimeout(UserWarning):
    """Warned when a result is returned unsimplified because its budget ran out."""


@contextmanager
def time_budget(seconds: float | None, exception: type = BudgetExceeded, owner: object = None):
    """Raise `exception` in the block after `seconds`; no limit for None or off the main thread.

    Uses SIGALRM, so it interrupts Python code (SymPy's included) but not one long call into C.
    A timer that was already running (an outer budget, a test's watchdog) is put back
    afterwards with the time it has left; if it would fire first, it stays in charge.
    """
    if seconds is not None and seconds < 0:
        raise ValueError("a time budget must be positive (or None for no limit)")
    if not seconds or threading.current_thread() is not threading.main_thread():
        yield
        return
    outer_delay, outer_interval = signal.getitimer(signal.ITIMER_REAL)
    if outer_delay and outer_delay <= seconds:
        yield  # the outer timer fires first and keeps its own handler
        return

    def expire(signum, frame):
        error = exception()
        error.owner = owner  # which budget ran out, for `within`
        raise error

    started = time.monotonic()
    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if outer_delay:
            left = max(outer_delay - (time.monotonic() - started), 1e-3)
            signal.setitimer(signal.ITIMER_REAL, left, outer_interval)


def within(seconds: float | None, compute: Callable[[], Result], fallback: Callable[[], Result]) -> Result:
    """compute(), or fallback() when it takes longer than `seconds` (None: no limit). Only this
    budget's expiry falls back: a budget set outside that runs out meanwhile is raised on."""
    mine = object()
    try:
        with time_budget(seconds, owner=mine):
            return compute()
    except BudgetExceeded as error:
        if getattr(error, "owner", None) is not mine:
            raise
    return fallback()
