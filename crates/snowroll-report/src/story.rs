//! The report's first screen: an abstract of the five headline results,
//! each linked to its claim, and the scenario they were computed for.
//!
//! The abstract is composed, not written: each of its result sentences is
//! the headline of its claim ([`crate::headline`]), which states the
//! finding with the numbers the check measured only when the check reached
//! the verdict the claims table expects, and otherwise says which verdict
//! it reached. A wrong model therefore changes the abstract (the tests in
//! `tests/claims.rs` feed one to each of the five).

use std::fmt::Write as _;

use crate::claim::ClaimResult;
use crate::findings::headline;
use crate::markup::{esc, prose};
use crate::ClaimId;

/// The claims the abstract states, in its order: the four circular
/// analyses disagree; the printed eq. (21) is wrong; the turn model's mean
/// is G/4, not 4G/9; a turn-model log hops when tan α > 2; the snowball
/// tends to G/6 for the swath 2r.
pub const ABSTRACT_CLAIMS: [ClaimId; 5] = [
    ClaimId::CircularAnalysesDiffer,
    ClaimId::LagrangianDiffersFromEnergy,
    ClaimId::MultiTurnMeanFourNinths,
    ClaimId::Fn10HopThreshold,
    ClaimId::SnowballTerminalFractions,
];

/// Most words the abstract may have (its opening and the five results;
/// the scenario under it is not counted).
pub const ABSTRACT_MAX_WORDS: usize = 120;

/// The abstract's sentences about results: for each claim of
/// [`ABSTRACT_CLAIMS`] among `claims`, its id and its headline, in order.
pub fn abstract_sentences(claims: &[ClaimResult]) -> Vec<(ClaimId, String)> {
    ABSTRACT_CLAIMS
        .iter()
        .filter_map(|&id| claims.iter().find(|r| r.claim.id == id))
        .map(|r| (r.claim.id, headline(r)))
        .collect()
}

/// The abstract as plain text: its opening, then the results.
pub fn abstract_text(claims: &[ClaimResult]) -> String {
    let mut text = OPENING.to_string();
    for (_, s) in abstract_sentences(claims) {
        let _ = write!(text, " {s}.");
    }
    text
}

/// The abstract's opening word, set in bold.
const OPENING: &str = "Abstract.";

/// One parameter of the scenario as the first screen states it: the
/// symbol, the value and the unit, from its key in the report's parameters.
fn scenario_item(key: &str, value: &str) -> String {
    let (symbol, unit) = match key {
        "alpha_deg" => return format!("α = {value}°"),
        "snow_depth" => ("b", " m"),
        "r0" => ("r0", " m"),
        "g" => ("g", " m/s²"),
        "density" => ("ρ", " kg/m³"),
        "length" => ("l", " m"),
        "v0" => ("v0", " m/s"),
        "rtol" => return format!("tolerances {value} (relative)"),
        "atol" => return format!("{value} (absolute)"),
        "long_run_turns" => return format!("{value} turns in the long runs"),
        other => (other, ""),
    };
    format!("{symbol} = {value}{unit}")
}

/// The scenario sentence: every parameter of the report, by symbol.
pub fn scenario_text(params: &[(String, String)]) -> String {
    let items: Vec<String> = params.iter().map(|(k, v)| scenario_item(k, v)).collect();
    format!("Computed for {}.", items.join(", "))
}

/// The first screen's section: the abstract, each result linked to its
/// row of the findings, then the scenario.
pub(crate) fn abstract_section(
    h: &mut String,
    claims: &[ClaimResult],
    params: &[(String, String)],
) {
    h.push_str("<section id=\"abstract\">\n<p class=\"abstract\">");
    let _ = write!(h, "<strong>{}</strong>", esc(OPENING));
    for (id, sentence) in abstract_sentences(claims) {
        let _ = write!(
            h,
            " <a href=\"#claim-{id}\" data-abstract=\"{id}\">{}</a>.",
            prose(&sentence),
            id = esc(id.as_str())
        );
    }
    h.push_str("</p>\n");
    let _ = writeln!(
        h,
        "<p id=\"scenario\" class=\"scenario\">{} <a href=\"#parameters\">All parameters</a>.</p>\n</section>",
        prose(&scenario_text(params))
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scenario_names_each_parameter_by_its_symbol_and_unit() {
        let params: Vec<(String, String)> =
            [("alpha_deg", "70"), ("snow_depth", "0.01"), ("r0", "0.1")]
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect();
        assert_eq!(
            scenario_text(&params),
            "Computed for α = 70°, b = 0.01 m, r0 = 0.1 m."
        );
    }
}
