//! Subnormal numbers in the single-precision factor of the Newton-Krylov preconditioner
//! ([`super::bordered_lu`]): the one place the solver sets the processor's flush-to-zero
//! arithmetic, and an audit that counts subnormals in the factor and in the GMRES vectors.
//!
//! Why a flag: the factor's entries decay through the elimination's fill past `f32`'s
//! smallest normal number in a continuum no diagonal scaling can lift, and an Intel core takes
//! a microcode assist for every subnormal operand (the measurements: docs/ACCURACY_NOTES.md,
//! "The Newton-Krylov preconditioner's factor").
//!
//! [`FlushToZero`] sets the FTZ and DAZ bits of the calling thread's MXCSR for the duration
//! of a factorisation or a triangular solve of the `f32` factor and restores them after. What
//! it changes in the arithmetic: within those calls, a result below 2^-126 (1.2e-38) is
//! replaced by zero, and a subnormal operand (none comes in: the entries and the right-hand
//! side are narrowed from `f64` inside the scope, where that narrowing flushes too) is read
//! as zero. The factor entries flushed are more than 30 decades below the factor's own
//! rounding (2^-24 of the O(1) pivots). Nothing else changes: the Jacobian products, GMRES,
//! the residuals and the multigrid cycles, all `f64`, keep the processor's default IEEE
//! arithmetic, and the bits do not depend on the caller's MXCSR (the flags are set, not
//! toggled) nor on the processor (FTZ and DAZ are the same on AMD and Intel). The
//! factorisation runs on the calling thread ([`super::fix_factorisation_parallelism`]), so a
//! per-thread flag covers it, on a sweep's rayon workers too. Other architectures than
//! x86-64: no flag is set (the factor keeps its subnormals; correct, only slower where the
//! processor traps them).

use std::cell::Cell;
use std::fmt::{self, Write};

/// MXCSR's flush-to-zero bit (results) and denormals-are-zero bit (operands).
#[cfg(target_arch = "x86_64")]
const FTZ_DAZ: u32 = 0x8040;

#[cfg(target_arch = "x86_64")]
fn read_mxcsr() -> u32 {
    let mut csr: u32 = 0;
    // SAFETY: stmxcsr stores the 32-bit control register to the given address, a local.
    unsafe {
        std::arch::asm!("stmxcsr [{}]", in(reg) &mut csr, options(nostack, preserves_flags));
    }
    csr
}

#[cfg(target_arch = "x86_64")]
fn write_mxcsr(csr: u32) {
    // SAFETY: ldmxcsr loads the control register from a local; `csr` is a value read by
    // `read_mxcsr`, with at most the FTZ and DAZ bits changed (no exception unmasked).
    unsafe {
        std::arch::asm!("ldmxcsr [{}]", in(reg) &csr, options(nostack, readonly, preserves_flags));
    }
}

/// Whether the calling thread flushes subnormal results to zero (always `false` off x86-64).
pub fn flushes_to_zero() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        read_mxcsr() & FTZ_DAZ != 0
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Flush-to-zero and denormals-are-zero on the calling thread while it lives; the thread's
/// former control word is restored when it drops.
pub(crate) struct FlushToZero {
    #[cfg(target_arch = "x86_64")]
    saved: u32,
}

impl FlushToZero {
    pub(crate) fn new() -> Self {
        #[cfg(target_arch = "x86_64")]
        {
            let saved = read_mxcsr();
            write_mxcsr(saved | FTZ_DAZ);
            FlushToZero { saved }
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            FlushToZero {}
        }
    }
}

impl Drop for FlushToZero {
    fn drop(&mut self) {
        #[cfg(target_arch = "x86_64")]
        write_mxcsr(self.saved);
    }
}

/// What an [`audit`] counted on its thread.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct SubnormalCounts {
    /// Factorisations examined.
    pub factors: usize,
    /// Their `L` and `U` entries (the supernodal blocks' explicit zeros included).
    pub factor_entries: usize,
    /// Subnormal ones among them.
    pub factor_subnormals: usize,
    /// The largest factor examined, in entries.
    pub largest_factor: usize,
    /// GMRES vectors examined: every Krylov basis vector the preconditioner is applied to,
    /// and its preconditioned vector.
    pub vectors: usize,
    /// Their entries.
    pub vector_entries: usize,
    /// Subnormal ones among them.
    pub vector_subnormals: usize,
}

thread_local! {
    static AUDIT: Cell<Option<SubnormalCounts>> = const { Cell::new(None) };
}

/// SubnormalCounts, on the calling thread, the subnormal entries of every preconditioner factor and
/// GMRES vector that `run` produces (a test's instrument: a factor is read through its debug
/// form, seconds for a level-8 one, since faer keeps its values private).
pub fn audit<T>(run: impl FnOnce() -> T) -> (T, SubnormalCounts) {
    let before = AUDIT.with(|a| a.replace(Some(SubnormalCounts::default())));
    let out = run();
    let counts = AUDIT.with(|a| a.replace(before)).unwrap_or_default();
    (out, counts)
}

fn auditing() -> bool {
    AUDIT.with(|a| a.get().is_some())
}

fn add(update: impl FnOnce(&mut SubnormalCounts)) {
    AUDIT.with(|a| {
        if let Some(mut c) = a.get() {
            update(&mut c);
            a.set(Some(c));
        }
    });
}

/// Records a GMRES vector in the thread's audit, if one runs.
pub(crate) fn record_vector(v: &[f64]) {
    if auditing() {
        let subnormal = v.iter().filter(|x| x.is_subnormal()).count();
        add(|c| {
            c.vectors += 1;
            c.vector_entries += v.len();
            c.vector_subnormals += subnormal;
        });
    }
}

/// Records a factor (anything whose debug form lists its values as `l_val: [..]` and
/// `ut_val: [..]`, as faer's supernodal LU does) in the thread's audit, if one runs.
pub(crate) fn record_factor(factor: &impl fmt::Debug) {
    if auditing() {
        let mut scan = FactorScan::default();
        // A scan never fails; a debug form without the two lists counts no entries.
        let _ = write!(scan, "{factor:?}");
        add(|c| {
            c.factors += 1;
            c.factor_entries += scan.entries;
            c.factor_subnormals += scan.subnormals;
            c.largest_factor = c.largest_factor.max(scan.entries);
        });
    }
}

/// Reads the `f32` lists `l_val: [..]` and `ut_val: [..]` out of a debug form as it is
/// written, without holding it (a level-8 factor's is over a gigabyte).
#[derive(Default)]
struct FactorScan {
    /// The last bytes outside a list, to find the next list's name.
    tail: Vec<u8>,
    inside: bool,
    token: Vec<u8>,
    entries: usize,
    subnormals: usize,
}

/// Whether a value written as `token` (Rust's shortest form) is a subnormal `f32`: only
/// the exponent is read unless it is the smallest normal number's, -38.
fn is_subnormal_f32(token: &[u8]) -> bool {
    let Some(e) = token.iter().position(|&b| b == b'e') else {
        return false;
    };
    let exponent: i32 = std::str::from_utf8(&token[e + 1..])
        .ok()
        .and_then(|t| t.parse().ok())
        .unwrap_or(0);
    match exponent {
        ..=-39 => true,
        -38 => std::str::from_utf8(token)
            .ok()
            .and_then(|t| t.parse::<f32>().ok())
            .is_some_and(|x| x.is_subnormal()),
        _ => false,
    }
}

impl FactorScan {
    fn push(&mut self, byte: u8) {
        if self.inside {
            match byte {
                b',' | b']' => {
                    if !self.token.is_empty() {
                        self.entries += 1;
                        self.subnormals += usize::from(is_subnormal_f32(&self.token));
                    }
                    self.token.clear();
                    self.inside = byte == b',';
                }
                b' ' => {}
                _ => self.token.push(byte),
            }
        } else {
            self.tail.push(byte);
            if self.tail.len() > 32 {
                self.tail.drain(..22);
            }
            self.inside = self.tail.ends_with(b" l_val: [") || self.tail.ends_with(b" ut_val: [");
        }
    }
}

impl Write for FactorScan {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        s.bytes().for_each(|b| self.push(b));
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug)]
    #[allow(dead_code)] // read through its debug form only
    struct Fake {
        l_col_ptr_for_val: Vec<usize>,
        l_val: Vec<f32>,
        ut_val: Vec<f32>,
        u_compress_cols: Vec<Vec<usize>>,
    }

    #[test]
    fn the_scan_counts_the_subnormal_values_of_both_lists_only() {
        let tiny = f32::MIN_POSITIVE / 4.0;
        let fake = Fake {
            l_col_ptr_for_val: vec![0, 3],
            l_val: vec![1.0, tiny, -tiny, 0.0, 1e-30, 1.2e-38, 1.1e-38],
            ut_val: vec![tiny, 2.5e38, -0.0, f32::MIN_POSITIVE],
            u_compress_cols: vec![vec![], vec![1]],
        };
        let ((), counts) = audit(|| record_factor(&fake));
        assert_eq!(counts.factors, 1);
        assert_eq!(counts.factor_entries, 11);
        // tiny twice, -tiny and 1.1e-38; not 1e-30, 1.2e-38 or the smallest normal.
        assert_eq!(counts.factor_subnormals, 4);
    }

    #[test]
    fn vectors_are_counted_only_inside_an_audit() {
        record_vector(&[f64::MIN_POSITIVE / 2.0]);
        let ((), counts) = audit(|| record_vector(&[1.0, f64::MIN_POSITIVE / 2.0, 0.0]));
        assert_eq!((counts.vectors, counts.vector_entries), (1, 3));
        assert_eq!(counts.vector_subnormals, 1);
    }

    #[test]
    fn the_guard_flushes_inside_and_restores_the_callers_arithmetic() {
        // black_box: the division happens at run time, under the thread's control word.
        let small = std::hint::black_box(f32::MIN_POSITIVE);
        assert!(
            !flushes_to_zero(),
            "the test thread starts with default arithmetic"
        );
        assert!((small / 4.0).is_subnormal());
        {
            let _ftz = FlushToZero::new();
            if cfg!(target_arch = "x86_64") {
                assert!(flushes_to_zero());
                assert_eq!(small / 4.0, 0.0);
            }
        }
        assert!(!flushes_to_zero());
        assert!((small / 4.0).is_subnormal());
    }
}
