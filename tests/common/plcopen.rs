//! Shared pieces of the PLCopen `SF_` block tests: the (v2.01, v1.0) code pairs of the
//! research tables and the two diagnostic profiles.

use super::Rng;
use safelogic::*;
use std::collections::BTreeSet;

/// A state's DiagCode in the (v2.01, v1.0) profiles.
pub type Code = (u16, u16);

/// Both diagnostic profiles, v2.01 first.
pub fn profiles() -> [u8; 2] {
    [SL_SF_PROFILE_V201, SL_SF_PROFILE_V10]
}

/// The code of `s` in `profile`.
pub fn code(profile: u8, s: Code) -> u16 {
    if profile == SL_SF_PROFILE_V10 {
        s.1
    } else {
        s.0
    }
}

/// `const NAME: Code = (v2.01, v1.0);` for every entry and `ALL`, every one in order.
/// Several entries share a line: it is a table.
#[allow(unused_macros)]
macro_rules! codes {
    ($($name:ident = $v2:literal / $v1:literal),* $(,)?) => {
        $(const $name: Code = ($v2, $v1);)*
        const ALL: [Code; [$($v2),*].len()] = [$($name),*];
    };
}
#[allow(unused_imports)]
pub(crate) use codes;

/// A random walk checked against a model: per profile, `seqs` sequences of `calls` calls,
/// drawn from `Rng(seed ^ profile)`; each profile's sequences together reach every state.
pub struct Walk<'a> {
    /// Names the block in failure messages.
    pub name: &'a str,
    pub seed: u64,
    pub profiles: Vec<u8>,
    pub seqs: usize,
    pub calls: usize,
    /// Every state (as the model numbers it) the sequences of a profile must reach.
    pub states: Vec<u16>,
}

impl<'a> Walk<'a> {
    /// Both profiles, 10,000 sequences of 40 calls.
    pub fn new(name: &'a str, seed: u64, states: impl IntoIterator<Item = u16>) -> Self {
        Walk {
            name,
            seed,
            profiles: profiles().to_vec(),
            seqs: 10_000,
            calls: 40,
            states: states.into_iter().collect(),
        }
    }

    /// `start` makes a sequence's case from the profile, the sequence's index and the
    /// generator; `call` makes one call of it, asserts the block against the model (its
    /// messages name the case) and returns the model's state.
    pub fn run<C>(
        &self,
        mut start: impl FnMut(u8, usize, &mut Rng) -> C,
        mut call: impl FnMut(&mut C, u8, &mut Rng) -> u16,
    ) {
        for &p in &self.profiles {
            let mut rng = Rng(self.seed ^ u64::from(p));
            let mut reached = BTreeSet::new();
            for seq in 0..self.seqs {
                let mut case = start(p, seq, &mut rng);
                for _ in 0..self.calls {
                    reached.insert(call(&mut case, p, &mut rng));
                }
            }
            let every: BTreeSet<u16> = self.states.iter().copied().collect();
            assert_eq!(
                reached, every,
                "{} profile {p}: every state reached",
                self.name
            );
        }
    }
}

/// Per sequence, how often each of `N` inputs changes: once in 2 to 11 calls.
pub fn rates<const N: usize>(rng: &mut Rng) -> [u64; N] {
    core::array::from_fn(|_| 2 + rng.next() % 10)
}

/// One call's input changes (`f[k]` once in `rates[k]` calls); Activate (input 0) mostly
/// stays as it is once TRUE and is soon set again once FALSE.
pub fn flips<const N: usize>(rng: &mut Rng, rates: &[u64; N], activate: &mut bool) -> [bool; N] {
    let f: [bool; N] = core::array::from_fn(|k| rng.next() % rates[k] == 0);
    *activate = if *activate {
        !(f[0] && rng.next() % 4 == 0)
    } else {
        f[0] || rng.next() % 3 == 0
    };
    f
}

/// One step of a transition table: the inputs changed before the call, the state expected
/// after it, and what the step shows ("" where the case's comment says it).
pub type Step<I> = (fn(&mut I), Code, &'static str);

/// A case of a transition table: the state it starts in and its steps.
pub type Case<'a, I> = (Code, &'a [Step<I>]);

/// Runs a transition table: each case starts in its state (`reach` gives a rig there and
/// its inputs) and makes its steps; `call` makes one call with the inputs and returns what
/// the call gave and what the step's state expects. A failure names the table (`label`:
/// block, profile), the case (its index and state), the step and its note.
#[track_caller]
pub fn step_table<R, I: Copy, T: PartialEq + std::fmt::Debug>(
    label: &str,
    cases: &[Case<I>],
    mut reach: impl FnMut(Code) -> (R, I),
    mut call: impl FnMut(&mut R, I, Code) -> (T, T),
) {
    for (k, (from, steps)) in cases.iter().enumerate() {
        let (mut rig, mut i) = reach(*from);
        for (n, (set, want, note)) in steps.iter().enumerate() {
            set(&mut i);
            let (got, expected) = call(&mut rig, i, *want);
            assert_eq!(
                got, expected,
                "{label}, case {k} from {from:04X?}, step {n}: {note}"
            );
        }
    }
}

/// R_TRIG as the PLCopen tables read an input: `(rising edge, static TRUE)` of `now`
/// against its value in the previous call, which `prev` keeps.
pub fn edges(prev: &mut bool, now: bool) -> (bool, bool) {
    let rt = now && !*prev;
    *prev = now;
    (rt, now && !rt)
}

/// A model's move to `next` at `now`: `since` (the time the state was entered) moves only
/// when the state changes. Returns `next`.
pub fn enter(state: &mut u16, since: &mut u32, next: u16, now: u32) -> u16 {
    if next != *state {
        *since = now;
    }
    *state = next;
    next
}
