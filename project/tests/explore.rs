//! Exhaustive state exploration of the blocks through their C functions
//! (docs/testing.md, "State exploration"): every TwinSAFE Boolean block, every PLCopen
//! block and CONNECTION SHUTDOWN to a fixed point here; the analog and press/motion blocks
//! in `explore_analog_and_motion_blocks` (ignored here, run by tools/deep-check.sh).
//!
//! A violated invariant prints its shortest trace as a one-block project and scenario and
//! replays them with the real `safelogic sim`, which must reach the same state and
//! outputs. `SAFELOGIC_EXPLORE_ONLY=<BLOCK>` explores one block type;
//! `SAFELOGIC_EXPLORE_EXPECT_VIOLATION=1` inverts the verdict (tools/explore_mutants.sh:
//! a broken block must be caught and its trace must replay).

mod explorer;

use explorer::{configs::configs, explore, scenario, Figures, Violation};
use safelogic::registry::{block_type_named, family, BlockType, Family, BLOCKS};
use safelogic::{SL_STATE_DELAYOUT, SL_STATE_ERRORDELAY};
use std::path::PathBuf;
use std::process::Command;

/// States the manual lists that no input sequence of the explored configurations reaches,
/// with the reason.
const UNREACHED: &[(&str, &str, &str)] = &[
    ("AND", "ERROR", NO_INPUT_ERROR),
    ("AND", "RESET", NO_INPUT_ERROR),
    ("OR", "ERROR", NO_INPUT_ERROR),
    ("OR", "RESET", NO_INPUT_ERROR),
    ("XOR", "ERROR", NO_INPUT_ERROR),
    ("XOR", "RESET", NO_INPUT_ERROR),
    ("DECOUPLE", "ERROR", NO_INPUT_ERROR),
    ("DECOUPLE", "RESET", NO_INPUT_ERROR),
    ("RS", "ERROR", NO_INPUT_ERROR),
    ("RS", "RESET", NO_INPUT_ERROR),
    ("SR", "ERROR", NO_INPUT_ERROR),
    ("SR", "RESET", NO_INPUT_ERROR),
    ("TON", "ERROR", NO_INPUT_ERROR),
    ("TON", "RESET", NO_INPUT_ERROR),
    ("TON2", "ERROR", NO_INPUT_ERROR),
    ("TON2", "RESET", NO_INPUT_ERROR),
    ("TOF", "ERROR", NO_INPUT_ERROR),
    ("TOF", "RESET", NO_INPUT_ERROR),
    // LOADSENSING has no Error output and no diag values: ERROR and RESET are the
    // library's own faults only (semantics LS1-LS6, the block's header comment).
    ("LOADSENSING", "ERROR", NO_INPUT_ERROR),
    ("LOADSENSING", "RESET", NO_INPUT_ERROR),
    // COUNTER_INT and _DINT reach their range error only 2^15 and 2^31 count edges from
    // the preset, beyond the bounded depth (DEPTH_BOUNDS); tests/counter.rs runs both.
    ("COUNTER_INT", "ERROR", COUNTER_RANGE),
    ("COUNTER_INT", "RESET", COUNTER_RANGE),
    ("COUNTER_DINT", "ERROR", COUNTER_RANGE),
    ("COUNTER_DINT", "RESET", COUNTER_RANGE),
    // The explored LIMIT configurations take both limits from the parameters (wInputActive
    // 0x0100, the first mask init accepts): Min > Max is then refused by init (SL_E_CONFIG,
    // docs/semantics.md L2), and ERROR (diag 1, limits crossing through an input) needs
    // the MinValue or MaxValue input active.
    ("LIMIT", "ERROR", LIMITS_FROM_PARAMETERS),
    ("LIMIT", "RESET", LIMITS_FROM_PARAMETERS),
    // Refused parameters are caught by init (SL_E_CONFIG): the explored configurations are
    // valid ones.
    (
        "SF_ResetButton",
        "TrailingMinimum > TrailingMaximum or TrailingMinimum < 100 ms",
        "parameters that init accepts never give it",
    ),
    (
        "SF_TestableSafetySensor",
        "TestTime above 150 ms",
        "parameters that init accepts never give it",
    ),
];

const COUNTER_RANGE: &str = "the signed range error lies beyond the bounded depth";

const LIMITS_FROM_PARAMETERS: &str =
    "limits from the parameters only: Min > Max is refused by init, ERROR needs a limit input";

/// The blocks explored to a bounded depth, with the reason: COUNTER's ActValue moves by
/// one per call through the whole range of its type, so its states are not finite in
/// practice; 12 calls from the preset 0 take it past its limit (3) both ways and to zero
/// again, and the unsigned variants below 0 into their range error.
const DEPTH_BOUNDS: &[(&str, usize)] = &[("COUNTER", 12)];

fn depth_bound(name: &str) -> Option<usize> {
    DEPTH_BOUNDS
        .iter()
        .find(|(b, _)| names_block(b, name))
        .map(|(_, d)| *d)
}

/// An `UNREACHED` row's block: the registry's name, or an analog block's base name for
/// every integer variant ("LIMIT" for LIMIT_INT … LIMIT_UDINT).
fn names_block(row: &str, name: &str) -> bool {
    row == name
        || name
            .strip_prefix(row)
            .is_some_and(|v| ["_INT", "_UINT", "_DINT", "_UDINT"].contains(&v))
}

/// The PLCopen blocks that exist in v2.01 only: their init refuses `nDiagProfile` 1, so
/// none of their v1.0 codes can appear (and the explorer finds no configuration with it).
const NO_V1_PROFILE: &[&str] = &["SF_PSE", "SF_ResetButton"];

/// Why ERROR (and RESET after it) is out of the inputs' reach: the block has no input error
/// (no discrepancy time, no feedback); only the library's own checks enter ERROR (a
/// corrupt private state, a parameter changed outside STOP, the clock going backwards),
/// and the explorer keeps the private state intact, the parameters fixed and the clock
/// monotonic.
const NO_INPUT_ERROR: &str =
    "no input error: only the library's integrity, parameter and clock checks enter it";

/// The blocks the test command explores, in every configuration. MUTING (ten driven BOOL
/// inputs, six timers) is explored in `explore_muting` (tools/deep-check.sh).
fn bounded_scope(b: &BlockType) -> bool {
    (b.info.tag < 16
        || family(b.info.tag) == Family::PlcOpen
        || b.info.name == "CONNECTION_SHUTDOWN")
        && b.info.name != "MUTING"
}

fn boolean_scope(b: &BlockType) -> bool {
    b.info.tag < 16 || family(b.info.tag) == Family::PlcOpen || b.info.name == "CONNECTION_SHUTDOWN"
}

/// Writes the violation's project and scenario, runs `safelogic sim` on them and returns
/// whether every expectation (the offending state and outputs) was met.
fn replay(v: &Violation) -> bool {
    let (proj, scen) = scenario::files(v);
    replay_files(&v.block.to_lowercase(), &proj, &scen)
}

fn replay_files(name: &str, proj: &str, scen: &str) -> bool {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("explore");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(format!("{name}.toml"));
    let s = dir.join(format!("{name}.scenario.toml"));
    std::fs::write(&p, proj).unwrap();
    std::fs::write(&s, scen).unwrap();
    println!(
        "--- {} ---\n{proj}--- {} ---\n{scen}",
        p.display(),
        s.display()
    );
    let out = Command::new(env!("CARGO_BIN_EXE_safelogic"))
        .arg("sim")
        .arg(&p)
        .arg(&s)
        .output()
        .expect("safelogic sim runs");
    let text = String::from_utf8_lossy(&out.stdout);
    println!(
        "safelogic sim:\n{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.status.success()
}

/// Explores every configuration of `ty`; prints the figures; returns them and the
/// violations.
fn run_block(ty: &'static BlockType) -> (Figures, Vec<Violation>, Vec<String>) {
    let mut total = Figures::default();
    let mut violations = Vec::new();
    let mut problems = Vec::new();
    // (profile, state value) reached: a PLCopen block's v1.0 DiagCodes count only when
    // reached with nDiagProfile 1, its v2.01 codes only with profile 0.
    let mut seen = std::collections::BTreeSet::new();
    let mut profiles = std::collections::BTreeSet::new();
    let cfgs = configs(ty);
    if cfgs.is_empty() {
        problems.push(format!(
            "{}: no configuration that init accepts",
            ty.info.name
        ));
    }
    for cfg in cfgs {
        let profile = cfg
            .params
            .iter()
            .find(|(f, _)| f.name == "nDiagProfile")
            .map_or(0, |(_, v)| *v);
        profiles.insert(profile);
        match explore(ty, &cfg, depth_bound(ty.info.name)) {
            Ok((fig, v)) => {
                total.configs += 1;
                total.states += fig.states;
                total.transitions += fig.transitions;
                total.depth = total.depth.max(fig.depth);
                total.secs += fig.secs;
                seen.extend(fig.state_values.iter().map(|v| (profile, *v)));
                if std::env::var_os("SAFELOGIC_EXPLORE_VERBOSE").is_some() {
                    println!(
                        "  {} {}: {} states, {} transitions, depth {}, {:.2} s, states {:X?}",
                        ty.info.name,
                        cfg.label,
                        fig.states,
                        fig.transitions,
                        fig.depth,
                        fig.secs,
                        fig.state_values
                    );
                }
                if let Some(v) = v {
                    violations.push(v);
                }
            }
            Err(e) => problems.push(e),
        }
    }
    if violations.is_empty() {
        let v1_explored = profiles.contains(&1);
        if family(ty.info.tag) == Family::PlcOpen
            && v1_explored == NO_V1_PROFILE.contains(&ty.info.name)
        {
            problems.push(format!(
                "{}: explored with the v1.0 profile: {v1_explored}, NO_V1_PROFILE disagrees",
                ty.info.name
            ));
        }
        let mut states = explorer::invariants::state_list(ty);
        states.retain(|(p, ..)| *p == 0 || v1_explored);
        let is_listed = |n: &str| {
            UNREACHED
                .iter()
                .any(|(b, s, _)| names_block(b, ty.info.name) && *s == n)
        };
        for (p, v, n) in &states {
            let (v, n) = (*v, n.as_str());
            let listed = is_listed(n);
            // Both ways: a listed state reached under every code it has (a PLCopen state
            // has its v2.01 and its v1.0 code, each in its own profile) is a stale entry.
            let stale = listed
                && states
                    .iter()
                    .filter(|(_, _, n2)| n2 == n)
                    .all(|(p2, v2, _)| seen.contains(&(*p2, *v2)));
            match (seen.contains(&(*p, v)), listed) {
                (false, false) => problems.push(format!(
                    "{}: state {n} ({v:#X}, profile {p}) never reached",
                    ty.info.name
                )),
                (true, true) if stale => problems.push(format!(
                    "{}: state {n} ({v}) is listed in UNREACHED but reached",
                    ty.info.name
                )),
                _ => {}
            }
        }
    }
    println!(
        "{:<26} {:>2} configs {:>8} states {:>11} transitions depth {:>3} {:>8.2} s",
        ty.info.name, total.configs, total.states, total.transitions, total.depth, total.secs
    );
    (total, violations, problems)
}

fn run(scope: impl Fn(&BlockType) -> bool) {
    let only = std::env::var("SAFELOGIC_EXPLORE_ONLY").ok();
    let expect_violation = std::env::var_os("SAFELOGIC_EXPLORE_EXPECT_VIOLATION").is_some();
    let mut violations = Vec::new();
    let mut problems = Vec::new();
    let t0 = std::time::Instant::now();
    let mut n = 0;
    for ty in BLOCKS.iter().filter(|b| scope(b)) {
        if only.as_deref().is_some_and(|o| o != ty.info.name) {
            continue;
        }
        n += 1;
        let (_, v, p) = run_block(ty);
        violations.extend(v);
        problems.extend(p);
    }
    println!(
        "{n} block types explored in {:.1} s",
        t0.elapsed().as_secs_f64()
    );
    for v in &violations {
        println!(
            "VIOLATION {} ({}): {} after {} steps",
            v.block,
            v.config.label,
            v.what,
            v.trace.len()
        );
    }
    let replayed: Vec<bool> = violations.iter().map(replay).collect();
    if expect_violation {
        assert!(n > 0, "no block named {only:?}");
        assert!(!violations.is_empty(), "the explorer caught nothing");
        assert!(
            replayed.iter().all(|r| *r),
            "a trace did not replay to the same state and outputs in safelogic sim"
        );
    } else {
        assert!(problems.is_empty(), "{problems:#?}");
        assert!(
            violations.is_empty(),
            "{} violations (traces above)",
            violations.len()
        );
    }
}

#[test]
fn explore_boolean_plcopen_and_connection_shutdown_blocks() {
    run(bounded_scope);
}

/// The group scenario (explorer/group.rs): ESTOP → AND in a group with connections
/// assigned, every group and member input, every group state but the customizing ones.
#[test]
fn explore_group() {
    let expect_violation = std::env::var_os("SAFELOGIC_EXPLORE_EXPECT_VIOLATION").is_some();
    let (fig, group_seen, estop_seen, v) = explorer::group::explore();
    println!(
        "{:<26} {:>2} configs {:>8} states {:>11} transitions depth {:>3} {:>8.2} s",
        "group (ESTOP -> AND)", fig.configs, fig.states, fig.transitions, fig.depth, fig.secs
    );
    if expect_violation {
        let v = v.expect("the explorer caught nothing in the group");
        println!("VIOLATION group: {} after {} steps", v.what, v.trace.len());
        let (proj, scen) = explorer::group::files(&v);
        assert!(
            replay_files("group", &proj, &scen),
            "the trace did not replay to the same states and outputs in safelogic sim"
        );
        return;
    }
    if let Some(v) = &v {
        let (proj, scen) = explorer::group::files(v);
        replay_files("group", &proj, &scen);
        panic!(
            "VIOLATION group: {} after {} steps (trace above)",
            v.what,
            v.trace.len()
        );
    }
    let missing: Vec<&str> = explorer::group::GROUP_STATES
        .iter()
        .filter(|(s, _)| !group_seen.contains(s))
        .map(|(_, n)| *n)
        .collect();
    assert!(
        missing.is_empty(),
        "group states never reached: {missing:?}"
    );
    // ESTOP's own exploration reaches every state; here its delayed output is off
    // (tEStopDelOutDelay 0), so DELAYOUT and ERRORDELAY are not entered, every other state
    // must be.
    let estop = block_type_named("ESTOP").unwrap();
    let missing: Vec<&str> = estop
        .info
        .states
        .iter()
        .filter(|(s, _)| {
            ![SL_STATE_DELAYOUT, SL_STATE_ERRORDELAY].contains(s) && !estop_seen.contains(s)
        })
        .map(|(_, n)| *n)
        .collect();
    assert!(
        missing.is_empty(),
        "ESTOP states never reached in the group: {missing:?}"
    );
}

#[test]
#[ignore = "minutes: run by tools/deep-check.sh (step explore)"]
fn explore_muting() {
    run(|b| b.info.name == "MUTING");
}

#[test]
#[ignore = "minutes: run by tools/deep-check.sh (step explore)"]
fn explore_analog_and_motion_blocks() {
    run(|b| !boolean_scope(b));
}
