"""docs/architecture.md lists every module of every subpackage of dhsym, and nothing that is gone:
each row of its table names a folder (`inverse/`, `inverse/numeric/`) and, in backticks in its second
column, modules of that folder (a folder may take several rows: inverse/ is grouped as the book)."""
import re
from pathlib import Path

ROOT = Path(__file__).parent.parent
PACKAGE = ROOT / "dhsym"
PAGE = ROOT / "docs" / "architecture.md"


def listed_modules() -> dict[str, set[str]]:
    """{folder as the page writes it ("dhsym/", "core/", "inverse/numeric/"): the modules its rows name}."""
    listed: dict[str, set[str]] = {}
    for line in PAGE.read_text(encoding="utf-8").splitlines():
        cells = line.split(" | ")
        if line.startswith("| `") and len(cells) >= 3:
            folder = cells[0].removeprefix("| ").strip("`")
            listed.setdefault(folder, set()).update(re.findall(r"`([a-z_0-9]+)`", cells[1]))
    return listed


def actual_modules() -> dict[str, set[str]]:
    """{folder: its modules}, every package of dhsym but its __init__ and __main__."""
    folders = {}
    for init in PACKAGE.rglob("__init__.py"):
        folder = init.parent.relative_to(PACKAGE).as_posix()
        folders["dhsym/" if folder == "." else folder + "/"] = {
            path.stem for path in init.parent.glob("*.py") if not path.stem.startswith("__")}
    return folders


def test_every_module_is_on_the_architecture_page_and_no_other():
    listed, actual = listed_modules(), actual_modules()
    missing = sorted(f"{folder}{m}" for folder, modules in actual.items() for m in modules - listed.get(folder, set()))
    gone = sorted(f"{folder}{m}" for folder, modules in listed.items() for m in modules - actual.get(folder, set()))
    assert (missing, gone) == ([], [])


def test_the_page_names_the_layers_in_the_order_the_layout_test_checks():
    from test_layout import LAYERS

    text = PAGE.read_text(encoding="utf-8")
    order = re.search(r"The layers, in order: (.*?); the package", text, re.S).group(1)
    assert re.findall(r"`([a-z]+)`", order) == LAYERS
