"""What the printed derivation calls its steps and its names, as a user reads them: a step is
labelled the law of cosines only where a squared distance (a triangle of the arm's lengths)
gives the cosine; a cosine read off a rotation element or a projection says so."""
import re

import pytest
from cli_runner import run_dhsym

COSINE = "a cos $\\theta$ = c"
LAW = "law of cosines"


def _labels(robot: str) -> dict:
    """{joint as LaTeX: [the labels of the steps that solve it]} from `dhsym ik ROBOT --format latex`."""
    status, out, err = run_dhsym("ik", robot, "--format", "latex")
    assert status == 0, err
    labels: dict = {}
    for label, joint in re.findall(r"% Step \d+ \((.*?)\), for \$(.*?)\$", out):
        labels.setdefault(joint, []).append(label)
    return labels


@pytest.mark.parametrize("robot, joint, label", [
    ("puma560", "\\theta_{5}", COSINE),  # c5 from element (2, 2) of 3T5
    ("stanford", "\\theta_{5}", COSINE),
    ("inline6", "\\theta_{5}", COSINE),
    ("cylindrical_wrist", "\\theta_{5}", COSINE),
    ("ur5", "\\theta_{5}", COSINE),  # a projection on axis 5
    ("ur5", "\\theta_{3}", LAW),
    ("planar2r", "\\theta_{2}", LAW),
    ("planar3r", "\\theta_{2}", LAW),
    ("inline6", "\\theta_{3}", LAW),
    ("scara", "\\theta_{2}", LAW),
])
def test_a_step_is_labelled_by_the_sub_problem_it_is(robot, joint, label):
    assert _labels(robot)[joint] == [label]


def test_law_of_cosines_only_from_a_squared_distance():
    _, out, _ = run_dhsym("ik", "puma560", "--format", "latex")
    for line in out.splitlines():
        if f"({LAW})" in line:
            assert "squared" in line, line
