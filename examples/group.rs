//! TwinSAFE groups in Rust (manual §3.1; KL6904 manual §5.1, §5.2):
//!   1. KL6904 5.1 on a group: ESTOP, EDM1 = K1/K2 feedback; a welded K1 is an EDM error
//!      that stops the group until it is repaired and acknowledged.
//!   2. KL6904 5.2 on a group: MON safety door with manual restart.
//!   3. ESTOP and MON feed an AND that drives one contactor K1. A discrepancy error on the
//!      MON stops the whole group in the same cycle until ErrAck is given; afterwards each
//!      block restarts by its own rules (MON by itself, ESTOP with its restart button).
//!
//! Prints a timeline; `cargo run --example group`.

use safelogic::group::{self, Member};
use safelogic::*;
use std::mem::offset_of;

/// The machine: one group, three blocks, two links.
struct Machine {
    g: SL_GROUP,
    links: [SL_LINK; 2],
    estop: FB_ESTOP,
    mon: FB_MON,
    and: FB_AND,
    t: u32,
}

const NAMES: [(&str, u16); 3] = [
    ("ESTOP", SL_TYPE_ESTOP),
    ("MON", SL_TYPE_MON),
    ("AND", SL_TYPE_AND),
];

impl Machine {
    fn new() -> Self {
        // ESTOP: EStopIn1/2 two-channel (e-stop S1), EDM1 = K1 feedback, restart S2.
        let mut estop = FB_ESTOP {
            wInputActive: 0b11,
            tDiscTime12: 30,
            dwOptions: SL_OPT_EDM1,
            ..Default::default()
        };
        // MON: door switches MonIn1/2, automatic restart.
        let mut mon = FB_MON {
            wInputActive: 0b11,
            tDiscTime12: 40,
            ..Default::default()
        };
        // AND: K1 runs only with the e-stop released AND the door closed.
        let mut and = FB_AND {
            wInputActive: 0b11,
            ..Default::default()
        };
        assert_eq!(estop.init(), SL_OK);
        assert_eq!(mon.init(), SL_OK);
        assert_eq!(and.init(), SL_OK);
        (estop.bEStopIn1, estop.bEStopIn2, estop.bEDM1) = (1, 1, 1);
        (mon.bMonIn1, mon.bMonIn2) = (1, 1);
        let mut m = Machine {
            g: SL_GROUP::default(),
            links: [SL_LINK::default(); 2],
            estop,
            mon,
            and,
            t: 0,
        };
        assert_eq!(group::init(&mut m.g, 3, 2), SL_OK);
        for _ in 0..3 {
            group::reserve_member(&mut m.g).expect("room for three members");
        }
        let wire = |src: u16, so: usize, dst: u16, d: usize| SL_LINK {
            nSrcMember: src,
            nSrcOffset: so as u16,
            nDstMember: dst,
            nDstOffset: d as u16,
            ..Default::default()
        };
        let l1 = wire(
            0,
            offset_of!(FB_ESTOP, bEStopOut),
            2,
            offset_of!(FB_AND, bAndIn1),
        );
        let l2 = wire(
            1,
            offset_of!(FB_MON, bMonOut),
            2,
            offset_of!(FB_AND, bAndIn2),
        );
        let mut ms: [&mut dyn Member; 3] = [&mut m.estop, &mut m.mon, &mut m.and];
        assert_eq!(
            group::add_link(&mut m.g, &mut ms[..], &mut m.links, l1),
            SL_OK
        );
        assert_eq!(
            group::add_link(&mut m.g, &mut ms[..], &mut m.links, l2),
            SL_OK
        );
        m
    }

    /// One 10 ms task cycle; prints a line when `what` is not empty.
    fn cycle(&mut self, what: &str) {
        let mut ms: [&mut dyn Member; 3] = [&mut self.estop, &mut self.mon, &mut self.and];
        let rc = group::cycle(&mut self.g, &mut ms[..], &self.links, self.t);
        if !what.is_empty() {
            let states: Vec<String> = ms
                .iter()
                .zip(NAMES)
                .map(|(m, (n, ty))| format!("{n}={:<5}", state_name(ty, m.state())))
                .collect();
            println!(
                "{:>5} ms | group {:<5} FbErr={} FbRun={} | {} | K1={:<3} | {}{}",
                self.t,
                group_state(self.g.nState),
                self.g.bFbErr,
                self.g.bFbRun,
                states.join(" "),
                if self.and.bAndOut == 1 { "on" } else { "off" },
                what,
                if rc == SL_OK {
                    String::new()
                } else {
                    format!(" [{}]", safelogic::base::types::status_str(rc))
                }
            );
        }
        self.t += 10;
    }
}

fn group_state(s: u8) -> &'static str {
    match s {
        SL_STATE_RUN => "RUN",
        SL_STATE_STOP => "STOP",
        SL_STATE_ERROR => "ERROR",
        SL_STATE_RESET => "RESET",
        group::SL_GROUP_STATE_START => "START",
        group::SL_GROUP_STATE_STOPERROR => "STOPERROR",
        _ => "?",
    }
}

/// A group with a single member, for the KL6904 examples.
fn single(g: &mut SL_GROUP, m: &mut dyn Member, ty: u16, t: u32, what: &str) {
    let mut ms: [&mut dyn Member; 1] = [m];
    let rc = group::cycle(g, &mut ms[..], &[], t);
    println!(
        "{t:>5} ms | group {:<5} FbErr={} | {:<5} | {what}{}",
        group_state(g.nState),
        g.bFbErr,
        state_name(ty, ms[0].state()),
        if rc == SL_OK {
            String::new()
        } else {
            format!(" [{}]", safelogic::base::types::status_str(rc))
        }
    );
}

fn new_group(members: u16) -> SL_GROUP {
    let mut g = SL_GROUP::default();
    assert_eq!(group::init(&mut g, members, 0), SL_OK);
    for _ in 0..members {
        group::reserve_member(&mut g).expect("room for the members");
    }
    g.bRun = 1;
    g
}

fn example_5_1() {
    println!("KL6904 5.1 on a group: ESTOP S1 (EStopIn1/2), contactors K1/K2 (EDM1), restart S2\n");
    let mut e = FB_ESTOP {
        wInputActive: 0b11,
        tDiscTime12: 30,
        dwOptions: SL_OPT_EDM1,
        ..Default::default()
    };
    assert_eq!(e.init(), SL_OK);
    (e.bEStopIn1, e.bEStopIn2, e.bEDM1) = (1, 1, 1);
    let mut g = new_group(1);
    let mut t = 0;
    let mut step = |g: &mut SL_GROUP, e: &mut FB_ESTOP, what: &str| {
        single(g, e, SL_TYPE_ESTOP, t, what);
        t += 10;
    };
    step(&mut g, &mut e, "group Run: ESTOP waits for S2");
    e.bRestart = 1;
    step(&mut g, &mut e, "S2 pressed");
    e.bRestart = 0;
    step(&mut g, &mut e, "S2 released: K1/K2 on");
    e.bEDM1 = 0;
    step(&mut g, &mut e, "K1/K2 picked up (EDM1 FALSE)");
    (e.bEStopIn1, e.bEStopIn2) = (0, 0);
    step(
        &mut g,
        &mut e,
        "S1 pressed: outputs off at once; K1 welded, EDM1 stays FALSE",
    );
    (e.bEStopIn1, e.bEStopIn2, e.bRestart) = (1, 1, 1);
    step(
        &mut g,
        &mut e,
        "S1 released, S2 pressed: EDM1 still FALSE -> EDM error, group ERROR",
    );
    assert_eq!(
        (e.nState, e.nDiag, g.nState),
        (SL_STATE_ERROR, SL_DIAG_EDM1, SL_STATE_ERROR)
    );
    (e.bRestart, e.bEDM1) = (0, 1);
    step(&mut g, &mut e, "K1 replaced (EDM1 TRUE)");
    g.bErrAck = 1;
    step(&mut g, &mut e, "ErrAck pressed");
    g.bErrAck = 0;
    step(&mut g, &mut e, "ErrAck released: ESTOP waits for S2 again");
    println!();
}

fn example_5_2() {
    println!(
        "KL6904 5.2 on a group: MON door switches S1/S2 (MonIn1/2), EDM1, manual restart S3\n"
    );
    let mut m = FB_MON {
        wInputActive: 0b11,
        tDiscTime12: 50,
        dwOptions: SL_OPT_EDM1 | SL_OPT_MANUAL_RESTART,
        ..Default::default()
    };
    assert_eq!(m.init(), SL_OK);
    (m.bMonIn1, m.bMonIn2, m.bEDM1) = (1, 1, 1);
    let mut g = new_group(1);
    let mut t = 0;
    let mut step = |g: &mut SL_GROUP, m: &mut FB_MON, what: &str| {
        single(g, m, SL_TYPE_MON, t, what);
        t += 10;
    };
    step(&mut g, &mut m, "group Run: MON waits for S3");
    m.bRestart = 1;
    step(&mut g, &mut m, "S3 pressed");
    m.bRestart = 0;
    step(&mut g, &mut m, "S3 released: K1/K2 on");
    m.bEDM1 = 0;
    step(&mut g, &mut m, "contactors picked up");
    m.bMonIn1 = 0;
    step(&mut g, &mut m, "door opens (S1): outputs off at once");
    (m.bMonIn2, m.bEDM1) = (0, 1);
    step(&mut g, &mut m, "S2 follows; contactors released");
    (m.bMonIn1, m.bMonIn2) = (1, 1);
    step(&mut g, &mut m, "door closed: stays SAFE until S3");
    m.bRestart = 1;
    step(&mut g, &mut m, "S3 pressed");
    m.bRestart = 0;
    step(&mut g, &mut m, "S3 released: on again");
    assert_eq!(m.nState, SL_STATE_RUN);
    println!();
}

fn main() {
    example_5_1();
    example_5_2();
    println!("Group: ESTOP + MON -> AND -> contactor K1 (EDM1 = K1 feedback), 10 ms cycle\n");
    let mut m = Machine::new();
    m.cycle("power-up, Run FALSE: every block in STOP");
    m.g.bRun = 1;
    m.cycle("Run TRUE: group RUN, ESTOP waits for its restart");
    m.cycle("MON restarts automatically");
    m.estop.bRestart = 1;
    m.cycle("S2 pressed: ESTOP START");
    m.estop.bRestart = 0;
    m.cycle("S2 released: ESTOP RUN; the AND runs after it, K1 on in the same cycle");
    m.estop.bEDM1 = 0;
    m.cycle("K1 picked up: its feedback EDM1 reads FALSE");
    m.mon.bMonIn1 = 0;
    m.cycle("door switch S1 opens, S2 does not: discrepancy starts, MonOut off");
    for _ in 0..3 {
        m.cycle("");
    }
    m.cycle("40 ms discrepancy: MON ERROR, the group stops every block in this cycle");
    (m.estop.bEDM1, m.mon.bMonIn1) = (1, 1);
    m.cycle("door closed, K1 released: still ERROR until acknowledged");
    m.g.bErrAck = 1;
    m.cycle("ErrAck pressed: group and MON RESET");
    m.g.bErrAck = 0;
    m.cycle("ErrAck released: group RUN");
    m.cycle("MON runs again by itself; ESTOP needs S2 again");
    m.estop.bRestart = 1;
    m.cycle("S2 pressed");
    m.estop.bRestart = 0;
    m.cycle("S2 released: K1 on again");
}
