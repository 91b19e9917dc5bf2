//! The connection block: CONNECTION SHUTDOWN, which a group wires to its FSoE
//! connection(s) by Connection ID.

pub mod connshutdown;
