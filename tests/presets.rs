//! Presets: every shipped file loads; invalid fixtures give one-line errors naming the field.

use asperity::input::preset::{list_available, Preset, BUILTIN};

#[test]
fn every_shipped_preset_loads_and_validates() {
    let mut n = 0;
    for entry in std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/presets")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let p = Preset::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            let scene = p.scene().unwrap();
            assert!(scene.spectrum().rms_gradient() > 0.0);
            n += 1;
        }
    }
    assert!(n >= 2);
    for (name, text) in BUILTIN {
        let p = Preset::parse(text, name).unwrap();
        assert_eq!(p.name, name);
    }
    assert!(list_available().iter().any(|(n, _)| n == "system-2"));
}

#[test]
fn system_presets_match_systems_md() {
    // systems.md: system I γ̃_glo = 0.024, system II 0.10 (semi-infinite); Tabor ≈ 3.2 and 1
    let s1 = Preset::resolve("system-1").unwrap().scene().unwrap();
    assert!((s1.gamma_glo() - 0.0242).abs() < 0.001, "{}", s1.gamma_glo());
    assert!(
        (s1.full_contact_energy() / 2.066 - 1.0).abs() < 2e-3,
        "{}",
        s1.full_contact_energy()
    );
    assert!((s1.tabor() - 3.2).abs() < 0.1, "{}", s1.tabor());
    let s2 = Preset::resolve("system-2").unwrap().scene().unwrap();
    assert!((s2.gamma_glo() - 0.10).abs() < 0.005, "{}", s2.gamma_glo());
    assert!((s2.tabor() - 1.0).abs() < 0.05, "{}", s2.tabor());
    // systems.md: at t = 1/(4 q_r) the full-contact elastic energy drops about 4-fold (we get
    // 4.06, γ̃_glo = 0.41). [S] §3.2 quotes γ̃_glo ≈ 0.3 there for its own (unpublished)
    // length set; with the ratios it does publish, 0.41 is what [S-10] and [S-4] give.
    let mut thin = s2.clone();
    thin.set_thickness_qr(0.25).unwrap();
    let ratio = thin.gamma_glo() / s2.gamma_glo();
    assert!((ratio - 4.0).abs() < 0.25, "{ratio}");
}

fn fixture_error(name: &str) -> String {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    let e = Preset::load(std::path::Path::new(&path)).unwrap_err().to_string();
    assert!(!e.contains('\n'), "error must be one line: {e}");
    e
}

#[test]
fn bad_presets_name_the_field_and_range() {
    let cases = [
        // lines are 1-based and point at the offending line (they were one too low)
        ("malformed.toml", &["line 2: surface: unclosed table"][..]),
        (
            "unknown-key.toml",
            &["line 11: surface.roughness: unknown field `roughness`"][..],
        ),
        (
            "negative-length.toml",
            &[
                "line 7: invalid surface.system_size_m",
                "-0.0001",
                "1e-12 <= system_size_m",
            ][..],
        ),
        (
            "short-above-rolloff.toml",
            &["surface.short_wavelength_m", "< rolloff_wavelength_m"][..],
        ),
        (
            "nan-hurst.toml",
            &["line 10: invalid surface.hurst = NaN", "0.001 <= hurst <= 1"][..],
        ),
        ("negative-thickness.toml", &["load.thickness_qr = -2", "or inf"][..]),
        ("zero-modulus.toml", &["material.contact_modulus_pa = 0"][..]),
        ("bad-model.toml", &["model.variant = 7", "1, 2, 3, 4"][..]),
    ];
    for (file, needles) in cases {
        let e = fixture_error(file);
        assert!(e.starts_with("preset "), "{file}: {e}");
        for n in needles {
            assert!(e.contains(n), "{file}: expected {n:?} in {e:?}");
        }
    }
}

#[test]
fn unknown_preset_lists_the_known_ones() {
    let e = Preset::resolve("no-such-system").unwrap_err().to_string();
    assert!(e.contains("system-1") && e.contains("system-2"), "{e}");
}
