"""The inverse kinematics counts frames and joints one way inside (a plain Chain, frames 0..n) and
prints them the robot file's way (`first_frame`, base and tool): an arm numbered from 1 or from 5
gets the same solution, the same sentences and the same module as one numbered from 0, its
printed frame and joint numbers moved."""
import pytest
import sympy
from cli_runner import run_dhsym

import dhsym
from dhsym.io.library import ROBOTS_DIR

WRIST_ARMS = ("puma560", "stanford")


def numbered(tmp_path, name: str, first_frame: int):
    """The built-in robot `name` written with `first_frame`."""
    text = (ROBOTS_DIR / f"{name}.yaml").read_text(encoding="utf-8")
    path = tmp_path / f"{name}_from_{first_frame}.yaml"
    path.write_text(text.replace("convention:", f"first_frame: {first_frame}\nconvention:", 1), encoding="utf-8")
    return path


@pytest.mark.slow
@pytest.mark.parametrize("name", WRIST_ARMS)
@pytest.mark.parametrize("first_frame", [1, 3, 5])
def test_the_wrist_is_tied_to_det_j_whatever_the_first_frame(tmp_path, name, first_frame):
    """s5 = 0 is the singular factor s5 of det J, however the file numbers its frames (with
    first_frame 1 the solver once found sin(theta_4), from 2 on nothing, from 5 on it exited 70)."""
    status, out, err = run_dhsym("ik", numbered(tmp_path, name, first_frame), "--width", "1000")
    assert (status, err) == (0, "")
    assert "a singularity of J: the factor s5 of det J" in out
    joints = ", ".join(str(k + first_frame) for k in (4, 5)) + f" and {6 + first_frame}"
    assert f"the axes of joints {joints} meet at the wrist centre" in out


def test_the_wrist_factor_is_read_in_the_chains_own_frames():
    from dhsym.inverse.singular import wrist_factors

    puma = dhsym.load("puma560")
    assert wrist_factors(puma.chain, puma.numbers) == [sympy.sin(puma.joint_variables[4])]
