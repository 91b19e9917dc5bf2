//! The "remote safe I/O" slave of a two-process FSoE pair over a real black channel (UDP on
//! 127.0.0.1): a TwinSAFE group with the FSoE slave connection (member 0) and a DECOUPLE
//! (member 1). DecIn1/DecIn2 are the two channels of an e-stop wired to this node (both
//! TRUE = released), sent to the master as SafeData bits 0 and 1 (`SL_LINK_TXBIT`); bit 0
//! received from the master (its ESTOP's EStopOut) drives DecIn3 (`SL_LINK_RXBIT`), shown
//! at DecOut3 — the safe output of this node. Partner: `examples/fsoe_master.rs`.
//!
//! ```sh
//! cargo run --release --example fsoe_slave -- 40001 40002
//! ```
//! Arguments: own UDP port, the master's UDP port. Commands on stdin: `press` / `release`
//! (the e-stop), `ack` (pulse of the group's ErrAck), `quit`. A `status …` line is printed whenever something changes.

use safelogic::fsoe::conn;
use safelogic::group::{self, Member, SL_LINK_RXBIT, SL_LINK_TXBIT};
use safelogic::*;
use std::io::BufRead;
use std::mem::offset_of;
use std::net::UdpSocket;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// Runs the slave node until `quit` (or the process is killed).
pub fn run(own_port: u16, peer_port: u16) {
    let sock = UdpSocket::bind(("127.0.0.1", own_port)).expect("bind");
    sock.set_nonblocking(true).expect("nonblocking");
    let peer = ("127.0.0.1", peer_port);

    let mut c = SL_FSOE_CONN {
        nConnectionId: 0x0107,
        nFsoeAddress: 0x0021,
        nRole: SL_FSOE_ROLE_SLAVE,
        nTxDataLen: 2,
        nRxDataLen: 2,
        tWatchdogTime: 100,
        ..Default::default()
    };
    assert_eq!(conn::init(&mut c), safelogic::Status::Ok);
    let mut dec = FB_DECOUPLE {
        wInputActive: 0b111,
        bDecIn1: 1,
        bDecIn2: 1,
        ..Default::default()
    };
    assert_eq!(dec.init(), SL_OK);
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
        let mut m: [&mut dyn Member; 2] = [&mut c, &mut dec];
        let link = |kind, src, so: usize, dst, d: usize| SL_LINK {
            nSrcMember: src,
            nSrcOffset: so as u16,
            nDstMember: dst,
            nDstOffset: d as u16,
            nKind: kind,
            aReserved: [0; 3],
        };
        for l in [
            link(SL_LINK_TXBIT, 1, offset_of!(FB_DECOUPLE, bDecOut1), 0, 0),
            link(SL_LINK_TXBIT, 1, offset_of!(FB_DECOUPLE, bDecOut2), 0, 1),
            link(SL_LINK_RXBIT, 0, 0, 1, offset_of!(FB_DECOUPLE, bDecIn3)),
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
    let mut rng = 0xD1B5_4A32_D192_ED03u64 ^ u64::from(std::process::id());
    let mut sent_count = c.nTxCount;
    let mut shown = None;
    let mut ack_pulse = 0u8;
    let mut buf = [0u8; 128];
    loop {
        let now = start.elapsed().as_millis() as u32;
        c.nRxFrameLen = 0;
        while let Ok(n) = sock.recv(&mut buf) {
            if n <= c.aRxFrame.len() {
                c.aRxFrame[..n].copy_from_slice(&buf[..n]);
                c.nRxFrameLen = n as u16;
            }
        }
        while let Ok(cmd) = cmd_rx.try_recv() {
            match cmd.as_str() {
                "press" => (dec.bDecIn1, dec.bDecIn2) = (0, 0),
                "release" => (dec.bDecIn1, dec.bDecIn2) = (1, 1),
                "ack" => ack_pulse = 3,
                "quit" => return,
                _ => eprintln!("commands: press, release, ack, quit"),
            }
        }
        g.bErrAck = u8::from(ack_pulse > 1);
        ack_pulse = ack_pulse.saturating_sub(1);
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        c.nSessionIdSeed = (rng >> 32) as u16;
        {
            let mut m: [&mut dyn Member; 2] = [&mut c, &mut dec];
            group::cycle(&mut g, &mut m[..], &links, now);
        }
        if c.nTxCount != sent_count && c.nTxFrameLen > 0 {
            sent_count = c.nTxCount;
            let _ = sock.send_to(&c.aTxFrame[..usize::from(c.nTxFrameLen)], peer);
        }
        let s = (g.nState, g.bComErr, c.nState, dec.bDecOut3);
        if shown != Some(s) {
            println!(
                "status t={now} group={} comerr={} conn={} out3={}",
                s.0, s.1, s.2, s.3
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
        eprintln!("usage: fsoe_slave <own UDP port> <master UDP port>");
        std::process::exit(2);
    };
    run(own, peer);
}
