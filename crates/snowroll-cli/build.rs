//! Links `csrc/closed_stdout.c` into the `snowroll` binary on Unix: a
//! constructor that notes a stdout closed at start, before Rust's runtime
//! hides it (see that file and `console::stdout_unusable`). The object is
//! passed to the linker whole (not in an archive, from which an object no
//! symbol refers to would be dropped with its constructor).

fn main() {
    println!("cargo:rerun-if-changed=csrc/closed_stdout.c");
    let unix = std::env::var("CARGO_CFG_UNIX").is_ok();
    if !unix {
        return;
    }
    let objects = cc::Build::new()
        .file("csrc/closed_stdout.c")
        .warnings(true)
        .compile_intermediates();
    for object in objects {
        println!("cargo:rustc-link-arg-bins={}", object.display());
    }
}
