//! What the explorer shows of a finished GFMD run ([`GfmdView`]): the numbers of the run at
//! p*, its sweep on the same map with the theory's on that map's spectrum, and the panel's rows
//! of the invariants the reduced grid kept (and what it could not keep), copied from the
//! engine's [`asperity::gfmd::GfmdResult`].

/// What the explorer shows of a finished GFMD run.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GfmdView {
    /// p* of the run.
    pub pressure: f64,
    /// Fraction of nodes in contact.
    pub a_r: f64,
    /// σ̄_c*.
    pub mean_contact_stress: f64,
    /// ū/h_rms.
    pub gap_rel: f64,
    /// Pr(σ*) histogram (bin centres, density), ∫ = a_r.
    pub pr: Vec<(f64, f64)>,
    /// Grid side N.
    pub grid: usize,
    /// FIRE steps.
    pub iterations: usize,
    /// Wall time (s).
    pub elapsed_s: f64,
    /// The theory's a_r on the same map (its discrete spectrum), if it could be evaluated.
    pub theory_a_r: Option<f64>,
    /// GFMD load sweep on the same map (p*, a_r, ū/h_rms), warm-started; empty until run.
    pub sweep: Vec<(f64, f64, f64)>,
    /// The theory on the same map's spectrum at the sweep's loads (p*, a_r, ū/h_rms): the
    /// reduced system GFMD ran, not the full scene of the other curves.
    pub theory_sweep: Vec<(f64, f64, f64)>,
    /// Reduced against full invariants for the panel: (label, "full → run") and what could not
    /// be kept.
    pub invariants: Vec<(String, String)>,
    /// Why the sweep on the same map is missing, where it failed (the run at p* stands).
    pub sweep_error: Option<String>,
}

impl GfmdView {
    /// Copies what the views need.
    pub fn from_result(r: &asperity::gfmd::GfmdResult) -> GfmdView {
        GfmdView {
            pressure: r.pressure,
            a_r: r.stats.a_r,
            mean_contact_stress: r.stats.mean_contact_stress,
            gap_rel: r.mean_gap_rel,
            pr: r.stats.pr.points(),
            grid: r.grid,
            iterations: r.iterations,
            elapsed_s: r.elapsed_s,
            theory_a_r: r.theory.as_ref().map(|t| t.stats.a_r),
            sweep: Vec::new(),
            theory_sweep: Vec::new(),
            invariants: r.reduction.as_ref().map_or_else(Vec::new, invariant_rows),
            sweep_error: None,
        }
    }

    /// Adds a GFMD sweep and the theory's sweep on the same map.
    pub fn with_sweep(mut self, sw: &asperity::gfmd::sweep::GfmdSweep) -> GfmdView {
        self.sweep = sw.rows.iter().map(|r| (r.p, r.a_r, r.mean_gap_rel)).collect();
        if let Some(t) = &sw.theory {
            self.theory_sweep = t.rows.iter().map(|r| (r.p, r.a_r, r.mean_gap_rel)).collect();
        }
        self
    }
}

/// Panel rows: γ̃_glo and μ_T of the run (and of the full system), λ_r/λ_s likewise, and a count of what was not kept.
fn invariant_rows(r: &asperity::gfmd::reduction::Reduction) -> Vec<(String, String)> {
    // the run's value and the full system's, e.g. "200.0 (full 2000)"
    let pair = |name: &str, reduced: f64, full: f64, digits: usize| {
        let sig = |x| crate::numfmt::sig(x, digits);
        (name.to_string(), format!("{} (full {})", sig(reduced), sig(full)))
    };
    // ratios like 200.000000000 (a quotient of lengths) in four significant digits
    let mut v = vec![pair("λr/λs", r.reduced.bandwidth, r.full.bandwidth, 4)];
    if r.full.gamma > 0.0 {
        v.push(pair("GFMD γ̃", r.reduced.gamma_glo, r.full.gamma_glo, 3));
        v.push(pair("GFMD μT", r.reduced.tabor, r.full.tabor, 3));
    }
    let lost: Vec<&str> = r
        .not_kept
        .iter()
        .filter(|k| !k.starts_with("bandwidth"))
        .map(|k| k.split(':').next().unwrap_or(k))
        .collect();
    if !lost.is_empty() {
        v.push(("not kept".to_string(), lost.join(", ")));
    }
    v
}
