"""Bounded work. Whether a result is worked out is decided before the work, from sizes and
counts (dhsym.core.estimate), so the answer is the same on any machine under any load. A time
limit remains only as a safety net, far above any normal case, for a bug or an input that no
estimate foresaw:

>>> with time_budget(5):
...     pass
>>> with time_budget(0.05, CommandTooSlow):
...     while True:
...         pass
Traceback (most recent call last):
dhsym.core.budget.CommandTooSlow

Without `signal.setitimer` (Windows) or off the main thread there is no safety net; the
estimates alone bound the work.
"""
from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager


class BudgetExceeded(BaseException):
    """Raised inside the budgeted block when time is up (a BaseException so that no
    `except Exception` inside SymPy can swallow it)."""


class CommandTooSlow(BaseException):
    """Raised when a whole command passes its safety net."""


def has_timer() -> bool:
    """Whether this platform can interrupt a computation after a time (not Windows)."""
    return hasattr(signal, "setitimer") and hasattr(signal, "SIGALRM")


@contextmanager
def time_budget(seconds: float | None, exception: type = BudgetExceeded):
    """Raise `exception` in the block after `seconds`; no limit for None, off the main thread,
    or where the platform has no interval timer.

    Uses SIGALRM, so it interrupts Python code (SymPy's included) but not one long call into C.
    A timer that was already running (an outer budget, a test's watchdog) is put back
    afterwards with the time it has left; if it would fire first, it stays in charge.
    """
    if seconds is not None and seconds < 0:
        raise ValueError("a time budget must be positive (or None for no limit)")
    if not seconds or not has_timer() or threading.current_thread() is not threading.main_thread():
        yield
        return
    outer_delay, outer_interval = signal.getitimer(signal.ITIMER_REAL)
    if outer_delay and outer_delay <= seconds:
        yield  # the outer timer fires first and keeps its own handler
        return

    def expire(signum, frame):
        raise exception()

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
