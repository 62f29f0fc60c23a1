//! The comment's words: its title block, abstract and sections, composed
//! from the claims' outcomes of the run. Every number comes from a claim's
//! measured text or the report's parameters ([`super::numbers`]); every
//! sentence that states a verdict is chosen by a `match` on that verdict.

use std::fmt::Write as _;

use crate::{ClaimId, ClaimResult, Report, Tally, Verdict};

use super::markup::notation;
use super::numbers::{after, after_from, claim, Number};
use super::{CommentError, FigureRef};

/// A parameter of the report's run, as recorded in its metadata.
fn param<'a>(report: &'a Report, key: &str) -> Result<&'a str, CommentError> {
    report
        .metadata
        .params
        .iter()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
        .ok_or_else(|| CommentError::MissingParam {
            key: key.to_string(),
        })
}

/// A parameter as a [`Number`].
fn param_number(report: &Report, key: &str) -> Result<Number, CommentError> {
    let text = param(report, key)?;
    let value = text
        .parse::<f64>()
        .map_err(|_| CommentError::MissingParam {
            key: key.to_string(),
        })?;
    Ok(Number {
        text: text.to_string(),
        value,
    })
}

/// An integer with thin spaces between groups of three digits.
fn grouped(digits: &str) -> String {
    let n = digits.len();
    digits
        .chars()
        .enumerate()
        .flat_map(|(i, c)| {
            let gap = i > 0 && (n - i).is_multiple_of(3) && n > 4;
            gap.then_some('\u{2009}').into_iter().chain([c])
        })
        .collect()
}

/// What the comment says when a check reached a verdict other than the
/// one its claim expects: the verdict, and no finding.
pub(super) fn not_reached(r: &ClaimResult) -> String {
    format!(
        "In this run the program's check of {} reached the verdict “{}”, not “{}”, so this comment states no finding about it.",
        notation(r.claim.paper_ref),
        verdict_words(r.verdict),
        verdict_words(r.claim.expected),
    )
}

/// A verdict in words, without the erratum's citation.
pub(super) fn verdict_words(v: Verdict) -> &'static str {
    match v {
        Verdict::Holds => "holds",
        Verdict::HoldsAfterCorrection(_) => "holds after a correction",
        Verdict::Refuted => "refuted",
        Verdict::Inconclusive => "inconclusive",
    }
}

/// The document's settings and its title block.
pub(super) fn preamble(out: &mut String, version: &str) {
    let _ = writeln!(
        out,
        r#"#set document(title: [Comment on K. T. McDonald, “Snowball/Log Rolling down a Snowy Slope”], author: ("snowroll {version}",), date: none)
#set page(paper: "a4", margin: (x: 2.3cm, top: 2.4cm, bottom: 2.6cm), numbering: "1")
#set text(font: "New Computer Modern", size: 10.5pt, lang: "en")
#set par(justify: true)
#set heading(numbering: "1.")
#show heading: set block(above: 1.4em, below: 0.8em)
#show figure: set block(breakable: true)
#show figure.caption: set text(size: 9pt)
#show figure.where(kind: table): set figure.caption(position: top)
#set enum(numbering: "[1]")

#align(center)[
  #text(size: 15pt, weight: "bold")[Comment on K. T. McDonald, \
  “Snowball/Log Rolling down a Snowy Slope”]
  #v(0.5em)
  #text(size: 11pt)[The snowroll program, version {version}]
  #v(0.2em)
  #text(size: 9pt)[Written by the program from the run recorded in it; every number below was computed by that run.]
]
#v(0.8em)"#
    );
}

/// The four terminal accelerations a/G of the circular analyses, as
/// measured (eqs. (4), (6), (14), (21) as printed).
fn terminal_fractions(r: &ClaimResult) -> Result<[Number; 4], CommentError> {
    Ok([
        after_from(r, "eq. (4) c_v", "a∞/G")?,
        after_from(r, "eq. (6) c_v", "a∞/G")?,
        after_from(r, "eq. (14) c_v", "a∞/G")?,
        after_from(r, "eq. (21) as printed c_v", "a∞/G")?,
    ])
}

/// The abstract: the tally and the headline results, each sentence chosen
/// by its claim's verdict.
pub(super) fn abstract_(out: &mut String, report: &Report) -> Result<(), CommentError> {
    let tally = Tally::of(&report.claims);
    let total = tally.holds + tally.holds_after_correction + tally.refuted + tally.inconclusive;
    let mut s = format!(
        "We have implemented every analysis of McDonald's note on a log that rolls down a snowy slope and picks up the snow, and checked {total} claims, the note's statements and answers to questions it leaves open, against closed forms and numerical integration: {} hold as printed, {} hold once a misprint is corrected, and {} are refuted",
        tally.holds, tally.holds_after_correction, tally.refuted
    );
    if tally.inconclusive > 0 {
        let _ = write!(s, ", while {} could not be decided", tally.inconclusive);
    }
    s.push_str(". ");
    let differ = claim(report, ClaimId::CircularAnalysesDiffer)?;
    s.push_str(&match differ.verdict {
        Verdict::Holds => {
            let f = terminal_fractions(differ)?;
            format!(
                "The four circular analyses of the note's §2 are four different equations of motion, with terminal accelerations {}, {}, {} and {} in units of $G = g sin alpha$. ",
                f[0].typ(), f[1].typ(), f[2].typ(), f[3].typ()
            )
        }
        _ => String::new(),
    });
    let lagrange = claim(report, ClaimId::LagrangianDiffersFromEnergy)?;
    s.push_str(match lagrange.verdict {
        Verdict::Refuted => "The Lagrangian one, eq. (21), differs from the energy equation only because it leaves out a term; with the term it is the same equation. ",
        _ => "",
    });
    let mean = claim(report, ClaimId::MultiTurnMeanFourNinths)?;
    s.push_str(&match mean.verdict {
        Verdict::Refuted => format!(
            "For the turn-by-turn model the long-run mean acceleration is {} $G$ with the collisions at the ends of the turns, not the $4G\\/9$ of eq. (79). ",
            after(mean, "with collisions")?.with_fraction()
        ),
        Verdict::Holds => "For the turn-by-turn model the long-run mean acceleration of eq. (79), $4G\\/9$, was confirmed by this run. ".to_string(),
        _ => String::new(),
    });
    let hop = claim(report, ClaimId::Fn10HopThreshold)?;
    s.push_str(&match hop.verdict {
        Verdict::Holds => {
            let angle = after(hop, "α* = arctan 2")?;
            format!(
                "Beyond the note, a turn-by-turn log leaves the snow in late turns exactly above the slope {}°, ",
                angle.typ()
            )
        }
        _ => String::new(),
    });
    let ball = claim(report, ClaimId::SnowballTerminalFractions)?;
    s.push_str(&match ball.verdict {
        Verdict::Holds => format!(
            "and an always-round snowball tends to {} $G$ under the torque about its centre.",
            after(ball, "torque-cm")?.with_fraction()
        ),
        _ => {
            "and the snowball's terminal acceleration was not established in this run.".to_string()
        }
    });
    let _ = writeln!(
        out,
        "#block(inset: (x: 1.5em))[#text(size: 9.5pt)[*Abstract.* {s}]]\n"
    );
    Ok(())
}

/// §1: what the note does, what the program did, the scenario of the run.
pub(super) fn introduction(out: &mut String, report: &Report) -> Result<(), CommentError> {
    let alpha = param_number(report, "alpha_deg")?;
    let b = param_number(report, "snow_depth")?;
    let r0 = param_number(report, "r0")?;
    let g = param_number(report, "g")?;
    let rho = param_number(report, "density")?;
    let l = param_number(report, "length")?;
    let v0 = param_number(report, "v0")?;
    let rtol = param_number(report, "rtol")?;
    let turns = param(report, "long_run_turns")?;
    let _ = writeln!(
        out,
        r#"= Introduction

McDonald's note \[1\] follows a log of radius $r$ that rolls without slipping down a slope of angle $alpha$ covered by snow of depth $b$, and takes up all the snow it meets. Its §2 keeps the cross section circular at all times and derives the motion four ways: torque about the centre of mass, torque about the line of contact, energy, and a Lagrangian. Its §3 follows the log turn by turn, with the snow wrapped on as a layer, which is closer to what a log does. The note compares the four circular results, asks whether the motion becomes steady, and estimates the long-run acceleration of the turn-by-turn log.

We implemented each of these analyses, and the turn-by-turn model in its first-order and exact geometries, in a program \[4\], and checked the note's statements against closed forms derived independently and against the numerical integration of each model (relative tolerance {rtol}). The run behind this comment is for $alpha$ = {alpha}°, $b$ = {b} m, $r_0$ = {r0} m, $g$ = {g} m/s², density {rho} kg/m³ (log and snow alike), log length {l} m, starting at {v0} m/s; the long turn-by-turn runs go to {turns} turns. Below, $G = g sin alpha$ and $C = g cos alpha$ are the components of gravity along and normal to the slope, and equation numbers are the note's.
"#,
        rtol = rtol.typ(),
        alpha = alpha.typ(),
        b = b.typ(),
        r0 = r0.typ(),
        g = g.typ(),
        rho = rho.typ(),
        l = l.typ(),
        v0 = v0.typ(),
        turns = grouped(turns),
    );
    Ok(())
}

/// §2: the four circular analyses (Fig. 1), the Lagrangian's missing
/// term, the terminal accelerations.
pub(super) fn circular(
    out: &mut String,
    report: &Report,
    fig: &FigureRef,
) -> Result<(), CommentError> {
    let differ = claim(report, ClaimId::CircularAnalysesDiffer)?;
    let lagrange = claim(report, ClaimId::LagrangianDiffersFromEnergy)?;
    out.push_str("= The four circular analyses\n\n");
    let first = match differ.verdict {
        Verdict::Holds => {
            let f = terminal_fractions(differ)?;
            format!(
                "The note states that the four analyses of §2 lead to different equations of motion, and they do. Integrated side by side (@{}), the torque analysis about the centre, eq. (4), tends to the terminal acceleration {} $G$; the torque about the contact line, eq. (6), to {} $G$; the energy balance, eq. (14), to {} $G$; and the Lagrangian equation (21) as printed to {} $G$. The note itself calls the circular shape unphysical: snow taken up along the line of contact would have to spread over the whole surface at once, and each analysis accounts for that differently. None of the four is the motion of a real log.",
                fig.label,
                f[0].with_fraction(), f[1].with_fraction(), f[2].with_fraction(), f[3].with_fraction()
            )
        }
        Verdict::Refuted => "In this run the four analyses of §2 were found not to differ as the note states: the program's check refutes the note's statement that they lead to different equations of motion.".to_string(),
        _ => not_reached(differ),
    };
    let _ = writeln!(out, "{first}\n");
    let second = match lagrange.verdict {
        Verdict::Refuted => format!(
            "The note presents eq. (21) as a fourth equation that “differs slightly” from the energy equation (14). We find instead that the two are one equation. The kinetic energy depends on the position $x$ through the radius $r(x)$, so $partial cal(L) \\/ partial x$ in eq. (19) must contain $partial T \\/ partial x$, which the note leaves out; and for a Lagrangian without explicit time dependence, Lagrange's equation and the conservation of energy cannot disagree. With the missing term restored, eq. (21) reproduces eq. (14) to {} $G$ over a grid of positions and speeds; as printed, it departs from eq. (14) by up to {} $G$ on the same grid. The statement that (21) is a different equation of motion is refuted: the difference is the omitted term.",
            after(lagrange, "max |a(21 corrected) − a(14)|/G")?.typ(),
            after(lagrange, "max |a₂₁ − a₁₄|/G")?.typ(),
        ),
        Verdict::Holds => "In this run the printed eq. (21) agreed with eq. (14), so the check did not find the term that eq. (19) leaves out; the note's remark that (21) differs slightly from (14) stands for this run.".to_string(),
        Verdict::Inconclusive => "In this run the check could not establish whether the printed eq. (21) differs from eq. (14) only by the term that eq. (19) leaves out: the models did not match the equations the note prints, so the comparison is inconclusive and no finding is stated.".to_string(),
        Verdict::HoldsAfterCorrection(_) => not_reached(lagrange),
    };
    let _ = writeln!(out, "{second}\n");
    let _ = writeln!(out, "{}\n", fig.markup);
    Ok(())
}
