//! The output of `snowroll fit`: a text report for people, or one JSON
//! object (`fits` sorted by rank). No number that is not finite is written:
//! JSON has `null` where there is none (a standard error the data do not
//! give, a condition number of a parameter without effect).

use anyhow::Result;
use serde_json::{json, Value};
use snowroll::fit::{FitSpec, ModelFit};
use snowroll::Scenario;
use snowroll_io::fit_record::{finite_or_null as num, fit_record};
use snowroll_io::measured::MeasuredTrack;
use snowroll_io::{RunParams, VERSION};

/// `x` to `digits` significant digits, as people read it.
fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return "none".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let mag = x.abs().log10().floor() as i32;
    if (-3..6).contains(&mag) {
        let decimals = (digits as i32 - 1 - mag).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.*e}", digits - 1)
    }
}

/// The JSON object.
pub fn json(
    data_name: &str,
    m: &MeasuredTrack,
    spec: &FitSpec,
    fits: &[ModelFit],
) -> Result<String> {
    let params = Scenario::new(spec.settings.scenario)
        .map(|s| serde_json::to_value(RunParams::new(&s, &spec.settings.options)))
        .ok()
        .transpose()?;
    let fits: Vec<Value> = fits.iter().map(fit_record).collect();
    let doc = json!({
        "version": VERSION,
        "data": {
            "file": data_name,
            "name": m.name,
            "columns": [m.columns.0, m.columns.1],
            "points": m.t.len(),
            "t_first_s": num(m.t[0]),
            "t_last_s": num(m.t[m.t.len() - 1]),
        },
        "free": spec.free,
        "params": params,
        "fits": fits,
    });
    Ok(serde_json::to_string_pretty(&doc)? + "\n")
}

/// The text report.
pub fn text(data_name: &str, m: &MeasuredTrack, spec: &FitSpec, fits: &[ModelFit]) -> String {
    let mut out = format!(
        "snowroll {VERSION} fit: {}, {} points, t = {} to {} s; free: {}\n\
         Levenberg-Marquardt on x(t); models ranked by AIC (lower is better)\n\n",
        describe(data_name, m),
        m.t.len(),
        sig(m.t[0], 4),
        sig(m.t[m.t.len() - 1], 4),
        spec.free.join(", ")
    );
    out += &format!(
        "{:<5}{:<22}{:>12}{:>12}{:>12}  {}\n",
        "rank", "model", "rms (m)", "AIC", "BIC", "converged"
    );
    for f in fits {
        out += &format!(
            "{:<5}{:<22}{:>12}{:>12}{:>12}  {}\n",
            f.rank,
            f.model.id(),
            sig(f.rms_m, 3),
            format!("{:.1}", f.aic),
            format!("{:.1}", f.bic),
            if f.converged { "yes" } else { "NO" }
        );
    }
    for f in fits {
        out += &format!(
            "\n{}. {} ({}): rms {} m, {} ({} iterations)\n",
            f.rank,
            f.model.id(),
            f.model.equation(),
            sig(f.rms_m, 3),
            if f.converged {
                format!("converged: {}", f.reason)
            } else {
                format!("NOT converged: {}", f.reason)
            },
            f.iterations
        );
        for p in &f.params {
            let err = p
                .stderr
                .map_or("(not fixed by the data: see below)".to_string(), |e| {
                    format!("± {}", sig(e, 2))
                });
            out += &format!("   {} = {} {err} {}\n", p.key, sig(p.value, 6), p.unit);
        }
        for (i, a) in f.params.iter().enumerate() {
            for (j, b) in f.params.iter().enumerate().skip(i + 1) {
                if let Some(r) = f.correlations[i][j] {
                    out += &format!("   correlation {} / {}: {:+.3}\n", a.key, b.key, r);
                }
            }
        }
        for u in &f.unseparated {
            out += &format!("   not separated: {}", u.text);
            if let (Some(v), Some(e)) = (u.value, u.rel_stderr) {
                out += &format!(" = {} ± {} %", sig(v, 5), sig(100.0 * e, 2));
            }
            out += "\n";
        }
    }
    out
}

/// The measured file as the outputs describe it.
pub(super) fn describe(data_name: &str, m: &MeasuredTrack) -> String {
    match &m.name {
        Some(name) => format!("{data_name} ({name})"),
        None => data_name.to_string(),
    }
}
