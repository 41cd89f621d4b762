//! The command line, in layers: `args` (every flag; the only file that knows clap) and
//! `config` (flags turned once into cases, solver parameters and the pipeline's context) at
//! the bottom; `print` and `progress` (what the commands share on stdout and stderr) above
//! them; one file per command on top. Commands call the library and print; the library
//! knows nothing of the command line.

pub mod accuracy;
pub mod args;
pub mod cache;
pub mod check;
pub mod config;
pub mod predict;
pub mod print;
pub mod progress;
pub mod shard;
pub mod slurm;
pub mod solve;
pub mod target;
pub mod thermal;
