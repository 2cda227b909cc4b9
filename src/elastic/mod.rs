//! The elastic body: the slab factor f(qt) of a slab of thickness t with a constant-stress far
//! side [S-4], which turns the half-space stiffness qE*/2 of mode q into qE*f(qt)/2. Used by
//! the inputs (γ̃_glo, u_ela^(f)), the theory and GFMD alike, so it sits below all three.

pub mod slab;
