//! The comment's later sections: the turn-by-turn model, what the note
//! leaves open, every claim by verdict, and the references. As in
//! [`super::text`], each verdict sentence is chosen by its verdict and
//! each number is read from the run.

use std::fmt::Write as _;

use crate::{ClaimId, Report, Verdict};

use super::markup::{esc, notation};
use super::numbers::{after, after_from, claim};
use super::text::verdict_words;
use super::{CommentError, FigureRef};

/// The turns a long-run mean is taken over, as the check printed them
/// (`10000–99999`), for the text.
fn turn_range(measured: &str) -> Option<String> {
    let rest = &measured[measured.find("over turns ")? + "over turns ".len()..];
    let range: String = rest
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '–')
        .collect();
    let (from, to) = range.split_once('–')?;
    Some(format!("{from} to {to}"))
}

/// §3: the turn-by-turn model's long run (Fig. 2): the mean acceleration
/// of eq. (79) and the speed of eq. (78).
pub(super) fn turn_model(
    out: &mut String,
    report: &Report,
    fig: &FigureRef,
) -> Result<(), CommentError> {
    let mean = claim(report, ClaimId::MultiTurnMeanFourNinths)?;
    let speed = claim(report, ClaimId::Eq78SpeedInTurnN)?;
    let settle = claim(report, ClaimId::MultiTurnNeverSettles)?;
    out.push_str("= The log turn by turn\n\n");
    out.push_str("In §3.4 the log rolls one full turn on its current cross section, then collides with the slope and starts the next turn on a radius larger by $b$; the note's eq. (73) is the equation of motion within a turn and eq. (89) the collision. ");
    out.push_str(&match settle.verdict {
        Verdict::Holds => format!(
            "As the note expects, the acceleration never becomes steady: within each late turn $a \\/ G$ swings from {} to {}. ",
            after(settle, "ranges over [")?.typ(),
            after_from(settle, "ranges over [", ",")?.typ(),
        ),
        Verdict::Refuted => "Contrary to the note, the acceleration settled in this run: the check found no swing within the late turns. ".to_string(),
        _ => String::new(),
    });
    out.push_str("The note then estimates the long-run motion from energy conservation.\n\n");
    let turns = turn_range(&mean.measured).unwrap_or_else(|| "late turns".to_string());
    let para = match mean.verdict {
        Verdict::Refuted => format!(
            "That estimate does not survive. Averaged over turns {turns} (@{}), the acceleration is {} $G$ within the turns and {} $G$ when the collisions are counted, in the first-order model of eq. (73) and in the exact geometry alike. The note's mean of $4G\\/9$ in eq. (79) is refuted. It rests on the kinetic energy of eq. (78), which is misprinted (Table 1), and on energy conservation across the collisions, which eq. (89) does not give: each collision conserves the angular momentum about the new line of contact and so loses a fraction of order $4b \\/ (3r)$ of the kinetic energy, a loss that never fades relative to the energy gained in a turn.",
            fig.label,
            after(mean, "in turn")?.with_fraction(),
            after(mean, "with collisions")?.with_fraction(),
        ),
        Verdict::Holds => format!(
            "In this run the long-run mean acceleration agreed with the note's $4G\\/9$ of eq. (79) (@{}), so the estimate is confirmed here.",
            fig.label
        ),
        Verdict::Inconclusive => format!(
            "In this run the check could not establish the long-run mean acceleration (@{}): the two turn models did not reach the limits derived for them, so the note's $4G\\/9$ of eq. (79) is neither confirmed nor refuted here.",
            fig.label
        ),
        Verdict::HoldsAfterCorrection(_) => super::text::not_reached(mean),
    };
    let _ = writeln!(out, "{para}\n");
    let para = match speed.verdict {
        Verdict::Refuted => format!(
            "The same holds for the speed. The note's eq. (78) gives $v^2 \\/ (pi g n^2 b sin alpha) = $ {}, and its kinetic energy corrected gives {}; the run gives {} at turn {}, the value that follows once the collisions' loss is included. Eq. (78) is refuted as an estimate of the speed.",
            after(speed, "printed")?.with_fraction(),
            after(speed, "with T = 3mv²/4,")?.with_fraction(),
            after(speed, "v²/(π g n² b sin α)")?.with_fraction(),
            esc(&after(speed, "turns, turn")?.text),
        ),
        Verdict::Holds => "In this run the speed of turn $n$ agreed with the note's eq. (78).".to_string(),
        Verdict::Inconclusive => "In this run the check could not establish the speed of turn $n$ against eq. (78): the two turn models did not reach the limit derived for them.".to_string(),
        Verdict::HoldsAfterCorrection(_) => super::text::not_reached(speed),
    };
    let _ = writeln!(out, "{para}\n\n{}\n", fig.markup);
    Ok(())
}

/// §4: what the note leaves open: the hop slope (fn. 10), the stall slope
/// (fn. 7), the regime map (Fig. 3) and the snowball (Fig. 4).
pub(super) fn open_questions(
    out: &mut String,
    report: &Report,
    regime: &FigureRef,
    ball_fig: &FigureRef,
) -> Result<(), CommentError> {
    let hop = claim(report, ClaimId::Fn10HopThreshold)?;
    let stall = claim(report, ClaimId::Fn7StallThreshold)?;
    let borders = claim(report, ClaimId::RegimeMapBorders)?;
    let ball = claim(report, ClaimId::SnowballTerminalFractions)?;
    let letter = claim(report, ClaimId::TptLetterClosedForm)?;
    out.push_str("= What the note leaves open\n\n");
    let para = match hop.verdict {
        Verdict::Holds => {
            let angle = after(hop, "α* = arctan 2")?;
            let tan = angle.value.to_radians().tan();
            let above = after(hop, "turns: at")?.value - angle.value;
            let below = angle.value - after_from(hop, "(in turn", "; at")?.value;
            format!(
                "Footnote 10 asks whether the log stays on the snow. In late turns the normal force per unit mass is smallest near the end of a turn, where it is $C - G\\/2$, so the turn-by-turn log leaves the snow exactly when $tan alpha$ exceeds {}, that is above $alpha$ = {}°. Started from rest {}° above that slope, the first-order model hops in turn {} and the exact one in turn {} (counting from 0); {}° below it, both complete {} turns without leaving the snow.",
                esc(&format!("{tan:.4}")),
                angle.typ(),
                esc(&format!("{above:.3}")),
                esc(&after(hop, "hops: true (in turn")?.text),
                esc(&after_from(hop, "turns-exact", "hops: true (in turn")?.text),
                esc(&format!("{below:.3}")),
                esc(&after(hop, "it completes")?.text),
            )
        }
        Verdict::Refuted | Verdict::Inconclusive => "Footnote 10 asks whether the log stays on the snow. In this run the turn models did not hop where the closed form says they should, so we state no hop slope.".to_string(),
        Verdict::HoldsAfterCorrection(_) => super::text::not_reached(hop),
    };
    let _ = writeln!(out, "{para}\n");
    let para = match stall.verdict {
        Verdict::Holds => format!(
            "At the other end, footnote 7 notes that a log too light for its snow cannot start. Setting the initial acceleration of eq. (14) to zero gives the stall slope in closed form, {}° for this run's $b$ and $r_0$, and the model started {}° below it does not move while {}° above it rolls on.",
            after(stall, "eq. (14): closed form")?.typ(),
            after(stall, "α* −")?.typ(),
            after(stall, "α* +")?.typ(),
        ),
        _ => format!("At the other end, footnote 7 notes that a log too light for its snow cannot start. {}", super::text::not_reached(stall)),
    };
    let _ = writeln!(out, "{para}\n");
    let para = match borders.verdict {
        Verdict::Holds => format!(
            "@{} maps the outcome over slope and snow depth for the turn-by-turn log started from rest: it stalls in its first turn below the stall slope, hops above the hop slope, and rolls on between. The borders found by bisection on the model lie within {}° (stall) and {}° (hop) of the closed forms.",
            regime.label,
            after(borders, "borders bisected in each row are at most")?.typ(),
            after(borders, "(stall) and")?.typ(),
        ),
        _ => format!("@{} maps the outcome over slope and snow depth. {}", regime.label, super::text::not_reached(borders)),
    };
    let _ = writeln!(out, "{para}\n\n{}\n", regime.markup);
    let para = match ball.verdict {
        Verdict::Holds => format!(
            "The note's title names a snowball, but its analysis is of a log. For a ball that stays round and takes up a swath of snow as wide as itself, the same four circular analyses give the terminal accelerations {} $G$ (torque about the centre), {} $G$ (torque about the contact point), {} $G$ (energy) and {} $G$ (the printed Lagrangian), as @{} shows.{}",
            after(ball, "torque-cm")?.with_fraction(),
            after(ball, "torque-contact")?.with_fraction(),
            after(ball, "; energy")?.with_fraction(),
            after(ball, "lagrangian-printed")?.with_fraction(),
            ball_fig.label,
            match letter.verdict {
                Verdict::Holds => " The first is the limit of the closed form in a letter to The Physics Teacher \\[3\\], which takes the torque about the centre; the program's check confirms that closed form, which starts from the bare-slope value and tends to that limit.",
                _ => "",
            },
        ),
        _ => format!("For a snowball that stays round, {}", super::text::not_reached(ball)),
    };
    let _ = writeln!(out, "{para}\n\n{}\n", ball_fig.markup);
    Ok(())
}

/// §5: every claim by verdict, by where it is in the note.
pub(super) fn all_claims(out: &mut String, report: &Report) {
    out.push_str("= Every claim checked\n\nThe program checks each claim below with its own tolerance, stated with the check; a claim is marked refuted only when the check has also measured what holds instead. By verdict, and by where the claim is in the note (or which part of the note it goes beyond):\n\n");
    for (verdict, title) in [
        (Verdict::Refuted, "Refuted"),
        (Verdict::HoldsAfterCorrection(""), "Hold after a correction"),
        (Verdict::Holds, "Hold as printed"),
        (Verdict::Inconclusive, "Not decided in this run"),
    ] {
        let claims: Vec<&str> = report
            .claims
            .iter()
            .filter(|r| verdict_words(r.verdict) == verdict_words(verdict))
            .map(|r| r.claim.paper_ref)
            .collect();
        if claims.is_empty() {
            continue;
        }
        // Each place once (two statements of one footnote are one place).
        let mut places: Vec<&str> = Vec::with_capacity(claims.len());
        for place in &claims {
            if !places.contains(place) {
                places.push(place);
            }
        }
        let places: Vec<String> = places.into_iter().map(notation).collect();
        let _ = writeln!(
            out,
            "- *{title}* ({} claims): {}.",
            claims.len(),
            places.join("; ")
        );
    }
    out.push('\n');
}

/// The references, in the order of their labels.
pub(super) fn references(out: &mut String, version: &str) {
    let _ = writeln!(
        out,
        r#"#heading(numbering: none)[References]

#set text(size: 9.5pt)
+ K. T. McDonald, “Snowball/Log Rolling down a Snowy Slope”, Joseph Henry Laboratories, Princeton University, in his collection of physics examples, #link("http://kirkmcd.princeton.edu/examples/")[kirkmcd.princeton.edu/examples].
+ S. L. Loney, _An Elementary Treatise on the Dynamics of a Particle and of Rigid Bodies_ (Cambridge University Press, 1909), cited by the note for the circular log's equation of motion.
+ “Analytic solution for a variable-mass snowball”, letter in _The Physics Teacher_ *57*, 436 (2019), on S. Rubin, _The Physics Teacher_ *57* (2019).
+ snowroll {}, the program that ran every check and wrote this comment, with its notes on the turn model and its list of the note's errata (reproduced in Tables 1 and 2)."#,
        esc(version)
    );
}
