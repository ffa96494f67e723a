"""`robot.ik()` in a notebook or a program: two threads solving two arms at once, a solution
pickled and deep-copied, a misspelt constant given to evaluate()."""
import copy
import pickle
import sys
import threading

import numpy as np
import pytest
import sympy

from dhsym.errors import UserError
from dhsym.inverse.equations import Equation
from dhsym.inverse.scan import scan
from dhsym.io.library import load


@pytest.mark.slow  # eight derivations, the threads switching often
def test_two_threads_solving_two_arms_at_once_get_what_one_thread_gets():
    """The search's memos belong to one call: a second search cannot clear them mid-derivation
    (they were module-level: KeyError in the other thread)."""
    arms = ["spatial3r", "scara", "cylindrical_rpp", "planar3r"]
    alone = {name: load(name).ik().text() for name in arms}
    found: dict = {}
    failures: list = []

    def solve(names):
        try:
            for name in names:
                found.setdefault(name, []).append(load(name).ik().text())  # a new robot: solved again
        except Exception as error:  # noqa: BLE001 - the test reports whatever a thread met
            failures.append(error)

    threads = [threading.Thread(target=solve, args=(arms,)), threading.Thread(target=solve, args=(arms[::-1],))]
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-5)  # the threads take turns often, as they may on a busy machine
    try:
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
    finally:
        sys.setswitchinterval(interval)
    assert failures == []
    assert found == {name: [text, text] for name, text in alone.items()}


class Interrupting(sympy.Symbol):
    """A joint variable whose hashing starts another search, as another thread may at any moment:
    inside each look-up of a memo keyed by it."""

    busy = False

    def __hash__(self):
        if not Interrupting.busy:
            Interrupting.busy = True
            try:
                scan([], [], set())  # a search of its own
            finally:
                Interrupting.busy = False
        return super().__hash__()


def test_a_search_started_during_another_leaves_its_memos_alone():
    """With module-level memos the second search cleared the first's between storing a value and
    reading it back: KeyError."""
    x, t = sympy.Symbol("x", real=True), Interrupting("theta_1", real=True)
    found = scan([Equation(x, sympy.cos(t), "position", "x")], [t], set())
    assert str(found.assignments) == "[(theta_1, atan2(sigma_1*sqrt(1 - x**2), x))]"


def test_a_solutions_branches_and_steps_pickle_and_copy_as_they_were_built():
    """SymPy rebuilds a pickled expression by evaluating it: the PUMA's −(pz(a3 + a2 c3) + …) came
    back multiplied out, not equal to the solution and printed otherwise."""
    solution = load("puma560").ik().solution
    for part in (solution.branches, solution.definitions, solution.steps):
        assert pickle.loads(pickle.dumps(part)) == part
        assert copy.deepcopy(part) == part


@pytest.mark.parametrize("name", ["planar2r", "puma560", "ur5"])
def test_a_solution_pickles_and_copies_and_prints_the_same(name):
    ik = load(name).ik()
    pose = np.eye(4)
    pose[:3, 3] = [0.3, 0.2, 0.1]
    for twin in (pickle.loads(pickle.dumps(ik)), copy.deepcopy(ik)):
        assert twin.solution.branches == ik.solution.branches and twin.solution.steps == ik.solution.steps
        assert (twin.text(), twin.json(), twin.code()) == (ik.text(), ik.json(), ik.code())
        assert np.allclose(twin.evaluate(pose), ik.evaluate(pose), equal_nan=True)


def test_a_misspelt_constant_is_an_error_naming_the_constants():
    ik = load("scara").ik()
    with pytest.raises(UserError, match="^SCARA has no constant d5; its constants are a_1, a_2$"):
        ik.evaluate(np.eye(4), d5=0.4)
    free = load("planar3r").ik(free=["theta_2"])
    with pytest.raises(UserError, match="has no constant theta_1; its constants are l_1, l_2, l_3, its --free "
                                        "joint variables theta_2$"):
        free.evaluate(np.eye(4), theta_1=0.1, theta_2=0.2)
    assert ik.evaluate(np.eye(4), a_2=0.5).shape == (2, 4)


def test_the_files_values_for_other_chapters_are_accepted_and_not_needed():
    """An imported arm's sample holds g and the links' masses for its dynamics: evaluate() takes the whole
    sample back without complaint, while a name the file does not have stays an error."""
    robot = load("planar2r").replace(sample={**load("planar2r").sample, sympy.Symbol("g", real=True): 9.81})
    ik = robot.ik()
    values = {str(k): v for k, v in robot.sample.items()}
    assert ik.evaluate(np.eye(4), **values).shape == (2, 2)
    with pytest.raises(UserError, match="has no constant gg"):
        ik.evaluate(np.eye(4), gg=1.0)
