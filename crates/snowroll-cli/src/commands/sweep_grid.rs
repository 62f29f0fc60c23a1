//! The grid of `snowroll sweep`: the flags over the `--grid` TOML file.

use std::collections::BTreeMap;
use std::fs;
use std::io::{BufRead, BufReader};
use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use clap::ValueEnum;
use snowroll::sweep::{Axis, AxisParam, Choices, Grid, GridError, Method, Values};
use snowroll::{CollisionModel, OnHop};

use crate::args::{sweep_axes, SweepArgs};
use crate::bounded::{self, MAX_SETTINGS_FILE};
use crate::clash::RunFile;

/// Whether `key` is a key of a sweep's grid: `model` or a sweep axis of
/// the parameter table.
pub(super) fn is_grid_key(key: &str) -> bool {
    key == "model" || sweep_axes().any(|p| p.key == key)
}

/// The values of a list setting (`stop,continue`) by their kebab-case ids.
fn choice_list<T: ValueEnum>(key: &str, text: &str) -> Result<Vec<T>> {
    text.split(',')
        .map(|id| {
            T::from_str(id.trim(), true).map_err(|_| {
                let ids: Vec<String> = T::value_variants()
                    .iter()
                    .filter_map(|v| v.to_possible_value().map(|p| p.get_name().to_string()))
                    .collect();
                anyhow!(
                    "--{}: unknown value {id:?}; expected one of {}",
                    key.replace('_', "-"),
                    ids.join(", ")
                )
            })
        })
        .collect()
}

/// The grid of the flags over the `--grid` file.
///
/// An axis that does not parse or holds a value out of range is reported as
/// it was given (`--alpha-deg 5:95:3: ...`, or `alpha_deg = 5:95:3 in
/// FILE: ...`) followed by the library's message, which names the key, the
/// bad value and the allowed range.
pub fn grid(args: &SweepArgs) -> Result<Grid> {
    let mut given: BTreeMap<String, String> = match &args.grid {
        Some(path) => grid_file(path)?,
        None => BTreeMap::new(),
    };
    let flags = flag_axes(args);
    for (key, value) in &flags {
        given.insert(key.to_string(), (*value).clone());
    }
    // Where an axis was given, for the messages.
    let origin = |key: &str, text: &str| match (flags.iter().any(|(k, _)| *k == key), &args.grid) {
        (false, Some(path)) => format!("{key} = {text} in {}", path.display()),
        _ => format!("--{} {text}", key.replace('_', "-")),
    };
    grid_of(given, &origin)
}

/// The grid of axis texts by snake-case key (`model`, `collision`,
/// `on_hop` and the numeric axes); `origin(key, text)` says where an axis
/// was given, for the messages.
pub fn grid_of(
    mut given: BTreeMap<String, String>,
    origin: &dyn Fn(&str, &str) -> String,
) -> Result<Grid> {
    let collision = match given.remove("collision") {
        Some(text) => choice_list::<CollisionModel>("collision", &text)?,
        None => Choices::default().collision,
    };
    let on_hop = match given.remove("on_hop") {
        Some(text) => choice_list::<OnHop>("on_hop", &text)?,
        None => Choices::default().on_hop,
    };
    let models = given.remove("model");
    let mut axes = Vec::new();
    for (key, text) in &given {
        let param = AxisParam::from_key(key).ok_or_else(|| anyhow!("unknown axis {key:?}"))?;
        let values = Values::parse(param.key(), text).map_err(|e| match e {
            GridError::Syntax { reason, .. } => {
                anyhow!("{}: cannot read it: {reason}", origin(key, text))
            }
            e => e.into(),
        })?;
        axes.push(Axis { param, values });
    }
    let models = match models {
        Some(text) => crate::args::parse_models(&text).context("--model")?,
        None => Vec::new(),
    };
    let grid = Grid::new(models, axes).map_err(|e| match e {
        GridError::Value { param, error } => {
            let text = given.get(param.key()).map_or("", String::as_str);
            anyhow!("{}: {error}", origin(param.key(), text))
        }
        e => e.into(),
    })?;
    Ok(grid.with_choices(Choices { collision, on_hop })?)
}

/// The files a sweep reads (`--config`, `--grid`) and writes (`-o`, its
/// rows file `partial`, `--plot`), for [`crate::clash::refuse_clashes`].
pub fn run_files<'a>(args: &'a SweepArgs, partial: Option<&'a Path>) -> Vec<RunFile<'a>> {
    let mut files = Vec::new();
    files.extend(
        args.config
            .as_deref()
            .map(|p| RunFile::input(p, "--config file")),
    );
    files.extend(
        args.grid
            .as_deref()
            .map(|p| RunFile::input(p, "--grid file")),
    );
    files.extend(
        args.output
            .as_deref()
            .map(|p| RunFile::output(p, "-o output")),
    );
    files.extend(partial.map(|p| RunFile::output(p, "rows file of the running sweep")));
    files.extend(
        args.plot
            .as_deref()
            .map(|p| RunFile::output(p, "--plot map")),
    );
    files
}

/// The axes given as flags, by snake-case key (`model` included).
pub fn flag_axes(a: &SweepArgs) -> Vec<(&'static str, &String)> {
    let model = a.model.as_ref().map(|m| ("model", m));
    model
        .into_iter()
        .chain(a.axes.given.iter().map(|(p, text)| (p.key, text)))
        .collect()
}

/// The axes of a `--grid` TOML file, as axis texts by snake-case key: a
/// string is taken as typed on the command line, a number as one value, an
/// array as a list.
fn grid_file(path: &Path) -> Result<BTreeMap<String, String>> {
    let shown = path.display();
    let text = bounded::read_text(path, MAX_SETTINGS_FILE, "--grid file", "a --grid file")?;
    if text.starts_with("# snowroll sweep") {
        bail!("{shown} is the output of a sweep: read it back with --config {shown}");
    }
    let table: toml::Table = text
        .parse()
        .map_err(|e: toml::de::Error| anyhow!("{shown}: {}", e.message()))?;
    let mut axes = BTreeMap::new();
    for (key, value) in table {
        let snake = key.replace('-', "_");
        if !is_grid_key(&snake) {
            let known: Vec<&str> = std::iter::once("model")
                .chain(sweep_axes().map(|p| p.key))
                .collect();
            bail!(
                "{shown}: unknown key {key:?}; expected one of {}",
                known.join(", ")
            );
        }
        let item = |v: &toml::Value| match v {
            toml::Value::String(s) => Ok(s.clone()),
            toml::Value::Integer(i) => Ok(i.to_string()),
            toml::Value::Float(x) => Ok(x.to_string()),
            other => Err(anyhow!(
                "{shown}: {key}: expected a number, a string or an array of them, not {}",
                other.type_str()
            )),
        };
        let text = match &value {
            toml::Value::Array(items) => items
                .iter()
                .map(item)
                .collect::<Result<Vec<_>>>()?
                .join(","),
            v => item(v)?,
        };
        if axes.insert(snake, text).is_some() {
            bail!("{shown}: {key} is given twice");
        }
    }
    Ok(axes)
}

/// What a sweep's output records of its run: its header's `# key: value`
/// lines (a CSV's `#` lines, a Parquet file's `snowroll.key` metadata).
/// Only the header is read, at most [`bounded::MAX_HEADER`] bytes.
fn recorded(path: &Path) -> Result<Vec<(String, String)>> {
    let shown = path.display();
    let cannot_read = || format!("cannot read config file {shown}");
    let mut reader = BufReader::new(fs::File::open(path).with_context(cannot_read)?);
    if reader
        .fill_buf()
        .with_context(cannot_read)?
        .starts_with(b"PAR1")
    {
        return recorded_parquet(path);
    }
    let mut lines = Vec::new();
    for line in bounded::read_header(&mut reader).with_context(cannot_read)? {
        let Some(comment) = line.trim_end_matches(['\n', '\r']).strip_prefix("# ") else {
            break;
        };
        if let Some(version) = comment.strip_prefix("snowroll sweep, version ") {
            lines.push(("version".to_string(), version.to_string()));
        } else if let Some((k, v)) = comment.split_once(": ") {
            lines.push((k.to_string(), v.to_string()));
        }
    }
    if lines.first().map(|(k, _)| k.as_str()) != Some("version") {
        bail!(
            "config file {shown} is not an output of `snowroll sweep` (its first line is not \
             `# snowroll sweep, version ...`)"
        );
    }
    Ok(lines)
}

/// The `snowroll.key` metadata of a Parquet output: only its footer is read.
#[cfg(feature = "parquet")]
fn recorded_parquet(path: &Path) -> Result<Vec<(String, String)>> {
    use parquet::file::reader::{FileReader, SerializedFileReader};
    let shown = path.display();
    let file = fs::File::open(path).with_context(|| format!("cannot read config file {shown}"))?;
    let reader = SerializedFileReader::new(file)
        .map_err(|e| anyhow!("config file {shown}: not a readable Parquet file: {e}"))?;
    let lines: Vec<(String, String)> = reader
        .metadata()
        .file_metadata()
        .key_value_metadata()
        .into_iter()
        .flatten()
        .filter_map(|kv| {
            let key = kv.key.strip_prefix("snowroll.")?;
            Some((key.to_string(), kv.value.clone().unwrap_or_default()))
        })
        .collect();
    if !lines.iter().any(|(k, _)| k == "version") {
        bail!("config file {shown} is not an output of `snowroll sweep` (no snowroll.version)");
    }
    Ok(lines)
}

/// Without Parquet support a Parquet file cannot be read back.
#[cfg(not(feature = "parquet"))]
fn recorded_parquet(path: &Path) -> Result<Vec<(String, String)>> {
    bail!(
        "config file {} is Parquet: this snowroll was built without Parquet (rebuild it with \
         `--features parquet`), or read back the CSV output",
        path.display()
    )
}

/// `args` with the sweep recorded in its `--config` file filling every
/// setting of the grid and the run that was not given as a flag, and the
/// recorded command line when no such flag was given (the header is then
/// the file's own, byte for byte). Without `--config`, `args` unchanged.
///
/// The axes come from the header's `# key: values` lines, so a sweep made
/// from a `--grid` file is read back without it; the shard and the method
/// from its `# shard:` and `# command:` lines. `--method` can only be
/// overridden to `ode` (`auto` is its default, not told apart from absent).
pub fn with_config(args: &SweepArgs) -> Result<(SweepArgs, Option<String>)> {
    let Some(path) = &args.config else {
        return Ok((args.clone(), None));
    };
    let shown = path.display();
    let lines = recorded(path)?;
    let get = |key: &str| lines.iter().find(|(k, _)| k == key).map(|(_, v)| v.clone());
    let Some(command) = get("command") else {
        bail!("config file {shown}: its `command` line is missing");
    };
    let overridden = !flag_axes(args).is_empty()
        || args.shard.is_some()
        || args.format.is_some()
        || args.method != Method::Auto;
    let mut merged = args.clone();
    let fill = |field: &mut Option<String>, key: &str| {
        if field.is_none() {
            *field = get(key);
        }
    };
    fill(&mut merged.model, "model");
    for p in sweep_axes() {
        merged.axes.fill(p, get(p.key));
    }
    if merged.model.is_none() {
        bail!("config file {shown}: its `model` line is missing");
    }
    if merged.shard.is_none() {
        let shard = get("shard").ok_or_else(|| anyhow!("config file {shown}: no `shard` line"))?;
        let shard = shard.split(',').next().unwrap_or("").trim().to_string();
        if shard != "0/1" {
            merged.shard = Some(shard);
        }
    }
    if merged.method == Method::Auto {
        merged.method =
            recorded_method(&command).map_err(|e| anyhow!("config file {shown}: {e}"))?;
    }
    merged.config = None;
    Ok((merged, (!overridden).then_some(command)))
}

/// The method a sweep's recorded command line ran with: `--method`'s value
/// when it names one, else `auto` (the default, which the line omits).
///
/// # Errors
/// An unknown method, named.
pub fn recorded_method(command: &str) -> Result<Method> {
    let words: Vec<&str> = command.split_whitespace().collect();
    match words.windows(2).find(|w| w[0] == "--method") {
        Some(w) => Method::from_str(w[1], true).map_err(|_| anyhow!("unknown --method {:?}", w[1])),
        None => Ok(Method::Auto),
    }
}
