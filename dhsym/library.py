"""The built-in robots shipped in dhsym/robots/, and lookup of a robot by name or path.

>>> "puma560" in builtin_names()
True
>>> load("puma560").chain.n
6
"""
from __future__ import annotations

from pathlib import Path

from .errors import UserError
from .robotfile import Robot, load_robot_file

ROBOTS_DIR = Path(__file__).parent / "robots"


def builtin_names() -> list[str]:
    return sorted(p.stem for p in ROBOTS_DIR.glob("*.yaml"))


def load(name_or_path: str) -> Robot:
    """A built-in robot by name, or a robot file by path."""
    path = Path(name_or_path)
    if name_or_path in builtin_names():
        return load_robot_file(ROBOTS_DIR / f"{name_or_path}.yaml")
    if path.suffix in (".yaml", ".yml") or path.exists() or "/" in name_or_path:
        return load_robot_file(path)
    raise UserError(f"unknown robot {name_or_path!r}; built-in robots are: {', '.join(builtin_names())}")
