"""Where installed data packages keep their robots (requirements-dev.txt pins them), for tests
that read real URDFs: a path that does not exist when the package is not installed, so that a
test can skip on `not path.exists()`."""
from __future__ import annotations

import importlib.metadata
from pathlib import Path


def package_folder(distribution: str, inside: str) -> Path:
    """The file or folder `inside` of the installed `distribution`, else /nonexistent."""
    try:
        return Path(importlib.metadata.distribution(distribution).locate_file(inside))
    except importlib.metadata.PackageNotFoundError:
        return Path("/nonexistent")


EXAMPLE_ROBOT_DATA = package_folder("example-robot-data", "cmeel.prefix/share/example-robot-data/robots")
RTB_XACRO = package_folder("rtb-data", "rtbdata/xacro")
