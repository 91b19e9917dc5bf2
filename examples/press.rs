//! An excentric press with an electronic cam controller (FB CAMMONITOR_UINT, manual §4.26):
//!
//! ```text
//!   crank encoder (0 … 8192 = 360°) ─ Position ─┐
//!   overrun cam, upward cam (hardware) ─────────┼─ CAMMONITOR_UINT ─ CamMonOK (press enable),
//!   Reset (start pulse), Press_Started ─────────┘                    UpwardsMove (muting),
//!                                                                      TDC, BDC, OverrunTDC
//! ```
//!
//! Limits as in the manual's example: TDC 8092 … 100, OverrunMax 800, BDC 3896 … 4296,
//! jitter 4, StopDetectionTime 50 ms; the hardware cams are checked (overrun cam on from
//! 6000 to 1500, upward cam from 4000 to 0°). Four strokes, each released by a Reset pulse:
//! two good ones (the press stops after TDC within OverrunMax), one that overruns TDC
//! (ERROR 0x400D, acknowledged), one whose upward cam fails (ERROR 0x4007).
//!
//! Prints a timeline (10 ms cycle), one line per change; `cargo run --example press`. The C
//! example `examples/c/press.c` prints the same lines (the test command diffs them).

use safelogic::group::state_name;
use safelogic::*;

const C: u32 = 8193;

/// The press: crank position (true), the cams it switches, the monitor.
struct Press {
    fb: FB_CAMMONITOR_UINT,
    pos: u32,
    t: u32,
    /// The upward cam is broken (stuck FALSE).
    upward_cam_broken: bool,
    last: String,
    /// Text IDs of the errors seen.
    seen: Vec<u16>,
}

impl Press {
    fn new() -> Self {
        let fb = FB_CAMMONITOR_UINT {
            wInputActive: SL_CAMMONITOR_ACTIVE_RESET
                | SL_CAMMONITOR_ACTIVE_POSITION
                | SL_CAMMONITOR_ACTIVE_PRESSSTARTED
                | SL_CAMMONITOR_ACTIVE_OVERRUNCAM
                | SL_CAMMONITOR_ACTIVE_UPWARDCAM,
            tStopDetectionTime: 50,
            tPressStartDelayTime: 200,
            tMoveDetectionTime: 100,
            nAllowedPositionJitter: 4,
            nMinPositionChange: 20,
            nMaxPosition: 8192,
            nTDC1LowerLimitFix: 8092,
            nTDC1UpperLimitFix: 100,
            nBDCLowerLimitFix: 3896,
            nBDCUpperLimitFix: 4296,
            nOverrunMaxFix: 800,
            ..Default::default()
        };
        let mut p = Press {
            fb,
            pos: 50,
            t: 0,
            upward_cam_broken: false,
            last: String::new(),
            seen: Vec::new(),
        };
        assert_eq!(p.fb.init(), SL_OK);
        p.fb.bRun = 1;
        p
    }

    /// One 10 ms cycle at the current position; prints a line when something changed.
    fn cycle(&mut self, note: &str) {
        let pos = self.pos;
        self.fb.bOverrunCam = u8::from(!(1500..6000).contains(&pos));
        self.fb.bUpwardCam = u8::from(pos >= 4000 && !self.upward_cam_broken);
        self.fb.nPosition = pos as u16;
        let rc = self.fb.cycle(self.t);
        let f = &self.fb;
        if f.nDiagTextId != 0 && !self.seen.contains(&f.nDiagTextId) {
            self.seen.push(f.nDiagTextId);
        }
        // A line when a state, a BOOL output or the message changes (or an event is noted).
        let key = format!(
            "{:<26} OK={} UP={} TDC={} BDC={} ERR={} text=0x{:04x}",
            state_name(SL_TYPE_CAMMONITOR_UINT, f.nState),
            f.bCamMonOK,
            f.bUpwardsMove,
            f.bTDC,
            f.bBDC,
            f.bError,
            f.nDiagTextId,
        );
        if key != self.last || !note.is_empty() || rc != SL_OK {
            println!(
                "{:6} ms  pos {:4}  {}  OverrunTDC {:4}  OverrunStop {:4}{}{}",
                self.t,
                pos,
                key,
                f.nOverrunTDC,
                f.nOverrunStop,
                if note.is_empty() { "" } else { "  <- " },
                note
            );
            self.last = key;
        }
        self.t += 10;
    }

    fn hold(&mut self, calls: u32, note: &str) {
        for i in 0..calls {
            self.cycle(if i == 0 { note } else { "" });
        }
    }

    fn reset_pulse(&mut self) {
        self.fb.bReset = 1;
        self.cycle("Reset TRUE");
        self.fb.bReset = 0;
        self.cycle("Reset FALSE (start released)");
    }

    /// A stroke: Press_Started on, clockwise at `speed` per cycle; Press_Started off at
    /// `brake_at` (the stop command), then the press coasts `coast` increments further at
    /// half speed and stands still.
    fn stroke(&mut self, speed: u32, brake_at: u32, coast: u32) {
        self.fb.bPressStarted = 1;
        let mut travelled = 0;
        let mut first = true;
        // Up to the stop command: once round past BDC, then to `brake_at`.
        loop {
            let next = (self.pos + speed) % C;
            let passes = travelled > C / 2 && (self.pos..self.pos + speed).contains(&brake_at);
            if passes {
                self.pos = brake_at;
                break;
            }
            self.pos = next;
            travelled += speed;
            self.cycle(if first {
                "Press_Started TRUE, press runs"
            } else {
                ""
            });
            first = false;
            if self.fb.nState == SL_STATE_ERROR {
                return;
            }
        }
        self.fb.bPressStarted = 0;
        self.cycle("Press_Started FALSE (stop command)");
        let mut left = coast;
        while left > 0 && self.fb.nState != SL_STATE_ERROR {
            let s = (speed / 2).min(left);
            left -= s;
            self.pos = (self.pos + s) % C;
            self.cycle("");
        }
        self.hold(8, "standstill");
    }
}

fn main() {
    println!("Excentric press: CAMMONITOR_UINT, TDC 8092..100, OverrunMax 800, BDC 3896..4296, cams checked\n");
    let mut p = Press::new();
    p.hold(1, "power on at TDC");
    p.reset_pulse();
    println!("-- stroke 1: normal");
    p.stroke(64, 8000, 256);
    p.reset_pulse();
    println!("-- stroke 2: normal");
    p.stroke(64, 8000, 200);
    p.reset_pulse();
    println!("-- stroke 3: the brake is late, the press overruns TDC past OverrunMax");
    p.stroke(64, 200, 900);
    p.fb.bErrAck = 1;
    p.cycle("ErrAck TRUE");
    p.fb.bErrAck = 0;
    p.cycle("ErrAck FALSE");
    p.reset_pulse();
    println!("-- stroke 4: the upward cam fails (stuck FALSE)");
    p.upward_cam_broken = true;
    p.stroke(64, 8000, 256);
    p.upward_cam_broken = false;
    p.fb.bErrAck = 1;
    p.cycle("ErrAck TRUE");
    p.fb.bErrAck = 0;
    p.cycle("ErrAck FALSE");
    assert_eq!(
        p.seen,
        [
            SL_TEXT_CAMMONITOR_LEFT_TDC,
            SL_TEXT_CAMMONITOR_UPWARDCAM_FALSE_LEFT
        ]
    );
}
