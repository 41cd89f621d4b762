//! Physics models: contact geometry, viscosity, density, rheology, lubricants, film formulas,
//! and the case that composes them into a dimensionless problem.

pub mod case;
pub mod checks;
pub mod datasheet;
pub mod density;
pub mod evaluations;
pub mod film;
pub mod flat_film;
pub mod hertz;
pub mod line_contact;
pub mod lubricant;
pub mod pressure_viscosity;
pub mod rheology;
pub mod thermal;
pub mod traction;
pub mod viscosity;
pub mod viscosity_index;
pub mod walther;
