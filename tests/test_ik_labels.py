"""What the printed derivation calls its steps and its names, as a user reads them: a step is
labelled the law of cosines only where a squared distance (a triangle of the arm's lengths)
gives the cosine; a cosine read off a rotation element or a projection says so."""
import re

import pytest
import sympy
from cli_runner import run_dhsym

from dhsym.inverse.equations import Equation
from dhsym.inverse.scan import scan

COSINE = "a cos $\\theta$ = c"
LAW = "law of cosines"


def _labels(robot: str) -> dict:
    """{joint as LaTeX: [the labels of the steps that solve it]} from `dhsym ik ROBOT --format latex`."""
    status, out, err = run_dhsym("ik", robot, "--format", "latex")
    assert status == 0, err
    labels: dict = {}
    for label, joint in re.findall(r"Step \d+ \((.*?)\), for \$(.*?)\$", out):
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


@pytest.mark.parametrize("robot", ["puma560", "ur5", "stanford", "planar3r", "scara_spong"])
def test_every_intermediate_name_the_text_uses_is_defined(robot):
    status, text, err = run_dhsym("ik", robot)
    assert status == 0, err
    assigned = set(re.findall(r"^ +(\S+) += ", text, re.MULTILINE))
    solved_as_one = next((line for line in text.splitlines() if line.startswith("Angles solved as one:")), "")
    used = set(re.findall(r"(?<![\w(])(θ\d{2,}|φ\d+|[CDK]\d*)(?![\w(])", text))
    for name in used:
        assert name in assigned, f"{name} is used but never assigned"
        if name[0] in "θφ":  # a sum of angles solved as one says which sum it is
            assert f"{name} = " in solved_as_one, f"{name} is not said to be a sum of angles"
    assert not re.search(r"[CDK]\d+²", text)  # no name reads as a square: D2²


def test_d_is_the_law_of_cosines_alone():
    _, puma, _ = run_dhsym("ik", "puma560")
    assert "C   = −r13 c1 s23 − r23 s1 s23 − r33 c23" in puma and "θ5  = atan2(√(1 − C²), C)" in puma
    assert not re.search(r"^ +D +=", puma, re.MULTILINE)  # the PUMA's elbow is Craig's K, its wrist C
    _, planar, _ = run_dhsym("ik", "planar2r")
    assert "D = (px² + py² − a1² − a2²)/(2 a1 a2)" in planar  # Spong's D
    assert "Angles solved as one: θ23 = θ2 + θ3" in puma


def test_a_second_name_of_one_letter_is_primed_not_numbered():
    # two cosines from two squared distances: D and D′ (D2 would read as D squared in 1 − D2²)
    p, q, r, t1, t2 = sympy.symbols("p q r theta_1 theta_2", real=True)
    found = scan([Equation(p * q + q * r + r * p, sympy.cos(t1), "position", ("x",), distance=True),
                  Equation(p * q - q * r + r * p, sympy.cos(t2), "position", ("y",), distance=True)], [t1, t2], set())
    names = [name.name for name, _ in found.assignments if name not in (t1, t2)]
    assert names == ["D", "Dʹ"]
    assert [step.subproblem.name for step in found.steps] == [LAW, LAW]
    one = scan([Equation(p * q + q * r + r * p, sympy.cos(t1), "position", ("x",))], [t1], set())
    assert [name.name for name, _ in one.assignments] == ["C", "theta_1"]  # not a distance: not D
    assert one.steps[0].subproblem.name == "a cos θ = c"
