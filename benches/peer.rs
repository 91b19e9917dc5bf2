//! The peer benchmark (issue "Faster than hand-written ST"): an E-stop written in plain ST
//! (`tools/peer/estop_peer.st`) compiled by matiec and gcc -O2, timed in one process beside
//! the direct C call `sl_estop_cycle` and the ST wrapper `FB_ESTOP` → library, steady and
//! random inputs, median and p99 ns per call and the ratios; beside them the floor of any
//! call timed this way (a call into another translation unit that returns at once, in the
//! same loop) and the target: the direct C call at most 1.0× the plain ST, steady, with the
//! inputs written before each call. The work is done by
//! `tools/peer_bench.py`, which the test command also runs briefly (so it cannot rot); this
//! is the full run: `cargo bench --bench peer` (3,000 batches of 1,000 calls per case).
//!
//! Needs `iec2c`: `$MATIEC_DIR/iec2c`, else `build/matiec` (built from
//! `../shared/vendor/matiec` with its `build_iec2c.sh` when missing); without it the bench
//! says why and does nothing. Uses `target/release/libsafelogic.a` (built here first).

use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    if !std::env::args().any(|a| a == "--bench") {
        println!("peer: run with `cargo bench --bench peer`");
        return;
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let Some(matiec) = matiec_dir(root) else {
        println!("peer: SKIPPED - no iec2c ($MATIEC_DIR, build/matiec, or ../shared/vendor/matiec to build it)");
        return;
    };
    let built = Command::new(env!("CARGO"))
        .args(["build", "--release", "--quiet", "--lib"])
        .current_dir(root)
        .status();
    assert!(
        built.is_ok_and(|s| s.success()),
        "cargo build --release failed"
    );
    let status = Command::new("python3")
        .arg(root.join("tools/peer_bench.py"))
        .arg("--iec2c")
        .arg(matiec.join("iec2c"))
        .arg("--matiec-lib")
        .arg(matiec.join("lib"))
        .arg("--workdir")
        .arg(root.join("build/peer-bench"))
        .args(["--batches", "3000", "--callgrind"])
        .current_dir(root)
        .status()
        .expect("python3 tools/peer_bench.py");
    assert!(
        status.success(),
        "the peer benchmark's scenario check failed"
    );
}

fn matiec_dir(root: &Path) -> Option<PathBuf> {
    if let Some(d) = std::env::var_os("MATIEC_DIR").map(PathBuf::from) {
        if d.join("iec2c").is_file() {
            return Some(d);
        }
    }
    let local = root.join("build/matiec");
    if local.join("iec2c").is_file() {
        return Some(local);
    }
    let script = root.join("../shared/vendor/matiec/build_iec2c.sh");
    let out = Command::new("bash").arg(script).arg(&local).output().ok()?;
    let dir = String::from_utf8_lossy(&out.stdout)
        .lines()
        .last()?
        .trim()
        .to_string();
    let dir = PathBuf::from(dir);
    dir.join("iec2c").is_file().then_some(dir)
}
