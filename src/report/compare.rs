//! The report of a comparison: every model's scores against one reference
//! ([`crate::fit::compare::score`]: per observable, the mean and largest relative error, the
//! L1 distance for Pr(σ*)), what `asperity compare` prints. A model that cannot be evaluated
//! on the scene (a variant without adhesion, a load it does not converge at) is reported with
//! the reason instead of scores.
//!
//! The models are named as front ends take them ([`models`]: the numbered models and the
//! variants, by a comma-separated list) or come from presets. The serialised field names are
//! those of `asperity compare --format json` (a public interface).

use crate::error::{Error, Field, Result};
use crate::fit::compare::{score, Score};
use crate::fit::reference::Reference;
use crate::input::model::{Model, ModelKind};
use crate::input::scene::Scene;
use serde::Serialize;

/// One model's row.
#[derive(Debug, Clone, Serialize)]
pub struct CompareRow {
    /// "model 1".."model 5", "YP08", "Xu24", or the name of the preset it came from.
    pub model: String,
    /// Per observable: observable, points, mean, max (relative errors; L1 for pr).
    pub scores: Vec<Score>,
    /// Why the model has no scores on this scene (e.g. a variant without adhesion); absent
    /// when it has.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// Every model against one reference.
#[derive(Debug, Clone, Serialize)]
pub struct CompareReport {
    /// "eq18", "gfmd" or the table's name.
    pub reference: String,
    /// One row per model, in the order given.
    pub models: Vec<CompareRow>,
}

/// The models of a comma-separated `list` of [`ModelKind`] names other than the custom model
/// (which comes from a preset), each with its label; the variants take their fudge factor from
/// `current` (the scene's model). An empty item is skipped.
///
/// # Errors
/// [`Error::Invalid`] naming `field` for a name that is not a model, or the custom model.
pub fn models(list: &str, current: &Model, field: &Field) -> Result<Vec<(String, Model)>> {
    let mut out = Vec::new();
    for t in list.split(',').map(str::trim).filter(|t| !t.is_empty()) {
        let kind: ModelKind = t.parse().map_err(|_| {
            Error::invalid_text(
                field.clone(),
                t,
                format!("a comma-separated list of {}", ModelKind::named_list()),
            )
        })?;
        if kind == ModelKind::Custom {
            let allowed = format!("{} (a custom model comes from a preset)", ModelKind::named_list());
            return Err(Error::invalid_text(field.clone(), t, allowed));
        }
        let m = Model::of_kind(kind, current)?;
        out.push((m.label(), m));
    }
    Ok(out)
}

/// Scores each of `models` (a name and a model) on `scene` against `reference`. A model that
/// cannot be evaluated gets a note instead: the error as `describe` words it (a front end
/// names the fields in its own terms).
pub fn compare(
    scene: &Scene,
    reference: &Reference,
    models: &[(String, Model)],
    describe: impl Fn(&Error) -> String,
) -> CompareReport {
    let rows = models
        .iter()
        .map(|(name, m)| {
            let (scores, note) = match score(scene, m, reference) {
                Ok(s) => (s, None),
                Err(e) => (Vec::new(), Some(describe(&e))),
            };
            CompareRow {
                model: name.clone(),
                scores,
                note,
            }
        })
        .collect();
    CompareReport {
        reference: reference.name.clone(),
        models: rows,
    }
}

impl CompareReport {
    /// The models of `models` (as given to [`compare`]) that have scores: those a chart can
    /// draw.
    pub fn scored<'a>(&self, models: &'a [(String, Model)]) -> Vec<(&'a str, Model)> {
        models
            .iter()
            .zip(&self.models)
            .filter(|(_, row)| row.note.is_none())
            .map(|((n, m), _)| (n.as_str(), *m))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_list_gives_labelled_models_and_refuses_the_custom_one_and_unknown_names() {
        let m = Model::named(3).unwrap();
        let field = Field::Other("models".into());
        let got = models("1, yp08,,4", &m, &field).unwrap();
        let labels: Vec<&str> = got.iter().map(|(l, _)| l.as_str()).collect();
        assert_eq!(labels, ["model 1", "YP08", "model 4"]);
        for bad in ["custom", "7", "1,nope"] {
            let e = models(bad, &m, &field).unwrap_err().to_string();
            assert!(e.contains("models"), "{bad}: {e}");
        }
    }
}
