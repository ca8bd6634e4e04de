//! Links the command-line program as a position-dependent executable on Linux.
//!
//! A position-independent executable (the toolchain's default) is relocated by the dynamic
//! loader at every start: some 3,400 relocations of its tables of pointers (vtables, string
//! slices), and the pages holding them copied on write. A report is a short process, where
//! that is a visible share of the run time: on the EN 15302 E1 pair as
//! `../shared/peer/awrcc/compare.sh` runs it (141 positions, one SVG), linking without PIE
//! took a run from 5.93 to 5.76 ms (medians of 40 alternated runs) and from 434 to 411 page
//! faults. What it gives up is the address randomisation of the program's own image (the
//! heap, the stack and the shared libraries stay randomised), a hardening that matters for
//! programs facing untrusted peers, not for a numerical tool reading its user's files.
//! Only the binaries are linked so; the library, its tests and the Python extension are not.
fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if os == "linux" {
        println!("cargo:rustc-link-arg-bins=-no-pie");
    }
}
