//! Problem specs: JSON wire types and their validation into a mechanism.
pub mod wire;
