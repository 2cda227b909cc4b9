//! The library's range table ([`asperity::limits`]) for the Python side of every argument:
//! `asperity/_args.py` converts each argument (its type, a count's wholeness, a value's range)
//! before the extension sees it, so that a wrong type, a negative count or a huge integer is
//! an `InputError` naming the argument and the range the CLI states for its flag, never
//! PyO3's `OverflowError` or an unnamed `TypeError`.
//!
//! [`allowed`] gives a field's range by its canonical key ([`asperity::error::Field::key`]); a few arguments
//! that have no library field (a seed, the PSD's bins per decade, the yp08/xu24 fudge factor)
//! have their ranges here, from the library's constants, under keys of the same style.

use asperity::error::{Allowed, Bound as End, Range};
use asperity::limits;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The range of the arguments without a library field, by key.
fn own_range(key: &str) -> Option<Range> {
    Some(match key {
        // any u64, as the CLI's --seed
        "gfmd.seed" => Range::whole(0.0, u64::MAX as f64),
        "psd.bins_per_decade" => {
            let (lo, hi) = asperity::surface::psd::BINS_PER_DECADE_RANGE;
            Range::closed(lo, hi)
        }
        "model.fudge_gamma" => {
            let (lo, hi) = asperity::input::model::FUDGE_GAMMA_RANGE;
            Range::open_closed(lo, hi)
        }
        _ => return None,
    })
}

fn bound(b: End) -> (Option<f64>, bool) {
    match b {
        End::Inclusive(x) => (Some(x), true),
        End::Exclusive(x) => (Some(x), false),
        _ => (None, false),
    }
}

/// `allowed(key, name)`: the range of the field with canonical key `key` as a dict (`lo`,
/// `lo_inclusive`, `hi`, `hi_inclusive` (None: unbounded), `whole`, `named` (values allowed
/// besides the range, e.g. "inf"), `describe`: the range in words about `name`), or None where
/// the field has no numeric range.
#[pyfunction]
pub fn allowed<'py>(py: Python<'py>, key: &str, name: &str) -> PyResult<Option<Bound<'py, PyDict>>> {
    let (range, named, describe) = match limits::FIELDS.iter().find(|f| f.key() == key) {
        Some(f) => match limits::allowed(f) {
            Some(Allowed::Range(r)) => (r, Vec::new(), Allowed::Range(r).describe(name)),
            Some(Allowed::RangeOr(r, named)) => {
                let describe = Allowed::RangeOr(r, named.clone()).describe(name);
                (r, named, describe)
            }
            _ => return Ok(None),
        },
        None => match own_range(key) {
            Some(r) => (r, Vec::new(), r.describe(name)),
            None => return Ok(None),
        },
    };
    let d = PyDict::new(py);
    let (lo, lo_inclusive) = bound(range.lo);
    let (hi, hi_inclusive) = bound(range.hi);
    d.set_item("lo", lo)?;
    d.set_item("lo_inclusive", lo_inclusive)?;
    d.set_item("hi", hi)?;
    d.set_item("hi_inclusive", hi_inclusive)?;
    d.set_item("whole", range.whole)?;
    d.set_item("named", named)?;
    d.set_item("describe", describe)?;
    Ok(Some(d))
}
