"""The page's one entry point: `handle` takes a request from the page (JSON text) and gives its
answer (JSON text), so that nothing but strings crosses between JavaScript and Python.

Requests: `{"kind": "show", "yaml": TEXT, "file": NAME, "show": "fk", "width": PT, "from": F, "to": T,
"frame": F, "point": P, "free": [...]}` (see `outputs.output`), `{"kind": "draw", "yaml": …,
"values": {name: number}, "view": "auto"}` and `{"kind": "slides", "yaml": …, "jacobian": bool,
"ik": bool}`. Each answer has `state`: "ready", with the result and the robot's `warnings`; or
"error", with the one-line `message` the command line prints after `dhsym: error:` (and its
`line` and `column` in the robot file, where it has a place), or "internal error …" for a bug.

>>> import json
>>> arm = "name: arm\\nconvention: standard\\njoints:\\n  - {joint: R, theta: theta_1, d: 0, a: a_1, alpha: 0}\\n"
>>> answer = json.loads(handle(json.dumps({"kind": "show", "show": "table", "file": "arm.yaml", "yaml": arm})))
>>> answer["state"], answer["parts"][1]["tex"].splitlines()[0]
('ready', '\\\\begin{array}{c|cccc}')
>>> answer = json.loads(handle(json.dumps({"kind": "show", "show": "fk", "file": "arm.yaml",
...     "yaml": arm.replace("alpha", "alfa")})))
>>> answer["state"], answer["line"], answer["column"], answer["message"][:40]
('error', 4, 46, "arm.yaml:4:46: unknown key 'alfa' in joi")
"""
from __future__ import annotations

import json
import traceback
from collections import OrderedDict

from ..core.robot import Robot
from ..errors import UserError
from ..io.robotfile import load_robot_text
from ..io.yamlsafe import MAX_FILE_BYTES
from . import drawing, outputs

ROBOTS_KEPT = 4  # robots read recently, each with the results it has worked out (switching tabs reuses them)
_robots: OrderedDict = OrderedDict()
# What the page cannot do, by the module that is missing, and what to use instead.
NOT_IN_THE_BROWSER = {"numpy": "pictures and numbers need numpy, which the page does not load",
                      "matplotlib": "pictures need matplotlib, which the page does not load",
                      "lxml": "URDF files need lxml, which the page does not load"}


def handle(request: str) -> str:
    """The answer to one request, as JSON text; never raises."""
    try:
        data = json.loads(request)
        return json.dumps({"state": "ready", **_answer(data)}, ensure_ascii=False)
    except UserError as error:
        return json.dumps({"state": "error", **error_place(error)}, ensure_ascii=False)
    except ImportError as error:
        missing = (error.name or "").split(".")[0]
        why = NOT_IN_THE_BROWSER.get(missing, f"it needs the package {missing or error}, which the page does not load")
        return json.dumps({"state": "error", "message": f"not available in the browser: {why}; use the command "
                           "line (see the README's Install)"}, ensure_ascii=False)
    except Exception as error:  # a bug in dhsym, as the command line says it
        return json.dumps({"state": "error", "internal": True, "traceback": traceback.format_exc(),
                           "message": f"internal error: {type(error).__name__}: {str(error)[:300]} (a bug in dhsym, "
                                      "not a mistake in your input; please report it with the robot file)"},
                          ensure_ascii=False)


def error_place(error: UserError) -> dict:
    """The message and, where the error has one, its line and column."""
    where = error.where
    place = {"line": where.line, "column": where.column} if where and where.line else {}
    return {"message": str(error), **place}


def _answer(data: dict) -> dict:
    robot = robot_of(data["yaml"], data.get("file") or "robot.yaml")
    warnings = list(robot.warnings)
    kind = data.get("kind")
    if kind == "show":
        result = outputs.output(robot, data.get("show", "fk"), data.get("width", outputs.MAX_WIDTH_PT),
                                start=data.get("from"), end=data.get("to"), frame=data.get("frame"),
                                point=data.get("point"), free=tuple(data.get("free") or ()))
        return {**result.json(), "frames": robot.numbering.frames(robot.chain), "warnings": warnings}
    if kind == "draw":
        return {"svg": drawing.arm_svg(robot, data.get("values") or {}, data.get("view", "auto")),
                "sliders": drawing.sliders(robot), "warnings": warnings}
    if kind == "slides":
        tex = outputs.slides(robot, data.get("from"), data.get("to"), bool(data.get("jacobian")),
                             bool(data.get("ik")), tuple(data.get("free") or ()))
        return {"tex": tex, "warnings": warnings}
    raise UserError(f"unknown request {kind!r}")


def robot_of(text: str, filename: str) -> Robot:
    """The robot of a robot file's text, read once while it stays among the last few."""
    key = (filename, text)
    if key in _robots:
        _robots.move_to_end(key)
        return _robots[key]
    if len(text.encode("utf-8")) > MAX_FILE_BYTES:
        raise UserError(f"{filename}: file is larger than {MAX_FILE_BYTES // (1 << 20)} MiB, the limit for robot "
                        "files")
    robot = load_robot_text(text, filename)
    _robots[key] = robot
    while len(_robots) > ROBOTS_KEPT:
        _robots.popitem(last=False)
    return robot


def builtin_robots() -> list[dict]:
    """Each built-in robot's name, title and file, for the page's picker (written at build time).

    >>> next(robot for robot in builtin_robots() if robot["name"] == "puma560")["title"]
    'PUMA 560'
    """
    from ..io.library import ROBOTS_DIR, builtin_names, load

    return [{"name": name, "title": load(name).name, "yaml": (ROBOTS_DIR / f"{name}.yaml").read_text("utf-8")}
            for name in builtin_names()]
