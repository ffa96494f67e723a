"""Fuzzing the two doors user text comes through: the expression parser and the robot-file loader.

Every input must end in a result (a real SymPy expression, a Robot whose chain computes) or
in dhsym's own UserError with a place and a one-line message: no other exception, and no
example may run longer than EXAMPLE_SECONDS. The example counts are set here, not by the
profile, so that every run (CI included) tries at least 2,000 inputs.
"""
import os
import re
from decimal import Decimal

import pytest
import sympy
import yaml
from cli_runner import run_dhsym
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from readers import load_robot_text

from dhsym import Chain, DHRow, Robot
from dhsym.checking.verify import numeric_error
from dhsym.core.budget import time_budget
from dhsym.errors import UserError
from dhsym.io.expr import Reading, parse_expression
from dhsym.io.robotfile import ROW_KEYS, TOP_KEYS
from dhsym.printing.notation import written_offsets
from dhsym.printing.printers import ExactPrinter, LatexPrinter, TextPrinter, chain_settings

pytestmark = pytest.mark.slow  # fuzzing: seconds to minutes per test

EXAMPLE_SECONDS = 5.0  # generous: a hang is what we look for, not a slow machine
FUZZ = settings(deadline=None, database=None, suppress_health_check=list(HealthCheck))
EXPRESSIONS, EXPRESSION_GARBAGE, ROBOTS, ROBOT_GARBAGE = 900, 700, 700, 300  # 2,600 inputs per run, and SLIPS


class ExampleTooSlow(BaseException):
    """One fuzz example ran past EXAMPLE_SECONDS."""


# --- expressions ------------------------------------------------------------------------------

NAMES = ["theta_1", "θ2", "l_1", "a_2", "d_3", "x", "pi", "π", "deg", "E", "I", "oo", "inf", "nan",
         "_deg", "__import__", "__class__", "ｓｉｎ", "eval", "open", "lambda_1", "𝜃"]
TOKENS = NAMES + [
    "sqrt", "sin", "cos", "(", ")", "+", "-", "−", "*", "/", "**", "^", "·", "×", "%", "//", "@", "~", ".", ",",
    "0", "1", "2", "9", "16", "17", "90", "0.5", ".5", "1e3", "1e999", "1e-99", "1_0", "0x1f", "07", "1j",
    "deg", "°", " ", "\t", "\n", "\x00", "#", "'", '"', "[", "]", "{", "}", ":", "=", ":=", "<", "and", "not",
    "lambda", "for", "in", "if", "else", "True", "None", "\\", "\u200b", "＿",
]
numbers = st.one_of(
    st.integers(-10**40, 10**40).map(str),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
    st.from_regex(r"[0-9]{1,4}(\.[0-9]{0,3})?(e-?[0-9]{1,3})?", fullmatch=True),
    st.from_regex(r"-?[0-9]{1,3}(\.[0-9])? ?(deg|°)", fullmatch=True),
)
leaves = st.one_of(numbers, st.sampled_from(NAMES))


def _grow(children):
    return st.one_of(
        st.tuples(children, st.sampled_from(["+", "-", "*", "/", "**", "^", " - ", "−"]), children)
        .map(lambda t: f"{t[0]}{t[1]}{t[2]}"),
        st.tuples(children, st.sampled_from(["+", "*", "/", "**"]), children).map(lambda t: f"({t[0]}){t[1]}({t[2]})"),
        st.tuples(st.sampled_from(["sqrt", "sin", "cos", "-", "+", ""]), children).map(lambda t: f"{t[0]}({t[1]})"),
    )


well_formed = st.recursive(leaves, _grow, max_leaves=24)
token_soup = st.lists(st.sampled_from(TOKENS), max_size=40).map("".join)
any_text = st.text(max_size=260)


def assert_expression_outcome(text: str) -> None:
    with time_budget(EXAMPLE_SECONDS, ExampleTooSlow):
        try:
            value = parse_expression(text)
        except UserError as error:
            assert error.where.line == 1 and 1 <= error.where.column <= len(text) + 1, (text, error)
            assert "\n" not in str(error), (text, error)
            return
    assert isinstance(value, sympy.Expr)
    assert all(symbol.is_real for symbol in value.free_symbols)
    assert not value.has(sympy.zoo, sympy.nan, sympy.oo, sympy.I)
    assert value.is_real is not False


@settings(FUZZ, max_examples=EXPRESSIONS)
@given(well_formed)
def test_fuzz_well_formed_expressions(text):
    assert_expression_outcome(text)


@settings(FUZZ, max_examples=EXPRESSION_GARBAGE)
@given(st.one_of(token_soup, any_text))
def test_fuzz_expression_garbage(text):
    assert_expression_outcome(text)


# --- robot files ------------------------------------------------------------------------------

JOINT_NAMES = ["theta_1", "theta_2", "q", "d_1", "d_2"]
good_angle = st.sampled_from(["0", "pi/2", "-pi/2", "pi", "90deg", "-90°", "90", "1.5708", "pi/4", "alpha_1"])
good_length = st.sampled_from(["0", "l_1", "a_2", "0.5", "1/3", "d_1 + 0.1", "sqrt(2)*l_1", "L_2"])
bad_value = st.one_of(
    st.sampled_from(["sin", "1/0", "sqrt(-1)", "x.y", "yes", "", "__import__('os')", "theta_1", "q", "9**9**9"]),
    numbers, well_formed, st.integers(), st.floats(), st.booleans(), st.none(),
    st.lists(st.integers(0, 9), max_size=2),
    st.dictionaries(st.sampled_from(["value", "x"]), st.integers(), max_size=1),
)


@st.composite
def good_row(draw, number):
    if draw(st.booleans()):
        offset = draw(st.sampled_from(["", " - pi/2", " + pi/2", " + 90", " + beta"]))
        return {"joint": "R", "alpha": draw(good_angle), "a": draw(good_length), "d": draw(good_length),
                "theta": f"theta_{number}{offset}", **({"var": f"theta_{number}"} if "beta" in offset else {})}
    return {"joint": "P", "alpha": draw(good_angle), "a": draw(good_length), "d": f"d_{number}",
            "theta": draw(st.sampled_from(["0", "pi/2", "90"]))}


@st.composite
def robot_documents(draw):
    """A valid robot description, then zero to two mistakes of the kinds people make."""
    rows = [draw(good_row(number)) for number in range(1, draw(st.integers(1, 4)) + 1)]
    doc = {"name": draw(st.text(max_size=12)), "convention": draw(st.sampled_from(["standard", "modified"])),
           "joints": rows}
    if draw(st.booleans()):
        doc["tool"] = [{draw(st.sampled_from(["Tx", "Tz", "Rz", "Rx"])): draw(good_length)}]
    for _ in range(draw(st.sampled_from([0, 0, 1, 1, 2]))):
        mistake = draw(st.sampled_from(["field", "drop", "key", "top", "convention", "sample", "rows", "step"]))
        target = draw(st.sampled_from(rows))
        if mistake == "field":
            target[draw(st.sampled_from(ROW_KEYS))] = draw(bad_value)
        elif mistake == "drop":
            target.pop(draw(st.sampled_from(sorted(target))), None)
        elif mistake == "key":
            target[draw(st.sampled_from(["alpah", "Theta", "th", "offset"]))] = draw(bad_value)
        elif mistake == "top":
            doc[draw(st.sampled_from(list(TOP_KEYS) + ["bogus", "joint"]))] = draw(bad_value)
        elif mistake == "convention":
            doc["convention"] = draw(st.sampled_from(["Craig", "craig", None, "MODIFIED", ["standard"]]))
        elif mistake == "sample":
            doc["sample"] = draw(st.dictionaries(st.sampled_from(["l_1", "a_2", "l1", "pi", "theta_1"]),
                                                 st.one_of(good_length, bad_value), max_size=3))
        elif mistake == "rows":
            doc["joints"] = draw(st.sampled_from([[], rows * 7, rows + [rows[0]], "R R R", None]))
        else:
            doc["base"] = [draw(st.dictionaries(st.sampled_from(["Rx", "Tz", "Rw"]), bad_value, max_size=2))]
    return doc


HOSTILE = ["\t", "&a ", "*a", "!!python/object/apply:os.system ['touch CANARY']", "---\n", "[", "]", "{", "}",
           ": ", "- ", "\x00", "\ufeff", "%TAG ! tag:x,\n", "\n", "  ", "#", "'", '"', "<<: *a\n", "? ", "!!str ",
           "\r", "\u2028", "\x85", "...\n"]


@st.composite
def robot_texts(draw):
    """A robot-like document dumped as YAML, sometimes hit with a few hostile edits."""
    text = yaml.safe_dump(draw(robot_documents()), default_flow_style=draw(st.sampled_from([None, True, False])),
                          allow_unicode=True, sort_keys=False)
    for _ in range(draw(st.sampled_from([0, 0, 0, 1, 2, 3]))):
        position = draw(st.integers(0, len(text)))
        text = text[:position] + draw(st.sampled_from(HOSTILE)) + text[position + draw(st.integers(0, 2)):]
    return text


def assert_robot_outcome(text: str) -> None:
    with time_budget(EXAMPLE_SECONDS, ExampleTooSlow):
        try:
            robot = load_robot_text(text, "fuzz.yaml")
        except UserError as error:
            assert error.where.file == "fuzz.yaml" and error.where.line >= 1 and error.where.column >= 1, error
            return
        assert isinstance(robot, Robot) and 1 <= robot.chain.n
        matrix = robot.chain.fk()  # a file that loads must also compute
    assert matrix.shape == (4, 4)
    assert all(symbol.is_real for symbol in matrix.free_symbols)
    assert all(warning.startswith("fuzz.yaml:") for warning in robot.warnings)


@pytest.fixture(scope="module", autouse=True)
def in_a_scratch_folder(tmp_path_factory):
    """Run where a canary would be seen: if any input ran code, CANARY would appear here."""
    folder, before = tmp_path_factory.mktemp("fuzz"), os.getcwd()
    os.chdir(folder)
    yield
    os.chdir(before)
    assert os.listdir(folder) == []


@settings(FUZZ, max_examples=ROBOTS)
@given(robot_texts())
def test_fuzz_robot_files(text):
    assert_robot_outcome(text)


@settings(FUZZ, max_examples=ROBOT_GARBAGE)
@given(st.one_of(any_text, st.lists(st.sampled_from(HOSTILE + ["convention: standard\n", "joints:\n", "a: b\n"]),
                                    max_size=30).map("".join)))
def test_fuzz_robot_file_garbage(text):
    assert_robot_outcome(text)


SLIP_ROBOT = """\
name: arm
convention: standard
joints:
  - {joint: R, alpha: 0, a: l_1, d: 0, theta: theta_1}
  - joint: R
    alpha: -pi/2
    a: 0
    d: d_2
    theta: theta_2
base: [{Tz: l_0}, {Rz: pi/2}]
tool:
  - Tx: l_3
"""
SLIPS = 400
PARSER_JARGON = re.compile(r"<\w[\w ]*>|'\?'|simple key")  # the parser's token names


@st.composite
def slipped_robot_texts(draw):
    """A good robot file with one or two typing slips: a line indented a little more or less, a
    tab, the space after - or : lost, a bracket dropped or swapped."""
    lines = SLIP_ROBOT.splitlines()
    for _ in range(draw(st.integers(1, 2))):
        number = draw(st.integers(0, len(lines) - 1))
        line = lines[number]
        slip = draw(st.sampled_from(["more", "less", "tab", "dash", "colon", "bracket", "swap"]))
        if slip == "more":
            line = " " * draw(st.integers(1, 3)) + line
        elif slip == "less":
            line = line[min(draw(st.integers(1, 3)), len(line) - len(line.lstrip(" "))):]
        elif slip == "tab":
            line = "\t" + line.lstrip(" ")
        elif slip in ("dash", "colon"):
            marks = [i for i in range(len(line) - 1) if line[i:i + 2] == ("- " if slip == "dash" else ": ")]
            if marks:
                i = draw(st.sampled_from(marks))
                line = line[:i + 1] + line[i + 2:]
        else:
            marks = [i for i, ch in enumerate(line) if ch in "{}[]"]
            if marks:
                i = draw(st.sampled_from(marks))
                swapped = {"{": "[", "}": "]", "[": "{", "]": "}"}[line[i]] if slip == "swap" else ""
                line = line[:i] + swapped + line[i + 1:]
        lines[number] = line
    return "\n".join(lines) + "\n"


@settings(FUZZ, max_examples=SLIPS)
@given(slipped_robot_texts())
def test_fuzz_typing_slips_get_plain_messages(text):
    """Every slip ends like any input (a robot or a located error), and a YAML syntax error
    names the slip in plain words, not in the parser's tokens."""
    assert_robot_outcome(text)
    try:
        load_robot_text(text, "fuzz.yaml")
    except UserError as error:
        assert not PARSER_JARGON.search(error.message), (text, error.message)


# --- numbers and angles as written: what is printed reads back to the exact value --------------

ROUND_TRIPS = 150
decimals = st.from_regex(r"-?[0-9]{1,3}\.[0-9]{1,6}", fullmatch=True)
pi_multiples = st.tuples(st.integers(-24, 24), st.sampled_from([1, 2, 3, 4, 6, 12])).map(lambda t: f"{t[0]}*pi/{t[1]}")
constant_angles = st.one_of(decimals, pi_multiples, st.sampled_from(["beta", "-beta", "1/3", "2/7", "0"]))
JOINTS = sympy.symbols("q1:4", real=True)
BETA = sympy.Symbol("beta", real=True)


def _plain(text: str) -> str:
    """Printed text (ASCII or Unicode) in the parser's syntax: − to -, a table's stars dropped,
    brackets made round, `cos q1` called, and juxtaposed factors (`0.5 l1`, `2(…)`) multiplied."""
    text = re.sub(r"\*(?!\*)", "", text.replace("**", "^")).replace("−", "-")
    text = text.translate(str.maketrans("[]{}", "()()"))
    text = re.sub(r"\b(cos|sin|sqrt) ([\w.]+)", r"\1(\2)", text)
    text = re.sub(r"(?<=[\w.)])\s+(?=[\w(])", "*", text)
    return re.sub(r"(?<=[\d)])(?=\()", "*", text)


@settings(FUZZ, max_examples=ROUND_TRIPS)
@given(st.one_of(st.lists(decimals, min_size=1, max_size=3).map(lambda x: (x, "+")),
                 st.lists(decimals, min_size=2, max_size=2).map(lambda x: (x, "*"))))
def test_decimals_print_as_decimals_that_read_back_exactly(case):
    literals, operator = case
    reading = Reading()
    value = parse_expression(f" {operator} ".join(f"({x})" for x in literals), reading=reading)
    for printer in (TextPrinter([], numbers=reading.numbers), TextPrinter([], numbers=reading.numbers, ascii=True),
                    LatexPrinter([], numbers=reading.numbers), ExactPrinter([], numbers=reading.numbers)):
        text = printer.doprint(value)
        assert "/" not in text and "frac" not in text, (literals, text)  # 0.81725, never 3269/4000
        assert parse_expression(_plain(text)) == value, (literals, text)
        assert sympy.sympify(_plain(text), rational=True) == value, (literals, text)
    if len(literals) == 1:  # a single literal prints as it was written, less its trailing zeros
        shown = TextPrinter([], numbers=reading.numbers, ascii=True).doprint(value)
        assert shown == ("0" if value == 0 else format(Decimal(literals[0]).normalize(), "f")), (literals, shown)


@settings(FUZZ, max_examples=ROUND_TRIPS)
@given(decimals, st.sampled_from(["l_1", "a_2", "d_3"]))
def test_a_decimal_stays_a_factor(literal, name):
    reading = Reading()
    value = parse_expression(f"{literal}*{name}", reading=reading)
    text = TextPrinter([], numbers=reading.numbers).doprint(value)
    assert value == 0 or "/" not in text, (literal, text)  # 0.425 l1, not (17 l1)/40
    exact = ExactPrinter([], numbers=reading.numbers).doprint(value)
    assert parse_expression(exact) == value
    assert sympy.sympify(exact, locals={name: sympy.Symbol(name, real=True)}, rational=True) == value


@settings(FUZZ, max_examples=ROUND_TRIPS)
@given(st.lists(constant_angles, min_size=1, max_size=3), st.sampled_from([sympy.cos, sympy.sin]),
       st.lists(st.sampled_from([1, -1]), min_size=3, max_size=3))
def test_offsets_print_as_written_and_mean_the_same(offsets, function, signs):
    """cos/sin of a signed sum of joint angles with offsets: SymPy may rewrite the angle (cos(x − π/4)
    becomes sin(x + π/4)); the printers give it back as written, and the text means the same value."""
    reading = Reading()
    written = [parse_expression(o, reading=reading) for o in offsets]
    chain = Robot(Chain([DHRow.revolute(q + o, variable=q) for q, o in zip(JOINTS, written)], "standard"),
                  numbers=reading.numbers)
    settings_ = chain_settings(chain)
    value = function(sympy.Add(*(sign * (q + o) for sign, q, o in zip(signs, JOINTS, written))))
    printer = TextPrinter(settings_, ascii=True)
    shown = printer.doprint(value)
    # each abbreviation's meaning, read back, is the angle the table wrote (offsets that are
    # multiples of π/2 folded into the notation); substituted into the text it gives the value
    text = shown
    for abbreviation in sorted(printer.used, key=lambda a: -len(a.label("ascii"))):
        meaning = printer.notation.meaning(abbreviation, "ascii")
        read = parse_expression(_plain(meaning))
        expected = (sympy.cos if abbreviation.function == "c" else sympy.sin)(printer.notation.angle(abbreviation))
        assert read == expected, (offsets, meaning)
        text = re.sub(rf"(?<![\w(]){re.escape(abbreviation.label('ascii'))}(?![\w])", f"({meaning})", text)
    assert _numerically_equal(parse_expression(_plain(text)), value), (offsets, shown, text)
    exact = ExactPrinter(settings_).doprint(value)
    names = {s.name: s for s in (*JOINTS, BETA)}
    assert _numerically_equal(sympy.sympify(exact, locals=names, rational=True), value), (offsets, exact)
    kept = written_offsets(chain.rows)  # an offset that is no multiple of π/2 shows, as written
    for abbreviation in printer.used:
        offset = printer.notation.offset(abbreviation)
        assert offset == sympy.Add(*(sign * kept.get(JOINTS[int(label) - 1], 0) for label, sign in
                                     abbreviation.indices)), (offsets, abbreviation)


@st.composite
def robots_as_written(draw):
    rows = []
    for k in range(1, draw(st.integers(1, 3)) + 1):
        offset = draw(st.sampled_from(["", " - pi/4", " + pi/6", " - pi/2", " + 0.1", " - 1/3"]))
        rows.append(f"  - {{joint: R, alpha: {draw(constant_angles)}, a: {draw(decimals)}, "
                    f"d: {draw(st.one_of(decimals, st.sampled_from(['l1', '0', '1/2'])))}, theta: q{k}{offset}}}")
    return "convention: standard\njoints:\n" + "\n".join(rows) + "\n"


@settings(FUZZ, max_examples=60)
@given(robots_as_written())
def test_robot_files_with_decimals_and_offsets_read_back_from_every_output(text):
    """The table (text and JSON) reads back to the file's exact values; the JSON matrix to the product."""
    import json

    robot = load_robot_text(text, "arm.yaml")
    chain = robot.chain
    names = {s.name: s for s in chain.symbols}
    commands = (["table", "-", "--ascii", "--width", "200"], ["table", "-", "--format", "json"],
                ["fk", "-", "--format", "json"])
    table, rows, fk = (run_dhsym(*argv, stdin=text).ok() for argv in commands)
    cells = [line.split(" | ")[1:] for line in table.splitlines()[4:]]
    assert len(cells) == chain.n
    for row, line in zip(chain.rows, cells):
        for field, cell in zip(("theta", "d", "a", "alpha"), line):
            assert parse_expression(_plain(cell.strip())) == getattr(row, field), (text, cell)
    for row, data in zip(chain.rows, json.loads(rows)["rows"]):
        for field in ("theta", "d", "a", "alpha"):
            assert sympy.sympify(data[field], locals=names, rational=True) == getattr(row, field), (text, data)
    matrix = sympy.Matrix([[sympy.sympify(element, locals=names, rational=True) for element in row]
                           for row in json.loads(fk)["matrix"]])
    assert numeric_error(matrix, chain.fk(raw=True)) < 1e-9, text


def _numerically_equal(a: sympy.Expr, b: sympy.Expr) -> bool:
    symbols = sorted(a.free_symbols | b.free_symbols, key=str)
    for seed in range(3):
        point = {s: 0.37 + 0.61 * k - 0.9 * seed for k, s in enumerate(symbols)}
        if abs(complex(a.evalf(subs=point)) - complex(b.evalf(subs=point))) > 1e-9:
            return False
    return True
