"""The shared parts of the reproduction article: its abstract, introduction, discussion and
references, every count in them computed from the papers' results (their
:class:`~pipeline.report.paper_parts.PaperParts`); nothing here names a paper.
"""

from __future__ import annotations

from collections.abc import Sequence

from pipeline.report.causes import plural
from pipeline.report.model import Block, Bullets, Paragraph, Section, Table
from pipeline.report.paper_parts import PaperParts
from pipeline.report.paper_section import MAIN_TITLES, discussion_section
from pipeline.report.vocabulary import (
    CAUSE_SHORT_WORDS,
    CAUSE_WORDS,
    DIFFERS_WORDS,
    MARK_WORDS,
    NEUTRAL_DIFFERS,
)

__all__ = ["abstract", "discussion", "introduction", "references"]


def _marks(papers: Sequence[PaperParts]) -> dict[str, int]:
    out = {m: 0 for m in MARK_WORDS}
    for p in papers:
        for line in p.score.summary.main_claims if p.score.summary else ():
            out[line.mark] = out.get(line.mark, 0) + 1
    return out


def abstract(papers: Sequence[PaperParts]) -> str:
    """One paragraph: what was reproduced, main claims first, then the counts."""
    marks = _marks(papers)
    n_main = sum(marks.values())
    n_eq = sum(len(p.equations) for p in papers)
    n_err = sum(p.score.differs.get("paper_error", 0) for p in papers)
    n_classified = sum(n for p in papers for k, n in p.score.differs.items() if k)
    n_differs = sum(p.score.audit.get("differs", 0) for p in papers)
    numbers = [n for p in papers for n in [p.score.numbers]]
    n_num = sum(sum(n.values()) for n in numbers)
    n_good = sum(n.get("reproduced", 0) + n.get("consistent", 0) for n in numbers)
    n_claim = sum(sum(p.score.claims.values()) for p in papers)
    n_upheld = sum(p.score.claims.get("upheld", 0) for p in papers)
    n_checks = sum(sum(p.score.self_checks.values()) for p in papers)
    n_checked = sum(p.score.self_checks.get("reproduced", 0) for p in papers)
    checks = (
        f" Counted apart from these, {n_checked} of {plural(n_checks, 'self-check')} passed "
        "(rows that check our code and derivation, not a number a paper measured)."
        if n_checks
        else ""
    )
    return (
        f"We reproduced {plural(len(papers), 'inertial-navigation paper')} from their equations "
        "up: every printed equation was transcribed and compared with a SymPy derivation from "
        "first principles, the numeric code was generated from the derived expressions, and "
        "every published number and claim was recomputed and judged by one verdict engine. "
        f"Of the papers' {plural(n_main, 'main claim')}, {marks['Re']} "
        f"{'is' if marks['Re'] == 1 else 'are'} reproduced ([Re]), {marks['not_Re']} "
        f"{'is' if marks['not_Re'] == 1 else 'are'} not ([¬Re]) and {marks['not_checkable']} "
        f"cannot be checked from what the papers publish. In all, {n_differs} of {n_eq} printed "
        f"equations differ from the derivation ("
        + (f"{n_err} of them errors of the paper" if n_classified else "not yet classified by kind")
        + "), "
        f"{n_good} of {n_num} published numbers are reproduced and {n_upheld} of "
        f"{plural(n_claim, 'claim verdict')} are upheld." + checks
    )


def introduction(papers: Sequence[PaperParts], appendix_names: Sequence[str]) -> Section:
    """What was done, how a verdict is reached, and how each paper's section reads."""
    words = [
        ["match", "equation", "the printed form equals the derivation (residual 0)"],
        ["differs", "equation", "the printed form differs; the derived form is used"],
        ["reproduced", "exact or approximate number", "equal to the printed digits (rounded or truncated), or within the tolerance its printed form gives"],
        ["consistent", "statistical number", "inside the Monte Carlo distribution (0.5-99.5 percentile rank)"],
        ["not_reproduced", "number", "outside the printed precision, tolerance or distribution"],
        ["upheld", "claim", "the claim's test holds on our results"],
        ["not_upheld", "claim", "the test fails; the evidence is in the claims table"],
        ["not_checkable", "equation, number, claim", "cannot be decided from what the paper publishes"],
    ]  # fmt: skip
    blocks: list[Block] = [
        Paragraph(
            f"This article reproduces {plural(len(papers), 'paper')} on inertial navigation. "
            "Each paper's equations were transcribed as printed and compared with a SymPy "
            "derivation from first principles; the simulations run code generated from the "
            "derived expressions; and the published numbers and claims were recomputed and "
            "compared with what the paper prints by a rule that fits their kind. Every count, "
            "number and verdict here is read from the result files the workflow wrote "
            "(equation_audit.csv, verdicts.csv and each paper's results); none is typed by hand."
        ),
        Paragraph(
            "Following ReScience C, each paper is judged by its main claims: [Re] when every "
            "verdict that bears on a claim holds, [¬Re] when any fails, not checkable otherwise. "
            "A number is exact (equal to the printed digits), approximate (printed as 'about X': "
            "within one unit of its last significant digit or 10 % of X, the larger; read off a "
            "plot: within half a tick of the figure's axis) or statistical (where the published "
            "value falls in our Monte Carlo distribution); a claim is a sentence of the paper "
            "judged by a named test. Rows that check our own code and derivation rather than a "
            "number a paper measured (an ideal sensor inverting its own formula) are self-checks, "
            "counted apart. A printed equation that differs is an "
            + ", an ".join(w for k, w in DIFFERS_WORDS.items() if k not in NEUTRAL_DIFFERS)
            + ", or, where the seed text cannot tell a slip of the OCR from one of the paper, "
            + " or ".join(f"'{DIFFERS_WORDS[k]}'" for k in sorted(NEUTRAL_DIFFERS))
            + " (grey); only an error of the paper is shown in red. A failing verdict names its root "
            "cause where one is identified, by a short title; its kind is one of: "
            + "; ".join(
                w if CAUSE_SHORT_WORDS.get(k, w) == w else f"{CAUSE_SHORT_WORDS[k]}, that is {w}"
                for k, w in CAUSE_WORDS.items()
            )
            + ". The front page counts the rows each cause explains; each paper's summary gives "
            "its causes in full."
        ),
        Paragraph(
            "Each paper's section has the same parts in the same order: "
            + ", ".join(MAIN_TITLES)
            + ". The discussion follows the papers, then the references; the appendices hold "
            + ", ".join(appendix_names)
            + ". Each paper also has a page of its own and an executed notebook beside this "
            "report, in the same template."
        ),
        Table(
            columns=["word", "applies to", "meaning"],
            rows=[[w, a, m] for w, a, m in words],
            caption="Verdict and status words",
            row_status=[w for w, _, _ in words],
        ),
    ]
    return Section("introduction", "Introduction", blocks)


def discussion(papers: Sequence[PaperParts]) -> Section:
    """The discussion: what was easy, what was hard and what each paper left open."""
    failing = sum(
        p.score.numbers.get("not_reproduced", 0) + p.score.claims.get("not_upheld", 0)
        for p in papers
    )
    identified = sum(
        1
        for p in papers
        if p.score.summary is not None and not p.score.summary.sentences[2].startswith("Cause: not")
    )
    blocks: list[Block] = [
        Paragraph(
            "What was easy, what was hard and what each paper left open, paper by paper; the "
            f"front of the report groups the {plural(failing, 'failing verdict')} by root cause "
            f"({identified} of {plural(len(papers), 'paper')} with a cause identified)."
        )
    ]
    subs = [discussion_section(p, f"discussion-{p.slug}") for p in papers]
    return Section("discussion", "Discussion", blocks, subs)


def references(papers: Sequence[PaperParts], generated_from: str) -> Section:
    """The reproduced papers' citations and this reproduction's version."""
    items = [f"[{k}] {p.title}. {p.citation}." for k, p in enumerate(papers, 1)]
    items.append(f"[{len(papers) + 1}] This reproduction, at git describe {generated_from}.")
    return Section("references", "References", [Bullets([i.replace("..", ".") for i in items])])
