//! `simulate --plot` and `turns --plot` (issue 22, item 5): the figure
//! shows the run's own numbers, one curve per model in each panel; the name
//! chooses SVG or PNG and anything else is refused; the figure may not
//! overwrite an input or the other output.

use std::fs;

use crate::support::run_in;

/// Height of one panel in the viewBox: 600 px shown, drawn 4× larger.
const PANEL_VIEWBOX: f64 = 600.0 * 4.0;

/// plotters places points on whole pixels of the 4× canvas, so a drawn
/// point lies within half a pixel of the exact position; 1.5 px leaves room
/// for the rounding of both ends of the scale too.
const PIXEL_TOL: f64 = 1.5;

/// The solid curves of an SVG figure, in drawing order: each polyline of
/// the plot (not of the legend) 2 px wide (8 in the 4× viewBox; axes and
/// ticks are 1), as its points. (A dashed curve is many short polylines.)
fn curves(svg: &str) -> Vec<Vec<(f64, f64)>> {
    strokes(svg).into_iter().map(|(_, c)| c).collect()
}

/// The stroke colour of each distinct curve piece of panel `k`, once each.
fn colours_in(svg: &str, k: usize) -> Vec<String> {
    let mut colours: Vec<String> = strokes(svg)
        .into_iter()
        .filter(|(_, c)| panel(c) == k)
        .map(|(s, _)| s)
        .collect();
    colours.sort();
    colours.dedup();
    colours
}

/// Every curve piece of the plot with its stroke colour.
fn strokes(svg: &str) -> Vec<(String, Vec<(f64, f64)>)> {
    let body = svg.split("<g class=\"legend\">").next().unwrap();
    body.split("<polyline")
        .skip(1)
        .filter_map(|p| {
            let attr = |k: &str| {
                let from = p.find(&format!("{k}=\"")).unwrap() + k.len() + 2;
                p[from..].split('"').next().unwrap().to_string()
            };
            (attr("stroke-width") == "8").then(|| {
                let pts = attr("points")
                    .split_whitespace()
                    .map(|xy| {
                        let (x, y) = xy.split_once(',').unwrap();
                        (x.parse().unwrap(), y.parse().unwrap())
                    })
                    .collect::<Vec<_>>();
                (attr("stroke"), pts)
            })
        })
        .filter(|(_, pts)| !pts.is_empty())
        .collect()
}

/// The panel (0 at the top) a curve is drawn in.
fn panel(curve: &[(f64, f64)]) -> usize {
    (curve[0].1 / PANEL_VIEWBOX) as usize
}

/// Column `name` of a CSV output (its `#` lines skipped).
fn column(csv: &str, name: &str) -> Vec<f64> {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let k = header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').nth(k).unwrap().parse().unwrap())
        .collect()
}

/// Checks that `curve` draws the points `(xs[i], ys[i])` on linear axes:
/// its pixels, mapped back through the scale its extreme points fix, are
/// the data, point by point, in order.
fn assert_draws(curve: &[(f64, f64)], xs: &[f64], ys: &[f64], what: &str) {
    assert_eq!(curve.len(), xs.len(), "{what}: one point per row");
    let span = |v: &[f64]| {
        v.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                (a.min(x), b.max(x))
            })
    };
    let (x0, x1) = span(xs);
    let (y0, y1) = span(ys);
    let (px0, px1) = span(&curve.iter().map(|p| p.0).collect::<Vec<_>>());
    let (py0, py1) = span(&curve.iter().map(|p| p.1).collect::<Vec<_>>());
    for (i, &(px, py)) in curve.iter().enumerate() {
        let want_x = px0 + (xs[i] - x0) / (x1 - x0) * (px1 - px0);
        // Pixel rows grow downwards: the largest value is the top row.
        let want_y = py0 + (y1 - ys[i]) / (y1 - y0) * (py1 - py0);
        assert!(
            (px - want_x).abs() < PIXEL_TOL && (py - want_y).abs() < PIXEL_TOL,
            "{what}: point {i} drawn at ({px}, {py}), the data give ({want_x}, {want_y})"
        );
    }
}

#[test]
fn simulate_plot_draws_the_runs_acceleration_speed_and_distance() {
    let dir = tempfile::tempdir().unwrap();
    let out = run_in(
        dir.path(),
        &[
            "simulate", "--model", "eq4", "--dt", "0.25", "--t-end", "6", "-o", "run.csv",
            "--plot", "run.svg",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = fs::read_to_string(dir.path().join("run.csv")).unwrap();
    let svg = fs::read_to_string(dir.path().join("run.svg")).unwrap();
    let curves = curves(&svg);
    // a/(g sin α), v, x, N, |F|/N: five panels of one model, one curve each.
    let panels: Vec<usize> = curves.iter().map(|c| panel(c)).collect();
    assert_eq!(panels, [0, 1, 2, 3, 4]);
    let t = column(&csv, "t_s");
    let g_along = 9.81 * 30_f64.to_radians().sin();
    let a: Vec<f64> = column(&csv, "a_m_s2").iter().map(|a| a / g_along).collect();
    assert_draws(&curves[0], &t, &a, "a/(g sin α)");
    assert_draws(&curves[1], &t, &column(&csv, "v_m_s"), "v");
    assert_draws(&curves[2], &t, &column(&csv, "x_m"), "x");
    assert_draws(&curves[3], &t, &column(&csv, "normal_n"), "N");
    assert!(svg.contains(">\ntorque-cm\n</text>"), "no legend entry");
    // Eq. (4) from rest starts at a = (2/3) g sin α (Appendix A, b → 0 at t = 0).
    assert!((a[0] - 2.0 / 3.0).abs() < 1e-12);
}

#[test]
fn a_list_of_three_models_draws_three_curves_in_each_panel() {
    let dir = tempfile::tempdir().unwrap();
    let out = run_in(
        dir.path(),
        &[
            "simulate",
            "--model",
            "eq4,eq6,eq14",
            "--dt",
            "0.25",
            "--t-end",
            "6",
            "-o",
            "all.csv",
            "--plot",
            "all.svg",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = fs::read_to_string(dir.path().join("all.csv")).unwrap();
    let svg = fs::read_to_string(dir.path().join("all.svg")).unwrap();
    let curves = curves(&svg);
    // Five panels (a/(g sin α), v, x, N, |F|/N), each with one curve of
    // each model in a colour of its own, models in the order given.
    for k in 0..5 {
        assert_eq!(colours_in(&svg, k).len(), 3, "panel {k}");
    }
    let v_panel: Vec<&Vec<(f64, f64)>> = curves.iter().filter(|c| panel(c) == 1).collect();
    assert_eq!(v_panel.len(), 3);
    // Each v curve draws its own model's rows of the one CSV: the three
    // share one scale, fixed by the extremes over all of them.
    let (lo, hi) = v_panel
        .iter()
        .flat_map(|c| c.iter().map(|p| p.1))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), y| {
            (l.min(y), h.max(y))
        });
    let v_all = column(&csv, "v_m_s");
    let v_max = v_all.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let ids = csv
        .lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').next().unwrap().to_string())
        .collect::<Vec<_>>();
    for (curve, id) in v_panel
        .iter()
        .zip(["torque-cm", "torque-contact", "energy"])
    {
        let v: Vec<f64> = v_all
            .iter()
            .zip(&ids)
            .filter(|(_, m)| *m == id)
            .map(|(v, _)| *v)
            .collect();
        assert_eq!(curve.len(), v.len(), "{id}");
        // From rest (v = 0 at the bottom) to the greatest speed of all (top):
        // pixel y is linear in v.
        for (p, v) in curve.iter().zip(&v) {
            let want = hi + (lo - hi) * v / v_max;
            assert!(
                (p.1 - want).abs() < PIXEL_TOL,
                "{id}: v = {v}: y {} not {want}",
                p.1
            );
        }
        assert!(
            svg.contains(&format!(">\n{id}\n</text>")),
            "no legend entry {id}"
        );
    }
}

#[test]
fn simulate_plot_with_the_ledger_adds_its_shares_and_png_is_a_png() {
    let dir = tempfile::tempdir().unwrap();
    let out = run_in(
        dir.path(),
        &[
            "simulate", "--model", "eq4", "--dt", "0.5", "--t-end", "4", "--ledger", "-o",
            "run.json", "--plot", "run.svg",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = fs::read_to_string(dir.path().join("run.svg")).unwrap();
    // Five panels and the ledger's: its five terms, a colour each (the
    // dashed ones in pieces), and the sum's markers.
    assert_eq!(colours_in(&svg, 5).len(), 5);
    for k in 0..5 {
        assert_eq!(colours_in(&svg, k).len(), 1, "panel {k}: one model");
    }
    assert!(svg.contains("sum of the shares"));
    let out = run_in(
        dir.path(),
        &[
            "simulate", "--model", "eq4", "--t-end", "2", "--plot", "run.PNG",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let png = fs::read(dir.path().join("run.PNG")).unwrap();
    assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    // IHDR: width, then height, 1.5 × (960, 5 panels of 600).
    let be = |i: usize| u32::from_be_bytes(png[i..i + 4].try_into().unwrap());
    assert_eq!((be(16), be(20)), (1440, 4500));
}

#[test]
fn turns_plot_draws_the_per_turn_means_and_extremes() {
    let dir = tempfile::tempdir().unwrap();
    let out = run_in(
        dir.path(),
        &[
            "turns", "--model", "turns", "--turns", "30", "-o", "t.csv", "--plot", "t.svg",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = fs::read_to_string(dir.path().join("t.csv")).unwrap();
    let svg = fs::read_to_string(dir.path().join("t.svg")).unwrap();
    let curves = curves(&svg);
    // Four accelerations of the one model in its one colour (the mean in
    // the turn solid, the others dashed or dotted), its start speeds, its
    // least N/(M g).
    assert_eq!(colours_in(&svg, 0).len(), 1);
    let solid: Vec<&Vec<(f64, f64)>> = curves.iter().filter(|c| c.len() == 30).collect();
    let panels: Vec<usize> = solid.iter().map(|c| panel(c)).collect();
    assert_eq!(panels, [0, 1, 2]);
    let k = column(&csv, "turn");
    let g_along = 9.81 * 30_f64.to_radians().sin();
    let over_g =
        |name: &str| -> Vec<f64> { column(&csv, name).iter().map(|a| a / g_along).collect() };
    assert_draws(solid[0], &k, &over_g("mean_a_turn_m_s2"), "mean in turn");
    assert_draws(solid[1], &k, &column(&csv, "v_start_m_s"), "v_start");
    assert_draws(
        solid[2],
        &k,
        &column(&csv, "min_normal_over_mg"),
        "least N/(M g)",
    );
    assert!(
        svg.contains("turns: greatest in the turn") && svg.contains("turns: least in the turn")
    );
}

#[test]
fn a_plot_name_that_is_not_svg_or_png_or_clashes_is_refused_before_the_run() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("c.toml"), "model = \"eq4\"\n").unwrap();
    for (args, says) in [
        (
            &["simulate", "--model", "eq4", "--plot", "run.pdf"][..],
            ".svg or .png",
        ),
        (
            &["simulate", "--model", "eq4", "--plot", "run"][..],
            ".svg or .png",
        ),
        (&["turns", "--plot", "t.svgz"][..], ".svg or .png"),
        (
            &[
                "simulate", "--model", "eq4", "-o", "same.svg", "--plot", "same.svg",
            ][..],
            "are the same file",
        ),
        (
            &["simulate", "--config", "c.toml", "--plot", "./c.toml"][..],
            "which this run reads",
        ),
    ] {
        let out = run_in(dir.path(), args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success() && err.contains(says),
            "{args:?}: {err}"
        );
    }
    // Nothing was written.
    let mut names: Vec<String> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, ["c.toml"]);
}
