//! The allowed values of a field: a [`Range`] of numbers with its two [`Bound`]s, or
//! [`Allowed`] in words (a range, a range or named values, or text), as an error states them.

use super::{fmt_value, Error, Field, Result};
use std::fmt;

/// One end of an allowed range.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Bound {
    /// The end value is allowed (`<=`).
    Inclusive(f64),
    /// Values must stay strictly beyond it (`<`).
    Exclusive(f64),
    /// No limit on this side.
    Unbounded,
}

/// An allowed interval of numbers, optionally whole numbers only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    /// Lower end.
    pub lo: Bound,
    /// Upper end.
    pub hi: Bound,
    /// Whole numbers only (counts, grid sides, seeds).
    pub whole: bool,
}

impl Range {
    /// `lo <= x <= hi`.
    pub const fn closed(lo: f64, hi: f64) -> Range {
        Range {
            lo: Bound::Inclusive(lo),
            hi: Bound::Inclusive(hi),
            whole: false,
        }
    }

    /// Whole numbers `lo <= n <= hi`.
    pub const fn whole(lo: f64, hi: f64) -> Range {
        Range {
            lo: Bound::Inclusive(lo),
            hi: Bound::Inclusive(hi),
            whole: true,
        }
    }

    /// `lo < x <= hi`.
    pub const fn open_closed(lo: f64, hi: f64) -> Range {
        Range {
            lo: Bound::Exclusive(lo),
            hi: Bound::Inclusive(hi),
            whole: false,
        }
    }

    /// `x > lo` (finite).
    pub const fn above(lo: f64) -> Range {
        Range {
            lo: Bound::Exclusive(lo),
            hi: Bound::Unbounded,
            whole: false,
        }
    }

    /// `x >= lo` (finite).
    pub const fn at_least(lo: f64) -> Range {
        Range {
            lo: Bound::Inclusive(lo),
            hi: Bound::Unbounded,
            whole: false,
        }
    }

    /// Whether `x` lies in the range (NaN never does; an unbounded end still excludes ±∞).
    pub fn contains(&self, x: f64) -> bool {
        let lo = match self.lo {
            Bound::Inclusive(l) => x >= l,
            Bound::Exclusive(l) => x > l,
            Bound::Unbounded => x > f64::NEG_INFINITY,
        };
        let hi = match self.hi {
            Bound::Inclusive(h) => x <= h,
            Bound::Exclusive(h) => x < h,
            Bound::Unbounded => x < f64::INFINITY,
        };
        lo && hi && (!self.whole || x.fract() == 0.0)
    }

    /// Checks `value` for `field`.
    ///
    /// # Errors
    /// [`Error::Invalid`] for `field` with this range when `value` lies outside it (or is NaN).
    pub fn check(&self, field: Field, value: f64) -> Result<f64> {
        if self.contains(value) {
            Ok(value)
        } else {
            Err(Error::invalid(field, value, *self))
        }
    }

    /// The range in words about a quantity called `name`, e.g. `1e-12 <= pressure <= 1000`,
    /// `a whole number 1 <= points <= 100000`, `range_m > 0`.
    pub fn describe(&self, name: &str) -> String {
        let lo = match self.lo {
            Bound::Inclusive(l) => Some(format!("{} <= ", fmt_value(l))),
            Bound::Exclusive(l) => Some(format!("{} < ", fmt_value(l))),
            Bound::Unbounded => None,
        };
        let hi = match self.hi {
            Bound::Inclusive(h) => Some(format!(" <= {}", fmt_value(h))),
            Bound::Exclusive(h) => Some(format!(" < {}", fmt_value(h))),
            Bound::Unbounded => None,
        };
        let core = match (lo, hi) {
            (Some(l), Some(h)) => format!("{l}{name}{h}"),
            (Some(l), None) => {
                // "0 < x" reads better as "x > 0"
                let (v, op) = match self.lo {
                    Bound::Exclusive(l) => (l, ">"),
                    Bound::Inclusive(l) => (l, ">="),
                    Bound::Unbounded => unreachable!(),
                };
                let _ = l;
                format!("{name} {op} {}", fmt_value(v))
            }
            (None, Some(h)) => format!("{name}{h}"),
            (None, None) => format!("{name} finite"),
        };
        if self.whole {
            format!("a whole number {core}")
        } else {
            core
        }
    }
}

/// What a field accepts: the typed bound an [`Error::Invalid`] carries, which each front end
/// renders in its own words ([`Allowed::describe`] is the library's).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Allowed {
    /// A numeric interval.
    Range(Range),
    /// A numeric interval or one of the named values (e.g. `inf` for the thickness).
    RangeOr(Range, Vec<String>),
    /// One of a list of choices.
    Choices(Vec<String>),
    /// A condition that is neither a range nor a list (e.g. W(a) >= 0 on [0, 1]), in words.
    Text(String),
}

impl Allowed {
    /// A list of choices.
    pub fn choices<S: ToString>(items: impl IntoIterator<Item = S>) -> Allowed {
        Allowed::Choices(items.into_iter().map(|s| s.to_string()).collect())
    }

    /// The allowed values in words, naming the quantity `name` inside a range.
    pub fn describe(&self, name: &str) -> String {
        match self {
            Allowed::Range(r) => r.describe(name),
            Allowed::RangeOr(r, extra) => format!("{}, or {}", r.describe(name), extra.join(" or ")),
            Allowed::Choices(c) => match c.len() {
                0 => "nothing".into(),
                1 => c[0].clone(),
                n => format!("{} or {}", c[..n - 1].join(", "), c[n - 1]),
            },
            Allowed::Text(t) => t.clone(),
        }
    }

    /// The numeric range, where there is one.
    pub fn range(&self) -> Option<&Range> {
        match self {
            Allowed::Range(r) | Allowed::RangeOr(r, _) => Some(r),
            _ => None,
        }
    }
}

impl fmt::Display for Allowed {
    /// [`Allowed::describe`] with the quantity called `value`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe("value"))
    }
}

impl From<Range> for Allowed {
    fn from(r: Range) -> Allowed {
        Allowed::Range(r)
    }
}

impl From<String> for Allowed {
    fn from(s: String) -> Allowed {
        Allowed::Text(s)
    }
}

impl From<&str> for Allowed {
    fn from(s: &str) -> Allowed {
        Allowed::Text(s.to_string())
    }
}

impl From<&String> for Allowed {
    fn from(s: &String) -> Allowed {
        Allowed::Text(s.clone())
    }
}
