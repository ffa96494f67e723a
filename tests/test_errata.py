"""Errata by kind: a verdict says whether the lecture erred or its transcript was damaged, and
shows the printed element as the transcript prints it next to dhsym's reading."""
import pytest
import sympy

from dhsym.checking import errata
from dhsym.checking.kinds import Kind

t5 = sympy.Symbol("theta_5", real=True)
d6 = sympy.Symbol("d_6", real=True)
derived = sympy.Matrix([[sympy.cos(t5) * d6, 0]])


def test_verbatim_text_is_shown_exactly_as_printed_next_to_the_reading():
    result = errata.compare_printed({(1, 1): "cos(theta_5) - d_6"}, derived, "3T6, line 410",
                                    reasons={(1, 1): errata.ocr("the product c5·d6 read as c5 - d6", lines=(410,))},
                                    verbatim={(1, 1): "c5 − d6"}, joint_variables=[t5])
    table = result.markdown()
    assert "`c5 − d6`" in table  # the transcript's order and minus sign, untouched
    assert "| read as |" in table and "**transcription damage** (l.410)" in table
    assert 'printed "c5 − d6" (read as ' in result.report()


def test_tally_keeps_genuine_errors_apart_from_transcription_damage():
    both = errata.compare_printed(["cos(theta_5)", "1"], derived, "two errata",
                                  reasons={(1, 1): errata.ocr("d6 lost"), (1, 2): errata.slide("1 for 0", lines=(3,))})
    kinds = [e.kind for e in both.errata]
    assert kinds == [Kind.OCR, Kind.SLIDE]
    assert errata.tally([both]) == ("genuine errors of the lecture: 1 (1 slide error), in 1 element; "
                                    "transcription damage: 1, in 1 element")
    assert both.summary().endswith("2 errata (1 transcription damage, 1 slide error)")


def test_a_reason_without_kind_stays_unclassified_and_says_so():
    result = errata.compare_printed({(1, 2): "1"}, derived, "t", reasons={(1, 2): "a sentence"})
    assert result.errata[0].kind is None and result.errata[0].reason == "a sentence"
    assert errata.tally([result]).endswith("unclassified: 1 element")
    assert "erratum at (1,2): printed 1, correct 0 — a sentence" in result.report()


def test_agreeing_elements_carry_no_kind_in_the_tally():
    result = errata.compare_printed({(1, 2): "0"}, derived, "t", reasons={(1, 2): errata.spoken("unused")})
    assert result.ok and errata.tally([result]) == "genuine errors of the lecture: 0; transcription damage: 0"


def test_confidence_is_one_of_three_words():
    assert errata.slide("x", lines=(1, 2), confidence="unsure").where() == "l.1/2, unsure"
    with pytest.raises(ValueError, match="confidence"):
        errata.slide("x", confidence="maybe")


def test_genuine_kinds_are_the_lectures_own():
    assert {k for k in Kind if k.genuine} == {Kind.SLIDE, Kind.SPOKEN, Kind.INCONSISTENCY}


def test_one_cause_shared_by_two_elements_is_one_error_in_two_elements():
    flip = errata.spoken("read the other way round", lines=(331,))
    result = errata.compare_printed(["1", "1"], sympy.Matrix([0, 0]), "t", reasons={(1, 1): flip, (2, 1): flip})
    assert errata.tally([result]).startswith("genuine errors of the lecture: 1 (1 spoken slip), in 2 elements")
