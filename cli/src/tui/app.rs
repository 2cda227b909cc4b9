//! The explorer's model as one name for the front ends: the state ([`super::state`]) and
//! its updates ([`super::update`]).

pub use super::state::*;

#[cfg(test)]
#[path = "app_tests.rs"]
mod tests;
