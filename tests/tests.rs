//! Integration tests: one binary, so the crate links once.

mod cli;
mod point_contact;
mod predict;
mod traction;
