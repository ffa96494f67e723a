"""ROS packages found the way ROS finds them: a folder with a package.xml whose `<name>` is the
package, for `$(find PKG)` in a .xacro file.

Where dhsym looks, and never elsewhere: the package that holds the file (its nearest folder
upward with a package.xml, at most 8 levels up), then the folder that holds that package (the
workspace, or the clone of a repository of several packages) searched downward, then each folder
the user names with `--package-path DIR`, in order. The searches go at most 6 folders deep and
visit at most 10,000 folders in all; hidden folders, folders marked CATKIN_IGNORE,
COLCON_IGNORE or AMENT_IGNORE, and symbolic links are skipped, and a package's own folders are
not searched for more packages (packages do not nest). The first package of a name wins.

A file in no package keeps dhsym's older rule: its folder is the tree, or the folder that holds
the package when the file is in a `urdf/`, `robots/`, `xacro/`, `model/` or `models/` folder.
Only where no package.xml names the package is a folder named like it taken (PKG,
PKG_description, PKG without _support or _description), one that is not a package and holds
none, at most two folders down: rtb-data, for one, ships ROS packages without their package.xml,
renamed (ROS-Industrial's abb_irb140 as abb_irb140_description).

>>> import tempfile
>>> root = Path(tempfile.mkdtemp())
>>> (root / "arm_support" / "urdf").mkdir(parents=True)
>>> _ = (root / "arm_support" / "package.xml").write_text("<package><name>arm_support</name></package>")
>>> packages = Packages(root / "arm_support" / "urdf" / "arm.xacro")
>>> packages.find("arm_support") == root / "arm_support", packages.find("gripper")
(True, None)
"""
from __future__ import annotations

from collections import deque
from pathlib import Path

from lxml import etree

from ..errors import UserError
from .xmlsource import read_regular_file

MAX_LEVELS_UP = 8
MAX_DEPTH = 6
MAX_FOLDERS = 10_000
MAX_MANIFEST_BYTES = 64 << 10
MANIFEST = "package.xml"
IGNORE_MARKERS = ("CATKIN_IGNORE", "COLCON_IGNORE", "AMENT_IGNORE")
PACKAGE_FOLDERS = ("urdf", "robots", "xacro", "model", "models")


class Packages:
    """The trees a .xacro file may read from, and the ROS packages in them."""

    def __init__(self, top: str | Path, package_paths=()):
        folder = Path(top).resolve().parent
        home = _package_above(folder)
        if home is not None:
            self.tree = home.parent if home.parent != home else home
        elif folder.name in PACKAGE_FOLDERS and folder.parent.parent != folder.parent:
            self.tree = folder.parent.parent
        else:
            self.tree = folder
        self.roots = [self.tree, *(checked_folder(path) for path in package_paths)]
        self.home = home
        self.index: dict[str, Path] | None = None
        self.plain: list[Path] = []  # folders that are no package and hold none, two levels down at most
        self.truncated = False

    def contains(self, path: Path) -> bool:
        """Whether `path` (resolved) lies in one of the trees."""
        return any(path.is_relative_to(root) for root in self.roots)

    def find(self, name: str) -> Path | None:
        """The folder of package `name`: by package.xml, else by a folder named like it."""
        if self.index is None:
            self.scan()
        if name in self.index:
            return self.index[name]
        names = {name, name + "_description", name.removesuffix("_support"), name.removesuffix("_description")}
        return next((folder for folder in self.plain if folder.name in names), None)

    def scan(self) -> None:
        """Index every package.xml in the trees, breadth first, within the bounds."""
        self.index, visited, holders = {}, 0, set()
        if self.home is not None:
            self.add(self.home)
        for root in self.roots:
            waiting = deque([(root, 0)])
            while waiting:
                folder, depth = waiting.popleft()
                if depth and any((folder / marker).exists() for marker in IGNORE_MARKERS):
                    continue
                visited += 1
                if visited > MAX_FOLDERS:
                    self.truncated = True
                    return
                if (folder / MANIFEST).is_file():
                    self.add(folder)
                    holders.update(folder.parents)
                    continue
                if depth <= 2:
                    self.plain.append(folder)
                if depth < MAX_DEPTH:
                    waiting.extend((child, depth + 1) for child in _subfolders(folder))
        self.plain = [folder for folder in self.plain if folder not in holders and folder != self.tree]

    def add(self, folder: Path) -> None:
        name = package_name(folder / MANIFEST)
        if name and name not in self.index:
            self.index[name] = folder

    def missing(self, name: str, shown) -> str:
        """Why `$(find name)` failed: which package, where dhsym looked, what to do."""
        places = " and ".join(shown(root) for root in self.roots)
        stopped = f" (the search stopped after {MAX_FOLDERS:,} folders)" if self.truncated else ""
        return (f"$(find {name}): no ROS package {name} (a folder whose {MANIFEST} has <name>{name}</name>) in "
                f"{places}{stopped}; give the folder that holds it with --package-path DIR (dhsym does not search "
                "ROS_PACKAGE_PATH)")


def package_name(manifest: Path) -> str | None:
    """The <name> of a package.xml, or None when it is unreadable (no DOCTYPE, no entities)."""
    try:
        data = read_regular_file(manifest, MAX_MANIFEST_BYTES, "package.xml files")
    except UserError:
        return None
    parser = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError:
        return None
    if root.getroottree().docinfo.internalDTD is not None:
        return None
    name = root.findtext("name")
    return name.strip() if name and name.strip() else None


def checked_folder(path) -> Path:
    """A --package-path folder, resolved; anything else is one clear error."""
    folder = Path(path)
    if not folder.is_dir():
        raise UserError(f"--package-path {path}: {'not a folder' if folder.exists() else 'no such folder'}")
    return folder.resolve()


def _package_above(folder: Path) -> Path | None:
    for candidate in [folder, *folder.parents][:MAX_LEVELS_UP + 1]:
        if (candidate / MANIFEST).is_file():
            return candidate
    return None


def _subfolders(folder: Path) -> list[Path]:
    try:
        entries = sorted(folder.iterdir())
    except OSError:
        return []
    return [entry for entry in entries if not entry.name.startswith(".") and not entry.is_symlink() and entry.is_dir()]
