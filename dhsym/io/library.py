"""The built-in robots shipped in dhsym/robots/, and lookup of a robot by name or path.

>>> "puma560" in builtin_names()
True
>>> load("puma560").chain.n
6
"""
from __future__ import annotations

import difflib
import os
from pathlib import Path

from ..core.robot import Robot
from ..errors import UserError
from .robotfile import load_robot_file

ROBOTS_DIR = Path(__file__).parent.parent / "robots"


def builtin_names() -> list[str]:
    """The names of the built-in robots, for `load`.

    >>> "puma560" in builtin_names()
    True
    """
    return sorted(p.stem for p in ROBOTS_DIR.glob("*.yaml"))


def load(name_or_path: str | os.PathLike) -> Robot:
    """A built-in robot by name, or a robot file by path (a str, or a `pathlib.Path` or any
    os.PathLike, which is always a path), with the warnings of its reading (`robot.warnings`).

    >>> load("planar2r")
    Robot('Planar elbow manipulator (2R)', standard DH, 2 joints: RR, frames 0..2)
    >>> load("spherical_wrist").numbering.frames(load("spherical_wrist").chain)
    [3, 4, 5, 6]
    >>> load(ROBOTS_DIR / "planar2r.yaml").chain.n
    2
    """
    return read(name_or_path)


def read(name_or_path: str | os.PathLike) -> Robot:
    """What `load` does (the command line's name for it).

    >>> read("puma")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    dhsym.errors.UserError: unknown robot 'puma'; built-in robots are: ..., ur5; did you mean 'puma560'?
    """
    if isinstance(name_or_path, os.PathLike):
        return load_robot_file(Path(os.fsdecode(name_or_path)))
    if not isinstance(name_or_path, str):
        raise TypeError(f"a robot is loaded by its built-in name or its file's path (str or os.PathLike), "
                        f"not {type(name_or_path).__name__}")
    names = builtin_names()
    if name_or_path in names:
        return load_robot_file(ROBOTS_DIR / f"{name_or_path}.yaml")
    path = Path(name_or_path)
    if name_or_path.strip() and (path.suffix in (".yaml", ".yml") or "/" in name_or_path or _is_file(path)):
        return load_robot_file(path)
    hint = difflib.get_close_matches(name_or_path.lower(), names, n=1, cutoff=0.5)
    if not hint:
        hint = [name for name in names if name_or_path and name.startswith(name_or_path.lower())][:1]
    suggestion = f"; did you mean {hint[0]!r}?" if hint else ""
    raise UserError(f"unknown robot {_shown(name_or_path)}; built-in robots are: {', '.join(names)}{suggestion}")


def _is_file(path: Path) -> bool:
    """Whether `path` names something on disk; a name the system refuses (too long) names nothing."""
    try:
        return path.exists()
    except (OSError, ValueError):  # ENAMETOOLONG, or a NUL character
        return False


def _shown(name: str, most: int = 60) -> str:
    """A name as an error quotes it, cut short past `most` characters.

    >>> _shown("puma")
    "'puma'"
    >>> print(_shown("arm_" * 64))
    'arm_arm_arm_arm_arm_arm_arm_arm_arm_arm_arm_arm_arm_arm_arm_'… (256 characters)
    """
    return repr(name) if len(name) <= most else f"{name[:most]!r}… ({len(name)} characters)"
