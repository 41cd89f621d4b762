use super::*;
use crate::physics::case::Physics;
use crate::physics::line_contact::LinePhysicalCase;

fn heavy_case() -> LinePhysicalCase {
    LinePhysicalCase {
        alpha_per_pa: 21.6e-9,
        eta0_pa_s: 8.24e-3,
        ph_pa: 3e9,
        um_m_s: 7.0,
        slip: 0.001,
        tau0_pa: 8e6,
        rx_m: 1.03875e-2,
        e_prime_pa: 226e9,
    }
}

#[test]
fn probe_heavy() {
    let pr = LineProblem::from_physical(&heavy_case(), Physics::figs_4_to_7()).unwrap();
    eprintln!("M {} L {} tau_c {}", pr.groups.m, pr.groups.l, pr.tau_c());
    for level in [6, 8, 10] {
        let mut obs = |p: &Progress| {
            eprintln!(
                "  L{} c{} r {:.3e} load {:.2e} hc {:.5e}",
                p.level, p.cycle, p.residual, p.load_error, p.h_central
            )
        };
        let params = Params {
            max_cycles: 30,
            ..Params::at_level(level)
        };
        let r = solve(&pr, &params, Some(&mut obs));
        match r {
            Ok(s) => eprintln!(
                "level {level}: hc {:.5e} moes {:.4} hmin {:.4} mu {:.4} t {:.3}",
                s.film.h_central,
                s.film.hc_moes,
                s.film.hmin_moes,
                s.friction.sliding,
                s.info.seconds
            ),
            Err(e) => eprintln!("level {level}: {e}"),
        }
    }
}

#[test]
fn probe_light() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    for (m, l) in [(10.0, 5.0), (20.0, 10.0), (50.0, 10.0), (100.0, 10.0)] {
        let d = LineDimensionlessCase {
            m,
            l,
            s_bar: 0.0,
            slip: 0.0,
            eta0_pa_s: None,
            ph_pa: None,
        };
        let pr = LineProblem::from_dimensionless(&d, physics).unwrap();
        eprintln!(
            "M {m} L {l} abar {} moes {}",
            pr.groups.alpha_bar,
            LineFilmFormula::Moes.hc(m, l)
        );
        for level in [6, 8, 10] {
            let params = Params {
                max_cycles: 30,
                ..Params::at_level(level)
            };
            let mut hist = Vec::new();
            let mut obs =
                |p: &Progress| hist.push((p.level, p.residual, p.load_error, p.h_central));
            let r = solve(&pr, &params, Some(&mut obs));
            match r {
                Ok(s) => eprintln!(
                    "  level {level}: hc {:.5e} moes {:.4} hmin {:.4} cyc {} t {:.3}",
                    s.film.h_central,
                    s.film.hc_moes,
                    s.film.hmin_moes,
                    s.info.cycles,
                    s.info.seconds
                ),
                Err(e) => eprintln!(
                    "  level {level}: {e} {:?}",
                    &hist[hist.len().saturating_sub(4)..]
                ),
            }
        }
    }
}

#[test]
fn probe_single() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    for (m, l) in [(10.0, 5.0), (20.0, 10.0), (100.0, 10.0)] {
        let d = LineDimensionlessCase {
            m,
            l,
            s_bar: 0.0,
            slip: 0.0,
            eta0_pa_s: None,
            ph_pa: None,
        };
        let pr = LineProblem::from_dimensionless(&d, physics).unwrap();
        for level in [4, 5, 6] {
            let params = Params {
                coarsest_level: level,
                coarsest_sweeps: 4000,
                coarsest_force_updates: 400,
                max_cycles: 1,
                tolerance: 1e30,
                load_tolerance: 1e30,
                ..Params::at_level(level)
            };
            let mut mg = Hierarchy::new(Model::new(&pr), &params, initial_h0(&pr));
            {
                let l0 = &mut mg.levels[0];
                for i in 0..=l0.n {
                    l0.p[i] = crate::physics::line_contact::LineHertz::pressure(l0.x(i));
                }
            }
            for rep in 0..5 {
                mg.cycle(0);
                let r = mg.residual_norm(0);
                let l = &mg.levels[0];
                eprintln!(
                    "M {m} level {level} rep {rep}: r {r:.3e} load {:.3e} hc {:.4e} h0 {:.4e}",
                    l.load_defect(),
                    friction::film(l, 1.0).h_central,
                    mg.h0
                );
            }
        }
    }
}

#[test]
fn probe_relax_fine() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    for (m, l) in [(20.0, 10.0)] {
        let d = LineDimensionlessCase {
            m,
            l,
            s_bar: 0.0,
            slip: 0.0,
            eta0_pa_s: None,
            ph_pa: None,
        };
        let pr = LineProblem::from_dimensionless(&d, physics).unwrap();
        for level in [7, 8] {
            let params = Params {
                coarsest_level: level,
                coarsest_sweeps: 500,
                coarsest_force_updates: 50,
                ..Params::at_level(level)
            };
            let mut mg = Hierarchy::new(Model::new(&pr), &params, initial_h0(&pr));
            {
                let l0 = &mut mg.levels[0];
                for i in 0..=l0.n {
                    l0.p[i] = crate::physics::line_contact::LineHertz::pressure(l0.x(i));
                }
            }
            for rep in 0..10 {
                mg.cycle(0);
                let r = mg.residual_norm(0);
                let l = &mg.levels[0];
                eprintln!(
                    "M {m} level {level} rep {rep}: r {r:.3e} load {:.3e} hc {:.4e} h0 {:.4e}",
                    l.load_defect(),
                    friction::film(l, 1.0).h_central,
                    mg.h0
                );
            }
        }
    }
}

#[test]
fn probe_twolevel() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    let d = LineDimensionlessCase {
        m: 20.0,
        l: 10.0,
        s_bar: 0.0,
        slip: 0.0,
        eta0_pa_s: None,
        ph_pa: None,
    };
    let pr = LineProblem::from_dimensionless(&d, physics).unwrap();
    for (lo, hi) in [(7u32, 8u32), (6, 8), (4, 8)] {
        let params = Params {
            coarsest_level: lo,
            max_cycles: 12,
            tolerance: 1e-14,
            ..Params::at_level(hi)
        };
        let mut obs = |p: &Progress| {
            eprintln!(
                "  ({lo}->{hi}) L{} c{} r {:.3e} load {:.2e} hc {:.5e}",
                p.level, p.cycle, p.residual, p.load_error, p.h_central
            )
        };
        let r = solve(&pr, &params, Some(&mut obs));
        eprintln!("{:?}", r.map(|s| s.film.h_central));
    }
}

#[test]
fn probe_invariant() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    let d = LineDimensionlessCase {
        m: 20.0,
        l: 10.0,
        s_bar: 0.0,
        slip: 0.0,
        eta0_pa_s: None,
        ph_pa: None,
    };
    let pr = LineProblem::from_dimensionless(&d, physics).unwrap();
    let params = Params {
        coarsest_level: 6,
        coarsest_sweeps: 500,
        coarsest_force_updates: 50,
        ..Params::at_level(7)
    };
    let mut mg = Hierarchy::new(Model::new(&pr), &params, initial_h0(&pr));
    // converge level 7 alone, treating it as a coarsest level by hand
    {
        let l = &mut mg.levels[1];
        for i in 0..=l.n {
            l.p[i] = crate::physics::line_contact::LineHertz::pressure(l.x(i));
        }
    }
    for _ in 0..20 {
        for _ in 0..50 {
            mg.relax(1);
        }
        let defect = mg.levels[1].load_defect();
        mg.h0 += 0.1 * defect;
    }
    eprintln!(
        "fine converged: r {:.3e} load {:.3e}",
        mg.residual_norm(1),
        mg.levels[1].load_defect()
    );
    for c in 0..5 {
        let before: Vec<f64> = mg.levels[1].p.clone();
        let h0b = mg.h0;
        mg.prepare(1);
        {
            let (lo, hi) = mg.levels.split_at_mut(1);
            transfer::coarsen(&hi[0], &mut lo[0], &mg.model, mg.h0);
        }
        let rc = mg.residual_norm(0);
        eprintln!(
            "cycle {c}: coarse residual after coarsen {rc:.3e}, coarse load defect {:.3e}",
            mg.levels[0].load_defect()
        );
        mg.cycle(0);
        let maxe = mg.levels[0]
            .p
            .iter()
            .zip(&mg.levels[0].pold)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        eprintln!(
            "   coarse change max {maxe:.3e}, h0 change {:.3e}",
            mg.h0 - h0b
        );
        {
            let (lo, hi) = mg.levels.split_at_mut(1);
            transfer::correct(&lo[0], &mut hi[0]);
        }
        let dp = mg.levels[1]
            .p
            .iter()
            .zip(&before)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        eprintln!(
            "   fine change {dp:.3e} fine residual {:.3e}",
            mg.residual_norm(1)
        );
    }
}

#[test]
fn probe_where() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    let d = LineDimensionlessCase {
        m: 20.0,
        l: 10.0,
        s_bar: 0.0,
        slip: 0.0,
        eta0_pa_s: None,
        ph_pa: None,
    };
    let pr = LineProblem::from_dimensionless(&d, physics).unwrap();
    let params = Params {
        coarsest_level: 6,
        coarsest_sweeps: 3000,
        coarsest_force_updates: 300,
        ..Params::at_level(7)
    };
    let mut mg = Hierarchy::new(Model::new(&pr), &params, initial_h0(&pr));
    {
        let l = &mut mg.levels[1];
        for i in 0..=l.n {
            l.p[i] = crate::physics::line_contact::LineHertz::pressure(l.x(i));
        }
    }
    for _ in 0..20 {
        for _ in 0..50 {
            mg.relax(1);
        }
        let defect = mg.levels[1].load_defect();
        mg.h0 += 0.1 * defect;
    }
    let show = |mg: &mut Hierarchy, tag: &str| {
        mg.prepare(1);
        let l = &mg.levels[1];
        let mut v: Vec<(f64, usize)> = (1..l.n)
            .filter(|&i| l.p[i] > 0.0)
            .map(|i| (l.residual(i).abs(), i))
            .collect();
        v.sort_by(|a, b| b.0.partial_cmp(&a.0).unwrap());
        let top: Vec<String> = v
            .iter()
            .take(6)
            .map(|(r, i)| format!("X={:.3} r={:.2e} xi={:.2e}", l.x(*i), r, l.xi(*i)[0]))
            .collect();
        eprintln!("{tag}: norm {:.3e} | {}", l.residual_norm(), top.join("; "));
    };
    show(&mut mg, "start");
    for c in 0..6 {
        mg.relax(1);
        mg.relax(1);
        show(&mut mg, &format!("c{c} pre"));
        mg.prepare(1);
        {
            let (lo, hi) = mg.levels.split_at_mut(1);
            transfer::coarsen(&hi[0], &mut lo[0], &mg.model, mg.h0);
        }
        mg.cycle(0);
        eprintln!("   coarse final residual {:.3e}", mg.residual_norm(0));
        {
            let (lo, hi) = mg.levels.split_at_mut(1);
            transfer::correct(&lo[0], &mut hi[0]);
        }
        show(&mut mg, &format!("c{c} corr"));
        mg.relax(1);
        show(&mut mg, &format!("c{c} post"));
    }
}

fn run_case(tag: &str, pr: &LineProblem, params: &Params) {
    let mut hist = Vec::new();
    let mut obs = |p: &Progress| hist.push(p.residual);
    let r = solve(pr, params, Some(&mut obs));
    let h: Vec<String> = hist.iter().map(|r| format!("{r:.1e}")).collect();
    match r {
        Ok(s) => eprintln!(
            "{tag}: OK hc {:.5e} moes {:.4} mu {:.4} cyc {} t {:.3} | {}",
            s.film.h_central,
            s.film.hc_moes,
            s.friction.sliding,
            s.info.cycles,
            s.info.seconds,
            h.join(" ")
        ),
        Err(e) => eprintln!(
            "{tag}: ERR {} | {}",
            e.to_string().chars().take(60).collect::<String>(),
            h.join(" ")
        ),
    }
}

#[test]
fn probe_params() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    let d = LineDimensionlessCase {
        m: 20.0,
        l: 10.0,
        s_bar: 0.0,
        slip: 0.0,
        eta0_pa_s: None,
        ph_pa: None,
    };
    let light = LineProblem::from_dimensionless(&d, physics).unwrap();
    let heavy = LineProblem::from_physical(&heavy_case(), Physics::figs_4_to_7()).unwrap();
    for (name, pr) in [("light", &light), ("heavy", &heavy)] {
        for gamma in [1, 2] {
            for coarsest in [4, 5, 6] {
                for level in [8, 10] {
                    let params = Params {
                        gamma,
                        coarsest_level: coarsest,
                        max_cycles: 40,
                        ..Params::at_level(level)
                    };
                    run_case(
                        &format!("{name} g{gamma} c{coarsest} L{level}"),
                        pr,
                        &params,
                    );
                }
            }
        }
    }
}

#[test]
fn probe_stall() {
    use crate::physics::line_contact::LineDimensionlessCase;
    use crate::physics::rheology::Rheology;
    let physics = Physics {
        rheology: Rheology::Newtonian,
        ..Physics::default()
    };
    let d = LineDimensionlessCase {
        m: 20.0,
        l: 10.0,
        s_bar: 0.0,
        slip: 0.0,
        eta0_pa_s: None,
        ph_pa: None,
    };
    let pr = LineProblem::from_dimensionless(&d, physics).unwrap();
    let params = Params {
        coarsest_level: 6,
        ..Params::at_level(8)
    };
    let mut mg = Hierarchy::new(Model::new(&pr), &params, initial_h0(&pr));
    {
        let l0 = &mut mg.levels[0];
        for i in 0..=l0.n {
            l0.p[i] = crate::physics::line_contact::LineHertz::pressure(l0.x(i));
        }
    }
    mg.make_top(0);
    mg.cycle(0);
    for k in 1..=2 {
        mg.make_top(k);
        mg.interpolate(k);
        for _ in 0..(if k == 2 { 30 } else { 2 }) {
            mg.cycle(k);
        }
    }
    for c in 0..4 {
        mg.cycle(2);
        mg.prepare(2);
        let l = &mg.levels[2];
        let mut v: Vec<(f64, usize)> = (1..l.n)
            .filter(|&i| l.p[i] > 0.0)
            .map(|i| (l.residual(i).abs(), i))
            .collect();
        v.sort_by(|a, b| b.0.partial_cmp(&a.0).unwrap());
        let top: Vec<String> = v
            .iter()
            .take(5)
            .map(|(r, i)| {
                format!(
                    "X={:.3} r={:.2e} xi={:.2e} P={:.3e}",
                    l.x(*i),
                    r,
                    l.xi(*i)[0].max(l.xi(*i)[1]),
                    l.p[*i]
                )
            })
            .collect();
        eprintln!(
            "c{c}: norm {:.3e} h0 {:.6e} | {}",
            l.residual_norm(),
            mg.h0,
            top.join("; ")
        );
        let last = (1..l.n).rev().find(|&i| l.p[i] > 0.0).unwrap();
        let s: Vec<String> = (last - 12..=last + 1)
            .map(|i| {
                format!(
                    "{:.3}:{:.2e}/{:.1e}",
                    l.x(i),
                    l.p[i],
                    l.residual(i.max(1).min(l.n - 1))
                )
            })
            .collect();
        eprintln!("    tail {}", s.join(" "));
    }
}

#[test]
fn probe_blowup() {
    let heavy = LineProblem::from_physical(&heavy_case(), Physics::figs_4_to_7()).unwrap();
    let params = Params {
        gamma: 1,
        coarsest_level: 6,
        max_cycles: 20,
        ..Params::at_level(10)
    };
    run_case("heavy c6 L10", &heavy, &params);
}
