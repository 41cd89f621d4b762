//! Integration tests: one binary, so the crate links once.

mod cli;
mod line_contact;
mod point_contact;
