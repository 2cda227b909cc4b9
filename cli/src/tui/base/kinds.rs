//! The chart selector's kinds and what each needs computed, and the model slots of `M`: plain
//! data shared by the state, the worker and the charts (a leaf module: it imports none of them;
//! the model slots are [`crate::looks`]'s).

use asperity::input::model::{Model, ModelKind, FUDGE_GAMMA_DEFAULT};
use asperity::input::scene::Scene;

/// One chart of the selector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChartKind {
    /// Pr(σ*), linear axes.
    Pr,
    /// Pr(σ*), log–log with asymptotes.
    PrLog,
    /// a_r(p*), log–log, with eq. (18).
    Area,
    /// a_r/p* against log p*, with eq. (18).
    AreaRatio,
    /// a_r(t·q_r) at the current p*.
    Thickness,
    /// σ̄_c*(p*).
    Stress,
    /// ū/h_rms(p*).
    Gap,
    /// Pr(σ*, q) at one resolution q of the march, with the wall −σ_a*(q): the theory built
    /// scale by scale.
    Scales,
    /// a_r(q) and σ_a*(q) along the resolution, with the scale view's current q.
    ScalesArea,
    /// The power spectrum C(q), log–log, with its cut-offs and self-affine fit.
    Psd,
}

/// What a chart needs computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Needs {
    /// Pr(σ*) at the current p* (of every drawn model).
    pub point: bool,
    /// The load sweep.
    pub loads: bool,
    /// The thickness sweep.
    pub thickness: bool,
    /// The scale-by-scale snapshots of Pr(σ*, q) at the current scene.
    pub scales: bool,
}

impl Needs {
    /// Union.
    pub fn or(self, o: Needs) -> Needs {
        Needs {
            point: self.point || o.point,
            loads: self.loads || o.loads,
            thickness: self.thickness || o.thickness,
            scales: self.scales || o.scales,
        }
    }
}

impl ChartKind {
    /// Every chart, in selector order.
    pub const ALL: [ChartKind; 10] = [
        ChartKind::Pr,
        ChartKind::PrLog,
        ChartKind::Area,
        ChartKind::AreaRatio,
        ChartKind::Thickness,
        ChartKind::Scales,
        ChartKind::ScalesArea,
        ChartKind::Stress,
        ChartKind::Gap,
        ChartKind::Psd,
    ];

    /// The name used in tours and file names.
    pub fn name(self) -> &'static str {
        match self {
            ChartKind::Pr => "pr",
            ChartKind::PrLog => "pr-loglog",
            ChartKind::Area => "area",
            ChartKind::AreaRatio => "area-ratio",
            ChartKind::Thickness => "thickness",
            ChartKind::Stress => "stress",
            ChartKind::Gap => "gap",
            ChartKind::Scales => "scales",
            ChartKind::ScalesArea => "scales-area",
            ChartKind::Psd => "psd",
        }
    }

    /// How a tour caption names it (`{chart:NAME}` reads "the WORDS chart"): what it plots.
    pub fn words(self) -> &'static str {
        match self {
            ChartKind::Pr => "Pr(σ*)",
            ChartKind::PrLog => "log–log Pr(σ*)",
            ChartKind::Area => "a_r(p*)",
            ChartKind::AreaRatio => "a_r/p*",
            ChartKind::Thickness => "a_r(t·q_r)",
            ChartKind::Stress => "σ̄_c*(p*)",
            ChartKind::Gap => "ū(p*)",
            ChartKind::Scales => "Pr(σ*, q)",
            ChartKind::ScalesArea => "a_r(q)",
            ChartKind::Psd => "C(q)",
        }
    }

    /// The chart named `s`.
    pub fn parse(s: &str) -> Option<ChartKind> {
        ChartKind::ALL.into_iter().find(|k| k.name() == s)
    }

    /// The next (`dir` = 1) or previous (−1) chart of the selector.
    pub fn cycle(self, dir: i32) -> ChartKind {
        let n = ChartKind::ALL.len() as i32;
        let i = ChartKind::ALL.iter().position(|k| *k == self).unwrap_or(0) as i32;
        ChartKind::ALL[(i + dir).rem_euclid(n) as usize]
    }

    /// The quantity of the preset's `[[reference]]` points this chart draws (GFMD data such
    /// as \[S\] Table 1), if any.
    pub fn reference_quantity(self) -> Option<&'static str> {
        match self {
            ChartKind::Area | ChartKind::AreaRatio | ChartKind::Thickness => Some("a_r"),
            ChartKind::Stress => Some("mean_contact_stress"),
            ChartKind::Gap => Some("mean_gap_rel"),
            ChartKind::Pr | ChartKind::PrLog | ChartKind::Scales | ChartKind::ScalesArea | ChartKind::Psd => None,
        }
    }

    /// What it needs computed.
    pub fn needs(self) -> Needs {
        match self {
            ChartKind::Pr | ChartKind::PrLog => Needs {
                point: true,
                ..Needs::default()
            },
            ChartKind::Thickness => Needs {
                thickness: true,
                ..Needs::default()
            },
            ChartKind::Scales | ChartKind::ScalesArea => Needs {
                scales: true,
                ..Needs::default()
            },
            ChartKind::Psd => Needs::default(),
            _ => Needs {
                loads: true,
                ..Needs::default()
            },
        }
    }
}

/// Model slot of a model: 0–3 for models 1–4, 4 for custom, 5 YP08, 6 Xu24, 7 model 5.
pub fn slot(m: &Model) -> usize {
    crate::looks::model_slot(m)
}

/// Legend name of a model slot.
pub fn slot_name(i: usize) -> String {
    match i {
        0..=3 => format!("model {}", i + 1),
        5 => "YP08".into(),
        6 => "Xu24".into(),
        7 => "model 5".into(),
        _ => "custom".into(),
    }
}

/// The named variants of the literature with a fudge parameter γ_f: the current one's γ_f
/// when it is that variant, else the default.
pub fn variants(current: &Model) -> [Model; 2] {
    [ModelKind::Yp08, ModelKind::Xu24].map(|k| {
        if current.kind == k {
            *current
        } else {
            Model::fudge(k, FUDGE_GAMMA_DEFAULT).expect("the default fudge parameter is valid")
        }
    })
}

/// The models drawn with `M`: 1–4; model 5 on an adhesive scene (without adhesion it is model
/// 3 exactly, so it would only hide model 3's curve); the current one when it is custom; and,
/// when the current one is YP08 or Xu24, both variants (the explorer skips any the scene does
/// not take: adhesion or a slab). The paper's four stay uncluttered where no variant is looked at.
pub fn overlay_models(scene: &Scene) -> Vec<Model> {
    let current = scene.model();
    let mut v: Vec<Model> = (1..=4).filter_map(|n| Model::named(n).ok()).collect();
    if scene.surface_energy_j_m2() > 0.0 {
        v.extend(Model::named(5).ok());
    }
    if current.kind == ModelKind::Custom {
        v.push(current);
    }
    if current.kind.is_fudge_variant() {
        v.extend(variants(&current));
    }
    v
}
