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
    page = result.markdown()
    assert "printed: `c5 − d6`" in page  # the transcript's order and minus sign, untouched
    assert "**(1,1)** transcription damage (l.410): the product c5·d6 read as c5 - d6" in page
    assert 'printed "c5 − d6" (read as ' in result.report()


def test_tally_keeps_genuine_errors_apart_from_transcription_damage():
    both = errata.compare_printed(["cos(theta_5)", "1"], derived, "two errata",
                                  reasons={(1, 1): errata.ocr("d6 lost"), (1, 2): errata.slide("1 for 0", lines=(3,))})
    kinds = [e.kind for e in both.errata]
    assert kinds == [Kind.OCR, Kind.SLIDE]
    assert errata.tally([both]) == ("genuine errors of the lecture: 1 (1 slide error), in 1 element; unsure: 0; "
                                    "transcription damage: 1, in 1 element")
    assert both.summary().endswith("2 errata (1 transcription damage, 1 slide error)")


def test_a_reason_without_kind_stays_unclassified_and_says_so():
    result = errata.compare_printed({(1, 2): "1"}, derived, "t", reasons={(1, 2): "a sentence"})
    assert result.errata[0].kind is None and result.errata[0].reason == "a sentence"
    assert errata.tally([result]).endswith("unclassified: 1 element")
    assert "erratum at (1,2): printed 1, correct 0 — a sentence" in result.report()


def test_agreeing_elements_carry_no_kind_in_the_tally():
    result = errata.compare_printed({(1, 2): "0"}, derived, "t", reasons={(1, 2): errata.spoken("unused")})
    assert result.ok and errata.tally([result]) == "genuine errors of the lecture: 0; unsure: 0"


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


def test_unsure_errors_and_corrected_slips_are_counted_apart_from_the_certain_ones():
    t1 = sympy.Symbol("theta_1", real=True)
    wanted = sympy.Matrix([[sympy.cos(t1), 0, 1, 2, 3]])
    doubt = errata.slide("c1 dropped, or the OCR lost it", lines=(412,), confidence="likely")
    result = errata.compare_printed(["1", "1", "0", "5", "9"], wanted, "t",
                                    reasons={(1, 1): doubt, (1, 2): doubt, (1, 3): errata.corrected("1, then 0"),
                                             (1, 4): errata.spoken("5 for 2"),
                                             (1, 5): errata.hypothetical("product of misprints")})
    assert errata.tally([result]) == ("genuine errors of the lecture: 1 (1 spoken slip), in 1 element; "
                                      "unsure: 1 (1 slide error), in 2 elements; corrected at once: 1; "
                                      "hypothetical: 1 element")
    assert not Kind.CORRECTED.genuine
    assert errata.printed_differences(e.cause for e in result.errata) == 4  # the hypothetical one was never printed


def test_a_comparison_that_agrees_is_one_line():
    t1 = sympy.Symbol("theta_1", real=True)
    whole = errata.compare_printed(sympy.eye(4), sympy.eye(4), "0T3")
    assert whole.markdown() == "✅ 0T3: all 16 elements agree"
    some = errata.compare_printed({(1, 1): "cos(theta_1)", (4, 4): "1"}, sympy.diag(sympy.cos(t1), 1, 1, 1), "0T1")
    assert some.markdown() == "✅ 0T1: all 2 printed elements agree"


def test_an_erratum_shows_dhsym_in_the_lectures_term_order_with_the_difference():
    c1, c4, c5, s1, s5, s6, c6 = sympy.symbols("c_1 c_4 c_5 s_1 s_5 s_6 c_6", real=True)
    derived = sympy.Matrix([[-c1 * c4 * c5 * s6 - s1 * s5 * s6 - c1 * c5]])
    printed = "-c_1*c_4*c_5*s_6 - c_1*c_5 - s_1*s_5*c_6"  # the lecture's order; its last term is wrong
    result = errata.compare_printed([printed], derived, "r12", reasons={(1, 1): errata.slide("c6 for s6")})
    page = result.markdown()
    # dhsym in the printed order: the two agreeing terms as printed, the differing one boxed, last
    assert (r"dhsym, in the printed order: $-c_{1} c_{4} c_{5} s_{6}$ $- c_{1} c_{5}$ $- \boxed{s_{1} s_{5} s_{6}}$"
            in page)
    assert r"printed − dhsym: $-s_{1} s_{5}(c_{6} - s_{6})$" in page
    assert "|" not in page  # no table: a long element breaks between its terms instead of shrinking


def test_printed_terms_keep_the_lectures_order_and_grouping():
    from dhsym.checking.regroup import printed_terms, regroup
    assert printed_terms("b - a*(c - d) + e") == ["b", "-a*(c - d)", "e"]
    a, b, c = sympy.symbols("a b c", real=True)
    pieces = regroup(printed_terms("c*(a + b) + 1"), c * (a - b) + 1)
    assert [differs for _, differs in pieces] == [True, False]
    assert pieces[0][0].args and sympy.expand(pieces[0][0]) == sympy.expand(c * (a - b))
