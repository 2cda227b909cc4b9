//! The least-squares problem of a fit ([`super::fit`]): residuals, their weights and the
//! Jacobian, for the Levenberg–Marquardt optimiser.
//!
//! ```text
//! r_i = (y_model,i − y_i)/s_i,   s_i = the reference's standard error of point i where it
//!                                     gives one, else |y_i|, and for a Pr(σ*) bin the peak
//!                                     of its histogram
//! J_ik = (r_i(x + h_k e_k) − r_i(x − h_k e_k))/(2h_k),   h_k = 1e-4·max(|x_k|, 0.1)
//! ```
//!
//! The difference is one-sided where one of its steps leaves the model's range (a fit at the
//! edge), and a coefficient set outside that range gets a large residual ([`PENALTY`]) so
//! that the optimiser steps back.

use super::predict::predict;
use super::reference::{Observable, Reference};
use super::Param;
use crate::error::Error;
use crate::input::model::Model;
use crate::input::scene::Scene;
use levenberg_marquardt::LeastSquaresProblem;
use nalgebra::storage::Owned;
use nalgebra::{DMatrix, DVector, Dyn};

/// The least-squares problem of one fit (module docs), as the optimiser sees it.
pub(super) struct Problem<'a> {
    scene: &'a Scene,
    reference: &'a Reference,
    params: &'a [Param],
    /// The starting model: the coefficients not fitted stay as they are.
    base: Model,
    /// The coefficients the optimiser last set.
    pub(super) x: DVector<f64>,
    /// The weights s_i.
    scale: Vec<f64>,
    /// The residuals at `x`.
    r: Option<DVector<f64>>,
    /// Evaluations of the theory at the reference so far (the Jacobian's own not counted).
    pub(super) evaluations: usize,
    /// The first error of the theory met on the way (a trial step it could not evaluate).
    pub(super) error: Option<Error>,
}

/// A residual that stands in where the theory cannot be evaluated (a coefficient set outside
/// the model's range during a trial step): large, so the optimiser steps back.
const PENALTY: f64 = 1e6;

impl<'a> Problem<'a> {
    /// The problem of fitting `params` of `start` to `reference` on `scene`, at x0.
    pub(super) fn new(
        scene: &'a Scene,
        reference: &'a Reference,
        params: &'a [Param],
        start: Model,
        x0: DVector<f64>,
    ) -> Problem<'a> {
        Problem {
            scene,
            reference,
            params,
            base: start,
            x: x0,
            scale: scales(reference),
            r: None,
            evaluations: 0,
            error: None,
        }
    }

    /// The model at coefficients `x`.
    pub(super) fn model_at(&self, x: &DVector<f64>) -> Model {
        let mut m = self.base;
        // w₀ moves c₁ at the new c₂: set it last
        for pass_w0 in [false, true] {
            for (p, v) in self.params.iter().zip(x.iter()) {
                if (*p == Param::W0) == pass_w0 {
                    p.set(&mut m, *v);
                }
            }
        }
        m
    }

    /// The residuals r_i at `x` (a [`PENALTY`] each where the theory cannot be evaluated).
    pub(super) fn residuals_at(&mut self, x: &DVector<f64>) -> DVector<f64> {
        self.evaluations += 1;
        let m = self.model_at(x);
        let n = self.reference.points.len();
        if m.validate().is_err() {
            return DVector::from_element(n, PENALTY);
        }
        match predict(self.scene, &m, self.reference) {
            Ok(y) => DVector::from_iterator(
                n,
                y.iter()
                    .zip(&self.reference.points)
                    .zip(&self.scale)
                    .map(|((y, o), s)| (y - o.value) / s),
            ),
            Err(e) => {
                if self.error.is_none() {
                    self.error = Some(e);
                }
                DVector::from_element(n, PENALTY)
            }
        }
    }

    /// The Jacobian of the residuals at `x`: central differences, one-sided where a step
    /// leaves the model's range.
    pub(super) fn jacobian_at(&mut self, x: &DVector<f64>) -> DMatrix<f64> {
        let n = self.reference.points.len();
        let mut j = DMatrix::zeros(n, x.len());
        for k in 0..x.len() {
            let h = 1e-4 * x[k].abs().max(0.1);
            let mut xp = x.clone();
            xp[k] += h;
            let mut xm = x.clone();
            xm[k] -= h;
            // one-sided where a step leaves the model's range (at its edge)
            let col = match (
                self.model_at(&xp).validate().is_ok(),
                self.model_at(&xm).validate().is_ok(),
            ) {
                (true, false) => (self.residuals_at(&xp) - self.residuals_at(x)) / h,
                (false, true) => (self.residuals_at(x) - self.residuals_at(&xm)) / h,
                _ => (self.residuals_at(&xp) - self.residuals_at(&xm)) / (2.0 * h),
            };
            j.set_column(k, &col);
        }
        j
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.x = x.clone();
        let r = self.residuals_at(x);
        self.r = Some(r);
    }

    fn params(&self) -> DVector<f64> {
        self.x.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        self.r.clone()
    }

    fn jacobian(&self) -> Option<DMatrix<f64>> {
        // the trait takes &self; the difference quotient needs evaluations of its own
        let mut me = Problem {
            scene: self.scene,
            reference: self.reference,
            params: self.params,
            base: self.base,
            x: self.x.clone(),
            scale: self.scale.clone(),
            r: None,
            evaluations: 0,
            error: None,
        };
        Some(me.jacobian_at(&self.x))
    }
}

/// The weights s_i of the residuals (module docs).
fn scales(reference: &Reference) -> Vec<f64> {
    reference
        .points
        .iter()
        .map(|o| match (o.error, o.observable) {
            (Some(e), _) => e,
            (None, Observable::Pr) => reference
                .points
                .iter()
                .filter(|q| q.observable == Observable::Pr && q.p == o.p)
                .map(|q| q.value)
                .fold(0.0f64, f64::max)
                .max(f64::MIN_POSITIVE),
            (None, _) => o.value.abs().max(f64::MIN_POSITIVE),
        })
        .collect()
}
