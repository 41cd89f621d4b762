//! The cases of the probes (`order_probe`, `nested_probe`, ...), named on their command lines,
//! and the parameters of one level solved alone.
use repro::physics::case::*;
use repro::solver::point::Params;

/// `case23` (Fig. 6 case 23: 5P4E, 40 C, 1 GPa, 12 m/s, S 0.5 %, tau0 6 MPa; Roelands,
/// Dowson-Higginson, Eyring), `d:M:L:SBAR` (Moes groups, circular, Barus, incompressible,
/// Eyring: `repro solve --m M --l L --s-bar SBAR`) or `p:LUBRICANT:T_C:PH_PA:UM:SLIP:TAU0_PA`
/// (circular, the Figs. 4-7 physics).
pub fn case_of(name: &str) -> Case {
    let name = if name == "case23" {
        "p:5p4e:40:1e9:12:0.005:6e6"
    } else {
        name
    };
    if let Some(rest) = name.strip_prefix("p:") {
        // p:LUBRICANT:T_C:PH_PA:UM:SLIP:TAU0_PA, circular, Figs. 4-7 physics.
        let f: Vec<&str> = rest.split(':').collect();
        let n = |i: usize| f[i].parse::<f64>().unwrap();
        return Case {
            spec: CaseForm::Physical(PhysicalCase {
                lubricant: LubricantSpec::Named {
                    lubricant: f[0].into(),
                    temperature_c: n(1),
                },
                ph_pa: n(2),
                um_m_s: n(3),
                slip: n(4),
                tau0_pa: n(5),
                rx_m: 1.03875e-2,
                ry_m: 1.03875e-2,
                e_prime_pa: 226e9,
            }),
            physics: Physics::figs_4_to_7(),
        };
    }
    let v: Vec<f64> = name
        .split(':')
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    Case::circular(v[0], v[1], v[2])
}

/// The rule's parameters for `problem` at `level` ([`Params::for_problem`]) without the
/// accuracy target, the error ladder and the refinement: the level alone, as the tau and
/// quadrature probes compare it with its neighbours.
// Not every probe that shares this module calls it.
#[allow(dead_code)]
pub fn level_alone(problem: &Problem, level: u32) -> Params {
    let mut params = Params::for_problem(problem, level);
    params.accuracy.target = None;
    params.accuracy.error_levels = 0;
    params.accuracy.refinement_levels = 0;
    params
}
