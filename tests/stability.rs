//! Stability where methods fail (issue #6): each test runs the failing method and the remedy and asserts both
//! sides, with the measured values in the comments. Coarse resolutions; the same measures run at any
//! resolution with `bowwave chart speed-accuracy CASE --variants ... --quantity ...`.

use bowwave::cases::{
    self,
    run::{run, RunOptions, RunResult},
    CaseFile,
};
use bowwave::methods::charts::apply_variant;

fn run_variant(case: &str, variant: &str, res: f64, end: f64) -> RunResult {
    run_variant_with(case, variant, res, end, false)
}

fn run_variant_with(case: &str, variant: &str, res: f64, end: f64, allow_energy_growth: bool) -> RunResult {
    let mut c: CaseFile = cases::load(case).unwrap();
    apply_variant(&mut c, variant).unwrap();
    run(
        &c,
        &RunOptions {
            res: Some(res),
            end_time: Some(end),
            allow_energy_growth,
            ..Default::default()
        },
    )
    .unwrap()
}

/// Hydrostatic tank (H/dx = 10) to t√(g/H) = 100: δ-SPH keeps the hydrostatic pressure in the top 0.2 H,
/// the Molteni–Colagrossi diffusion without the gradient correction (5.4) drifts there (the failure that
/// motivated (5.2), Antuono et al. 2010). Measured mean |p − ρ0 g (H − z)|/(ρ0 g H): δ-SPH 0.022 (0.0069 at
/// H/dx = 20), Molteni–Colagrossi 0.33 (0.14 at H/dx = 20).
#[test]
fn molteni_diffusion_drifts_near_the_free_surface_where_delta_sph_holds() {
    let t = 100.0 / 9.81f64.sqrt();
    let delta = run_variant("hydrostatic", "delta-sph", 10.0, t);
    // The drift creates energy (1e-3 M g H by t√(g/H) = 5.6), which the runner would diagnose and stop:
    // first check that it does, then let it run to measure the drift.
    let stopped = run_variant("hydrostatic", "molteni", 10.0, t);
    assert!(matches!(
        stopped.blowup.map(|b| b.reason),
        Some(bowwave::sph::solver::BlowUpReason::EnergyGrowth { .. })
    ));
    let molteni = run_variant_with("hydrostatic", "molteni", 10.0, t, true);
    assert!(delta.blowup.is_none() && molteni.blowup.is_none());
    let (ed, em) = (
        bowwave::validation::near_surface_pressure_error(&delta),
        bowwave::validation::near_surface_pressure_error(&molteni),
    );
    println!("near-surface pressure error: δ-SPH {ed:.3e}, Molteni–Colagrossi {em:.3e}");
    assert!(
        ed < 0.04,
        "δ-SPH must keep the hydrostatic pressure near the surface: {ed}"
    );
    assert!(em > 0.15, "the uncorrected diffusion must show its drift: {em}");
    assert!(em > 5.0 * ed);
}

/// Dam break (H/dx = 20) at t√(g/H) = 2: the pressure noise (RMS of p minus its kernel-smoothed field, over
/// ρ g H) is at least 5× lower with δ-SPH than with standard WCSPH (no density diffusion). Measured: 0.051
/// against 0.377 (7.4×).
#[test]
fn delta_sph_pressure_is_five_times_less_noisy_than_wcsph() {
    let t = 2.0 / (9.81f64 / 0.6).sqrt();
    let noise = |variant: &str| {
        let r = run_variant("dam-break", variant, 20.0, t);
        assert!(
            r.blowup.is_none(),
            "{variant} stopped: {:?}",
            r.blowup.map(|b| b.to_string())
        );
        r.sim.pressure_noise() / (1000.0 * 9.81 * 0.6)
    };
    let (nd, nw) = (noise("delta-sph"), noise("wcsph"));
    println!(
        "pressure noise / (ρ g H): δ-SPH {nd:.3e}, WCSPH {nw:.3e}, ratio {:.1}",
        nw / nd
    );
    assert!(nw >= 5.0 * nd, "δ-SPH {nd} against WCSPH {nw}");
    assert!(nd < 0.1);
}

/// Artificial viscosity below the threshold of §4.1.1 (α > 0.01): the dam break (H/dx = 20) to t√(g/H) = 6,
/// after the impact, judged by the pressure noise against the limit of `charts::NOISE_LIMIT` (0.2 ρ g H).
/// Measured (`bowwave chart stability dam-break --rows alpha=0,...,alpha=0.05 --cols wcsph,delta-sph`): without
/// density diffusion the noise is 3.9, 3.2, 1.8, 1.9, 1.4, 1.1 ρgH at α = 0, 0.002, 0.005, 0.01, 0.02, 0.05 —
/// above the limit at every α tried, and worst below α = 0.01; with δ-SPH it is 0.46 at α = 0 (fails) and
/// 0.11–0.12 from α = 0.002 to 0.02 (holds). This test, to t√(g/H) = 6 exactly: WCSPH 4.03 (α = 0) and 1.45
/// (α = 0.02), δ-SPH 0.40 (α = 0) and 0.109 (α = 0.02).
#[test]
fn without_viscosity_or_diffusion_the_dam_break_goes_noisy() {
    let t = 6.0 / (9.81f64 / 0.6).sqrt();
    let noise = |variants: &[&str]| {
        let mut c: CaseFile = cases::load("dam-break").unwrap();
        // The thesis's δ-SPH and WCSPH as they are, without particle shifting (which keeps even δ-SPH without
        // viscosity quiet, session 27: what this test shows would not be seen).
        apply_variant(&mut c, "no-shifting").unwrap();
        for v in variants {
            apply_variant(&mut c, v).unwrap();
        }
        let r = run(
            &c,
            &RunOptions {
                res: Some(20.0),
                end_time: Some(t),
                ..Default::default()
            },
        )
        .unwrap();
        match r.blowup {
            Some(_) => f64::INFINITY,
            None => r.sim.pressure_noise() / (1000.0 * 9.81 * 0.6),
        }
    };
    let limit = bowwave::methods::charts::NOISE_LIMIT;
    let w0 = noise(&["wcsph", "alpha=0"]);
    let w2 = noise(&["wcsph", "alpha=0.02"]);
    let d0 = noise(&["delta-sph", "alpha=0"]);
    let d2 = noise(&["delta-sph", "alpha=0.02"]);
    println!("noise/(ρgH): WCSPH α=0 {w0:.3}, α=0.02 {w2:.3}; δ-SPH α=0 {d0:.3}, α=0.02 {d2:.3}");
    assert!(w0 > limit && w2 > limit, "standard WCSPH is noisy at both α");
    assert!(w0 > 2.0 * w2, "and noisier below the threshold");
    assert!(d0 > limit, "δ-SPH without any viscosity fails too");
    assert!(d2 < limit, "the default δ-SPH (α = 0.02) holds");
}

/// A 2D+t case at Fr 0.5 (coarse dx/L = 2e-3, to x/L = 0.2): standard WCSPH against δ-SPH, on the pressure
/// noise at the end. On the Wigley hull (exact geometry, so the bounds do not move when an approximated hull is
/// regenerated): 0.0107 against 0.0772 ρgD, 7.2×. It ran on the Athena approximation until session 24: 0.0131
/// against 0.0720 (5.5×) on the earlier one; on the regenerated hull, whose run-up collapses at x/L 0.19–0.24,
/// 0.0354 against 0.1414 (4.0×), noisier for both, above the absolute bound set from the earlier hull's flow.
#[test]
fn twodt_wcsph_is_noisier_than_delta_sph() {
    use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
    use bowwave::sph::density_diffusion::DensityDiffusion;
    use bowwave::twodt::{run, scene};
    let hull = std::sync::Arc::new(HullSurface::new(
        &HullOffsets::read(std::path::Path::new("hulls/wigley.csv")).unwrap(),
    ));
    let result = |diffusion: DensityDiffusion, name: &str| {
        let cfg = scene::TwoDtConfig {
            fr: 0.5,
            dx: Some(2e-3),
            until: scene::Until::X(0.2),
            output_dx: 0.05,
            diffusion,
            ..Default::default()
        };
        let opts = run::TwoDtOptions::quiet(std::env::temp_dir().join(format!("bowwave-2dt-{name}")));
        run::run(hull.clone(), &cfg, &opts).unwrap().ran().unwrap()
    };
    let d = result(DensityDiffusion::DeltaSph, "delta");
    let w = result(DensityDiffusion::None, "wcsph");
    assert!(d.blowup.is_none() && w.blowup.is_none());
    let (nd, nw) = (d.pressure_noise_over_rho_g_d, w.pressure_noise_over_rho_g_d);
    println!(
        "2D+t pressure noise / (ρgD): δ-SPH {nd:.4}, WCSPH {nw:.4}, ratio {:.2}",
        nw / nd
    );
    assert!(
        nw > 3.0 * nd,
        "WCSPH must show its noise in the 2D+t run: {nd} against {nw}"
    );
    assert!(nd < 0.03, "δ-SPH stays quiet: {nd}");
}

/// Regression (issue #35, session 27): with the particle shifting on, the coarse dam break (H/dx 8) was stopped
/// at step 11 as an unstable integration, its mechanical energy 1.03e-3 of M g H above the start: the shift
/// moves particles along the column's vertical face, up into its top corner, and so adds potential energy of its
/// own (the raw balance peaks at 1.32e-3 M g H over the whole run). The energy check now discounts the shift's work
/// (`Simulation::shift_energy`), and the run goes on; the discounted balance still only dissipates.
#[test]
fn particle_shifting_work_is_not_taken_for_an_unstable_integration() {
    let r = run_variant("dam-break", "sun2017", 8.0, 0.3);
    assert!(r.blowup.is_none(), "{:?}", r.blowup);
    assert!(
        r.sim.shift_energy > 0.0,
        "the shift added no potential energy: {}",
        r.sim.shift_energy
    );
}
