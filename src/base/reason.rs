//! Why a block refuses its parameters: every block's parameter check is a list of rules
//! ([`RuleDef`]), each naming the field it reads, the kind of rule ([`Rule`]) and the
//! manual's Text ID where the manual has one. The first rule a configuration breaks is its
//! [`Refusal`]: the field, the rule and the offending values, which `sl_reason_text` writes
//! as one sentence ("TWOHAND: tDiscTimePairs (3000 ms) must be <= 500 ms"). The status
//! stays what it was (SL_E_CONFIG, or a PLCopen parameter error); nothing is stored in the
//! block, so the sentence is computed again from the caller's struct when asked.

/// How a value is written in a sentence.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// A plain integer.
    Plain,
    /// Milliseconds ("500 ms").
    Ms,
    /// A bit mask or option word ("0x0300").
    Hex,
}

/// The kind of rule a parameter breaks. `a` is the offending value, `b` the bound or the
/// other value the rule compares it with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// a ≤ b (a limit of the manual or of the library).
    AtMost,
    /// a ≥ b.
    AtLeast,
    /// a ≠ 0.
    NotZero,
    /// a = b (the one value allowed).
    Equals,
    /// a is a multiple of b.
    MultipleOf,
    /// a is one of the values listed.
    OneOf(&'static str),
    /// a has no bit outside the mask b.
    NoBitsOutside,
    /// a has every bit of the mask b set.
    BitsSet,
    /// a has at least one bit of the mask b set.
    AnyBitOf,
    /// a has every bit of the mask b clear.
    BitsClear,
    /// a ≠ 0 when the named condition holds.
    NotZeroWhen(&'static str),
    /// a has the bits of the mask b both set or both clear.
    BothOrNeither,
    /// a has at least b bits set.
    MinBits,
    /// a ≤ the named other field (b).
    NotAbove(&'static str),
    /// a < the named other field (b).
    Below(&'static str),
    /// a > the named other field (b).
    Above(&'static str),
    /// a ≠ 0 needs the bits b set in the named field.
    Needs(&'static str),
    /// a = 0 unless the named condition holds (b: the condition's field value).
    ZeroUnless(&'static str),
    /// The manual's relation of a Text ID ("TDC1UpperLimit must be > AllowedPositionJitter"),
    /// with the message's parameters 2 and 3 (a, b).
    Message(&'static str),
}

/// The documented library reason codes: one per kind of rule, for a refusal the manual has
/// no Text ID for (docs/c-integration.md lists them).
pub const SL_REASON_CODE_BASE: u16 = 0xE000;

impl Rule {
    /// The library reason code of this kind of rule.
    pub const fn code(self) -> u16 {
        SL_REASON_CODE_BASE
            + match self {
                Rule::AtMost => 1,
                Rule::AtLeast => 2,
                Rule::NotZero => 3,
                Rule::Equals => 4,
                Rule::MultipleOf => 5,
                Rule::OneOf(_) => 6,
                Rule::NoBitsOutside => 7,
                Rule::BitsSet => 8,
                Rule::BothOrNeither => 9,
                Rule::MinBits => 10,
                Rule::NotAbove(_) => 11,
                Rule::Below(_) => 12,
                Rule::Above(_) => 13,
                Rule::Needs(_) => 14,
                Rule::ZeroUnless(_) => 15,
                Rule::Message(_) => 16,
                Rule::AnyBitOf => 17,
                Rule::BitsClear => 18,
                Rule::NotZeroWhen(_) => 19,
            }
    }
}

/// What a rule says without its test: the field, the rule, how its values are written and
/// its code (the manual's Text ID, or 0 for the rule's library code).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RuleInfo {
    /// The C field the rule reads (for a table row, the row's field).
    pub field: &'static str,
    /// The kind of rule.
    pub rule: Rule,
    /// How `a` and `b` are written.
    pub unit: Unit,
    /// The manual's Text ID, 0 = none (the library code [`Rule::code`] applies).
    pub text_id: u16,
}

impl RuleInfo {
    /// The code a refusal by this rule reports: the manual's Text ID or the library code.
    pub const fn code(&self) -> u16 {
        if self.text_id != 0 {
            self.text_id
        } else {
            self.rule.code()
        }
    }
}

/// A broken rule's values: `a`, `b` and, for a table rule, the row (1-based).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Hit {
    /// The offending value.
    pub a: i64,
    /// The bound or other value.
    pub b: i64,
    /// The table row (1-based), 0 = not a table rule.
    pub row: u8,
    /// The field, where one rule covers several fields (a discrepancy time of any pair);
    /// "" = the rule's field.
    pub field: &'static str,
}

impl Hit {
    /// The same values found in the field `name`.
    pub const fn in_field(mut self, name: &'static str) -> Self {
        self.field = name;
        self
    }

    /// The same values found in table row `row` (1-based).
    pub const fn in_row(mut self, row: u8) -> Self {
        self.row = row;
        self
    }
}

/// `Some(Hit)` when `bad`: the values of a broken rule.
#[inline]
pub fn when(bad: bool, a: impl Into<i64>, b: impl Into<i64>) -> Option<Hit> {
    bad.then(|| Hit {
        a: a.into(),
        b: b.into(),
        row: 0,
        field: "",
    })
}

/// One rule of a block's parameter check over its parameters `P`.
pub struct RuleDef<P> {
    /// What the rule says.
    pub info: RuleInfo,
    /// The rule's test: the values when `P` breaks it.
    pub test: fn(&P) -> Option<Hit>,
}

impl<P> RuleDef<P> {
    /// A rule with the library's code.
    pub const fn new(
        field: &'static str,
        rule: Rule,
        unit: Unit,
        test: fn(&P) -> Option<Hit>,
    ) -> Self {
        Self {
            info: RuleInfo {
                field,
                rule,
                unit,
                text_id: 0,
            },
            test,
        }
    }

    /// The same rule with the manual's Text ID.
    pub const fn text_id(mut self, id: u16) -> Self {
        self.info.text_id = id;
        self
    }
}

/// The common rules in one line each, over the parameter value `|p| v`:
/// `rule!(equals "wInputActive", |p| p.active, WANT)` (hex, v = WANT),
/// `rule!(no_bits_outside "dwOptions", |p| p.options, KNOWN)` (hex, no bit outside KNOWN),
/// `rule!(at_most "tDelay" in Ms, |p| p.delay, MAX)` (v ≤ MAX),
/// `rule!(not_zero "tDelay" in Ms, |p| p.delay)` (v ≠ 0).
macro_rules! rule {
    (@ $field:literal, $rule:ident, $unit:ident, |$p:ident| $test:expr) => {
        $crate::base::reason::RuleDef::new(
            $field,
            $crate::base::reason::Rule::$rule,
            $crate::base::reason::Unit::$unit,
            |$p| $test,
        )
    };
    (equals $field:literal, |$p:ident| $v:expr, $want:expr) => {
        $crate::base::reason::rule!(@ $field, Equals, Hex, |$p| {
            let want = $want;
            $crate::base::reason::when($v != want, $v, want)
        })
    };
    (no_bits_outside $field:literal, |$p:ident| $v:expr, $known:expr) => {
        $crate::base::reason::rule!(@ $field, NoBitsOutside, Hex, |$p| {
            let known = $known;
            $crate::base::reason::when($v & !known != 0, $v, known)
        })
    };
    (at_most $field:literal in $unit:ident, |$p:ident| $v:expr, $max:expr) => {
        $crate::base::reason::rule!(@ $field, AtMost, $unit, |$p| $crate::base::reason::when($v > $max, $v, $max))
    };
    (not_zero $field:literal in $unit:ident, |$p:ident| $v:expr) => {
        $crate::base::reason::rule!(@ $field, NotZero, $unit, |$p| $crate::base::reason::when($v == 0, 0, 0))
    };
}
pub(crate) use rule;

/// The first rule of `rules` that `p` breaks, with its index in `rules`.
pub fn check<P>(rules: &[RuleDef<P>], p: &P) -> Option<Refusal> {
    rules.iter().enumerate().find_map(|(i, r)| {
        (r.test)(p).map(|hit| Refusal {
            index: i,
            info: r.info,
            hit,
        })
    })
}

/// A refused configuration: the rule it breaks (index in the block's list) and the values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// The index of the rule in the block's list.
    pub index: usize,
    /// What the rule says.
    pub info: RuleInfo,
    /// The values.
    pub hit: Hit,
}

impl Refusal {
    /// The sentence: `"<block>[ row N]: <field> (<a>) <rule>"`, then the code
    /// ("LIMIT_INT: nMinimumValue (5) must be <= nMaximumValue (3) [Text ID 0x4090]").
    pub fn write(&self, block: &str, w: &mut Writer) {
        let RuleInfo {
            field, rule, unit, ..
        } = self.info;
        let Hit { a, b, row, .. } = self.hit;
        let field = if self.hit.field.is_empty() {
            field
        } else {
            self.hit.field
        };
        w.push(block);
        if row != 0 {
            w.push(" row ");
            w.int(i64::from(row));
        }
        w.push(": ");
        w.push(field);
        if let Rule::Message(text) = rule {
            // The manual's relation, with the message's parameters.
            w.push(": ");
            w.push(text);
            w.push(" (Par2 ");
            w.int(a);
            w.push(", Par3 ");
            w.int(b);
            w.push(")");
        } else {
            w.push(" (");
            w.value(a, unit);
            w.push(") ");
        }
        match rule {
            Rule::AtMost => w.rel("must be <= ", b, unit),
            Rule::AtLeast => w.rel("must be >= ", b, unit),
            Rule::NotZero => w.push("must not be 0"),
            Rule::Equals => w.rel("must be ", b, unit),
            Rule::MultipleOf => w.rel("must be a multiple of ", b, unit),
            Rule::OneOf(list) => {
                w.push("must be one of ");
                w.push(list);
            }
            Rule::NoBitsOutside => w.rel("has bits outside ", b, Unit::Hex),
            Rule::BitsSet => {
                w.rel("must have bits ", b, Unit::Hex);
                w.push(" set");
            }
            Rule::AnyBitOf => {
                w.rel("must have one of the bits ", b, Unit::Hex);
                w.push(" set");
            }
            Rule::BitsClear => {
                w.rel("must have bits ", b, Unit::Hex);
                w.push(" clear");
            }
            Rule::NotZeroWhen(cond) => {
                w.push("must not be 0 when ");
                w.push(cond);
            }
            Rule::BothOrNeither => {
                w.rel("must have bits ", b, Unit::Hex);
                w.push(" both set or both clear");
            }
            Rule::MinBits => {
                w.rel("must have at least ", b, Unit::Plain);
                w.push(" bits set");
            }
            Rule::NotAbove(other) => w.other("must be <= ", other, b, unit),
            Rule::Below(other) => w.other("must be < ", other, b, unit),
            Rule::Above(other) => w.other("must be > ", other, b, unit),
            Rule::Needs(other) => {
                w.push("needs ");
                w.push(other);
                w.rel(" bits ", b, Unit::Hex);
                w.push(" set");
            }
            Rule::ZeroUnless(cond) => {
                w.push("must be 0 unless ");
                w.push(cond);
            }
            Rule::Message(_) => {}
        }
        if self.info.text_id != 0 {
            w.push(" [Text ID ");
            w.hex(i64::from(self.info.text_id), 4);
        } else {
            w.push(" [reason ");
            w.hex(i64::from(rule.code()), 4);
        }
        w.push("]");
    }
}

/// Writes text into a byte buffer, truncating where it is full.
pub struct Writer<'a> {
    out: &'a mut [u8],
    len: usize,
}

impl<'a> Writer<'a> {
    /// An empty writer over `out`.
    pub fn new(out: &'a mut [u8]) -> Self {
        Self { out, len: 0 }
    }

    /// Bytes written.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Nothing written yet.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends `s` (as much as fits).
    pub fn push(&mut self, s: &str) {
        self.bytes(s.as_bytes());
    }

    fn bytes(&mut self, s: &[u8]) {
        let room = self.out.len().saturating_sub(self.len);
        let n = s.len().min(room);
        if let (Some(dst), Some(src)) = (self.out.get_mut(self.len..self.len + n), s.get(..n)) {
            dst.copy_from_slice(src);
            self.len += n;
        }
    }

    /// Appends a decimal integer.
    pub fn int(&mut self, v: i64) {
        let mut digits = [0u8; 20];
        let mut n = v.unsigned_abs();
        let mut i = digits.len();
        loop {
            i -= 1;
            digits[i] = b'0' + (n % 10) as u8;
            n /= 10;
            if n == 0 {
                break;
            }
        }
        if v < 0 {
            self.push("-");
        }
        self.bytes(&digits[i..]);
    }

    /// Appends `0x` and at least `width` upper-case hex digits.
    pub fn hex(&mut self, v: i64, width: usize) {
        let v = v as u64;
        let mut digits = [0u8; 16];
        let mut n = v;
        let mut i = digits.len();
        while n != 0 || digits.len() - i < width {
            i -= 1;
            digits[i] = b"0123456789ABCDEF"[(n & 0xF) as usize];
            n >>= 4;
        }
        self.push("0x");
        self.bytes(&digits[i..]);
    }

    /// Appends a value in its unit.
    pub fn value(&mut self, v: i64, unit: Unit) {
        match unit {
            Unit::Plain => self.int(v),
            Unit::Ms => {
                self.int(v);
                self.push(" ms");
            }
            Unit::Hex => self.hex(v, 4),
        }
    }

    fn rel(&mut self, words: &str, b: i64, unit: Unit) {
        self.push(words);
        self.value(b, unit);
    }

    fn other(&mut self, words: &str, other: &str, b: i64, unit: Unit) {
        self.push(words);
        self.push(other);
        self.push(" (");
        self.value(b, unit);
        self.push(")");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sentence(r: &Refusal) -> String {
        let mut buf = [0u8; 200];
        let mut w = Writer::new(&mut buf);
        r.write("X", &mut w);
        let n = w.len();
        String::from_utf8(buf[..n].to_vec()).unwrap()
    }

    #[test]
    fn sentences_name_field_rule_values_and_code() {
        let rules: [RuleDef<(u32, i32)>; 2] = [
            RuleDef::new("tA", Rule::AtMost, Unit::Ms, |p: &(u32, i32)| {
                when(p.0 > 500, p.0, 500)
            }),
            RuleDef::new("nB", Rule::NotAbove("nC"), Unit::Plain, |p: &(u32, i32)| {
                when(p.1 > -100, p.1, -100)
            })
            .text_id(0x4090),
        ];
        assert_eq!(check(&rules, &(500, -100)), None);
        let r = check(&rules, &(3000, 0)).unwrap();
        assert_eq!(r.index, 0);
        assert_eq!(
            sentence(&r),
            "X: tA (3000 ms) must be <= 500 ms [reason 0xE001]"
        );
        let r = check(&rules, &(1, -80)).unwrap();
        assert_eq!(
            sentence(&r),
            "X: nB (-80) must be <= nC (-100) [Text ID 0x4090]"
        );
        let mut small = [0u8; 4];
        let mut w = Writer::new(&mut small);
        w.int(i64::MIN);
        assert_eq!(w.len(), 4);
        assert_eq!(&small, b"-922");
    }
}
