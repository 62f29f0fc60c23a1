//! `snowroll fit DATA`: the models fitted to a measured trajectory by the
//! library's least squares ([`snowroll::fit`]), ranked, written as text or
//! JSON ([`super::fit_text`]), and drawn with `--plot`.

use std::io::{Read, Write};
use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use snowroll::fit::{self, FitSpec, ModelFit, Track};
use snowroll::{ModelKind, Param, Settings};
use snowroll_io::measured::read_track;
use snowroll_report::fit_plot::{fit_panels, FitCurve};

use super::figure;
use super::fit_text;
use crate::args::{FitArgs, FitFormat};
use crate::clash::{refuse_clashes, RunFile};
use crate::config;
use crate::console::report;
use crate::sink::Sink;

/// The largest data file read, bytes: a video's track is a few thousand
/// lines, and memory stays bounded whatever is named.
const MAX_DATA_BYTES: u64 = 16 << 20;
/// Points of each fitted curve in the figure.
const CURVE_POINTS: usize = 400;

/// Reads the data, fits each model, writes the ranking (and the figure).
pub fn run(args: FitArgs) -> Result<()> {
    let given = match &args.config {
        Some(path) => {
            let file = config::load(path, config::Origin::Simulate)?;
            args.params.given.clone().or(&file.shared())
        }
        None => args.params.given.clone(),
    };
    let mut files = vec![RunFile::input(&args.data, "DATA file")];
    if let Some(c) = &args.config {
        files.push(RunFile::input(c, "--config file"));
    }
    if let Some(p) = &args.plot {
        files.push(RunFile::output(p, "--plot figure"));
    }
    refuse_clashes(&files)?;
    let plot = args
        .plot
        .as_deref()
        .map(|p| figure::plot_format(p).map(|f| (p, f)))
        .transpose()?;
    let columns = args.columns.as_deref().map(parse_columns).transpose()?;
    let data_name = args.data.display().to_string();
    let text = read_data(&args.data)?;
    let measured = read_track(&text, columns).map_err(|e| anyhow!("{data_name}: {e}"))?;
    let track = Track::new(measured.t.clone(), measured.x.clone())
        .map_err(|e| anyhow!("{data_name}: {e}"))?;

    let atol_given = Param::of_key("atol").is_some_and(|p| given.get(p).is_some());
    let settings = given.apply(Settings::default())?;
    let spec = FitSpec {
        settings,
        atol_given,
        free: args
            .free
            .clone()
            .unwrap_or_else(|| fit::DEFAULT_FREE.map(String::from).to_vec()),
        t0: args.t0,
        x0: args.x0,
        max_iterations: match args.max_iterations {
            Some(0) => bail!("--max-iterations 0: give N >= 1"),
            Some(n) => n,
            None => fit::MAX_ITERATIONS,
        },
    };
    let models = chosen_models(&args, &spec)?;
    let fits = fit::fit(&track, &models, &spec)?;
    let out = match args.format.unwrap_or_default() {
        FitFormat::Text => fit_text::text(&data_name, &measured, &spec, &fits),
        FitFormat::Json => fit_text::json(&data_name, &measured, &spec, &fits)?,
    };
    let mut sink = Sink::stdout();
    sink.write_all(out.as_bytes())
        .and_then(|()| sink.commit())
        .context("writing to stdout")?;
    for f in fits.iter().filter(|f| !f.converged) {
        report!("warning: {} did not converge: {}", f.model.id(), f.reason);
    }
    if let Some((path, format)) = plot {
        let label = data_label(measured.name.as_deref().unwrap_or(&data_name));
        let mut prov =
            figure::provenance(&fits.iter().map(|f| f.model).collect::<Vec<_>>(), &given);
        // A free parameter's flag gave its start, not its value: each model
        // fitted its own (the text and JSON outputs give them).
        prov.params.retain(|(k, _)| !spec.free.contains(k));
        prov.params.push(("free".into(), spec.free.join(",")));
        draw(path, format, &fits, &track, &label, &prov)?;
    }
    Ok(())
}

/// The models asked for, or every model that can run the scenario (the
/// others named on stderr).
fn chosen_models(args: &FitArgs, spec: &FitSpec) -> Result<Vec<ModelKind>> {
    if let Some(list) = &args.model {
        return Ok(list.models().to_vec());
    }
    let (ok, refused) = fit::models_that_take(&ModelKind::ALL, spec);
    for (m, why) in refused {
        report!("note: {} is not fitted: {why}", m.id());
    }
    if ok.is_empty() {
        bail!("no model can run this scenario (see the notes above)");
    }
    Ok(ok)
}

/// The figure: the data (named `label`) with each fit's curve, and the
/// residuals, written to `path`.
fn draw(
    path: &Path,
    format: figure::PlotFormat,
    fits: &[ModelFit],
    track: &Track,
    label: &str,
    prov: &snowroll_report::plot::Provenance,
) -> Result<()> {
    let curves = fits
        .iter()
        .map(|f| curve(f, track))
        .collect::<Result<Vec<_>>>()?;
    let points: Vec<(f64, f64)> = track
        .t()
        .iter()
        .copied()
        .zip(track.x().iter().copied())
        .collect();
    let panels = fit_panels(&points, label, &curves);
    figure::write(path, format, &panels, prov)
}

/// `TIME,DISTANCE`.
fn parse_columns(text: &str) -> Result<(&str, &str)> {
    match text.split_once(',') {
        Some((t, x)) if !t.trim().is_empty() && !x.trim().is_empty() && !x.contains(',') => {
            Ok((t.trim(), x.trim()))
        }
        _ => bail!("--columns {text:?}: give two column names, TIME,DISTANCE (e.g. --columns t,x)"),
    }
}

/// The text of DATA (`-`: stdin), at most [`MAX_DATA_BYTES`].
fn read_data(path: &Path) -> Result<String> {
    let name = path.display();
    let mut bytes = Vec::new();
    let limit = MAX_DATA_BYTES + 1;
    if path.as_os_str() == "-" {
        std::io::stdin()
            .lock()
            .take(limit)
            .read_to_end(&mut bytes)
            .context("reading DATA from stdin")?;
    } else {
        std::fs::File::open(path)
            .and_then(|f| f.take(limit).read_to_end(&mut bytes))
            .with_context(|| format!("reading DATA file {name}"))?;
    }
    if bytes.len() as u64 > MAX_DATA_BYTES {
        bail!(
            "DATA file {name} is larger than {} MiB: a measured track is far smaller",
            MAX_DATA_BYTES >> 20
        );
    }
    String::from_utf8(bytes).map_err(|e| anyhow!("DATA file {name} is not UTF-8 text: {e}"))
}

/// A fit's curve on a fine grid from the earlier of t0 and the first data
/// time to the last, and its residuals.
fn curve(f: &ModelFit, track: &Track) -> Result<FitCurve> {
    let t = track.t();
    let (a, b) = (f.t0.min(t[0]), t[t.len() - 1]);
    let times: Vec<f64> = (0..CURVE_POINTS)
        .map(|i| a + (b - a) * i as f64 / (CURVE_POINTS - 1) as f64)
        .collect();
    let xs = f.curve(&times)?;
    Ok(FitCurve {
        model: f.model,
        rank: f.rank,
        curve: times.into_iter().zip(xs).collect(),
        residuals: t.iter().copied().zip(f.residuals.iter().copied()).collect(),
    })
}

/// The data's entry in the figure's legend: `data (SYNTHETIC)` for data
/// that say they are synthetic, else `data: NAME`, shortened.
fn data_label(name: &str) -> String {
    if name.to_ascii_lowercase().contains("synthetic") {
        return "data (SYNTHETIC)".into();
    }
    let short: String = name.chars().take(32).collect();
    if short.len() < name.len() {
        format!("data: {short}…")
    } else {
        format!("data: {short}")
    }
}
