"""`dhsym ik` refuses what it cannot finish from measures taken before any algebra (the table's
entries multiplied out, the size of the equations, the motions the unknown joints make), and a
`--free` hint names a joint only after a derivation with it made a parameter has worked.
(The corpus tests/bad_inputs/cli_ik_* holds the same refusals as a user meets them.)"""
import importlib
from pathlib import Path

import pytest

import dhsym.inverse.redundant
from dhsym import load
from dhsym.errors import UserError
from dhsym.io.library import ROBOTS_DIR

CORPUS = Path(__file__).parent / "bad_inputs"
IMPORTED = Path(__file__).parent / "data" / "imported"


@pytest.fixture
def no_search(monkeypatch):
    """The equations are never built: a refusal comes from the measures alone."""
    def refuse(*args, **kwargs):
        raise AssertionError("the derivation started")

    solver = importlib.import_module("dhsym.inverse.methods")  # where the methods build their equations
    for name in ("transform_equations", "point_equations"):
        monkeypatch.setattr(solver, name, refuse)


@pytest.mark.parametrize("name, message", [
    ("cli_ik_entry_multiplies_out", "joint row 3 a multiplies out to 969 terms, and the inverse kinematics' "
                                    "equations square it"),
    ("cli_ik_24_joints_18_free", "would hold more than the 60,000 expression nodes that dhsym searches"),
])
def test_too_much_work_is_refused_before_the_derivation_starts(name, message, no_search):
    robot = load(str(CORPUS / f"{name}.yaml"))
    free = [f"theta_{k}" for k in range(4, 22)] if "free" in name else []
    with pytest.raises(UserError, match=message):
        robot.ik(free=free)


def test_more_unknowns_than_the_arm_has_motions_is_refused_before_the_derivation(no_search, monkeypatch):
    """A planar arm moves its end in three ways: four unknown joints leave a family of solutions."""
    monkeypatch.setattr(dhsym.inverse.redundant, "_derives", lambda chain, sample, numbers, free: False)
    robot = load(str(CORPUS / "cli_ik_planar_4r_redundant.yaml"))
    with pytest.raises(UserError, match="4 of them unknown, but they move its end in only 3 independent ways: make 1 "
                                        "of them a parameter with --free; none of the 3 choices dhsym tried"):
        robot.ik()


@pytest.mark.slow  # three derivations of the iiwa
def test_the_free_hint_is_a_joint_that_works():
    """The iiwa's middle joint θ4 is the elbow between a spherical shoulder and wrist (S-R-S): with it
    a parameter the two are at a fixed distance, and the other six joints move the end in five ways
    only. θ3 works, and is the one named."""
    with pytest.raises(UserError, match="^KUKA LBR iiwa 14 R820 \\(7-axis, iiwa-like\\) has 7 joints; with theta_4 "
                                        "a parameter the 6 unknown joints move its end in only 5 independent ways, "
                                        "where all of its joints move it in 6: make another joint the parameter with "
                                        "--free, e.g. --free theta_3$"):
        load("iiwa7").ik(free=["theta_4"])
    with pytest.raises(UserError, match="a pose fixes only 6: make 1 of them a parameter with --free, e.g. "
                                        "--free theta_3$"):
        load("iiwa7").ik()
    assert len(load("iiwa7").ik(free=["theta_3"]).branches) == 8
    planar = load(str(CORPUS / "cli_ik_planar_4r_redundant.yaml"))
    hint = (CORPUS / "cli_ik_planar_4r_redundant.expected").read_text().split("--free ")[-1].split()
    assert len(planar.ik(free=hint).branches) == 2


def test_no_hint_where_no_choice_works():
    with pytest.raises(UserError, match="make 1 of them a parameter with --free; none of the 7 choices dhsym tried "
                                        "leaves a closed form by the course's rules$"):
        load(str(IMPORTED / "baxter_arm.yaml")).ik()


def test_the_hint_derives_a_bounded_number_of_choices(monkeypatch):
    tried = []
    monkeypatch.setattr(dhsym.inverse.redundant, "_derives",
                        lambda chain, sample, numbers, free: tried.append(free) and False)
    with pytest.raises(UserError, match="none of the 4 choices dhsym tried"):  # θ4 is passed over before deriving
        load("iiwa7").ik()
    assert len(tried) == dhsym.inverse.redundant.HINT_DERIVATIONS == 3


def test_the_built_in_arms_are_far_within_the_bounds():
    from dhsym.inverse.bounds import POOL_MAX_NODES, pool_size

    sizes = {path.stem: pool_size(load(str(path)).chain) for path in ROBOTS_DIR.glob("*.yaml")}
    assert max(sizes.values()) < POOL_MAX_NODES / 4, sizes
