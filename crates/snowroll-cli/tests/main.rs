//! Every integration test of `snowroll-cli` in one binary (one link instead of
//! one per file); each file is a module, named as before.

mod cli;
mod crash_safety;
mod determinism;
mod fuzz_findings;
mod guards;
mod inputs;
mod output_files;
mod paper;
mod reproduce;
mod resume_merge;
mod streaming;
mod support;
mod sweep;
mod sweep_warnings;
