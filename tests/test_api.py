"""`import dhsym` is the one import a notebook or a script needs: every exported name resolves
and shows an example, the import itself is cheap (each name is imported on first use), and a
command of the command line imports only what it uses."""
import argparse
import importlib
import subprocess
import sys
from pathlib import Path

import pytest

import dhsym
from dhsym.cli import app

HEAVY = ("numpy", "matplotlib", "yaml", "sympy", "lxml")


def _probe(code: str) -> list[str]:
    """The lines `code` prints in a fresh interpreter."""
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return result.stdout.splitlines()


@pytest.mark.parametrize("name", dhsym.__all__)
def test_each_exported_name_resolves_and_shows_an_example(name):
    value = getattr(dhsym, name)
    assert value is not None
    assert ">>>" in (value.__doc__ or ""), f"dhsym.{name} has no example in its docstring"


def test_dir_lists_exactly_the_exported_names():
    assert dir(dhsym) == sorted(dhsym.__all__)
    assert {"load", "Chain", "show", "plot", "fk", "jacobian", "convert", "check", "screws", "import_urdf", "ik",
            "errata", "verify"} <= set(dhsym.__all__)


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="has no attribute 'lod'"):
        dhsym.lod  # noqa: B018


def test_star_import_leaves_ipythons_display_alone():
    namespace = {"display": "IPython's"}
    exec("from dhsym import *", namespace)  # our own constant text
    assert namespace["display"] == "IPython's"
    assert "show" in namespace and callable(namespace["show"].table)


def test_import_dhsym_imports_nothing_heavy():
    loaded = _probe(f"import sys, dhsym\nprint(sorted(m for m in {HEAVY!r} if m in sys.modules))")
    assert loaded == ["[]"]


def test_names_import_their_modules_on_first_use_only():
    lines = _probe("import sys, dhsym\narm = dhsym.load('planar2r')\ndhsym.fk(arm)\n"
                   "print('numpy' in sys.modules, 'dhsym.velocity' in sys.modules)\n"
                   "dhsym.plot\nprint('numpy' in sys.modules, 'dhsym.velocity' in sys.modules)")
    assert lines == ["False False", "True False"]


def test_the_command_table_names_what_each_module_registers():
    registered = {}
    for module in dict.fromkeys(app.COMMANDS.values()):
        parser = argparse.ArgumentParser()
        commands = parser.add_subparsers()
        importlib.import_module(f"dhsym.cli.{module}").add_parsers(commands)
        registered.update(dict.fromkeys(commands.choices, module))
    assert registered == app.COMMANDS


@pytest.mark.parametrize("command, unused", [
    (["fk", "planar2r"], ["dhsym.velocity", "dhsym.geometry", "dhsym.inverse", "dhsym.latex.document",
                          "dhsym.cli.jacobian", "dhsym.cli.plot", "dhsym.cli.urdf_import", "dhsym.io.axesfile",
                          "numpy"]),
    (["table", "planar2r"], ["dhsym.velocity", "dhsym.geometry", "dhsym.inverse", "dhsym.cli.latex", "numpy"]),
])
def test_a_command_imports_only_what_it_uses(command, unused):
    code = ("import contextlib, io, sys\nfrom dhsym.cli import main\n"
            f"with contextlib.redirect_stdout(io.StringIO()):\n    status = main({command!r})\n"
            f"print(status, sorted(m for m in {unused!r} if m in sys.modules))")
    assert _probe(code) == ["0 []"]


def test_the_dhsym_process_runs_a_command_and_reports_a_mistake():
    done = subprocess.run([sys.executable, "-m", "dhsym.cli", "fk", "planar2r"], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0 and "a1 c1 + a2 c12" in done.stdout, done.stderr
    mistake = subprocess.run([sys.executable, "-m", "dhsym.cli", "fk", "puma650"], capture_output=True, text=True,
                             timeout=300)
    assert mistake.returncode == 2 and mistake.stderr.startswith("dhsym: error: unknown robot 'puma650'")


def test_check_compares_robots_by_name_or_path_and_expressions_by_value():
    from pathlib import Path

    import sympy

    arm = dhsym.convert(dhsym.load("planar3r"), "modified")
    assert dhsym.check(arm, "planar3r").same
    assert dhsym.check(arm, Path(dhsym.__file__).parent / "robots" / "planar3r.yaml").same
    different = dhsym.check(dhsym.load("planar2r"), "planar3r")
    assert not different.same and "2 and 3 joints" in different.message
    t = sympy.Symbol("t", real=True)
    assert dhsym.check(sympy.cos(t) ** 2, 1 - sympy.sin(t) ** 2)
    assert not dhsym.check(sympy.cos(t), sympy.sin(t))


def test_fk_takes_the_frames_the_chain_takes():
    arm = dhsym.load("planar3r")
    assert dhsym.fk(arm) == arm.fk()
    assert dhsym.fk(arm, 1, 2) == arm.transform(1, 2)
    assert dhsym.fk(arm, raw=True) == arm.transform(arm.first_frame, arm.last_frame, raw=True)


@pytest.mark.parametrize("module", sorted(set(app.COMMANDS.values())))
def test_each_command_module_imports_on_its_own(module):
    """The dispatcher imports only the command's module, so no command may rely on another having been imported."""
    assert _probe(f"import dhsym.cli.{module}\nprint('ok')") == ["ok"]


def test_a_name_longer_than_a_file_name_may_be_is_a_user_error():
    from dhsym.errors import UserError

    for name in ("arm_" * 64, "arms/" * 900):  # 256 characters; a path past PATH_MAX
        with pytest.raises(UserError) as raised:
            dhsym.load(name)
        assert "\n" not in str(raised.value) and len(str(raised.value)) < 5000


IMPORTED = str(Path(__file__).parent / "data" / "imported" / "long_decimals.yaml")


@pytest.mark.parametrize("name", ["puma560", "spherical_wrist", "ur5", "finger_rrr", IMPORTED])
def test_a_robot_and_its_chain_survive_pickle_and_deepcopy_with_their_kinematics(name):
    """A notebook's robot can be pickled (multiprocessing, a saved session) or deep-copied: the copy has
    the same kinematics, frame numbers, sample values and written numbers, and prints the same."""
    import copy
    import pickle

    from dhsym.printing.render import text_matrix, text_printer

    robot = dhsym.load(name)
    robot.fk()  # what it worked out stays behind: the copy works it out again
    for twin in (pickle.loads(pickle.dumps(robot)), copy.deepcopy(robot)):
        assert twin.fk() == robot.fk() and twin.fk(raw=True) == robot.fk(raw=True)
        assert (twin.name, twin.frames, twin.warnings, twin.numbers) == (robot.name, robot.frames, robot.warnings,
                                                                         robot.numbers)
        assert dict(twin.sample) == dict(robot.sample) and twin.joint_variables == robot.joint_variables
        assert text_matrix(twin.fk(), text_printer(twin)) == text_matrix(robot.fk(), text_printer(robot))
    for chain in (pickle.loads(pickle.dumps(robot.chain)), copy.deepcopy(robot.chain)):
        assert chain.fk() == robot.chain.fk() and chain.rows == robot.chain.rows


def test_load_takes_a_path_as_a_str_or_any_path_like():
    file = Path(dhsym.__file__).parent / "robots" / "planar2r.yaml"

    class PathLike:
        def __fspath__(self):
            return str(file)

    assert dhsym.load(file).fk() == dhsym.load(str(file)).fk() == dhsym.load(PathLike()).fk() == \
        dhsym.load("planar2r").fk()
    assert dhsym.load(file).file == str(file)
    with pytest.raises(dhsym.UserError, match="planar2r: cannot read file: No such file or directory"):
        dhsym.load(Path("planar2r"))  # a path is a path, never a built-in name
    with pytest.raises(TypeError, match="by its built-in name or its file's path .str or os.PathLike., not int"):
        dhsym.load(3)
