//! The loader: a checked [`Project`] becomes groups of [`AnyBlock`]s in `Vec`s (loading
//! allocates), wired through `safelogic::group::add_link`. [`Runtime::cycle`] and the
//! process-image reads and writes do not allocate (tests/alloc.rs in this crate).

use crate::project::{Place, Project};
use safelogic::any::AnyBlock;
use safelogic::group::{self, link_kind, Member, SL_LINK};
use safelogic::{SL_GROUP, SL_OK};

/// One loaded group.
#[derive(Debug)]
pub struct LoadedGroup {
    /// The group's struct.
    pub g: SL_GROUP,
    /// Its members in execution order.
    pub blocks: Vec<AnyBlock>,
    /// Its links (sorted by the group).
    pub links: Vec<SL_LINK>,
}

/// A loaded project, ready to cycle.
#[derive(Debug)]
pub struct Runtime {
    /// The groups, in execution order.
    pub groups: Vec<LoadedGroup>,
}

/// The group's name for its state value.
pub fn group_state_name(s: u8) -> &'static str {
    match s {
        safelogic::SL_STATE_RUN => "RUN",
        safelogic::SL_STATE_STOP => "STOP",
        safelogic::SL_STATE_ERROR => "ERROR",
        safelogic::SL_STATE_RESET => "RESET",
        group::SL_GROUP_STATE_START => "START",
        group::SL_GROUP_STATE_STOPERROR => "STOPERROR",
        _ => "?",
    }
}

impl Runtime {
    /// Builds every group of the project: members through the registry (values, init),
    /// then the links. A group whose `bRun` no process-image input drives runs (TRUE).
    pub fn load(p: &Project) -> Result<Runtime, String> {
        let mut groups = Vec::new();
        for (gi, pg) in p.groups.iter().enumerate() {
            let blocks = pg
                .members
                .iter()
                .map(|m| m.build().map_err(|e| format!("member `{}`: {e}", m.name)))
                .collect::<Result<Vec<_>, _>>()?;
            let n = u16::try_from(blocks.len()).map_err(|_| "too many members")?;
            let nl = u16::try_from(pg.links.len()).map_err(|_| "too many links")?;
            let run_driven = p.inputs.iter().flat_map(|s| &s.places).any(
                |pl| matches!(pl, Place::Group { group, field } if *group == gi && *field == "bRun"),
            );
            let mut lg = LoadedGroup {
                g: SL_GROUP {
                    bConnections: u8::from(pg.connections),
                    ..Default::default()
                },
                blocks,
                links: vec![SL_LINK::default(); pg.links.len()],
            };
            if group::init(&mut lg.g, n, nl) != SL_OK {
                return Err(format!("group `{}`: init refused", pg.name));
            }
            lg.g.bRun = u8::from(!run_driven);
            for _ in 0..n {
                group::reserve_member(&mut lg.g)
                    .map_err(|e| format!("group `{}`: {e}", pg.name))?;
            }
            for l in &pg.links {
                let link = SL_LINK {
                    nSrcMember: l.src as u16,
                    nSrcOffset: l.src_field.offset,
                    nDstMember: l.dst as u16,
                    nDstOffset: l.dst_field.offset,
                    nKind: link_kind(l.src_field.kind).ok_or("unlinkable type")?,
                    aReserved: [0; 3],
                };
                let rc = group::add_link(&mut lg.g, &mut lg.blocks[..], &mut lg.links, link);
                if rc != SL_OK {
                    return Err(format!("group `{}`: link refused ({rc})", pg.name));
                }
            }
            groups.push(lg);
        }
        Ok(Runtime { groups })
    }

    /// Writes a process-image input (a member input or a group input).
    pub fn write(&mut self, place: &Place, value: i64) {
        match *place {
            Place::Member {
                group,
                member,
                field,
            } => {
                self.groups[group].blocks[member].set_input_bits(field.offset, value as u32);
            }
            Place::Group { group, field } => {
                let g = &mut self.groups[group].g;
                let v = u8::from(value != 0);
                match field {
                    "bRun" => g.bRun = v,
                    "bErrAck" => g.bErrAck = v,
                    "bModuleFault" => g.bModuleFault = v,
                    "bComErrIn" => g.bComErrIn = v,
                    _ => g.bComStartupIn = v,
                }
            }
        }
    }

    /// Reads any place (signed types as signed).
    pub fn read(&self, place: &Place) -> i64 {
        match *place {
            Place::Member {
                group,
                member,
                field,
            } => self.groups[group].blocks[member].value(field).unwrap_or(0),
            Place::Group { group, field } => {
                let g = &self.groups[group].g;
                i64::from(match field {
                    "bRun" => g.bRun,
                    "bErrAck" => g.bErrAck,
                    "bModuleFault" => g.bModuleFault,
                    "bComErrIn" => g.bComErrIn,
                    "bComStartupIn" => g.bComStartupIn,
                    "bComErr" => g.bComErr,
                    "bFbErr" => g.bFbErr,
                    "bOtherErr" => g.bOtherErr,
                    "bComStartup" => g.bComStartup,
                    "bFbRun" => g.bFbRun,
                    "bInRun" => g.bInRun,
                    "nState" => g.nState,
                    _ => return i64::from(g.nDiag),
                })
            }
        }
    }

    /// One task cycle at `now`: every group in order. Returns the worst status (SL_OK
    /// or the first non-OK one).
    pub fn cycle(&mut self, now: u32) -> i32 {
        let mut rc = SL_OK;
        for lg in &mut self.groups {
            let r = group::cycle(&mut lg.g, &mut lg.blocks[..], &lg.links, now);
            if rc == SL_OK {
                rc = r;
            }
        }
        rc
    }

    /// The state name of member `m` of group `g`.
    pub fn member_state(&self, g: usize, m: usize) -> &'static str {
        self.groups[g].blocks[m].state_name()
    }

    /// The state name of group `g`.
    pub fn group_state(&self, g: usize) -> &'static str {
        group_state_name(self.groups[g].g.nState)
    }
}
