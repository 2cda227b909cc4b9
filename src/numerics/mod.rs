//! Numerical building blocks shared by the theory and GFMD: 2-D real FFTs, the adaptive ODE
//! integrator.

pub mod fft2;
pub mod ode;
