"""The package's shape: layers import one way, no module takes another's private names, modules
stay small, commands import only what they need, and a plain `pip install .` works."""
import ast
import os
import subprocess
import sys
import venv
from pathlib import Path

import pytest

PACKAGE = Path(__file__).parent.parent / "dhsym"
# Each layer may import the layers before it (and itself), never one after it.
# `checking.verify` (equality by algebra and numbers) is plain math, so it sits right under core;
# `geometry` (frames from joint axes) is math on core that the robot-file reader uses for `axes:`.
LAYERS = ["errors", "core", "checking.verify", "geometry", "io", "velocity", "inverse", "printing", "latex", "plot",
          "checking", "cli"]
# Conveniences reach up, lazily inside a method: Jupyter shows a chain or a robot as its DH
# table, `.jacobian()` and `.ik()` hand over to the layers built on core, and the object
# `.ik()` returns shows itself as text and LaTeX.
ALLOWED_UPWARD = {("core.chain", "printing.render"), ("core.chain", "velocity.jacobian"),
                  ("core.chain", "inverse.api"), ("core.robot", "printing.render"), ("core.robot", "velocity.jacobian"),
                  ("core.robot", "inverse.api"), ("inverse.api", "latex.ik"), ("inverse.api", "printing.ik")}


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        name = ".".join(path.relative_to(PACKAGE).with_suffix("").parts)
        yield name.removesuffix(".__init__").removesuffix("__init__"), path


def _imports(name: str, path: Path):
    """(imported module relative to dhsym, imported names, at module level?) for each relative import."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    top_level = {id(node) for node in tree.body}
    parts = [part for part in name.split(".") if part]
    package = parts if path.name == "__init__.py" else parts[:-1]
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.level:
            base = package[:len(package) - (node.level - 1)] if node.level > 1 else package
            target = ".".join(base + ([node.module] if node.module else []))
            yield target, [alias.name for alias in node.names], id(node) in top_level


def _layer(module: str) -> int:
    """The position of the most specific layer that holds `module`."""
    if not module:
        return len(LAYERS)
    parts = module.split(".")
    return next(LAYERS.index(".".join(parts[:k])) for k in range(len(parts), 0, -1) if ".".join(parts[:k]) in LAYERS)


def test_layers_import_one_way():
    upward = []
    for name, path in _modules():
        for target, names, _ in _imports(name, path):
            for imported in ([f"{target}.{n}" for n in names] if _layer(target) == len(LAYERS) else [target]):
                if name and _layer(imported) > _layer(name) and (name, imported) not in ALLOWED_UPWARD:
                    upward.append(f"{name} imports {imported}")
    assert upward == []


def test_no_module_imports_a_private_name_of_another():
    private = [f"{name} imports {target}.{n}" for name, path in _modules() for target, names, _ in _imports(name, path)
               for n in names if n.startswith("_")]
    assert private == []


def test_modules_stay_small():
    sizes = {name: len(path.read_text(encoding="utf-8").splitlines()) for name, path in _modules()}
    assert {name: size for name, size in sizes.items() if size > 400} == {}


@pytest.mark.parametrize("command", [["fk", "puma560"], ["table", "ur5"], ["links", "planar3r"],
                                     ["latex", "planar2r", "--document", "snippet"], ["list"]])
def test_commands_without_pictures_import_no_numpy(command):
    probe = ("import sys, io, contextlib\nfrom dhsym.cli import main\n"
             f"with contextlib.redirect_stdout(io.StringIO()):\n    status = main({command!r})\n"
             "print(status, sorted(m for m in ('numpy', 'matplotlib') if m in sys.modules))")
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    assert result.stdout.split("\n")[0] == "0 []", result.stderr


def test_a_plain_pip_install_works_from_another_folder(tmp_path):
    """The wheel must hold every subpackage and the robot files (a flat `packages = [...]` once dropped them).

    The fresh venv borrows SymPy and friends from this one through a .pth line (installing them again takes a
    minute and tests pip, not dhsym); dhsym itself is built and installed by the fresh venv's own pip."""
    environment = tmp_path / "venv"
    venv.create(environment, with_pip=True)
    python = environment / "bin" / "python"
    fresh_site = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                                capture_output=True, text=True, check=True).stdout.strip()
    ours = next(p for p in sys.path if p.endswith("site-packages"))
    Path(fresh_site, "borrowed.pth").write_text(ours + "\n")
    root = Path(__file__).parent.parent
    install = subprocess.run([str(python), "-m", "pip", "install", "-q", "--disable-pip-version-check",
                              "--no-deps", str(root)],
                             capture_output=True, text=True, timeout=600)
    assert install.returncode == 0, install.stderr[-2000:]
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    env = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    for command, expected in ((["fk", "puma560"], "px  = c1(a2 c2 + a3 c23 − d4 s23) − d3 s1"),
                              (["latex", "planar3r"], "\\begin{frame}")):
        result = subprocess.run([str(environment / "bin" / "dhsym"), *command], cwd=elsewhere, capture_output=True,
                                text=True, timeout=120, env=env)
        assert result.returncode == 0 and expected in result.stdout, result.stderr
    where = subprocess.run([str(python), "-c", "import dhsym; print(dhsym.__file__)"], cwd=elsewhere,
                           capture_output=True, text=True, env=env).stdout
    assert where.startswith(fresh_site)
