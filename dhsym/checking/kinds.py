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


UNCLASSIFIED = "unclassified"


def tally(kinds) -> str:
    """One line that keeps the lecture's own errors apart from transcription damage.

    `kinds` holds a Kind (or None, for an erratum nobody has classified) per differing element.

    >>> print(tally([Kind.SLIDE, Kind.OCR, Kind.OCR, Kind.SPOKEN, Kind.HYPOTHETICAL]))
    2 genuine errors of the lecture (1 slide error, 1 spoken slip); 2 elements damaged in transcription; 1 hypothetical
    >>> print(tally([]))
    0 genuine errors of the lecture; 0 elements damaged in transcription
    """
    counts = Counter(kinds)
    genuine = [kind for kind in Kind if kind.genuine and counts[kind]]
    total = sum(counts[kind] for kind in genuine)
    detail = ", ".join(counted(counts[kind], kind.value) for kind in genuine)
    parts = [counted(total, "genuine error") + " of the lecture" + (f" ({detail})" if detail else ""),
             counted(counts[Kind.OCR], "element") + " damaged in transcription"]
    if counts[Kind.HYPOTHETICAL]:
        parts.append(f"{counts[Kind.HYPOTHETICAL]} hypothetical")
    if counts[None]:
        parts.append(f"{counts[None]} {UNCLASSIFIED}")
    return "; ".join(parts)


def counted(number: int, noun: str) -> str:
    """'1 spoken slip', '2 inconsistencies': a count and its noun, in the plural where needed."""
    if number == 1:
        return f"1 {noun}"
    return f"{number} {noun[:-1] + 'ies' if noun.endswith('y') else noun + 's'}"
