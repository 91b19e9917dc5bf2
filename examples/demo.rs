//! The KL6904 application examples 5.1 (machine with an emergency stop, FB ESTOP) and 5.2
//! (machine with safety door monitoring, FB MON), run against a simulated machine.
//!
//!     cargo run --example demo            # both examples
//!     cargo run --example demo -- 5.1     # only the emergency stop
//!     cargo run --example demo -- 5.2     # only the safety door
//!
//! The blocks are called through the C ABI (`sl_estop_init`/`sl_estop_cycle`,
//! `sl_mon_init`/`sl_mon_cycle`), exactly as a C or PLC host calls them: fill in the input
//! fields, call the cycle function with the task time, read the outputs, `nState` and
//! `nDiag`. The task runs every millisecond on a simulated clock, so every run prints the
//! same timeline. Contactors K1 and K2 are simulated with a pick-up and a release delay and
//! a mechanically linked (mirror) NC auxiliary contact, which is TRUE while the contactor
//! is released; a welded contactor stays picked up when its coil is switched off.
//!
//! One line is printed whenever an input, a contactor, the state, an output, the
//! diagnosis or the returned status changes, and whenever the script does something.

use safelogic::*;

/// Task cycle of the simulated safety task.
const CYCLE_MS: u32 = 1;
/// Contactor pick-up delay (coil energised → contacts closed, mirror contact open).
const PICKUP_MS: u32 = 8;
/// Contactor release delay (coil off → contacts open, mirror contact closed).
const RELEASE_MS: u32 = 5;

// ---------------------------------------------------------------------------------------
// The simulated machine
// ---------------------------------------------------------------------------------------

/// A contactor with forced (mirror) contacts, e.g. a Siemens Sirius.
struct Contactor {
    coil: bool,
    coil_since: u32,
    picked: bool,
    welded: bool,
}

impl Contactor {
    fn new() -> Self {
        Contactor {
            coil: false,
            coil_since: 0,
            picked: false,
            welded: false,
        }
    }

    /// Follows the coil after the pick-up or release delay. A welded contactor cannot
    /// release.
    fn update(&mut self, coil: bool, now: u32) {
        if coil != self.coil {
            self.coil = coil;
            self.coil_since = now;
        }
        let delay = if coil { PICKUP_MS } else { RELEASE_MS };
        let stuck = self.welded && self.picked;
        if self.picked != coil && !stuck && now.wrapping_sub(self.coil_since) >= delay {
            self.picked = coil;
        }
    }

    /// The NC mirror contact: closed (TRUE) while the contactor is released.
    fn mirror(&self) -> bool {
        !self.picked
    }

    fn label(&self) -> &'static str {
        match (self.picked, self.welded) {
            (true, true) => "WELD",
            (true, false) => "on",
            (false, _) => "off",
        }
    }
}

/// Signals the operator and the wiring put on the block's inputs (besides EDM1, which the
/// contactors produce).
#[derive(Clone, Copy, PartialEq, Eq)]
struct Panel {
    in1: bool,
    in2: bool,
    restart: bool,
    errack: bool,
    run: bool,
}

/// What the script does at a given time.
#[derive(Clone, Copy)]
enum Act {
    /// Prints a heading for the next episode.
    Say,
    /// Only a comment on this cycle's line.
    Note,
    In1(bool),
    In2(bool),
    Restart(bool),
    ErrAck(bool),
    Run(bool),
    /// The main contacts of K1 (0) or K2 (1) weld.
    Weld(usize),
    /// Contactor K1 (0) or K2 (1) is replaced by a good one.
    Replace(usize),
}

struct Step {
    t: u32,
    act: Act,
    note: &'static str,
}

const fn at(t: u32, act: Act, note: &'static str) -> Step {
    Step { t, act, note }
}

// ---------------------------------------------------------------------------------------
// The two blocks behind one interface (C ABI calls)
// ---------------------------------------------------------------------------------------

trait Guard {
    fn abi_init(&mut self) -> i32;
    fn abi_cycle(&mut self, now: u32) -> i32;
    /// Writes the panel and EDM1 into the input fields.
    fn write_inputs(&mut self, p: &Panel, edm1: bool);
    /// (undelayed output, delayed output, Error)
    fn outputs(&self) -> (u8, u8, u8);
    fn state(&self) -> u8;
    fn diag(&self) -> u16;
    /// Names of the discrepancy groups for diag bits 0-3.
    const PAIRS: [&'static str; 4];
}

impl Guard for FB_ESTOP {
    fn abi_init(&mut self) -> i32 {
        FunctionBlock::init(self)
    }
    fn abi_cycle(&mut self, now: u32) -> i32 {
        FunctionBlock::cycle(self, now)
    }
    fn write_inputs(&mut self, p: &Panel, edm1: bool) {
        self.bEStopIn1 = u8::from(p.in1);
        self.bEStopIn2 = u8::from(p.in2);
        self.bRestart = u8::from(p.restart);
        self.bErrAck = u8::from(p.errack);
        self.bRun = u8::from(p.run);
        self.bEDM1 = u8::from(edm1);
    }
    fn outputs(&self) -> (u8, u8, u8) {
        (self.bEStopOut, self.bEStopDelOut, self.bError)
    }
    fn state(&self) -> u8 {
        self.nState
    }
    fn diag(&self) -> u16 {
        self.nDiag
    }
    const PAIRS: [&'static str; 4] = [
        "disc. EStopIn1/2",
        "disc. EStopIn3/4",
        "disc. EStopIn5/6",
        "disc. EStopIn7/8",
    ];
}

impl Guard for FB_MON {
    fn abi_init(&mut self) -> i32 {
        FunctionBlock::init(self)
    }
    fn abi_cycle(&mut self, now: u32) -> i32 {
        FunctionBlock::cycle(self, now)
    }
    fn write_inputs(&mut self, p: &Panel, edm1: bool) {
        self.bMonIn1 = u8::from(p.in1);
        self.bMonIn2 = u8::from(p.in2);
        self.bRestart = u8::from(p.restart);
        self.bErrAck = u8::from(p.errack);
        self.bRun = u8::from(p.run);
        self.bEDM1 = u8::from(edm1);
    }
    fn outputs(&self) -> (u8, u8, u8) {
        (self.bMonOut, self.bMonDelOut, self.bError)
    }
    fn state(&self) -> u8 {
        self.nState
    }
    fn diag(&self) -> u16 {
        self.nDiag
    }
    const PAIRS: [&'static str; 4] = [
        "disc. MonIn1/2",
        "disc. MonIn3/4",
        "disc. Secure1/2",
        "disc. group 4",
    ];
}

/// "RUN", "SAFE", ... from the library. ESTOP's states are a subset of MON's, same names.
fn state_name(state: u8) -> String {
    safelogic::state_name(SL_TYPE_MON, state).to_string()
}

/// "SL_E_CLOCK" etc. (the part of the status text before the colon).
fn status_name(status: i32) -> String {
    let text = safelogic::base::types::status_str(status);
    text.split(':').next().unwrap_or(text).to_string()
}

/// `nDiag` as hex and the names of its bits.
fn diag_text<B: Guard>(diag: u16) -> String {
    if diag == 0 {
        return "0x0000".to_string();
    }
    let mut names: Vec<String> = Vec::new();
    for (bit, name) in B::PAIRS.iter().enumerate() {
        if diag & (1 << bit) != 0 {
            let safe_in = diag & (1 << (bit + 8)) != 0;
            names.push(if safe_in {
                format!("{name} (safe inputs after disc.)")
            } else {
                name.to_string()
            });
        }
    }
    for (mask, name) in [
        (SL_DIAG_EDM1, "EDM1"),
        (SL_DIAG_EDM2, "EDM2"),
        (SL_DIAG_PARAM_CHANGED, "parameter changed"),
        (SL_DIAG_CLOCK, "clock"),
        (SL_DIAG_CORRUPT, "corrupt"),
    ] {
        if diag & mask != 0 {
            names.push(name.to_string());
        }
    }
    format!("0x{diag:04X} {}", names.join(", "))
}

// ---------------------------------------------------------------------------------------
// The simulation
// ---------------------------------------------------------------------------------------

/// Everything a line of the timeline shows.
#[derive(Clone, PartialEq, Eq)]
struct Snapshot {
    panel: Panel,
    edm1: bool,
    k: [&'static str; 2],
    state: u8,
    outputs: (u8, u8, u8),
    diag: u16,
    status: i32,
}

fn b(v: bool) -> u8 {
    u8::from(v)
}

fn print_header() {
    println!(
        "  {:>6} | {:>3} {:>3} {:>3} {:>4} {:>3} | {:<8} {:>3} {:>3} {:>3} | {:<25} | {:<4} {:<4} | event",
        "t [ms]", "In1", "In2", "Rst", "EDM1", "Ack", "state", "Out", "Del", "Err", "diag", "K1", "K2"
    );
    println!(
        "  {:-<6}-+-{:-<20}-+-{:-<20}-+-{:-<25}-+-{:-<9}-+-{:-<40}",
        "", "", "", "", "", ""
    );
}

fn print_row<B: Guard>(t: Option<u32>, s: &Snapshot, notes: &[String]) {
    let time = t.map_or("init".to_string(), |t| t.to_string());
    let mut event = notes.join("; ");
    if s.status != SL_OK {
        if !event.is_empty() {
            event.push_str("; ");
        }
        event.push_str(&format!("call returned {}", status_name(s.status)));
    }
    println!(
        "  {:>6} | {:>3} {:>3} {:>3} {:>4} {:>3} | {:<8} {:>3} {:>3} {:>3} | {:<25} | {:<4} {:<4} | {}",
        time,
        b(s.panel.in1),
        b(s.panel.in2),
        b(s.panel.restart),
        b(s.edm1),
        b(s.panel.errack),
        state_name(s.state),
        s.outputs.0,
        s.outputs.1,
        s.outputs.2,
        diag_text::<B>(s.diag),
        s.k[0],
        s.k[1],
        event
    );
}

/// Column meanings of one example.
struct Labels {
    title: &'static str,
    legend: &'static [&'static str],
}

/// Runs `script` against `fb` (parameters already set) with the contactors K1 and K2 on
/// the undelayed output and their mirror contacts in series on EDM1.
fn simulate<B: Guard>(fb: &mut B, labels: &Labels, script: &[Step]) {
    println!();
    println!("{}", labels.title);
    println!("{}", "=".repeat(labels.title.len()));
    for line in labels.legend {
        println!("  {line}");
    }
    println!();
    print_header();

    let mut panel = Panel {
        in1: true,
        in2: true,
        restart: false,
        errack: false,
        run: false,
    };
    let mut k = [Contactor::new(), Contactor::new()];

    // Power-up: init writes the power-up image (STOP, outputs FALSE).
    fb.write_inputs(&panel, true);
    let status = fb.abi_init();
    let mut last = Snapshot {
        panel,
        edm1: true,
        k: [k[0].label(), k[1].label()],
        state: fb.state(),
        outputs: fb.outputs(),
        diag: fb.diag(),
        status,
    };
    print_row::<B>(
        None,
        &last,
        &["power-up: init() latches the parameters".to_string()],
    );

    let end = script.last().map_or(0, |s| s.t) + 300;
    let mut t = 0u32;
    while t <= end {
        // 1. What the operator, the machine and the maintenance staff do now.
        let mut notes: Vec<String> = Vec::new();
        for step in script.iter().filter(|s| s.t == t) {
            match step.act {
                Act::Say => {
                    println!("  {:>6} |  --- {}", "", step.note);
                    continue;
                }
                Act::Note => {}
                Act::In1(v) => panel.in1 = v,
                Act::In2(v) => panel.in2 = v,
                Act::Restart(v) => panel.restart = v,
                Act::ErrAck(v) => panel.errack = v,
                Act::Run(v) => panel.run = v,
                Act::Weld(i) => k[i].welded = true,
                Act::Replace(i) => {
                    k[i] = Contactor::new();
                    k[i].coil = fb.outputs().0 == 1;
                }
            }
            if !step.note.is_empty() {
                notes.push(step.note.to_string());
            }
        }

        // 2. The contactors follow the output the block wrote in the previous cycle.
        let coil = fb.outputs().0 == 1;
        let before = [k[0].picked, k[1].picked];
        for c in k.iter_mut() {
            c.update(coil, t);
        }
        let edm1 = k[0].mirror() && k[1].mirror();
        for (up, how) in [(true, "picked up"), (false, "released")] {
            let moved: Vec<&str> = ["K1", "K2"]
                .iter()
                .zip(before.iter().zip(&k))
                .filter(|(_, (was, c))| **was != c.picked && c.picked == up)
                .map(|(name, _)| *name)
                .collect();
            if !moved.is_empty() {
                notes.push(format!("{} {how}", moved.join(" and ")));
            }
        }
        if before.iter().zip(&k).any(|(was, c)| *was != c.picked) {
            notes.push(format!("EDM1 = {}", u8::from(edm1)));
        }

        // 3. One task cycle of the block through the C ABI.
        fb.write_inputs(&panel, edm1);
        let status = fb.abi_cycle(t);

        // 4. Print what changed.
        let now = Snapshot {
            panel,
            edm1,
            k: [k[0].label(), k[1].label()],
            state: fb.state(),
            outputs: fb.outputs(),
            diag: fb.diag(),
            status,
        };
        if now.state != last.state {
            let to = state_name(now.state);
            notes.push(if now.state == SL_STATE_ERROR {
                let bits: Vec<String> = (0..16)
                    .filter(|b| now.diag & (1 << b) != 0)
                    .map(|b| b.to_string())
                    .collect();
                let plural = if bits.len() == 1 { "" } else { "s" };
                format!("=> {to}, Error TRUE, diag bit{plural} {}", bits.join(", "))
            } else {
                format!("=> {to}")
            });
        }
        if now != last || !notes.is_empty() {
            print_row::<B>(Some(t), &now, &notes);
        }
        last = now;
        t += CYCLE_MS;
    }
}

// ---------------------------------------------------------------------------------------
// KL6904 application example 5.1: machine with an emergency stop
// ---------------------------------------------------------------------------------------

fn example_5_1() {
    // FB ESTOP: EStopIn1/EStopIn2 = the two NC channels of e-stop S1, a pair with a
    // discrepancy time of 100 ms; EDM1 active; no delay for EStopDelOut.
    let mut fb = FB_ESTOP {
        wInputActive: 0b0000_0011,
        wInputNegated: 0,
        tDiscTime12: 100,
        tEStopDelOutDelay: 0,
        dwOptions: SL_OPT_EDM1,
        ..FB_ESTOP::default()
    };
    let labels = Labels {
        title: "KL6904 application example 5.1: machine with an emergency stop (FB ESTOP)",
        legend: &[
            "In1/In2 = EStopIn1/EStopIn2: the two NC channels of e-stop S1 (1 = not pressed),",
            "          one pair, discrepancy time 100 ms",
            "Rst     = Restart: push button S2 (1 = pressed); Ack = ErrAck of the TwinSAFE group",
            "EDM1    = mirror contacts of K1 and K2 in series (1 = both released), EDM1 active",
            "Out/Del/Err = EStopOut / EStopDelOut (delay 0 ms) / Error; K1 and K2 are switched by",
            "          EStopOut (pick-up 8 ms, release 5 ms); FbRun TRUE from t = 0; task cycle 1 ms",
            "K1/K2   = off / on / WELD (main contacts welded: stays on with the coil off)",
        ],
    };
    use Act::*;
    let script = [
        at(
            0,
            Say,
            "power-up: the group starts; the outputs stay off until S2 is operated",
        ),
        at(0, Run(true), "FbRun TRUE"),
        at(200, Restart(true), "S2 pressed, S1 and EDM1 are TRUE"),
        at(
            400,
            Restart(false),
            "S2 released (falling edge): outputs on",
        ),
        at(1000, Say, "emergency stop"),
        at(
            1000,
            In1(false),
            "S1 pressed: channel 1 opens, EStopOut off at once",
        ),
        at(
            1003,
            In2(false),
            "channel 2 opens 3 ms later (inside the discrepancy time)",
        ),
        at(1500, In1(true), "S1 unlatched: channel 1 closes"),
        at(
            1502,
            In2(true),
            "channel 2 closes; the outputs stay off until a restart",
        ),
        at(2000, Restart(true), "S2 pressed"),
        at(2150, Restart(false), "S2 released: outputs on"),
        at(
            2800,
            Say,
            "welded contactor: the EDM1 check prevents the restart",
        ),
        at(
            2800,
            Weld(0),
            "the main contacts of K1 weld (not visible yet: K1 is on)",
        ),
        at(3200, In1(false), "S1 pressed: EStopOut off"),
        at(3202, In2(false), "channel 2 opens"),
        at(3700, In1(true), "S1 unlatched"),
        at(3702, In2(true), "channel 2 closes"),
        at(4000, Restart(true), "S2 pressed while EDM1 = 0 (K1 welded)"),
        at(4150, Restart(false), "S2 released: no effect in ERROR"),
        at(
            4500,
            ErrAck(true),
            "ErrAck refused: the EDM1 fault remains (K1 still welded)",
        ),
        at(4600, ErrAck(false), "ErrAck released"),
        at(
            5000,
            Replace(0),
            "maintenance replaces K1: its mirror contact closes",
        ),
        at(5500, ErrAck(true), "ErrAck rising edge, no fault left"),
        at(
            5600,
            ErrAck(false),
            "ErrAck falling edge; a restart is still required",
        ),
        at(6000, Restart(true), "S2 pressed"),
        at(6150, Restart(false), "S2 released: outputs on"),
        at(
            6800,
            Say,
            "discrepancy error: a defective contact block on channel 2",
        ),
        at(
            6800,
            In1(false),
            "S1 pressed, channel 2 stays closed: the discrepancy timer runs",
        ),
        at(6900, Note, "channel 1 and 2 differed for 100 ms"),
        at(7300, In1(true), "S1 unlatched: both channels agree again"),
        at(7400, Say, "the contact block of channel 2 is replaced"),
        at(7500, ErrAck(true), "ErrAck rising edge"),
        at(7600, ErrAck(false), "ErrAck falling edge"),
        at(8000, Restart(true), "S2 pressed"),
        at(8150, Restart(false), "S2 released: outputs on"),
    ];
    simulate(&mut fb, &labels, &script);
}

// ---------------------------------------------------------------------------------------
// KL6904 application example 5.2: machine with safety door monitoring
// ---------------------------------------------------------------------------------------

fn example_5_2() {
    // FB MON: MonIn1/MonIn2 = door switches S1/S2 (NC, closed while the door is closed), a
    // pair with a discrepancy time of 200 ms; EDM1 active; manual restart with S3; no
    // delay for MonDelOut; no Secure inputs, no function test.
    let mut fb = FB_MON {
        wInputActive: 0b0000_0011,
        wInputNegated: 0,
        tDiscTime12: 200,
        tMonDelOutDelay: 0,
        dwOptions: SL_OPT_EDM1 | SL_OPT_MANUAL_RESTART,
        ..FB_MON::default()
    };
    let labels = Labels {
        title: "KL6904 application example 5.2: machine with safety door monitoring (FB MON)",
        legend: &[
            "In1/In2 = MonIn1/MonIn2: door switches S1/S2, NC (1 = door closed), one pair,",
            "          discrepancy time 200 ms",
            "Rst     = Restart: push button S3, manual restart active; Ack = ErrAck of the group",
            "EDM1    = mirror contacts of K1 and K2 in series (1 = both released), EDM1 active",
            "Out/Del/Err = MonOut / MonDelOut (delay 0 ms) / Error; K1 and K2 are switched by",
            "          MonOut (pick-up 8 ms, release 5 ms); FbRun TRUE from t = 0; task cycle 1 ms",
            "K1/K2   = off / on (contactor state)",
        ],
    };
    use Act::*;
    let script = [
        at(
            0,
            Say,
            "power-up: door closed; the outputs stay off until S3 is operated",
        ),
        at(0, Run(true), "FbRun TRUE"),
        at(200, Restart(true), "S3 pressed, S1, S2 and EDM1 are TRUE"),
        at(
            350,
            Restart(false),
            "S3 released (falling edge): outputs on",
        ),
        at(1000, Say, "the door is opened and closed again"),
        at(
            1000,
            In1(false),
            "door opened: S1 opens, MonOut off at once",
        ),
        at(
            1040,
            In2(false),
            "S2 opens 40 ms later (inside the discrepancy time)",
        ),
        at(2000, In2(true), "door closed: S2 closes"),
        at(
            2025,
            In1(true),
            "S1 closes; the outputs stay off (manual restart)",
        ),
        at(2500, Restart(true), "S3 pressed"),
        at(2650, Restart(false), "S3 released: outputs on"),
        at(
            3200,
            Say,
            "S3 held while the door opens (manual 4.5.4, sample 3)",
        ),
        at(
            3200,
            Restart(true),
            "S3 pressed while running: no effect in RUN",
        ),
        at(3400, In1(false), "door opened while S3 is held"),
        at(
            3401,
            Note,
            "Restart TRUE in SAFE: EDM1 is checked at once, K1/K2 have not released yet",
        ),
        at(3440, In2(false), "S2 opens"),
        at(3600, Restart(false), "S3 released"),
        at(4000, In2(true), "door closed"),
        at(4020, In1(true), "S1 closes"),
        at(
            4300,
            ErrAck(true),
            "ErrAck rising edge: K1/K2 have released, EDM1 = 1",
        ),
        at(4400, ErrAck(false), "ErrAck falling edge"),
        at(4700, Restart(true), "S3 pressed"),
        at(4850, Restart(false), "S3 released: outputs on"),
        at(
            5500,
            Say,
            "door switch S2 misaligned: it does not open with the door",
        ),
        at(5500, In1(false), "door opened: S1 opens, S2 stays closed"),
        at(5700, Note, "S1 and S2 differed for 200 ms"),
        at(
            6500,
            In1(true),
            "door closed: S1 and S2 agree again, Error stays until ErrAck",
        ),
        at(6600, Say, "the actuator of S2 is realigned"),
        at(6800, ErrAck(true), "ErrAck rising edge"),
        at(6900, ErrAck(false), "ErrAck falling edge"),
        at(7200, Restart(true), "S3 pressed"),
        at(7350, Restart(false), "S3 released: outputs on"),
    ];
    simulate(&mut fb, &labels, &script);
}

fn main() {
    let which: Vec<String> = std::env::args().skip(1).collect();
    let want = |name: &str| which.is_empty() || which.iter().any(|a| a == name);
    println!("safelogic demo: the KL6904 application examples on a simulated machine");
    println!("(safelogic is not a certified safety component; see README.md)");
    if want("5.1") {
        example_5_1();
    }
    if want("5.2") {
        example_5_2();
    }
    if !want("5.1") && !want("5.2") {
        eprintln!("usage: cargo run --example demo [-- 5.1|5.2]");
        std::process::exit(2);
    }
}
