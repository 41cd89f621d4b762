//! Integration tests: one binary, so the crate links once.

mod at_the_heaviest_load;
mod browser;
mod check;
mod cli;
mod continuation;
mod csv_columns;
mod error_bracket;
mod ladder_starts;
mod line_contact;
mod lss;
mod lubricant;
mod mastercurve;
mod one_rule;
mod point_accuracy;
mod point_composite;
mod point_contact;
mod predict;
mod revision;
mod shards;
mod support;
mod tau_extrapolation;
mod text;
mod traction;
