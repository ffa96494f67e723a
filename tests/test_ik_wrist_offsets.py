"""An offset on the wrist's middle joint (θ5 + 1, + 0.3, + π/7): the solver takes θ5 + c as the
angle φ it solves for, and the wrist's pairs degenerate where sin φ = 0. That sentence named φ as if
it were a joint (exit 70, "phi_2 is not in list"); it is said in the joint's angle, sin(θ5 + c), and
every branch reaches random poses with the joints among them."""
import json
from pathlib import Path

import numpy as np
import pytest
from cli_runner import run_dhsym
from ik_checks import check_branches_reach, check_json, random_joints, sample_constants

from dhsym import load
from dhsym.io.library import ROBOTS_DIR

DATA = Path(__file__).parent / "data"
OFFSETS = ["1", "0.3", "pi/7"]
WRISTS = {"puma560": "theta: theta_5}", "ur5": "theta: theta_5}", "stanford": "theta: theta_5}",
          "inline6": "theta: theta_5}", "cylindrical_wrist": "theta: theta_5}"}


def offset_file(text: str, wrist: str, offset: str, folder: Path, name: str) -> Path:
    assert text.count(wrist) == 1
    path = folder / f"{name}.yaml"
    path.write_text(text.replace(wrist, wrist.replace("5", f"5 + {offset}", 1)), encoding="utf-8")
    return path


def check_reaches(path: Path) -> None:
    robot = load(str(path))
    ik = robot.ik()
    assert len(ik.branches) == len(load(str(path)).ik().branches) > 1
    check_json(json.dumps(ik.json()), robot)
    check_branches_reach(ik.function(), robot, sample_constants(robot),
                         random_joints(robot, np.random.default_rng(7), 8))


@pytest.mark.slow  # fifteen six-joint arms, a second each
@pytest.mark.parametrize("offset", OFFSETS)
@pytest.mark.parametrize("name", list(WRISTS))
def test_a_wrist_offset_solves_and_reaches_the_pose(name, offset, tmp_path):
    text = (ROBOTS_DIR / f"{name}.yaml").read_text(encoding="utf-8")
    check_reaches(offset_file(text, WRISTS[name], offset, tmp_path, f"{name}_offset"))


@pytest.mark.slow
@pytest.mark.parametrize("offset", OFFSETS)
def test_the_imported_ur5_with_a_wrist_offset(offset, tmp_path):
    imported = tmp_path / "ur5.yaml"
    run_dhsym("import", str(DATA / "ur5.urdf"), "--tip", "tool0", "-o", str(imported))
    check_reaches(offset_file(imported.read_text(encoding="utf-8"), "theta: q_5,", offset, tmp_path, "ur5_offset"))


@pytest.mark.slow
def test_the_puma_says_where_its_wrist_lines_up_with_the_offset(tmp_path):
    text = (ROBOTS_DIR / "puma560.yaml").read_text(encoding="utf-8")
    path = offset_file(text, WRISTS["puma560"], "1", tmp_path, "puma_offset")
    out = " ".join(run_dhsym("ik", str(path)).ok().split())
    assert ("s5 = 0: θ4 is not determined on its own: the axes on either side of θ5 line up, and at θ5 + 1 = 0 "
            "only θ4 + θ6 is determined, at θ5 + 1 = π only θ4 − θ6") in out
    assert "a singularity of J: the factor s5 of det J" in out and "s5 = sin(θ5 + 1)" in out
    check_reaches(path)
