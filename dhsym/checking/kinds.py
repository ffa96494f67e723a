"""What kind of error an erratum is, where the transcript shows it, and how sure the reading is.

A lecture's transcript mixes the lecture's own errors with damage done in transcribing it, so a
verdict records its kind:

>>> cause = spoken("says d3 where the table gives -d3", lines=(203,))
>>> cause.kind.genuine, cause.describe()
(True, 'spoken slip (l.203): says d3 where the table gives -d3')
>>> ocr("theta read as alpha", lines=(262,)).kind.genuine
False

Where the transcript cannot settle the reading, say how sure it is:

>>> slide("c1 missing", lines=(412,), confidence="likely").describe()
'slide error (l.412, likely): c1 missing'
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from enum import Enum


class Kind(Enum):
    """Where an erratum comes from. The first three are errors of the lecture itself."""

    SLIDE = "slide error"  # a printed slide, matrix or note is wrong
    SPOKEN = "spoken slip"  # the speech says something the slides and the algebra do not
    INCONSISTENCY = "inconsistency"  # two places of the lecture disagree and one must be wrong
    OCR = "transcription damage"  # the transcript garbled what the lecture shows (OCR, speech-to-text)
    HYPOTHETICAL = "hypothetical"  # not printed: a product of misprinted factors, worked out here
    CORRECTED = "slip corrected by the lecturer"  # said wrong and put right a moment later

    @property
    def genuine(self) -> bool:
        """Is this an error of the lecture (rather than of its transcript, or a worked consequence)?"""
        return self in (Kind.SLIDE, Kind.SPOKEN, Kind.INCONSISTENCY)


CONFIDENCES = ("certain", "likely", "unsure")


@dataclass(frozen=True)
class Cause:
    """Why a printed element differs: its kind, a sentence, the transcript lines, a confidence."""

    kind: Kind | None  # None: nobody has classified it
    why: str
    lines: tuple[int, ...] = ()
    confidence: str = "certain"

    def __post_init__(self):
        if self.confidence not in CONFIDENCES:
            raise ValueError(f"confidence must be one of {', '.join(CONFIDENCES)}, not {self.confidence!r}")
        object.__setattr__(self, "lines", tuple(self.lines))

    def where(self) -> str:
        """'l.203' or 'l.356/364, likely': the lines and any doubt, for a report."""
        parts = ["l." + "/".join(map(str, self.lines))] if self.lines else []
        if self.confidence != "certain":
            parts.append(self.confidence)
        return ", ".join(parts)

    def describe(self) -> str:
        where = self.where()
        label = self.kind.value if self.kind else UNCLASSIFIED
        return f"{label}{f' ({where})' if where else ''}: {self.why}"


def slide(why: str, lines=(), confidence: str = "certain") -> Cause:
    return Cause(Kind.SLIDE, why, lines, confidence)


def spoken(why: str, lines=(), confidence: str = "certain") -> Cause:
    return Cause(Kind.SPOKEN, why, lines, confidence)


def inconsistency(why: str, lines=(), confidence: str = "certain") -> Cause:
    return Cause(Kind.INCONSISTENCY, why, lines, confidence)


def ocr(why: str, lines=(), confidence: str = "certain") -> Cause:
    return Cause(Kind.OCR, why, lines, confidence)


def hypothetical(why: str, lines=(), confidence: str = "certain") -> Cause:
    return Cause(Kind.HYPOTHETICAL, why, lines, confidence)


def corrected(why: str, lines=(), confidence: str = "certain") -> Cause:
    """A slip the lecturer puts right a moment later: worth a note, not an error of the lecture."""
    return Cause(Kind.CORRECTED, why, lines, confidence)


UNCLASSIFIED = "unclassified"


def tally(causes) -> str:
    """One line that counts the lecture's certain errors apart from the unsure ones, the slips it
    corrects at once, the damage done by transcribing it and what is only worked out here.

    `causes` holds the Cause of each differing element (None where nobody classified it). One
    cause shared by several elements is one error, so both are counted: errors and elements.
    A genuine cause counts as an error of the lecture only when it is certain; a "likely" or
    "unsure" one is listed apart. Parts after the first two are left out when they are zero.

    >>> slip, damage = spoken("pi - phi1"), ocr("l lost")
    >>> doubt = slide("c1 missing?", confidence="unsure")
    >>> causes = [slip, slip, damage, slide("1 for 0"), doubt, doubt, corrected("pi/2, then -pi/2"),
    ...           hypothetical("product")]
    >>> print(tally(causes).replace("; ", ";\\n"))
    genuine errors of the lecture: 2 (1 slide error, 1 spoken slip), in 3 elements;
    unsure: 1 (1 slide error), in 2 elements;
    corrected at once: 1;
    transcription damage: 1, in 1 element;
    hypothetical: 1 element
    >>> print(tally([None]))
    genuine errors of the lecture: 0; unsure: 0; unclassified: 1 element
    """
    causes = list(causes)
    known = [cause for cause in causes if cause is not None and cause.kind is not None]

    def part(label, chosen, detail=True, elements=True):
        errors = set(chosen)
        by_kind = Counter(cause.kind for cause in errors)
        kinds = ", ".join(counted(by_kind[kind], kind.value) for kind in Kind if by_kind[kind])
        text = f"{label}: {len(errors)}" + (f" ({kinds})" if detail and kinds else "")
        return text + (f", in {counted(len(chosen), 'element')}" if elements and chosen else "")

    certain = [c for c in known if c.kind.genuine and c.confidence == "certain"]
    unsure = [c for c in known if c.kind.genuine and c.confidence != "certain"]
    parts = [part("genuine errors of the lecture", certain), part("unsure", unsure)]
    fixed = [c for c in known if c.kind is Kind.CORRECTED]
    if fixed:
        parts.append(part("corrected at once", fixed, detail=False, elements=False))
    damaged = [c for c in known if c.kind is Kind.OCR]
    if damaged:
        parts.append(part("transcription damage", damaged, detail=False))
    worked_out = sum(c.kind is Kind.HYPOTHETICAL for c in known)
    if worked_out:
        parts.append(f"hypothetical: {counted(worked_out, 'element')}")
    unclassified = len(causes) - len(known)
    if unclassified:
        parts.append(f"{UNCLASSIFIED}: {counted(unclassified, 'element')}")
    return "; ".join(parts)


def printed_differences(causes) -> int:
    """How many printed elements differ: every erratum but the hypothetical ones, which are worked
    out here and were never printed.

    >>> printed_differences([spoken("d3 for -d3"), hypothetical("product"), None])
    2
    """
    return sum(not (cause is not None and cause.kind is Kind.HYPOTHETICAL) for cause in causes)


def counted(number: int, noun: str) -> str:
    """'1 spoken slip', '2 inconsistencies': a count and its noun, in the plural where needed."""
    if number == 1 or noun.endswith("damage"):  # damage is uncountable
        return f"{number} {noun}"
    return f"{number} {noun[:-1] + 'ies' if noun.endswith('y') else noun + 's'}"
