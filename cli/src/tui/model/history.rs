//! The load history of the explorer: which branch of a hysteresis the user's path has reached.
//!
//! Inside a hysteresis window (docs/physics.md §4: at a load with two stable self-consistent
//! roots) the state depends on the path. Loading from small p* follows the loading branch
//! (the lowest stable root) until it ends at the jump-in load, where the contact jumps onto
//! the unloading branch (the highest stable root); unloading back down stays on it until it
//! ends at the pull-off load, where the contact drops back onto the loading branch. Turning
//! t·q_r, γ_s or the model moves the window under the load: a loading path whose branch ends
//! jumps in, an unloading path whose branch ends drops off, as a quasi-static change would.
//!
//! [`LoadHistory`] is pure data with a pure update: the loads the path visits are recorded in
//! order ([`LoadHistory::visit`]) and walked through the window of their scene once it is
//! known ([`LoadHistory::resolve`]), so stepping faster than the engine computes loses no
//! jump. The headless commands do not use it: they report the loading branch.

/// The branch the path is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Path {
    /// The loading branch (or the only one).
    Loading,
    /// The unloading branch (the contact has jumped in).
    Unloading,
}

impl Path {
    /// `loading` or `unloading` (the names of the engine's branches).
    pub fn name(self) -> &'static str {
        match self {
            Path::Loading => "loading",
            Path::Unloading => "unloading",
        }
    }
}

/// Why the path is on its branch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Why {
    /// The explorer started, a preset or a tour step was loaded, or `r` reset the history.
    Start,
    /// The loading branch ended: the load reached the jump-in load p* (or the window moved
    /// below the load).
    JumpedIn(f64),
    /// The unloading branch ended: the load fell to the pull-off load p*.
    PulledOff(f64),
    /// The scene has no hysteresis window: one branch.
    NoWindow,
    /// The preset put its scene on this branch (`[load] branch = "unloading"`: an export made
    /// on the unloading branch).
    Preset,
}

/// What a scene's load sweep says about its hysteresis window.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Window {
    /// p* above which the loading branch no longer exists (in the sweep's range).
    pub jump_in: Option<f64>,
    /// p* below which the unloading branch no longer exists (in the sweep's range).
    pub pull_off: Option<f64>,
    /// Whether the sweep found a second branch anywhere in its range.
    pub hysteresis: bool,
}

/// The branch the user's path has reached, why, and the loads visited since the last window
/// was known.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadHistory {
    /// The branch.
    pub on: Path,
    /// Why.
    pub why: Why,
    pending: Vec<f64>,
}

impl Default for LoadHistory {
    fn default() -> Self {
        LoadHistory::new()
    }
}

impl LoadHistory {
    /// On the loading branch, nothing visited.
    pub fn new() -> LoadHistory {
        LoadHistory {
            on: Path::Loading,
            why: Why::Start,
            pending: Vec::new(),
        }
    }

    /// Back to the loading branch (`r`, a preset, a tour step).
    pub fn reset(&mut self) {
        *self = LoadHistory::new();
    }

    /// Back to the branch a preset puts its scene on: the unloading branch where its
    /// `[load] branch` says so (`unloading`), else the loading branch.
    pub fn reset_to(&mut self, unloading: bool) {
        self.reset();
        if unloading {
            self.on = Path::Unloading;
            self.why = Why::Preset;
        }
    }

    /// Records a load the path reached (in order).
    pub fn visit(&mut self, p: f64) {
        if p.is_finite() {
            self.pending.push(p);
        }
    }

    /// Forgets the loads not walked yet (their window will not be known: the scene's system
    /// changed before its sweep came).
    pub fn forget_pending(&mut self) {
        self.pending.clear();
    }

    /// Walks the visited loads through the window of their scene, in order; returns whether
    /// the branch changed.
    pub fn resolve(&mut self, w: &Window) -> bool {
        let before = self.on;
        for p in std::mem::take(&mut self.pending) {
            self.step(p, w);
        }
        self.on != before
    }

    fn step(&mut self, p: f64, w: &Window) {
        match self.on {
            Path::Loading => {
                if let Some(j) = w.jump_in.filter(|j| p >= *j) {
                    self.on = Path::Unloading;
                    self.why = Why::JumpedIn(j);
                }
            }
            Path::Unloading => {
                if let Some(q) = w.pull_off.filter(|q| p <= *q) {
                    self.on = Path::Loading;
                    self.why = Why::PulledOff(q);
                } else if !w.hysteresis {
                    self.on = Path::Loading;
                    self.why = Why::NoWindow;
                }
            }
        }
    }

    /// A few words for the panel: the branch, and how it was reached where it was not by
    /// loading from small p*.
    pub fn label(&self) -> String {
        match self.why {
            Why::JumpedIn(_) => format!("{} (jumped in)", self.on.name()),
            Why::PulledOff(_) => format!("{} (pulled off)", self.on.name()),
            Why::Preset => format!("{} (preset)", self.on.name()),
            Why::Start | Why::NoWindow => self.on.name().to_string(),
        }
    }

    /// One line: the branch and why (the status line says it when the branch changes).
    pub fn describe(&self) -> String {
        let s = crate::numfmt::sig;
        match (self.on, self.why) {
            (Path::Unloading, Why::JumpedIn(j)) => format!(
                "unloading branch: the loading branch ended at p* = {} (jump-in); stepping down stays here until pull-off; r resets",
                s(j, 3)
            ),
            (Path::Loading, Why::PulledOff(q)) => format!(
                "loading branch: the unloading branch ended at p* = {} (pull-off)",
                s(q, 3)
            ),
            (Path::Loading, Why::NoWindow) => "one branch: no hysteresis window at this scene".into(),
            (on, Why::Preset) => format!("{} branch, as the preset's [load] branch says; r resets to it", on.name()),
            (on, _) => format!("{} branch (loaded from small p*)", on.name()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const W: Window = Window {
        jump_in: Some(2.4e-4),
        pull_off: Some(5e-5),
        hysteresis: true,
    };

    fn walk(h: &mut LoadHistory, loads: &[f64], w: &Window) -> Path {
        for &p in loads {
            h.visit(p);
        }
        h.resolve(w);
        h.on
    }

    #[test]
    fn up_through_the_window_jumps_in_and_back_down_stays_until_pull_off() {
        let mut h = LoadHistory::new();
        assert_eq!(walk(&mut h, &[1e-4, 2e-4], &W), Path::Loading);
        assert_eq!(h.why, Why::Start);
        assert_eq!(walk(&mut h, &[2.5e-4], &W), Path::Unloading);
        assert_eq!(h.why, Why::JumpedIn(2.4e-4));
        let d = h.describe();
        assert!(
            d.starts_with("unloading branch: the loading branch ended at p* = ") && d.contains("(jump-in)"),
            "{d}"
        );
        // back down into the window: still unloading
        assert_eq!(walk(&mut h, &[2.24e-4, 1e-4, 6e-5], &W), Path::Unloading);
        // below pull-off: the contact drops onto the loading branch, and stays there going up
        assert_eq!(walk(&mut h, &[4e-5], &W), Path::Loading);
        assert_eq!(h.why, Why::PulledOff(5e-5));
        assert_eq!(walk(&mut h, &[1e-4, 2e-4], &W), Path::Loading);
    }

    #[test]
    fn loads_visited_before_the_window_is_known_are_walked_in_order() {
        // up past jump-in and back into the window before any sweep came: unloading
        let mut h = LoadHistory::new();
        assert_eq!(walk(&mut h, &[1e-4, 3e-4, 2e-4], &W), Path::Unloading);
        // down past pull-off and back up into the window: loading
        assert_eq!(walk(&mut h, &[4e-5, 1e-4], &W), Path::Loading);
        // nothing visited: nothing changes
        assert!(!h.resolve(&W));
    }

    #[test]
    fn a_window_moved_under_the_load_by_t_or_gamma_acts_likewise() {
        // at p* = 1e-4 on the loading branch; a thinner slab moves jump-in below the load
        let mut h = LoadHistory::new();
        walk(&mut h, &[1e-4], &W);
        let thinner = Window {
            jump_in: Some(8e-5),
            pull_off: Some(1e-5),
            hysteresis: true,
        };
        h.visit(1e-4);
        assert!(h.resolve(&thinner));
        assert_eq!((h.on, h.why), (Path::Unloading, Why::JumpedIn(8e-5)));
        // γ_s turned off: no window, one branch
        let none = Window {
            jump_in: None,
            pull_off: None,
            hysteresis: false,
        };
        h.visit(1e-4);
        h.resolve(&none);
        assert_eq!((h.on, h.why), (Path::Loading, Why::NoWindow));
        // a window whose pull-off moved above the load drops the unloading path
        let mut h = LoadHistory::new();
        walk(&mut h, &[3e-4, 1e-4], &W);
        let higher = Window {
            jump_in: Some(5e-4),
            pull_off: Some(2e-4),
            hysteresis: true,
        };
        h.visit(1e-4);
        h.resolve(&higher);
        assert_eq!((h.on, h.why), (Path::Loading, Why::PulledOff(2e-4)));
    }

    #[test]
    fn a_preset_on_the_unloading_branch_starts_there_and_pulls_off_below_the_window() {
        let mut h = LoadHistory::new();
        h.reset_to(true);
        assert_eq!((h.on, h.why), (Path::Unloading, Why::Preset));
        assert_eq!(h.label(), "unloading (preset)");
        // inside the window it stays; below pull-off it drops onto the loading branch
        assert_eq!(walk(&mut h, &[1e-4, 2.24e-4, 1e-4], &W), Path::Unloading);
        assert_eq!(walk(&mut h, &[4e-5], &W), Path::Loading);
        h.reset_to(false);
        assert_eq!(h, LoadHistory::new());
    }

    #[test]
    fn reset_goes_back_to_the_loading_branch() {
        let mut h = LoadHistory::new();
        walk(&mut h, &[3e-4], &W);
        assert_eq!(h.on, Path::Unloading);
        h.reset();
        assert_eq!(h, LoadHistory::new());
    }
}
