//! The figure of `snowroll fit --plot` (and Python's `FitResult.plot()`
//! reads the same columns): the measured points with each fitted model's
//! x(t) above, and each model's residuals (model − data) below, one colour
//! per model, in the order of the ranking. The panels only draw what the fit
//! computed; they run nothing.

use snowroll::ModelKind;

use crate::plot::{Axis, Chart, Marker, Series, Style};

/// One fitted model: its curve on a fine grid and its residuals at the
/// data times.
#[derive(Debug, Clone)]
pub struct FitCurve {
    /// The model.
    pub model: ModelKind,
    /// Its rank (1 = best).
    pub rank: usize,
    /// (t, x) on a fine grid, s and m.
    pub curve: Vec<(f64, f64)>,
    /// (t, model − data) at the data times, s and m.
    pub residuals: Vec<(f64, f64)>,
}

/// The two panels: `data` ((t, x), s and m, named `data_name` in the
/// legend, which says SYNTHETIC when the data are) with every fitted curve,
/// and the residuals.
pub fn fit_panels(data: &[(f64, f64)], data_name: &str, fits: &[FitCurve]) -> Vec<Chart> {
    let time = || Axis::linear("time t", "s").column("t_s");
    let mut top = Chart::new(
        "fit",
        "distance x: data and each fitted model",
        time(),
        Axis::linear("distance x", "m").column("x_m"),
    )
    .with_series(
        Series::new(data_name, data.to_vec())
            .style(Style::Markers)
            .marker(Marker::Circle),
    );
    // The zero line first, so that each model has the same colour in both
    // panels (a chart hands out colours by series index).
    let (t_lo, t_hi) = data
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &(t, _)| {
            (a.min(t), b.max(t))
        });
    let mut bottom = Chart::new(
        "fit-residuals",
        "residuals: model − data",
        time(),
        Axis::linear("residual", "m").column("residual_m"),
    )
    .with_series(Series::new("zero", vec![(t_lo, 0.0), (t_hi, 0.0)]).style(Style::Dotted));
    for (k, f) in fits.iter().enumerate() {
        let name = format!("{}. {}", f.rank, f.model.id());
        let style = Style::ALL[k % 4];
        top = top.with_series(Series::new(&name, f.curve.clone()).style(style));
        bottom = bottom.with_series(
            Series::new(&name, f.residuals.clone())
                .style(style)
                .marker(Marker::Circle),
        );
    }
    vec![top, bottom]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::{render_panels_svg, Provenance};

    #[test]
    fn the_fit_figure_draws_the_data_every_model_and_the_residuals() {
        let data: Vec<(f64, f64)> = (0..10)
            .map(|i| (i as f64 * 0.1, (i * i) as f64 * 0.01))
            .collect();
        let fits = [ModelKind::Energy, ModelKind::TorqueCm]
            .iter()
            .enumerate()
            .map(|(k, &model)| FitCurve {
                model,
                rank: k + 1,
                curve: data.clone(),
                residuals: data.iter().map(|&(t, _)| (t, 0.001 * k as f64)).collect(),
            })
            .collect::<Vec<_>>();
        let panels = fit_panels(&data, "data (SYNTHETIC)", &fits);
        assert_eq!(panels.len(), 2);
        assert_eq!(panels[0].series.len(), 3);
        assert_eq!(panels[1].series.len(), 3);
        let svg = render_panels_svg(&panels, &Provenance::default()).unwrap();
        for word in ["SYNTHETIC", "1. energy", "2. torque-cm", "residuals"] {
            assert!(svg.contains(word), "{word}");
        }
    }
}
