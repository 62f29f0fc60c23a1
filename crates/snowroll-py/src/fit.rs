//! `snowroll._snowroll.fit`: the library's least squares
//! ([`snowroll::fit`]) on times and distances given from Python, each
//! fit's record the CLI's JSON one ([`snowroll_io::fit_record`]), plus the
//! residuals and each fitted model's curve for `FitResult.plot()`.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use snowroll::fit::{self as lib, FitSpec, Track};
use snowroll::params::Scope;
use snowroll::{ModelKind, Param, Settings};
use snowroll_io::fit_record::fit_record;

use crate::{given, keyword, to_py, value_error};

/// Points of each fitted curve.
const CURVE_POINTS: usize = 400;

/// Fits each model's x(t) to the points (`t` in s, `x` in m); returns
/// `{"fits": [record + "residuals_m", "curve_t_s", "curve_x_m"], "free",
/// "skipped": [(model, reason)], "version"}`, fits sorted by rank.
#[pyfunction]
#[pyo3(signature = (t, x, *, models = None, free = None, t0 = None, x0 = None, max_iterations = None, **params))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn fit<'py>(
    py: Python<'py>,
    t: Vec<f64>,
    x: Vec<f64>,
    models: Option<Vec<String>>,
    free: Option<Vec<String>>,
    t0: Option<f64>,
    x0: Option<f64>,
    max_iterations: Option<usize>,
    params: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let given = given("fit", &[Scope::Shared], params)?;
    let err = |e: lib::FitError| PyValueError::new_err(e.render(&keyword));
    let track = Track::new(t, x).map_err(err)?;
    let atol_given = Param::of_key("atol").is_some_and(|p| given.get(p).is_some());
    let settings = given.apply(Settings::default()).map_err(value_error)?;
    if max_iterations == Some(0) {
        return Err(PyValueError::new_err("max_iterations must be at least 1"));
    }
    let spec = FitSpec {
        settings,
        atol_given,
        free: free.unwrap_or_else(|| lib::DEFAULT_FREE.map(String::from).to_vec()),
        t0,
        x0,
        max_iterations: max_iterations.unwrap_or(lib::MAX_ITERATIONS),
    };
    let (kinds, skipped) = match models {
        Some(ids) => (
            ids.iter()
                .map(|m| m.parse::<ModelKind>())
                .collect::<Result<Vec<_>, _>>()
                .map_err(value_error)?,
            Vec::new(),
        ),
        None => lib::models_that_take(&ModelKind::ALL, &spec),
    };
    if kinds.is_empty() {
        return Err(PyValueError::new_err("no model can run this scenario"));
    }
    let fits = py.detach(|| lib::fit(&track, &kinds, &spec)).map_err(err)?;
    let list = PyList::empty(py);
    for f in &fits {
        let record = to_py(py, &fit_record(f))?;
        let d = record.cast::<PyDict>()?;
        d.set_item("residuals_m", f.residuals.clone())?;
        let tt = track.t();
        let (a, b) = (f.t0.min(tt[0]), tt[tt.len() - 1]);
        let times: Vec<f64> = (0..CURVE_POINTS)
            .map(|i| a + (b - a) * i as f64 / (CURVE_POINTS - 1) as f64)
            .collect();
        let curve = f.curve(&times).map_err(err)?;
        d.set_item("curve_t_s", times)?;
        d.set_item("curve_x_m", curve)?;
        list.append(d)?;
    }
    let out = PyDict::new(py);
    out.set_item("fits", list)?;
    out.set_item("free", spec.free.clone())?;
    out.set_item("t_s", track.t().to_vec())?;
    out.set_item("x_m", track.x().to_vec())?;
    let skipped: Vec<(String, String)> = skipped
        .into_iter()
        .map(|(m, why)| (m.id().to_string(), why))
        .collect();
    out.set_item("skipped", skipped)?;
    out.set_item("version", snowroll_io::VERSION)?;
    Ok(out)
}
