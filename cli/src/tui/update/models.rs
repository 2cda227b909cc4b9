//! Changing the model: one picked (`m` cycles 1, 2, 3, 4, custom, YP08, Xu24, 5) or typed. A
//! model the scene does not take (a variant of the literature on an adhesive or slab scene)
//! leaves the scene as it is and says why.

use crate::tui::model::app::App;
use asperity::error::Result;
use asperity::input::model::Model;

impl App {
    pub(crate) fn try_model(&mut self, m: Result<Model>) {
        match m {
            Ok(m) => match self.params.scene.clone().with_model(m) {
                Ok(s) => self.set_scene(s),
                Err(e) => self.fail(e),
            },
            Err(e) => self.fail(e),
        }
    }

    /// The next model in the cycle 1, 2, 3, 4, custom, YP08, Xu24, 5; the variants are skipped
    /// (with the reason in the status line) where the scene does not take them.
    pub(crate) fn cycle_model(&mut self, dir: i32) {
        let m = self.params.scene.model();
        let [yp08, xu24] = crate::tui::base::kinds::variants(&m);
        let cycle = [
            Model::named(1),
            Model::named(2),
            Model::named(3),
            Model::named(4),
            Model::custom(m.c1, m.c2, m.alpha, m.k_griffith, m.cap),
            Ok(yp08),
            Ok(xu24),
            Model::named(5),
        ];
        let n = cycle.len() as i32;
        // the cycle is in the order of the model slots (model 5 is slot 7)
        let cur = crate::tui::base::kinds::slot(&m) as i32;
        let mut skipped = Vec::new();
        for k in 1..n {
            let next = &cycle[(cur + dir * k).rem_euclid(n) as usize];
            match next
                .clone()
                .and_then(|nm| self.params.scene.clone().with_model(nm).map(|s| (nm, s)))
            {
                Ok((_, s)) => {
                    self.set_scene(s);
                    if !skipped.is_empty() {
                        self.info(format!(
                            "{} skipped: defined for the adhesionless half-space only (gamma_s = 0, t = inf)",
                            skipped.join(" and ")
                        ));
                    }
                    return;
                }
                Err(e) => match next {
                    Ok(nm) if nm.kind.is_fudge_variant() => skipped.push(nm.label()),
                    _ => return self.fail(e),
                },
            }
        }
    }
}
