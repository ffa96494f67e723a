"""Errors a user can cause, carrying where in their input they happened.

>>> err = UserError("unknown key 'alpah'", Location("arm.yaml", 4, 12))
>>> str(err)
"arm.yaml:4:12: unknown key 'alpah'"
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Location:
    """A place in a user's input; line and column count from 1.

    >>> print(Location("arm.yaml", 4, 12))
    arm.yaml:4:12
    """

    file: str
    line: int | None = None
    column: int | None = None

    def shifted(self, columns: int) -> "Location":
        """The same place moved right by `columns` on its line."""
        if self.column is None:
            return self
        return Location(self.file, self.line, self.column + columns)

    def __str__(self) -> str:
        parts = [self.file]
        if self.line is not None:
            parts.append(str(self.line))
            if self.column is not None:
                parts.append(str(self.column))
        return ":".join(parts)


class UserError(Exception):
    """A mistake in the user's input or command line: reported in one line, exit status 2.

    >>> import dhsym
    >>> try:
    ...     dhsym.load("puma650")
    ... except dhsym.UserError as error:
    ...     print(str(error)[:42])
    unknown robot 'puma650'; built-in robots a
    """

    def __init__(self, message: str, where: Location | None = None):
        super().__init__(message)
        self.message = message
        self.where = where

    def __str__(self) -> str:
        return f"{self.where}: {self.message}" if self.where else self.message


class NoClosedForm(UserError):
    """A closed-form inverse kinematics refused because the arm has none by the course's rules (the
    command line then names the numeric command that answers instead)."""
