"""`solve`: the closed-form inverse kinematics of a chain, as every surface asks for it: the joints
made parameters checked, a redundant arm told which joints would do, the robot file's decimals
solved as the symbols they are written as and folded back (dhsym.inverse.written), the branches
named by what is true of the arm (dhsym.inverse.naming).

It takes a plain `Chain` (frames 0..n) and, as explicit arguments, what the robot file says that
the solution needs: numbers for the constants (`sample`), how it wrote its numbers (`numbers`),
its name and file for the messages. A robot is an error at once:

>>> import dhsym
>>> puma = dhsym.load("puma560")
>>> len(solve(puma.chain, sample=puma.sample, numbers=puma.numbers).branches)
8
>>> solve(puma)
Traceback (most recent call last):
TypeError: a plain Chain (frames 0..n) is needed here, not Robot; a robot's is robot.chain, its printed numbers \
robot.numbering

The free joint variables are named by symbol or by name; a name the chain lacks is one clear error:

>>> free_variables(dhsym.load("planar2r").chain, ["theta_2"])
(theta_2,)
>>> free_variables(dhsym.load("planar2r").chain, ["theta_3"], "Planar 2R")
Traceback (most recent call last):
dhsym.errors.UserError: --free theta_3: Planar 2R has no joint variable theta_3; its joint variables are theta_1, \
theta_2
"""
from __future__ import annotations

from ..core.chain import Chain, plain
from ..core.numbers import WrittenNumbers
from ..errors import UserError
from .bounds import redundancy, redundant_message, refuse_unbounded
from .derive import derive
from .naming import checked_names
from .redundant import working_free
from .solution import Solution
from .written import as_written, with_names, with_written_symbols


def solve(chain: Chain, free=(), *, sample=None, numbers: WrittenNumbers | None = None, name: str = "",
          path: str = "") -> Solution:
    """The solution of `chain` with the joint variables `free` (symbols or names) kept as
    parameters, its decimals as the robot file wrote them (`numbers`), its branches named;
    `sample` gives numbers for the constants, `name` and `path` (the robot file) name it in
    messages."""
    chain, numbers = plain(chain), numbers or WrittenNumbers()
    sample = {symbol: value for symbol, value in (sample or {}).items() if symbol in chain.symbols}  # not masses
    path = path or name or "<robot>"
    variables = free_variables(chain, free, name)
    redundant = redundancy(chain, variables, sample)
    if redundant:  # a closed form needs other or more parameters: which ones, checked by deriving with them
        refuse_unbounded(chain, path)  # else no choice could be derived
        kept, count = ((), redundant.needed) if redundant.lost else (variables, redundant.extra)
        example, tried = working_free(chain, sample, numbers, kept, count) if count else ((), 0)
        raise UserError(redundant_message(name, variables, redundant, example, tried))
    numbers = with_names(chain, numbers)  # long decimals (an import's 15 digits) are written as names
    solving, solving_sample, written = with_written_symbols(chain, sample, numbers)
    solution = derive(solving, variables, sample=solving_sample, numbers=numbers, name=name, path=path)
    solution = as_written(solution, chain, sample, numbers) if written else solution
    return checked_names(solution)


def free_variables(chain: Chain, names, name: str = "", option: str = "--free") -> tuple:
    """The joint variables `names` (symbols or their names) in joint order, each checked; `name`:
    the robot's, for the message."""
    chain = plain(chain)
    variables = {v.name: v for v in chain.joint_variables}
    chosen = []
    for item in names:
        text = getattr(item, "name", str(item))
        if text not in variables:
            raise UserError(f"{option} {text}: {name or 'the robot'} has no joint variable {text}; its joint "
                            f"variables are {', '.join(variables)}")
        chosen.append(variables[text])
    return tuple(v for v in chain.joint_variables if v in chosen)
