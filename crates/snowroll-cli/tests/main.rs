//! Every integration test of `snowroll-cli` in one binary (one link instead of
//! one per file); each file is a module, named as before.

mod cli;
mod comment;
mod crash_safety;
mod determinism;
mod edges;
mod fit;
mod fuzz_findings;
mod guards;
mod inputs;
mod last_step;
mod merge_bytes;
mod model_list;
mod module_cycles;
mod output_files;
mod paper;
mod plot;
mod reproduce;
mod resume_merge;
#[cfg(feature = "serve")]
mod serve;
mod source_text;
mod streaming;
mod support;
mod sweep;
mod sweep_warnings;
