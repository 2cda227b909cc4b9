//! `asperity sweep`: one row per value of the swept knob with a_r, ū/h_rms, ū, σ̄_c*,
//! ⟨δσ_c²⟩*, a_r/p*, the [S-18] reference, U and convergence.
//!
//! `--over pressure` (the default) sweeps p* ([`asperity::theory::sweep`]: continuation, one
//! shared gap table); `--over thickness` (t·q_r, log-spaced) and `--over gamma` (γ_s, linear)
//! evaluate each value as its own scene at `--pressure` ([`asperity::theory::knob`]), each
//! point exactly what `run` gives for it.

use super::SceneArgs;
use asperity::error::{Error, Field, Result};
use asperity::theory::closed_form::eq18_area;
use asperity::theory::engine::Options;
use asperity::theory::knob::{self, Knob, KnobSpec};
use asperity::theory::sweep::{self, one_line, Sweep, SweepRow, SweepSpec};
use clap::{Args, ValueEnum};
use serde::Serialize;

/// Output format of `sweep`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SweepFormat {
    /// Comma-separated, one header line then one row per load.
    Csv,
    /// One JSON object with `rows` (and the resolved scene).
    Json,
}

/// The knob a sweep turns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Over {
    /// p* (log-spaced).
    Pressure,
    /// t·q_r (log-spaced), at --pressure.
    Thickness,
    /// γ_s in J/m² (linearly spaced), at --pressure.
    Gamma,
}

/// Arguments of `sweep`.
#[derive(Debug, Clone, Args)]
pub struct SweepArgs {
    /// Scene.
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The knob to sweep: pressure (p*), thickness (t*q_r) or gamma (gamma_s, J/m^2).
    #[arg(long, value_enum, default_value_t = Over::Pressure, allow_hyphen_values = true)]
    pub over: Over,
    /// First value of the swept knob.
    #[arg(long, allow_hyphen_values = true, value_parser = super::parse::sweep_end)]
    pub from: f64,
    /// Last value of the swept knob.
    #[arg(long, allow_hyphen_values = true, value_parser = super::parse::sweep_end)]
    pub to: f64,
    /// Number of values from --from to --to (log-spaced; linear for gamma).
    #[arg(long, default_value_t = 64, allow_hyphen_values = true, value_parser = super::parse::count_in("points", 1, 100_000))]
    pub points: usize,
    /// Reduced pressure p* of a thickness or gamma sweep (default: the preset's).
    #[arg(long, allow_hyphen_values = true, value_parser = super::number(Field::Pressure))]
    pub pressure: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = SweepFormat::Csv, allow_hyphen_values = true)]
    pub format: SweepFormat,
    /// Load sweeps: the theory along a load cycle (up on the loading branch, back down on the
    /// unloading branch while it exists), as `gfmd --cycle` walks it.
    #[arg(long)]
    pub cycle: bool,
}

/// The CSV header (the first nine columns are the public interface of the load sweep; the
/// rest were added with `--over`).
pub const CSV_HEADER: &str = "p,a_r,mean_gap_rel,mean_gap,mean_contact_stress,elastic_energy,converged,\
elastic_energy_reduced,mean_gap_error,contact_stress_variance,a_r_over_p,a_r_eq18,thickness_qr,gamma,\
a_r_unloading,branches,mean_gap_lower_rel,mean_gap_upper_rel,contact_load,mean_gap_unloading_rel,\
mean_gap_unloading_error,mean_gap_unloading_lower_rel,contact_load_unloading,trust_inside,trust_a_r_log_error,reason";

/// One row of `sweep` (CSV columns and JSON keys). Unavailable numbers are null (empty cells).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    /// The engine's row (p*, a_r, ū, σ̄_c*, U, converged, …, ⟨δσ_c²⟩*).
    #[serde(flatten)]
    pub row: SweepRow,
    /// a_r/p*.
    pub a_r_over_p: f64,
    /// a_r of [S-18] at this p*, where it applies (γ_s = 0, semi-infinite); else null.
    pub a_r_eq18: Option<f64>,
    /// t·q_r; null for a semi-infinite body.
    pub thickness_qr: Option<f64>,
    /// γ_s (J/m²).
    pub gamma: f64,
    /// Whether this row's scene lies inside asperity's GFMD reference set
    /// ([`asperity::fit::trust`]).
    pub trust_inside: bool,
    /// Mean |ln(theory/GFMD)| of a_r measured at the reference set's nearest points.
    pub trust_a_r_log_error: f64,
    /// Why the row has no numbers (the solver's error, or why the mean gap is unavailable),
    /// on one line; null for a complete row.
    pub reason: Option<String>,
}

impl Row {
    /// The row of `row` for `scene` at the row's load (adds a_r/p*, [S-18] and the trust
    /// read-out).
    pub fn new(row: SweepRow, scene: &asperity::input::scene::Scene) -> Row {
        let (thickness_qr, gamma) = (scene.thickness_qr(), scene.surface_energy_j_m2());
        let eq18 = (gamma == 0.0 && thickness_qr.is_infinite()).then(|| eq18_area(row.p));
        let at = scene.clone().with_pressure(row.p).unwrap_or_else(|_| scene.clone());
        let trust = asperity::fit::trust::assess(&at);
        Row {
            row,
            a_r_over_p: row.a_r / row.p,
            a_r_eq18: eq18,
            thickness_qr: thickness_qr.is_finite().then_some(thickness_qr),
            gamma,
            trust_inside: trust.inside,
            trust_a_r_log_error: trust.a_r_log_error,
            reason: None,
        }
    }

    /// The row with `reason` (see [`Row::reason`]).
    pub fn with_reason(self, reason: Option<String>) -> Row {
        Row { reason, ..self }
    }
}

/// A CSV field: as is, or quoted (RFC 4180) when it holds a comma, a quote or a line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The JSON object printed by `sweep --format json`.
#[derive(Debug, Clone, Serialize)]
pub struct SweepOutput {
    /// Preset name.
    pub preset: String,
    /// The swept knob.
    pub over: Over,
    /// Resolved inputs (at --from).
    pub scene: asperity::input::scene::SceneSummary,
    /// One row per value.
    pub rows: Vec<Row>,
    /// Engine evaluations spent.
    pub evaluations: usize,
    /// p* at which the contact is full (of the scene at --from).
    pub full_contact_pressure: f64,
    /// Whether a_r rose and ū fell with the load (load sweeps; true for other knobs).
    pub monotone: bool,
    /// Loads (p*) of the rows that did not converge.
    pub failed_loads: Vec<f64>,
    /// Values of the swept knob whose rows did not converge.
    pub failed_values: Vec<f64>,
    /// What failed; absent when every value converged.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// Load sweeps: p* above which the loading branch no longer exists (the jump into
    /// contact), where the range holds it; null otherwise (and for other knobs).
    pub jump_in_pressure: Option<f64>,
    /// Load sweeps: p* below which the unloading branch no longer exists (pull-off), where
    /// the range holds it; null otherwise.
    pub pull_off_pressure: Option<f64>,
    /// The edges of hysteresis windows inside the range, in the swept knob's values, each
    /// with `value` and `kind` ("jump_in": the small-contact branch ends there, the contact
    /// jumps in; "pull_off": the large-contact branch ends). Load sweeps: the edges above;
    /// thickness and gamma sweeps: every edge between two neighbouring values that differ in
    /// the number of stable branches, refined by bisection.
    pub window_edges: Vec<asperity::theory::hysteresis::KnobEdge>,
    /// With `--cycle`: the theory's path up, back down and on into tension (rows with
    /// `branch`), where the unloading branch ends, the theory's pull-off, and why the path
    /// stops where it does.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cycle: Option<asperity::theory::cycle::TheoryCycle>,
}

/// The edges of a load sweep's window as [`SweepOutput::window_edges`] (ascending p*).
fn load_edges(pull_off: Option<f64>, jump_in: Option<f64>) -> Vec<asperity::theory::hysteresis::KnobEdge> {
    use asperity::theory::hysteresis::{EdgeKind, KnobEdge};
    [(pull_off, EdgeKind::PullOff), (jump_in, EdgeKind::JumpIn)]
        .into_iter()
        .filter_map(|(v, kind)| v.map(|value| KnobEdge { value, kind }))
        .collect()
}

/// Formats rows as CSV.
pub fn csv(rows: &[Row]) -> String {
    let mut out = String::from(CSV_HEADER);
    // an unavailable value (a load that did not converge, or a gap below one) is left empty
    let f = |x: f64| if x.is_finite() { format!("{x:e}") } else { String::new() };
    let o = |x: Option<f64>| x.map_or(String::new(), f);
    for row in rows {
        let r = &row.row;
        out.push_str(&format!(
            "\n{:e},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
            r.p,
            f(r.a_r),
            f(r.mean_gap_rel),
            f(r.mean_gap),
            f(r.mean_contact_stress),
            f(r.elastic_energy),
            r.converged,
            f(r.elastic_energy_reduced),
            f(r.mean_gap_error),
            f(r.contact_stress_variance),
            f(row.a_r_over_p),
            o(row.a_r_eq18),
            row.thickness_qr.map_or("inf".to_string(), f),
            f(row.gamma),
            f(r.a_r_unloading),
            r.branches,
            f(r.mean_gap_lower_rel),
            f(r.mean_gap_upper_rel),
            f(r.contact_load),
            f(r.mean_gap_unloading_rel),
            f(r.mean_gap_unloading_error),
            f(r.mean_gap_unloading_lower_rel),
            f(r.contact_load_unloading),
            row.trust_inside,
            f(row.trust_a_r_log_error),
            row.reason.as_deref().map_or(String::new(), csv_field),
        ));
    }
    out
}

/// Runs the sweep `args` asks for; returns the JSON object (rows included).
pub fn compute(args: &SweepArgs) -> Result<SweepOutput> {
    if args.cycle && args.over != Over::Pressure {
        return Err(Error::field(
            "--cycle",
            "set",
            "only with --over pressure (a load cycle runs over p*)",
        ));
    }
    match args.over {
        Over::Pressure => {
            if let Some(p) = args.pressure {
                return Err(Error::invalid(
                    Field::Pressure,
                    p,
                    "only with --over thickness or --over gamma (a load sweep runs from --from to --to)",
                ));
            }
            let spec = SweepSpec {
                from: args.from,
                to: args.to,
                points: args.points,
            };
            spec.validate()?;
            let (preset, scene) = args.scene.resolve(Some(args.from))?;
            let sw: Sweep = sweep::sweep(&scene, &spec, &Options::default(), None)?;
            let cycle = if args.cycle {
                Some(asperity::theory::cycle::path_through_tension(
                    &sw,
                    &scene,
                    &Options::default().adhesion,
                    None,
                )?)
            } else {
                None
            };
            let rows = sw
                .rows
                .iter()
                .zip(&sw.reasons)
                .map(|(r, why)| Row::new(*r, &scene).with_reason(why.clone()))
                .collect();
            Ok(SweepOutput {
                preset: preset.name.clone(),
                over: Over::Pressure,
                scene: scene.summary(),
                rows,
                evaluations: sw.evaluations,
                full_contact_pressure: sw.full_contact_pressure,
                monotone: sw.monotone,
                failed_values: sw.failed_loads.clone(),
                failed_loads: sw.failed_loads,
                note: sw.note,
                window_edges: load_edges(sw.pull_off_pressure, sw.jump_in_pressure),
                jump_in_pressure: sw.jump_in_pressure,
                pull_off_pressure: sw.pull_off_pressure,
                cycle,
            })
        }
        Over::Thickness | Over::Gamma => knob_output(args),
    }
}

/// `--over thickness|gamma`: the knob sweep at `--pressure`, each row what `run` gives there.
fn knob_output(args: &SweepArgs) -> Result<SweepOutput> {
    let knob = if args.over == Over::Thickness {
        Knob::Thickness
    } else {
        Knob::Gamma
    };
    let spec = KnobSpec {
        knob,
        from: args.from,
        to: args.to,
        points: args.points,
    };
    spec.validate()?;
    let (preset, scene) = args.scene.resolve(args.pressure)?;
    let first = knob.apply(&scene, args.from);
    let points = knob::knob_sweep(&scene, &spec, &Options::default(), true, None)?;
    let window_edges =
        asperity::theory::hysteresis::knob_edges(&scene, knob, &points, &Options::default().adhesion, None)?;
    let unit = asperity::theory::energy::energy_unit(&scene);
    let mut notes = Vec::new();
    let mut failed = Vec::new();
    let rows: Vec<Row> = points
        .iter()
        .map(|pt| {
            let reason = match (&pt.result, &pt.gap) {
                (Err(e), _) => {
                    failed.push(pt.value);
                    Some(one_line(&e.to_string()))
                }
                (Ok(_), Err(e)) => Some(one_line(&format!("mean gap unavailable: {e}"))),
                (Ok(_), Ok(_)) => None,
            };
            if let Some(why) = &reason {
                notes.push(format!("value {:e}: {why}", pt.value));
            }
            let r = pt.row(scene.pressure(), unit);
            Row::new(r, &pt.scene).with_reason(reason)
        })
        .collect();
    let note = (!notes.is_empty()).then(|| {
        format!(
            "{} of {} values did not converge or lack the gap; their cells are empty (null): {}",
            notes.len(),
            points.len(),
            notes.join("; ")
        )
    });
    Ok(SweepOutput {
        preset: preset.name.clone(),
        over: args.over,
        scene: first.summary(),
        rows,
        evaluations: points.len(),
        full_contact_pressure: asperity::theory::gap::full_contact_pressure(&first),
        monotone: true,
        failed_loads: failed.iter().map(|_| scene.pressure()).collect(),
        failed_values: failed,
        note,
        jump_in_pressure: None,
        pull_off_pressure: None,
        window_edges,
        cycle: None,
    })
}

/// Runs `asperity sweep`; returns the text to print.
pub fn run(args: &SweepArgs) -> Result<String> {
    let out = compute(args)?;
    if let Some(note) = &out.note {
        eprintln!("asperity sweep: {note}");
    }
    Ok(match (args.format, &out.cycle) {
        (SweepFormat::Csv, Some(c)) => cycle_csv(c),
        (SweepFormat::Csv, None) => csv(&out.rows),
        (SweepFormat::Json, _) => serde_json::to_string_pretty(&out).expect("serialisable"),
    })
}

/// The CSV of `sweep --cycle`: `#` lines (where the unloading branch ends, the jump-in, why the
/// path stops), then `branch,p,a_r,mean_gap_rel,mean_contact_stress,on_unloading_branch`.
pub fn cycle_csv(c: &asperity::theory::cycle::TheoryCycle) -> String {
    let f = |x: f64| if x.is_finite() { format!("{x:e}") } else { String::new() };
    let mut out = String::new();
    if let Some(p) = c.unloading_branch_ends {
        out.push_str(&format!("# unloading_branch_ends: {}\n", f(p)));
    }
    if let Some(p) = c.jump_in_pressure {
        out.push_str(&format!("# jump_in_pressure: {}\n", f(p)));
    }
    if let Some(p) = c.pull_off_pressure {
        out.push_str(&format!("# pull_off_pressure: {}\n", f(p)));
    }
    if let Some([lost, held]) = c.pull_off_bracket {
        out.push_str(&format!("# pull_off_bracket: {} {}\n", f(lost), f(held)));
    }
    if let Some(b) = c.tension_bound {
        out.push_str(&format!("# tension_bound: {}\n", f(b)));
    }
    out.push_str(&format!("# note: {}\n", c.note));
    out.push_str(CYCLE_CSV_HEADER);
    for r in &c.rows {
        out.push_str(&format!(
            "\n{},{},{},{},{},{}",
            r.branch.name(),
            f(r.p),
            f(r.a_r),
            f(r.mean_gap_rel),
            f(r.mean_contact_stress),
            r.on_unloading_branch
        ));
    }
    out
}

/// The columns of `sweep --cycle --format csv`.
pub const CYCLE_CSV_HEADER: &str = "branch,p,a_r,mean_gap_rel,mean_contact_stress,on_unloading_branch";
