//! The report's opening: the problem in words, a drawing of its geometry,
//! the table of models (each with its equation of motion written out from
//! the same coefficients the program integrates) and the symbols.
//!
//! The drawing is a schematic, not a chart: a few SVG primitives placed by
//! hand. `plotters` draws data on axes and has no notion of a labelled
//! diagram, so the SVG is written here directly.

use std::f64::consts::PI;
use std::fmt::Write as _;

use super::markup::{esc, prose};
use super::ClaimId;
use snowroll::models::{as_fraction, Coefficients, ModelKind};

/// The note, cited in full.
pub(super) const NOTE_CITATION: &str = "K. T. McDonald, \u{201c}Snowball/Log Rolling down a Snowy Slope\u{201d}, \
     Joseph Henry Laboratories, Princeton University (physics examples, kirkmcd.princeton.edu/examples)";

/// `p X/(q Y)` with the ones left out: `7bv²/(6πr²)`, `bv²/(2πr²)`, `bv²/(πr²)`.
fn term(c: f64, num: &str, den: &str) -> String {
    match as_fraction(c) {
        Some((1, 1)) => format!("{num}/({den})"),
        Some((p, 1)) => format!("{p}{num}/({den})"),
        Some((1, q)) => format!("{num}/({q}{den})"),
        Some((p, q)) => format!("{p}{num}/({q}{den})"),
        None => format!("{c}·{num}/({den})"),
    }
}

/// The equation of motion of a circular model, written out from its
/// coefficients (the common form of `models::circular`).
fn circular_equation(c: &Coefficients) -> String {
    if !c.accretes {
        return "a = 2G/3".to_string();
    }
    let lhs = if c.inertia_b2 == 0.0 {
        "a".to_string()
    } else {
        format!("a (1 + {})", term(c.inertia_b2, "b²", "6π²r²"))
    };
    let mut rhs = format!("2G/3 − {}", term(c.drag, "bv²", "πr²"));
    let lift: Vec<String> = [
        (c.lift, term(c.lift, "b", "πr")),
        (c.lift_b2, term(c.lift_b2, "b²", "3πr²")),
    ]
    .into_iter()
    .filter(|(k, _)| *k != 0.0)
    .map(|(_, t)| t)
    .collect();
    match lift.len() {
        0 => {}
        1 => {
            let _ = write!(rhs, " − C {}", lift[0]);
        }
        _ => {
            let _ = write!(rhs, " − C [{}]", lift.join(" + "));
        }
    }
    format!("{lhs} = {rhs}")
}

/// The equation of motion of any model, in words and symbols.
pub(super) fn equation_of_motion(kind: ModelKind) -> String {
    match (kind, kind.derivation()) {
        (_, Some(d)) => {
            let eq = circular_equation(&d.coefficients());
            if kind.is_circular() && d.coefficients().accretes {
                format!("{eq}, with πr² = πr0² + bx (eq. (8))")
            } else {
                eq
            }
        }
        (ModelKind::Loney, None) => {
            "v² = 2Gs/(5b) + K s⁻⁷ᐟ³, s = πr₀² + bx, K from v(0) (the closed form of eq. (4))"
                .to_string()
        }
        (ModelKind::Turns, None) => {
            "within turn k: eq. (73) for θ(t) with the radius and mass of eq. (76), \
             rₖ = r0 + kb; at θ = 2π the collision of eq. (89)"
                .to_string()
        }
        _ => "within a turn: energy conservation of the disk plus the growing layer, exact mass \
              properties (eq. (88), with (87) corrected); at θ = 2π the collision of eq. (89)"
            .to_string(),
    }
}

/// The late-time acceleration over G, as a fraction.
pub(super) fn terminal_text(kind: ModelKind) -> String {
    match kind.terminal_fraction() {
        Some(f) => match as_fraction(f) {
            Some((p, q)) => format!("{p}/{q}"),
            None => format!("{f:.4}"),
        },
        None => format!(
            "none: a/G swings within every turn; its long-run mean tends to 1/3 within turns, \
             1/4 with the collisions (measured, claim {})",
            ClaimId::MultiTurnMeanFourNinths
        ),
    }
}

/// The symbols every claim uses.
pub(super) const SYMBOLS: [(&str, &str, &str); 17] = [
    ("α", "slope angle", "degrees on the command line"),
    ("g", "gravitational acceleration", "m/s²"),
    (
        "G = g sin α",
        "component of gravity along the slope; accelerations are quoted as a/G",
        "m/s²",
    ),
    (
        "C = g cos α",
        "component of gravity normal to the slope",
        "m/s²",
    ),
    ("b", "depth of the snow layer, normal to the slope", "m"),
    ("r0, r", "initial and current radius of the log", "m"),
    (
        "s = πr²",
        "cross-section; πr² = πr0² + bx while the log is circular (eq. (8))",
        "m²",
    ),
    (
        "ρ, l",
        "density of log and snow, length of the log",
        "kg/m³, m",
    ),
    ("m", "mass of log plus the snow it has picked up", "kg"),
    ("x", "distance rolled down the slope", "m"),
    ("v, a", "speed and acceleration down the slope", "m/s, m/s²"),
    (
        "a∞",
        "late-time (terminal) acceleration of a circular model",
        "m/s²",
    ),
    ("k", "turn number, counted from 0 (§3.4)", "1"),
    (
        "rₖ, mₖ",
        "radius and mass at the start of turn k: rₖ = r0 + kb (eq. (74))",
        "m, kg",
    ),
    (
        "θ, ω",
        "angle rolled within the current turn, and its rate",
        "rad, rad/s",
    ),
    ("K", "number of turns a long-run mean is taken over", "1"),
    (
        "L_C",
        "angular momentum about the contact line (conserved by the collision, eq. (89))",
        "kg m²/s",
    ),
];

/// The name of the geometry drawing's file in `figures/` (`report.md` links it).
pub(super) const GEOMETRY_FIGURE: &str = "geometry";

/// The geometry drawing's caption, shared by `report.html` and `report.md`.
pub(super) const GEOMETRY_CAPTION: &str = "The slope makes the angle α with the horizontal; \
         gravity has the component G = g sin α along it and C = g cos α into it. Snow of depth b lies ahead of \
         the log (downhill); behind it the ground is bare. The log of radius r touches the snow surface along \
         the contact line; the layer it has picked up in the current turn (angle θ) is wrapped on it. After a \
         full turn (θ = 2π) the layer closes into a ring: the radius becomes r + b and the centre rises by b \
         (dashed) — the collision of eq. (89).";

/// The opening section of `report.html`.
pub(super) fn intro_section(h: &mut String) {
    h.push_str("<section id=\"problem\">\n<h2>The problem</h2>\n");
    let _ = writeln!(
        h,
        "<p>A log (a long cylinder) rolls without slipping down a slope of angle α covered by a layer of \
         snow of depth b, and picks up all the snow it rolls over, so its radius and mass grow as it goes. \
         How does it accelerate? The note — {} — answers with several analyses that disagree: while the log \
         is taken as circular at all times (§2), torque about the centre, torque about the contact line, \
         energy conservation and a Lagrangian give different equations of motion; followed turn by turn (§3), \
         the log wraps one layer per turn and collides with the snow at each full turn. This report runs \
         every one of them and judges each claim of the note by a computation that could have come out \
         otherwise. The project's corrections of the note are listed under <a href=\"#errata\">Errata</a>.</p>",
        esc(NOTE_CITATION)
    );
    h.push_str("<figure id=\"geometry\" class=\"figure\">\n<div class=\"svg-wrap\">");
    h.push_str(&geometry_svg());
    let _ = writeln!(
        h,
        "</div>\n<figcaption><strong>The geometry.</strong> {GEOMETRY_CAPTION}</figcaption>\n</figure>"
    );
    h.push_str(
        "<details class=\"fold\" id=\"models\"><summary><h3>The models</h3></summary>\n<p>Each model is one equation of motion; the circular ones share \
         one form and differ in coefficients, written out below from the coefficients the program \
         integrates.</p>\n<div class=\"table-wrap\"><table class=\"parting models\">\n<thead><tr>\
         <th scope=\"col\">Model (alias)</th><th scope=\"col\">Note</th>\
         <th scope=\"col\">Equation of motion</th><th scope=\"col\">Assumptions</th>\
         <th scope=\"col\">a∞/G</th></tr></thead>\n<tbody>\n",
    );
    for kind in ModelKind::ALL {
        let _ = writeln!(
            h,
            "<tr id=\"model-{id}\"><td><code>{id}</code> (<code>{alias}</code>)</td><td>{note}</td>\
             <td>{eq}</td><td>{desc}; {validity}</td><td>{terminal}</td></tr>",
            id = esc(kind.id()),
            alias = esc(kind.alias()),
            note = prose(kind.equation()),
            eq = prose(&equation_of_motion(kind)),
            desc = prose(kind.description()),
            validity = prose(kind.validity().statement),
            terminal = prose(&terminal_text(kind)),
        );
    }
    h.push_str("</tbody></table></div>\n</details>\n");
    h.push_str(
        "<details class=\"fold\" id=\"symbols\"><summary><h3>Symbols</h3></summary>\n<div class=\"table-wrap\"><table class=\"parting symbols\">\n\
         <thead><tr><th scope=\"col\">Symbol</th><th scope=\"col\">Meaning</th><th scope=\"col\">Unit</th>\
         </tr></thead>\n<tbody>\n",
    );
    for (sym, meaning, unit) in SYMBOLS {
        let _ = writeln!(
            h,
            "<tr><td>{}</td><td>{}</td><td>{}</td></tr>",
            prose(sym),
            prose(meaning),
            esc(unit)
        );
    }
    h.push_str("</tbody></table></div>\n</details>\n</section>\n");
}

/// A point of the slope's frame (u down the slope, w normal to it, in px)
/// on the page.
fn page(u: f64, w: f64, alpha: f64, origin: (f64, f64)) -> (f64, f64) {
    let (s, c) = alpha.sin_cos();
    (origin.0 + u * c + w * s, origin.1 + u * s - w * c)
}

fn polygon(points: &[(f64, f64)], style: &str) -> String {
    let pts: Vec<String> = points
        .iter()
        .map(|(x, y)| format!("{x:.1},{y:.1}"))
        .collect();
    format!("<polygon points=\"{}\" {style}/>", pts.join(" "))
}

/// The schematic: slope, snow layer, log with its partial layer, contact
/// line, the radius after a full turn, and the angle α. Drawn at α = 20°
/// with b/r exaggerated, so that the layer can be seen.
pub(super) fn geometry_svg() -> String {
    let alpha = 20f64.to_radians();
    let (r, b) = (70.0, 16.0);
    let origin = (330.0, 205.0); // the contact line on the page
    let at = |u: f64, w: f64| page(u, w, alpha, origin);
    let mut s = String::new();
    let _ = write!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 660 330\" width=\"660\" height=\"330\" \
         role=\"img\" aria-label=\"Geometry: a log of radius r on a slope of angle alpha with snow of depth b\" \
         font-family=\"DejaVu Sans, sans-serif\" font-size=\"14\">"
    );
    snow_and_ground(&mut s, &at, b);
    layer_of_this_turn(&mut s, &at, r, b);
    log_and_radius(&mut s, &at, origin, r, b);
    depth_and_layer_labels(&mut s, &at, r, b);
    direction_of_motion(&mut s, &at, b);
    slope_angle(&mut s, &at, alpha, b);
    s.push_str("</svg>");
    s
}

/// The snow ahead of the log (depth `b`, px) and the ground under it; `at`
/// places a point of the slope's frame on the page.
fn snow_and_ground(s: &mut String, at: &impl Fn(f64, f64) -> (f64, f64), b: f64) {
    // Snow ahead of the log: -b < w < 0, from the contact line downhill.
    s.push_str(&polygon(
        &[at(0.0, 0.0), at(320.0, 0.0), at(320.0, -b), at(0.0, -b)],
        "fill=\"#dcecf8\" stroke=\"#7aa6c9\"",
    ));
    // The ground under the snow, bare behind the log.
    let (g0, g1) = (at(-330.0, -b), at(320.0, -b));
    let _ = write!(
        s,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#5b4a3a\" stroke-width=\"3\"/>",
        g0.0, g0.1, g1.0, g1.1
    );
}

/// The layer picked up in the current turn around the log of radius `r`
/// (snow depth `b`, px).
fn layer_of_this_turn(s: &mut String, at: &impl Fn(f64, f64) -> (f64, f64), r: f64, b: f64) {
    // The layer picked up in the current turn: the annular sector r < r' < r + b
    // over θ' in [0, θ] measured back from the contact line; its element
    // (r', θ') sits at (−r' sin θ', r − r' cos θ') from the contact line.
    let theta = 1.25 * PI;
    let n = 60;
    let mut ring: Vec<(f64, f64)> = (0..=n)
        .map(|i| {
            let t = theta * i as f64 / n as f64;
            at(-(r + b) * t.sin(), r - (r + b) * t.cos())
        })
        .collect();
    ring.extend((0..=n).rev().map(|i| {
        let t = theta * i as f64 / n as f64;
        at(-r * t.sin(), r - r * t.cos())
    }));
    s.push_str(&polygon(&ring, "fill=\"#b9d7ee\" stroke=\"#4f7fa6\""));
}

/// The log of radius `r` and its outline after a full turn (radius `r + b`),
/// the radius to the contact line at `origin` (page px) and the contact line.
fn log_and_radius(
    s: &mut String,
    at: &impl Fn(f64, f64) -> (f64, f64),
    origin: (f64, f64),
    r: f64,
    b: f64,
) {
    // The log.
    let centre = at(0.0, r);
    let _ = write!(
        s,
        "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{r}\" fill=\"#c89b6d\" stroke=\"#7a5230\" stroke-width=\"2\"/>",
        centre.0, centre.1
    );
    // After a full turn: radius r + b, centre raised by b (dashed).
    let lifted = at(0.0, r + b);
    let _ = write!(
        s,
        "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"{}\" fill=\"none\" stroke=\"#1f5f99\" stroke-dasharray=\"6 4\" stroke-width=\"1.5\"/>",
        lifted.0,
        lifted.1,
        r + b
    );
    // Radius r, from the centre to the contact line.
    let _ = write!(
        s,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#1d2329\" stroke-width=\"1.5\"/>",
        centre.0, centre.1, origin.0, origin.1
    );
    let rl = at(8.0, r / 2.0);
    let _ = write!(s, "<text x=\"{:.1}\" y=\"{:.1}\">r</text>", rl.0, rl.1);
    let _ = write!(
        s,
        "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"4\" fill=\"#c0392b\"/>",
        origin.0, origin.1
    );
    let cl = at(-4.0, -b - 22.0);
    let _ = write!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" fill=\"#c0392b\">contact line</text>",
        cl.0, cl.1
    );
}

/// The depth `b` marked at the far end of the snow, and the labels of the
/// snow, of this turn's layer and of the radius after a full turn (px).
fn depth_and_layer_labels(s: &mut String, at: &impl Fn(f64, f64) -> (f64, f64), r: f64, b: f64) {
    // Depth b, at the far end of the snow.
    let (b0, b1) = (at(300.0, 0.0), at(300.0, -b));
    let _ = write!(
        s,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#1d2329\"/>",
        b0.0, b0.1, b1.0, b1.1
    );
    let bl = at(306.0, 14.0);
    let _ = write!(s, "<text x=\"{:.1}\" y=\"{:.1}\">b</text>", bl.0, bl.1);
    let sl = at(150.0, 8.0);
    let _ = write!(s, "<text x=\"{:.1}\" y=\"{:.1}\">snow</text>", sl.0, sl.1);
    let tl = at(-(r + b), 2.0 * r);
    let _ = write!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">layer of this turn (θ)</text>",
        tl.0 - 8.0,
        tl.1
    );
    let nl = at(r + b + 8.0, r + b);
    let _ = write!(
        s,
        "<text x=\"{:.1}\" y=\"{:.1}\" fill=\"#1f5f99\">after θ = 2π: radius r + b</text>",
        nl.0, nl.1
    );
}

/// The arrow of the direction of motion and of G, along the slope, drawn
/// 60 px beneath the ground line (which lies `b` px below the snow's surface).
fn direction_of_motion(s: &mut String, at: &impl Fn(f64, f64) -> (f64, f64), b: f64) {
    // Direction of motion and of G, along the slope.
    let (d0, d1) = (at(-270.0, -b - 60.0), at(-170.0, -b - 60.0));
    let _ = write!(
        s,
        "<defs><marker id=\"geo-arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"7\" \
         markerHeight=\"7\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"#1d2329\"/></marker></defs>\
         <line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#1d2329\" stroke-width=\"1.5\" \
         marker-end=\"url(#geo-arrow)\"/><text x=\"{:.1}\" y=\"{:.1}\">x, v, G = g sin α</text>",
        d0.0,
        d0.1,
        d1.0,
        d1.1,
        d1.0 + 6.0,
        d1.1 + 4.0
    );
}

/// The horizontal and the slope angle `alpha` (rad) at the uphill end of the
/// ground line (`b` px below the snow's surface).
fn slope_angle(s: &mut String, at: &impl Fn(f64, f64) -> (f64, f64), alpha: f64, b: f64) {
    // The horizontal and the angle α where the ground line meets it.
    let corner = at(-330.0, -b);
    let _ = write!(
        s,
        "<line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"#5b6670\" stroke-dasharray=\"3 3\"/>",
        corner.0,
        corner.1,
        corner.0 + 150.0,
        corner.1
    );
    let arc_r = 90.0;
    let _ = write!(
        s,
        "<path d=\"M{:.1},{:.1} A{arc_r},{arc_r} 0 0 1 {:.1},{:.1}\" fill=\"none\" stroke=\"#5b6670\"/>\
         <text x=\"{:.1}\" y=\"{:.1}\">α</text>",
        corner.0 + arc_r,
        corner.1,
        corner.0 + arc_r * alpha.cos(),
        corner.1 + arc_r * alpha.sin(),
        corner.0 + arc_r + 6.0,
        corner.1 + 18.0
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equations_are_written_out_from_the_coefficients_as_the_note_prints_them() {
        // The note's own forms: eq. (4), (6), (15), (32), (14) and (21) as printed.
        let cases = [
            (ModelKind::TorqueCm, "a = 2G/3 − 7bv²/(6πr²)"),
            (ModelKind::TorqueContact, "a = 2G/3 − 3bv²/(2πr²)"),
            (ModelKind::EnergyThin, "a = 2G/3 − bv²/(2πr²) − C b/(πr)"),
            (ModelKind::QuasiCircular, "a = 2G/3 − bv²/(2πr²)"),
            (
                ModelKind::Energy,
                "a (1 + b²/(6π²r²)) = 2G/3 − bv²/(2πr²) − C [b/(πr) + b²/(3πr²)]",
            ),
            (
                ModelKind::LagrangianPrinted,
                "a (1 + b²/(6π²r²)) = 2G/3 − bv²/(πr²) − C [b/(πr) + b²/(3πr²)]",
            ),
            (ModelKind::Snowless, "a = 2G/3"),
        ];
        for (kind, want) in cases {
            let got = equation_of_motion(kind);
            assert!(got.starts_with(want), "{kind}: {got}");
        }
    }

    #[test]
    fn terminal_fractions_print_as_the_note_states_them() {
        // fn. 4: G/5; eq. (35): G/3; the contact torque G/6; eq. (21) printed 2G/9.
        for (kind, want) in [
            (ModelKind::TorqueCm, "1/5"),
            (ModelKind::Loney, "1/5"),
            (ModelKind::TorqueContact, "1/6"),
            (ModelKind::Energy, "1/3"),
            (ModelKind::LagrangianPrinted, "2/9"),
            (ModelKind::Snowless, "2/3"),
        ] {
            assert_eq!(terminal_text(kind), want, "{kind}");
        }
    }

    #[test]
    fn the_drawing_is_one_svg_element_within_its_view_box() {
        let svg = geometry_svg();
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>"));
        assert_eq!(svg.matches("<svg").count(), 1);
        // Every coordinate lies inside the 660 × 330 view box.
        for attr in [
            " x=\"", " y=\"", " cx=\"", " cy=\"", " x1=\"", " y1=\"", " x2=\"", " y2=\"",
        ] {
            for piece in svg.split(attr).skip(1) {
                let v: f64 = piece.split('"').next().unwrap().parse().unwrap();
                let limit = if attr.contains('x') { 660.0 } else { 330.0 };
                assert!((0.0..=limit).contains(&v), "{attr}{v} outside the drawing");
            }
        }
    }
}
