"""`dhsym ik --numeric`: every real solution in numbers at a pose, for any six-joint arm (and a
redundant one with --free), where the closed form is refused or not wanted; and what `dhsym ik`
says when it refuses a closed form: the numeric command that answers instead.

    dhsym ik hc10.yaml --numeric                          # at a sample pose
    dhsym ik hc10.yaml --numeric --q q_1=30deg q_5=1.2    # at the pose these joints make
    dhsym ik hc10.yaml --numeric --pose "px=0.5, pz=0.4"  # that pose with px and pz replaced
    dhsym ik hc10.yaml --format python > hc10_ik.py       # no closed form: the module is numeric
"""
from __future__ import annotations

import json

from ..errors import UserError
from .assignments import parse_assignments, target_elements
from .messages import warn


def add_arguments(sub) -> None:
    """The options of `dhsym ik` that the numeric solution reads."""
    sub.add_argument("--numeric", action="store_true",
                     help="every real solution in numbers at a pose (any six-joint arm, no closed form needed), "
                          "with the arm's numbers and the target; --format python writes a numeric module")
    sub.add_argument("--q", dest="joints", metavar="NAME=EXPR", nargs="+", action="extend", default=[],
                     help="with --numeric: joint values that make the target, e.g. --q q_1=30deg q_2=0.5 (the others "
                          "from a sample configuration: 0.3, -0.4, 0.5, ... rad); a --free joint takes its value here")
    sub.add_argument("--pose", metavar="ELEMENTS",
                     help="with --numeric: elements of the target that replace those of the --q pose, e.g. "
                          "--pose \"px=0.5, pz=0.3\"")
    sub.add_argument("--set", dest="constants", metavar="NAME=EXPR", nargs="+", action="extend", default=[],
                     help="with --numeric: a constant's number, e.g. --set a_2=0.4 (default: the file's sample values)")


def wanted(args) -> bool:
    """Whether the command asks for the numeric solution; --q, --pose and --set ask for it only with --numeric."""
    if not args.numeric and (args.joints or args.pose is not None or args.constants):
        option = "--q" if args.joints else "--pose" if args.pose is not None else "--set"
        raise UserError(f"{option} gives numbers to the numeric solution; add --numeric")
    return args.numeric


def run(robot, args, refusal: str = "") -> str:
    """The numeric answer in the format asked for; `refusal` says why the closed form was not used."""
    from ..api.ik import numeric_inverse_kinematics
    from ..inverse.numeric.answer import answer  # numpy, only when numbers are asked for

    if args.format == "latex":
        raise UserError("the numeric solution has no LaTeX form; use --format text, json or python")
    inverse = numeric_inverse_kinematics(robot, args.free, parse_assignments(robot, args.constants, "--set"))
    if args.format == "python":
        return inverse.code(command=command(args, numeric=not refusal))
    found = answer(inverse, parse_assignments(robot, args.joints, "--q"), target_elements(args.pose, "--pose"))
    if args.format == "json":
        from ..printing.ik_numeric import numeric_json

        return json.dumps(numeric_json(found, refusal, robot), indent=2, ensure_ascii=False)
    from ..printing.ik_numeric import numeric_text

    return numeric_text(found, args.width, args.ascii, robot=robot, refusal=refusal)


def refused(robot, args, refusal: UserError) -> str:
    """After the closed form is refused: the numeric module for --format python (a program gets a
    working ik()), else the refusal with the numeric command that answers instead."""
    if args.format == "python":
        try:
            text = run(robot, args, refusal.message)
        except UserError as error:
            said = error.message.removeprefix("the numeric inverse kinematics needs numbers: ")
            raise UserError(f"{refusal.message}; a numeric module{' needs numbers' if said != error.message else ''}: "
                            f"{said}") from None
        warn([f"{refusal.message}: the module finds every solution numerically"])
        return text
    raise UserError(refusal.message + _numeric_hint(robot, args)) from None


def command(args, numeric: bool) -> str:
    """The command line that answers: `dhsym ik ROBOT [--free …] --numeric` (with --format python)."""
    free = f" --free {' '.join(args.free)}" if args.free else ""
    suffix = (" --numeric" if numeric else "") + (" --format python" if args.format == "python" else "")
    return f"dhsym ik {args.robot}{free}{suffix}"


def _numeric_hint(robot, args) -> str:
    """What the refusal adds: the numeric command, where it lists the solutions (six unknown joints
    that move the tool in six directions), ` once …` when the constants lack numbers; else nothing,
    or why no list exists."""
    chain = robot.chain
    if chain.n - len(set(args.free)) != 6:
        return ""
    hint = f"; `{command(args, numeric=True)}` gives every solution in numbers"
    missing = sorted(s.name for s in chain.symbols - set(chain.joint_variables) if s not in robot.sample)
    if missing:
        return hint + f" once its constants have numbers: add --set {' '.join(f'{n}=…' for n in missing[:3])}" + \
            (" …" if len(missing) > 3 else "")
    try:
        from ..inverse.numeric.arm import numeric_arm
        from ..inverse.numeric.solver import free_positions
        from ..inverse.numeric.variants import check_rank
    except ImportError:  # no numpy: the numeric command will say which extra it needs
        return hint
    try:
        arm = numeric_arm(robot.chain, sample=robot.sample, name=robot.name)
        check_rank(arm, free_positions(arm, args.free))
    except UserError as reason:
        return f"; nor a list in numbers: {reason.message}"
    return hint
