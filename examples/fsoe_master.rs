//! The logic master of a two-process FSoE pair over a real black channel (UDP on
//! 127.0.0.1): a TwinSAFE group with the FSoE master connection (member 0) and an ESTOP
//! (member 1) whose two channels are the bits 0 and 1 received from the slave
//! (`SL_LINK_RXBIT`); its EStopOut is sent back as bit 0 (`SL_LINK_TXBIT`). Partner:
//! `examples/fsoe_slave.rs`. Docs: docs/fsoe.md.
//!
//! ```sh
//! cargo run --release --example fsoe_slave  -- 40001 40002 &
//! cargo run --release --example fsoe_master -- 40002 40001
//! ```
//! Arguments: own UDP port, the slave's UDP port. Commands on stdin: `restart` (pulse of the
//! ESTOP's Restart), `ack` (pulse of the group's ErrAck), `quit`. A `status …` line is
//! printed whenever something changes (`since_rx`: ms since the last frame from the slave,
//! `gap`: ms since the previous cycle). Stop the slave and the group enters ERROR (ComErr,
//! diag 2) within the watchdog time with EStopOut FALSE; start it again and `ack`.
//!
//! The library builds and checks the frames; this program only carries them. The session
//! seed here is an xorshift of the clock: a product takes it from the OS (getrandom).

use safelogic::fsoe::conn;
use safelogic::group::{self, Member, SL_LINK_RXBIT, SL_LINK_TXBIT};
use safelogic::*;
use std::io::BufRead;
use std::mem::offset_of;
use std::net::UdpSocket;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// Watchdog of the connection (ms).
pub const WATCHDOG_MS: u32 = 100;
/// SafeData bytes per direction.
const DATA_LEN: u16 = 2;

/// What the master node shows.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
struct Status {
    group: u8,
    diag: u16,
    com_err: u8,
    startup: u8,
    conn: u8,
    inputs: (u8, u8),
    out: u8,
}

/// Runs the master node until `quit` (or the process is killed).
pub fn run(own_port: u16, peer_port: u16) {
    let sock = UdpSocket::bind(("127.0.0.1", own_port)).expect("bind");
    sock.set_nonblocking(true).expect("nonblocking");
    let peer = ("127.0.0.1", peer_port);

    let mut c = SL_FSOE_CONN {
        nConnectionId: 0x0107,
        nFsoeAddress: 0x0021,
        nRole: SL_FSOE_ROLE_MASTER,
        nTxDataLen: DATA_LEN,
        nRxDataLen: DATA_LEN,
        tWatchdogTime: WATCHDOG_MS,
        ..Default::default()
    };
    assert_eq!(conn::init(&mut c), safelogic::Status::Ok);
    let mut estop = FB_ESTOP {
        wInputActive: 0b11,
        ..Default::default()
    };
    assert_eq!(estop.init(), SL_OK);
    let mut g = SL_GROUP {
        bRun: 1,
        ..Default::default()
    };
    let mut links = [SL_LINK::default(); 3];
    assert_eq!(group::init(&mut g, 2, 3), SL_OK);
    for _ in 0..2 {
        group::reserve_member(&mut g).expect("member");
    }
    {
        let mut m: [&mut dyn Member; 2] = [&mut c, &mut estop];
        let link = |kind, src, so: usize, dst, d: usize| SL_LINK {
            nSrcMember: src,
            nSrcOffset: so as u16,
            nDstMember: dst,
            nDstOffset: d as u16,
            nKind: kind,
            aReserved: [0; 3],
        };
        for l in [
            link(SL_LINK_RXBIT, 0, 0, 1, offset_of!(FB_ESTOP, bEStopIn1)),
            link(SL_LINK_RXBIT, 0, 1, 1, offset_of!(FB_ESTOP, bEStopIn2)),
            link(SL_LINK_TXBIT, 1, offset_of!(FB_ESTOP, bEStopOut), 0, 0),
        ] {
            assert_eq!(group::add_link(&mut g, &mut m[..], &mut links, l), SL_OK);
        }
    }

    let (cmd_tx, cmd_rx) = mpsc::channel::<String>();
    std::thread::spawn(move || {
        for line in std::io::stdin().lock().lines() {
            let Ok(line) = line else { break };
            if cmd_tx.send(line.trim().to_string()).is_err() {
                break;
            }
        }
    });

    let start = Instant::now();
    let mut rng = 0x9E37_79B9_7F4A_7C15u64 ^ u64::from(std::process::id());
    let mut sent_count = c.nTxCount;
    let mut last_rx = 0u32;
    let mut shown: Option<Status> = None;
    let mut restart_pulse = 0u8;
    let mut ack_pulse = 0u8;
    let mut buf = [0u8; 128];
    let mut prev = 0u32;
    loop {
        let now = start.elapsed().as_millis() as u32;
        // The time since the previous cycle (a loaded machine stretches it).
        let gap = now.wrapping_sub(prev);
        prev = now;
        // The newest datagram of the right size is this cycle's received frame.
        c.nRxFrameLen = 0;
        while let Ok(n) = sock.recv(&mut buf) {
            if n <= c.aRxFrame.len() {
                c.aRxFrame[..n].copy_from_slice(&buf[..n]);
                c.nRxFrameLen = n as u16;
                last_rx = now;
            }
        }
        while let Ok(cmd) = cmd_rx.try_recv() {
            match cmd.as_str() {
                "restart" => restart_pulse = 3,
                "ack" => ack_pulse = 3,
                "quit" => return,
                _ => eprintln!("commands: restart, ack, quit"),
            }
        }
        // A pulse: TRUE for two cycles, then FALSE (the falling edge acts).
        estop.bRestart = u8::from(restart_pulse > 1);
        restart_pulse = restart_pulse.saturating_sub(1);
        g.bErrAck = u8::from(ack_pulse > 1);
        ack_pulse = ack_pulse.saturating_sub(1);
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        c.nSessionIdSeed = (rng >> 32) as u16;

        {
            let mut m: [&mut dyn Member; 2] = [&mut c, &mut estop];
            group::cycle(&mut g, &mut m[..], &links, now);
        }
        if c.nTxCount != sent_count && c.nTxFrameLen > 0 {
            sent_count = c.nTxCount;
            let _ = sock.send_to(&c.aTxFrame[..usize::from(c.nTxFrameLen)], peer);
        }
        let s = Status {
            group: g.nState,
            diag: g.nDiag,
            com_err: g.bComErr,
            startup: g.bComStartup,
            conn: c.nState,
            inputs: (estop.bEStopIn1, estop.bEStopIn2),
            out: estop.bEStopOut,
        };
        if shown != Some(s) {
            println!(
                "status t={now} group={} diag={} comerr={} startup={} conn={} in={}{} out={} since_rx={} gap={gap}",
                s.group,
                s.diag,
                s.com_err,
                s.startup,
                s.conn,
                s.inputs.0,
                s.inputs.1,
                s.out,
                now.wrapping_sub(last_rx)
            );
            shown = Some(s);
        }
        std::thread::sleep(Duration::from_millis(1));
    }
}

#[allow(dead_code)]
fn main() {
    let args: Vec<u16> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("a UDP port"))
        .collect();
    let [own, peer] = args[..] else {
        eprintln!("usage: fsoe_master <own UDP port> <slave UDP port>");
        std::process::exit(2);
    };
    run(own, peer);
}
