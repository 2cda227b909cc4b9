//! The explorer's words for the library's fields and errors: a bad value is named by the
//! label the panel shows (`t·q_r`, `p*`, `γ_s`), not by a CLI flag or a preset key. The CLI
//! has its own rendering (`cli::field_name`); the library names neither.

use asperity::error::{Error, Field};

/// The panel's label for a field, or the library's canonical key where the panel has none.
pub fn field_label(field: &Field) -> String {
    match field {
        Field::Pressure => "p*".into(),
        Field::Thickness => "t·q_r".into(),
        Field::SurfaceEnergy => "γ_s (J/m²)".into(),
        Field::Model => "model".into(),
        Field::C1 => "c1".into(),
        Field::C2 => "c2".into(),
        Field::WeightCoefficients => "(c1, c2)".into(),
        Field::Alpha => "alpha".into(),
        Field::KGriffith => "k_G".into(),
        other => format!("preset {}", other.key()),
    }
}

/// One line for the status bar: invalid input in the explorer's words, anything else as the
/// library says it.
pub fn describe(e: &Error) -> String {
    match e {
        Error::Invalid { field, value, allowed } => {
            format!("invalid {} = {value}: allowed {allowed}", field_label(field))
        }
        other => other.to_string(),
    }
}

/// The gist of an engine message, for a chart's title: its innermost reason (what follows
/// the last "did not converge: " or "unavailable: ") up to the first parenthesis, colon or
/// semicolon. The chart's body and the status line carry the whole message.
pub fn brief(msg: &str) -> String {
    let mut s = msg;
    while let Some((i, n)) = ["did not converge: ", "unavailable: "]
        .iter()
        .filter_map(|m| s.find(m).map(|i| (i, m.len())))
        .min()
    {
        s = &s[i + n..];
    }
    let cut = s.find([';', ':', '(']).unwrap_or(s.len());
    s[..cut].trim().trim_end_matches(',').to_string()
}

/// The file a measured spectrum came from (its name, without the directories), or None for
/// the preset's own spectrum.
pub fn surface_name(scene: &asperity::input::scene::Scene) -> Option<String> {
    match scene.spectrum() {
        asperity::surface::spectrum::Spectrum::Tabulated(t) => Some(surface_name_of(t)),
        _ => None,
    }
}

/// A table's file name without the directories.
pub fn surface_name_of(t: &asperity::surface::tabulated::Tabulated) -> String {
    std::path::Path::new(&t.source)
        .file_name()
        .map_or_else(|| t.source.clone(), |n| n.to_string_lossy().into_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn invalid_values_are_named_by_the_panel_label() {
        let e = Error::Invalid {
            field: Field::Thickness,
            value: "-1".into(),
            allowed: "t·q_r > 0".into(),
        };
        let s = describe(&e);
        assert!(s.starts_with("invalid t·q_r = -1"), "{s}");
        assert!(!s.contains("--") && !s.contains("load.thickness_qr"), "{s}");
        assert_eq!(describe(&Error::Cancelled), "cancelled");
        assert_eq!(field_label(&Field::Hurst), "preset surface.hurst");
    }

    #[test]
    fn the_gist_of_a_message_is_its_innermost_reason() {
        let gap = "mean gap did not converge: 16 of 62 loads did not converge (the first: x); their rows are \
                   empty (null); mean gap unavailable: mean gap (energy route) did not converge: the stored \
                   elastic energy falls from p* = 1.4250e0 to 1.5735e0 (by 1.23e-4 of its range): the loads";
        assert_eq!(
            brief(gap),
            "the stored elastic energy falls from p* = 1.4250e0 to 1.5735e0"
        );
        assert_eq!(brief("invalid p* = -1: allowed p* > 0"), "invalid p* = -1");
        assert_eq!(brief("cancelled"), "cancelled");
    }
}
