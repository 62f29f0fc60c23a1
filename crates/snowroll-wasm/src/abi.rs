//! The module's interface to the page: plain functions over the module's
//! memory, no generated glue. The page writes the request (UTF-8 JSON)
//! into the buffer [`request_buffer`] returns, calls [`run`], and reads the
//! answer from [`answer_ptr`] / [`answer_len`] (the output's bytes, or the
//! error message when `run` returned 1). The module imports one function,
//! `env.progress(fraction)`, told the fraction done during a long run.
//!
//! `#[no_mangle]` keeps the exports' names; the `unsafe_code` lint counts
//! it as unsafe (two exports of one name would clash at link time), which
//! is why this module allows the lint. The one `unsafe` block calls the
//! page's `progress`, which takes a number and touches no memory of the
//! module; the buffers are Rust's own vectors, handed out as pointers only.
#![allow(unsafe_code)]

use std::cell::RefCell;

use crate::{answer, Command};

thread_local! {
    /// The request written by the page.
    static REQUEST: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    /// The last answer (or error message).
    static ANSWER: RefCell<Vec<u8>> = const { RefCell::new(Vec::new()) };
    /// g sin α of the last run, m/s².
    static G_ALONG: RefCell<f64> = const { RefCell::new(0.0) };
}

#[cfg(target_arch = "wasm32")]
mod host {
    #[link(wasm_import_module = "env")]
    extern "C" {
        /// The page's progress line: the fraction of the run done.
        pub fn progress(fraction: f64);
    }
}

/// Tells the page the fraction done (nothing on the host).
fn report(fraction: f64) {
    #[cfg(target_arch = "wasm32")]
    // SAFETY: a function of the page taking one number; it touches no
    // memory of this module.
    unsafe {
        host::progress(fraction)
    };
    #[cfg(not(target_arch = "wasm32"))]
    let _ = fraction;
}

/// A buffer of `len` bytes for the request; its address.
#[no_mangle]
pub extern "C" fn request_buffer(len: usize) -> *mut u8 {
    REQUEST.with(|r| {
        let mut r = r.borrow_mut();
        r.clear();
        r.resize(len, 0);
        r.as_mut_ptr()
    })
}

/// Runs command `command` (0: the parameter table, 1: simulate, 2: turns)
/// on the request; 0 when it answered, 1 when the answer is an error
/// message, 2 for an unknown command.
#[no_mangle]
pub extern "C" fn run(command: u32) -> u32 {
    let command = match command {
        0 => Command::Params,
        1 => Command::Simulate,
        2 => Command::Turns,
        _ => return 2,
    };
    let request = REQUEST.with(|r| String::from_utf8_lossy(&r.borrow()).into_owned());
    let (status, body, g) = match answer(command, &request, &mut report) {
        Ok(a) => (0, a.body, a.g_along),
        Err(message) => (1, message.into_bytes(), 0.0),
    };
    ANSWER.with(|a| *a.borrow_mut() = body);
    G_ALONG.with(|x| *x.borrow_mut() = g);
    status
}

/// The address of the last answer.
#[no_mangle]
pub extern "C" fn answer_ptr() -> *const u8 {
    ANSWER.with(|a| a.borrow().as_ptr())
}

/// The length of the last answer, bytes.
#[no_mangle]
pub extern "C" fn answer_len() -> usize {
    ANSWER.with(|a| a.borrow().len())
}

/// g sin α of the last run, m/s² (0 after an error).
#[no_mangle]
pub extern "C" fn g_along() -> f64 {
    G_ALONG.with(|x| *x.borrow())
}
