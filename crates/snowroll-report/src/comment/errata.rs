//! The errata of the note (the project's `docs/errata.md`, compiled in) as
//! the comment's two tables: where, as printed, as corrected. The columns
//! of how each was found and which check shows it are the report's; the
//! comment cites the program for them.

use std::fmt::Write as _;

use super::markup::notation;

/// The errata, compiled in (the same file the report renders).
const ERRATA_MD: &str = include_str!("../../../../docs/errata.md");

/// One row of an errata table: where, printed, corrected.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Erratum {
    /// Where in the note.
    pub place: String,
    /// As printed.
    pub printed: String,
    /// As corrected.
    pub corrected: String,
}

/// The rows of the errata's tables, one list per table in their order
/// (misprints, errors of derivation).
pub(super) fn errata_tables() -> Vec<Vec<Erratum>> {
    let mut tables: Vec<Vec<Erratum>> = Vec::new();
    let mut in_table = false;
    for line in ERRATA_MD.lines() {
        let line = line.trim();
        if !line.starts_with('|') {
            in_table = false;
            continue;
        }
        let cells: Vec<&str> = line.trim_matches('|').split(" | ").map(str::trim).collect();
        if cells.first() == Some(&"Where") {
            tables.push(Vec::new());
            in_table = true;
            continue;
        }
        let separator = line.chars().all(|c| matches!(c, '|' | '-' | ':' | ' '));
        if separator || !in_table || cells.len() < 3 {
            continue;
        }
        if let Some(table) = tables.last_mut() {
            table.push(Erratum {
                place: cells[0].to_string(),
                printed: cells[1].to_string(),
                corrected: cells[2].to_string(),
            });
        }
    }
    tables
}

/// A corrected form as the comment prints it: a path of the program's
/// notes becomes a citation of the program.
fn corrected_text(cell: &str) -> String {
    notation(cell)
}

/// The two errata tables as typst figures, with their captions.
pub(super) fn errata_section(out: &mut String) {
    let tables = errata_tables();
    let captions = [
        "Misprints of the note: the argument around each is right and only the printed expression is wrong.",
        "Errors of derivation: an argument of the note is incomplete or rests on an assumption that does not hold.",
    ];
    out.push_str("= Errata\n\nTables 1 and 2 list every place where the printed note and our derivation disagree, with the form the program uses. The program's list also records how each was found and which of its checks shows it \\[4\\]; where no computation can tell the printed form from the corrected one (in the first turn $r = r_0$, so some misprints have no numerical consequence), it says so.\n\n");
    for (rows, caption) in tables.iter().zip(captions) {
        let _ = writeln!(
            out,
            "#figure(\n  kind: table,\n  caption: [{caption}],\n  {{\n    set text(size: 8pt)\n    set par(justify: false)\n    table(\n      columns: (auto, 1fr, 1fr),\n      align: left,\n      inset: (x: 3pt, y: 3.5pt),\n      stroke: (x, y) => if y == 0 {{ (bottom: 0.6pt) }} else {{ (bottom: 0.2pt + luma(190)) }},\n      table.header([*Where*], [*Printed*], [*Corrected*]),"
        );
        for e in rows {
            let _ = writeln!(
                out,
                "      [{}], [{}], [{}],",
                notation(&e.place),
                notation(&e.printed),
                corrected_text(&e.corrected)
            );
        }
        out.push_str("    )\n  },\n)\n\n");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_errata_tables_are_read_whole() {
        let tables = errata_tables();
        assert_eq!(tables.len(), 2);
        // Every row of docs/errata.md that is not a header or separator.
        let rows = ERRATA_MD
            .lines()
            .filter(|l| l.starts_with("| ") && !l.starts_with("| Where"))
            .count();
        assert_eq!(tables.iter().map(Vec::len).sum::<usize>(), rows);
        assert!(tables[0].iter().any(|e| e.place == "(70)"));
        assert!(tables[1].iter().any(|e| e.place == "(19)–(21)"));
    }
}
