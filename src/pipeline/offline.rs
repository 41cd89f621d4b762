//! Offline assembly (`--offline`): a target built from the cache alone. Before anything is
//! built, every job of the run must have a verified entry, or the error names every case
//! that lacks one, with its target and key.

use super::cache::{Cache, Lookup};
use super::job::Job;
use super::outcome::CaseOutcome;
use crate::pipeline::error::PipelineError;

/// The jobs of `jobs` that `cache` has no verified entry for (with the reason for a corrupt
/// one).
pub fn missing<'j>(jobs: &'j [Job], cache: &Cache) -> Vec<(&'j Job, Option<PipelineError>)> {
    jobs.iter()
        .filter_map(|j| match cache.get::<CaseOutcome>(&j.key) {
            Lookup::Hit(..) => None,
            Lookup::Miss => Some((j, None)),
            Lookup::Corrupt(why) => Some((j, Some(why))),
        })
        .collect()
}

/// The message of an offline run that lacks entries: every missing case, by target, label and
/// key.
pub fn missing_message(missing: &[(String, &Job, Option<PipelineError>)], cache: &Cache) -> String {
    let mut msg = format!(
        "--offline: {} case(s) missing from the cache {} (an offline build never solves; run the missing shards or merge their caches first):",
        missing.len(),
        cache.dir().display()
    );
    for (target, job, why) in missing {
        msg.push_str(&format!("\n  {target}: {} [key {}]", job.label, job.key));
        if let Some(why) = why {
            msg.push_str(&format!(" (corrupt entry: {why})"));
        }
    }
    msg
}

/// Checks that `cache` holds every job of `list` (each with the target that needs it); the
/// error lists all that it lacks, across targets.
pub fn check_complete(cache: &Cache, list: &[(String, Job)]) -> Result<(), PipelineError> {
    let jobs: Vec<Job> = list.iter().map(|(_, j)| j.clone()).collect();
    let absent: Vec<(String, &Job, Option<PipelineError>)> = missing(&jobs, cache)
        .into_iter()
        .map(|(j, why)| {
            let target = list
                .iter()
                .find(|(_, lj)| lj.key == j.key)
                .map(|(t, _)| t.clone())
                .unwrap_or_default();
            (target, j, why)
        })
        .collect();
    if absent.is_empty() {
        Ok(())
    } else {
        Err(PipelineError::Offline(missing_message(&absent, cache)))
    }
}
