//! Links the command-line program for a short process on Linux: as a position-dependent
//! executable, statically where the C library's archives are installed (else with GCC's
//! unwinder built in instead of loaded from `libgcc_s.so.1`), and with the functions a
//! report runs gathered in one place.
//!
//! A report is a short process, where what the dynamic loader does at every start is a
//! visible share of the run time (on the EN 15302 E1 pair as
//! `../shared/peer/awrcc/compare.sh` runs it, 141 positions and one SVG, about 5 ms):
//!
//! - A position-independent executable (the toolchain's default) is relocated at every
//!   start: some 3,400 relocations of its tables of pointers (vtables, string slices), and
//!   the pages holding them copied on write. Linking without PIE took a run from 5.93 to
//!   5.76 ms (medians of 40 alternated runs) and from 434 to 411 page faults. What it gives
//!   up is the address randomisation of the program's own image (the heap, the stack and the
//!   shared libraries stay randomised), a hardening that matters for programs facing
//!   untrusted peers, not for a numerical tool reading its user's files.
//! - The program is linked statically where it can be: by `link/cc-static`, the linker that
//!   `.cargo/config.toml` names for x86_64 GNU/Linux, where the C compiler has the static
//!   archives of the C library and of GCC's unwinder. No dynamic loader runs then: no shared
//!   library to find, map and relocate, no symbol to look up. rustc writes the standard
//!   library's system libraries for a dynamic link; `link/cc-static` turns them into
//!   archives for the link that asks for `-static` (the program's; every other link, of
//!   tests, build scripts, macros and the Python extension, goes to `cc` as rustc wrote it).
//!   Measured on the compare scene run after the peer (medians of 150 and 120 alternated runs):
//!   5.30 -> 4.97 ms, and 5.79 -> 5.45 ms in a slower hour of the shared machine; page
//!   faults about 400 -> 360; 22.03 -> 21.77 M instructions. What it gives up: the C library's
//!   functions that load modules at run time (name services for users and hosts, `dlopen`)
//!   work only with the same C library installed, and the program uses none of them; a
//!   security fix to the C library reaches the program when it is built again. Panics,
//!   threads and backtraces work as before (a test program linked so: caught, dropped,
//!   joined, traced). `cargo install` from the registry, another linker or another target
//!   link dynamically, as below. `link/cc-static` then copies the program over itself in
//!   large writes: as the linker wrote it, a few kB at a time, the page cache holds it in
//!   pages of 4 kB, which every run maps one by one; copied, it is held in large folios
//!   (the compare scene 5.19 ms as linked, 4.77-4.88 ms copied; 4 kB writes 5.17 ms;
//!   medians of 30 alternated runs), until the cache drops them (a program paged in by
//!   running it is held in 4 kB pages).
//! - Linked dynamically, the standard library unwinds panics with GCC's unwinder, which it
//!   links from the shared `libgcc_s.so.1`: a second library to map, relocate and fault in
//!   at every start besides `libc` and `libm`. Its static archive `libgcc_eh.a` (the same
//!   unwinder, shipped with GCC wherever `libgcc_s` is) linked whole into the program
//!   defines those symbols first, and `--as-needed` then drops `libgcc_s.so.1`:
//!   `wheelrail --version` 1.48 -> 1.31 ms, the compare scene 5.22 -> 5.06 ms (medians of
//!   300 and 40 alternated runs). Panics unwind as before (catching, dropping,
//!   backtraces). Where the archive is not found (another C compiler, a cross build) the
//!   program links `libgcc_s` as usual.
//! - The functions a report runs lie scattered over the program's 3 MB of code, so that its
//!   first run of each touches a new page of it, and the kernel maps the program's code in
//!   64 kB steps (a page fault each, slower when the caches are cold, as after the peer in
//!   `compare.sh`). The linker-script fragment `link/hot-text.ld` gathers them (their
//!   sections, by symbol, hashes as wildcards, and the C library's archive members where it
//!   is linked statically) into one output section before the rest (`INSERT BEFORE .text`;
//!   GNU ld and LLD both read it; `scripts/hot_text.py` writes it from callgrind runs of
//!   the EN 15302 E1 report, the functions of its core, one figure in SVG, first): the
//!   program's own pages faulted in 66 -> 48 (all page faults 415 -> 396), the compare
//!   scene run after the peer 5.76 -> 5.65 and 5.46 -> 5.38 ms (two runs of 200 alternated
//!   pairs, medians), 4.81 -> 4.76 ms run after itself. Linked statically, with the C
//!   library's functions and the core first: faults on code 39 -> 23, the compare scene
//!   5.45 -> 5.29 ms (120 alternated runs). A function missing from it only stays with the
//!   rest. Not where another linker is configured (`RUSTC_LINKER`, `-C linker`), which may
//!   read no linker scripts.
//!
//! Only the binaries are linked so; the library, its tests and the Python extension are not.
use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=RUSTC_LINKER");
    println!("cargo:rerun-if-changed=link/hot-text.ld");
    println!("cargo::rustc-check-cfg=cfg(hot_text)");
    println!("cargo::rustc-check-cfg=cfg(linked_static)");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if os != "linux" {
        return;
    }
    println!("cargo:rustc-link-arg-bins=-no-pie");
    let linker = linker();
    if let Some(script) = hot_text_script(&linker) {
        println!("cargo:rustc-link-arg-bins=-Wl,-T,{}", script.display());
        // For the test that the program was linked so (`tests/cli.rs`).
        println!("cargo:rustc-cfg=hot_text");
    }
    let unwinder = gnu_archive(&linker, "libgcc_eh.a");
    // Statically by `link/cc-static` where the C library's archive is found too.
    if linker == Linker::Ours && unwinder.is_some() && gnu_archive(&linker, "libc.a").is_some() {
        println!("cargo:rustc-link-arg-bins=-static");
        println!("cargo:rustc-cfg=linked_static");
    } else if let Some(unwinder) = unwinder {
        println!("cargo:rustc-link-arg-bins=-Wl,--whole-archive");
        println!("cargo:rustc-link-arg-bins={}", unwinder.display());
        println!("cargo:rustc-link-arg-bins=-Wl,--no-whole-archive");
    }
}

/// The linker rustc runs for the program.
#[derive(PartialEq)]
enum Linker {
    /// The toolchain's default, `cc`.
    Toolchain,
    /// `link/cc-static`, which `.cargo/config.toml` names for x86_64 GNU/Linux: it passes
    /// `cc` its arguments.
    Ours,
    /// Another configured linker: for the target (`RUSTC_LINKER`, its path) or in the flags
    /// (`-C linker`, the one rustc runs; its path unknown here).
    Other(Option<String>),
}

fn linker() -> Linker {
    let flags = std::env::var("CARGO_ENCODED_RUSTFLAGS").unwrap_or_default();
    if flags.split('\x1f').any(|f| f.contains("linker")) {
        return Linker::Other(None);
    }
    match std::env::var("RUSTC_LINKER") {
        Ok(l) if Path::new(&l).ends_with("link/cc-static") => Linker::Ours,
        Ok(l) if !l.is_empty() => Linker::Other(Some(l)),
        _ => Linker::Toolchain,
    }
}

/// The static archive `name` as the C compiler that links the program finds it, for a native
/// GNU build only (`None` otherwise, or where the compiler has no such file).
fn gnu_archive(linker: &Linker, name: &str) -> Option<PathBuf> {
    let var = |name: &str| std::env::var(name).unwrap_or_default();
    if var("CARGO_CFG_TARGET_ENV") != "gnu" || var("TARGET") != var("HOST") {
        return None;
    }
    let compiler = match linker {
        Linker::Other(Some(path)) => path.as_str(),
        _ => "cc",
    };
    let out = Command::new(compiler)
        .arg(format!("-print-file-name={name}"))
        .output()
        .ok()?;
    // Without the file, the compiler prints the bare name back.
    let path = PathBuf::from(String::from_utf8(out.stdout).ok()?.trim());
    (out.status.success() && path.is_absolute() && path.is_file()).then_some(path)
}

/// `link/hot-text.ld` for the toolchain's own linker or ours: `None` where another linker is
/// configured, which may read no linker scripts, or where the path would not survive `-Wl,`
/// (a comma in it).
fn hot_text_script(linker: &Linker) -> Option<PathBuf> {
    if matches!(linker, Linker::Other(_)) {
        return None;
    }
    let var = |name: &str| std::env::var(name).unwrap_or_default();
    let script = PathBuf::from(var("CARGO_MANIFEST_DIR")).join("link/hot-text.ld");
    (script.is_file() && !script.to_string_lossy().contains(',')).then_some(script)
}
