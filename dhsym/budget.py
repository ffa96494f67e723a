"""A time budget for simplification, so a huge chain prints its raw product instead of hanging.

>>> with time_budget(5):
...     pass
"""
from __future__ import annotations

import signal
import threading
from contextlib import contextmanager


class BudgetExceeded(BaseException):
    """Raised inside the budgeted block when time is up (a BaseException so that no
    `except Exception` inside SymPy can swallow it)."""


class SimplificationTimeout(UserWarning):
    """Warned when a result is returned unsimplified because its budget ran out."""


@contextmanager
def time_budget(seconds: float | None):
    """Raise BudgetExceeded in the block after `seconds`; no limit for None or off the main thread."""
    if not seconds or threading.current_thread() is not threading.main_thread():
        yield
        return

    def expire(signum, frame):
        raise BudgetExceeded()

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
