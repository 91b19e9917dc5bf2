//! The FSoE CRC (ABI-2 §13.7, fsoe.md §4): CRC-16 with the "Safety polynomial" 0x139B7,
//! register 0, unreflected, no final XOR, over the octets followed by three zero octets
//! (the x^24 factor of the ETG.5100 Annex A two-table routine).

use crc::{Algorithm, Crc};

/// Plain CRC-16 over the FSoE safety polynomial (x^16 implicit).
pub const CRC_16_FSOE_BASE: Algorithm<u16> = Algorithm {
    width: 16,
    poly: 0x39B7,
    init: 0x0000,
    refin: false,
    refout: false,
    xorout: 0x0000,
    check: 0xDDE2,
    residue: 0x0000,
};

const FSOE_CRC: Crc<u16> = Crc::<u16>::new(&CRC_16_FSOE_BASE);

/// CRC_k of one block: `recv_crc0`, `conn_id`, `seq` (little endian), `cmd`, the block index
/// (little endian, only for k > 0) and the block's 1 or 2 octets, then three zero octets.
pub fn fsoe_crc(recv_crc0: u16, conn_id: u16, seq: u16, cmd: u8, index: u16, block: &[u8]) -> u16 {
    let mut d = FSOE_CRC.digest();
    d.update(&recv_crc0.to_le_bytes());
    d.update(&conn_id.to_le_bytes());
    d.update(&seq.to_le_bytes());
    d.update(&[cmd]);
    if index > 0 {
        d.update(&index.to_le_bytes());
    }
    d.update(block);
    d.update(&[0, 0, 0]);
    d.finalize()
}

/// The next sequence number: +1, 65535 wraps to 1 (0 is never used).
pub const fn next_seq(seq: u16) -> u16 {
    if seq == u16::MAX {
        1
    } else {
        seq + 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base_check_value() {
        assert_eq!(FSOE_CRC.checksum(b"123456789"), 0xDDE2);
    }

    #[test]
    fn known_answers() {
        assert_eq!(fsoe_crc(0, 0, 1, 0x4E, 0, &[0x12, 0x34]), 0x4D07);
        assert_eq!(fsoe_crc(0, 0, 1, 0x4E, 0, &[0x12]), 0xA176);
        assert_eq!(fsoe_crc(0xABCD, 7, 2, 0x36, 1, &[0xDE, 0xAD]), 0xBC47);
    }
}
