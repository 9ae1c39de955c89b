//! The wedge check of the 2D+t machinery: a "hull" whose sections are wedges of fixed deadrise β whose
//! apex sinks linearly with x is, in 2D+t, a rigid wedge entering the water at constant speed V = U k.
//! The same scene is run twice, once with the hull-section wall built from the spline surface (w_n from
//! (10.4)) and once with a rigid wedge profile translated at −V, and both are compared with Wagner's
//! flat-plate theory (data/reference/wagner_*_DERIVED.csv; thesis-independent, see its README):
//! wetted (pile-up) height above the apex z_wet = (π/2) V t and vertical force per unit length
//! F = (π³/4) ρ V³ t cot²β for the whole wedge (half of it in our half domain).

use super::scene::{build, TwoDtConfig, Until};
use crate::driver::{drive, Flow, Observer, Outcome};
use crate::geometry::hull_file::{HullMeta, HullOffsets, HullStatus, Station};
use crate::geometry::surface::HullSurface;
use crate::sph::deforming_wall::{DeformingWall, Profile};
use crate::sph::polyline_wall::{FluidSide, VertexMotion};
use crate::sph::solver::Simulation;
use nalgebra::Vector2;
use std::sync::Arc;

type V2 = Vector2<f64>;

/// The wedge case (units of L, g, ρ0).
#[derive(Clone, Copy, Debug)]
pub struct WedgeSpec {
    pub deadrise_deg: f64,
    /// Ship speed U (Froude number).
    pub fr: f64,
    /// Apex slope: the apex sinks by `slope` per unit x, so V = U·slope.
    pub slope: f64,
    /// Penetration at the end of the run.
    pub penetration: f64,
    /// Fine spacing dx/L.
    pub dx: f64,
}

impl Default for WedgeSpec {
    fn default() -> Self {
        WedgeSpec {
            deadrise_deg: 30.0,
            fr: 1.0,
            slope: 0.5,
            penetration: 0.03,
            dx: 1.0e-3,
        }
    }
}

/// The x/L at which the apex touches the calm level.
const X_TOUCH: f64 = 0.01;

impl WedgeSpec {
    fn tan_beta(&self) -> f64 {
        self.deadrise_deg.to_radians().tan()
    }
    fn apex(&self, x: f64) -> f64 {
        -self.slope * (x - X_TOUCH)
    }
    fn deck(&self) -> f64 {
        4.0 * self.penetration
    }
    /// Hull offsets of the wedge hull: 21 stations over x ∈ [0, X_TOUCH + 2 penetration/slope].
    pub fn offsets(&self) -> HullOffsets {
        let x_end = X_TOUCH + 2.0 * self.penetration / self.slope;
        let stations = (0..21)
            .map(|k| {
                let x = x_end * k as f64 / 20.0;
                let za = self.apex(x);
                let y_top = (self.deck() - za) / self.tan_beta();
                Station {
                    x,
                    points: (0..11)
                        .map(|j| {
                            let f = j as f64 / 10.0;
                            [f * y_top, za + f * (self.deck() - za)]
                        })
                        .collect(),
                }
            })
            .collect();
        HullOffsets {
            meta: HullMeta {
                name: format!("wedge{}", self.deadrise_deg),
                status: HullStatus::Exact,
                length_m: 1.0,
                draft_m: self.penetration,
                beam_m: 2.0 * self.penetration / self.tan_beta(),
                model_scale: 1.0,
                transom: false,
                transom_immersion_m: 0.0,
                source: "bowwave::twodt::wedge (analytic wedge)".into(),
                notes: Default::default(),
            },
            stations,
        }
    }
}

/// One sample of a wedge run.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct WedgeSample {
    /// Penetration depth V t.
    pub penetration: f64,
    /// Wagner-equivalent wetted height above the apex, (π/2) × the centre of pressure along the side
    /// (times sinβ), / (V t).
    pub pileup_over_vt: f64,
    /// Vertical force on the half wedge / (ρ V³ t), from the impulse 2 ∫F dt / (ρ V³ t²).
    pub force_coefficient: f64,
}

/// Result of the comparison.
#[derive(Clone, Debug, serde::Serialize)]
pub struct WedgeComparison {
    pub spec_deadrise_deg: f64,
    pub dx: f64,
    pub twodt: Vec<WedgeSample>,
    pub rigid: Vec<WedgeSample>,
    /// Wagner: z_wet/(V t) = π/2.
    pub wagner_pileup_over_vt: f64,
    /// Wagner, half wedge: F/(ρ V³ t) = (π³/8) cot²β.
    pub wagner_force_coefficient: f64,
}

/// Runs the wedge in 2D+t (`rigid = false`) or as a rigid wedge, sampling at the given penetrations.
pub fn run_wedge(spec: &WedgeSpec, rigid: bool, at: &[f64]) -> anyhow::Result<Vec<WedgeSample>> {
    let hull = Arc::new(HullSurface::new(&spec.offsets()));
    let x_end = X_TOUCH + at.iter().copied().fold(0.0, f64::max) / spec.slope;
    let cfg = TwoDtConfig {
        fr: spec.fr,
        dx: Some(spec.dx),
        coarse_ratio: 1.0,
        until: Until::X(x_end),
        ..Default::default()
    };
    let mut scene = build(hull, &cfg)?;
    let v = scene.profile.u * spec.slope;
    let t_start = scene.profile.t_start;
    // The stem is at x = 0, the section's start (x0).
    let t_touch = scene.profile.t_at(X_TOUCH);
    if rigid {
        let s = *spec;
        let (z_cut, z_top, tb) = (scene.geom.z_cut, scene.geom.z_top, spec.tan_beta());
        let profile = move |t: f64| {
            let moving = t >= t_start;
            let za = if moving { -v * (t - t_touch) } else { s.apex(0.0) };
            let vz = if moving { -v } else { 0.0 };
            let y_top = (z_top - za) / tb;
            Profile {
                points: vec![V2::new(0.0, z_cut), V2::new(0.0, za), V2::new(y_top, z_top)],
                motion: VertexMotion {
                    vel: vec![V2::zeros(), V2::new(0.0, vz), V2::new(0.0, vz)],
                    acc: vec![V2::zeros(); 3],
                },
            }
        };
        let support = scene.sim.kernel.support;
        scene.sim.boundaries[1] = Box::new(DeformingWall::new(
            "rigid-wedge",
            Box::new(profile),
            FluidSide::Right,
            spec.dx,
            support,
        ));
    }
    scene.settle()?;
    let mut targets: Vec<f64> = at.to_vec();
    targets.sort_by(f64::total_cmp);
    let tb = spec.tan_beta();
    let mut sampler = WedgeSampler {
        targets: targets.into_iter().rev().collect(),
        v,
        t_touch,
        dx: spec.dx,
        dir: V2::new(1.0, tb).normalize(),
        n: V2::new(tb, -1.0).normalize(),
        stepped: false,
        impulse: 0.0,
        last: None,
        moments: (0.0, 0.0),
        out: vec![],
    };
    match drive(&mut scene.sim, &mut [&mut sampler])? {
        Outcome::BlewUp(b) => anyhow::bail!("wedge run blew up: {b}"),
        Outcome::Finished | Outcome::Halted(_) => Ok(sampler.out),
    }
}

/// The wedge's samples at the asked penetrations. The force is integrated in time (trapezoids, every step
/// after the touch) and the coefficient taken from the impulse: ∫F dt = C ρ V³ t²/2 for F = C ρ V³ t, which
/// filters the SPH pressure noise. The pressure moments along the side in the similarity variable s/(V t)
/// are summed over the last quarter of each interval: a single instant is too noisy for the centre of
/// pressure.
struct WedgeSampler {
    /// Penetrations still to sample, the next one last.
    targets: Vec<f64>,
    v: f64,
    t_touch: f64,
    dx: f64,
    dir: V2,
    n: V2,
    stepped: bool,
    impulse: f64,
    last: Option<(f64, f64)>,
    moments: (f64, f64),
    out: Vec<WedgeSample>,
}

impl Observer<Simulation<2>> for WedgeSampler {
    fn observe(&mut self, sim: &mut Simulation<2>) -> anyhow::Result<Flow> {
        let v = self.v;
        if let Some(&pen) = self.targets.last() {
            if std::mem::replace(&mut self.stepped, true) && sim.time > self.t_touch {
                sim.refresh();
                let f = sim.boundary_forces()[1].y;
                let t = sim.time - self.t_touch;
                let (t0, f0) = self.last.unwrap_or((0.0, 0.0));
                self.impulse += 0.5 * (f + f0) * (t - t0);
                self.last = Some((t, f));
                if t > 0.75 * pen / v {
                    let (a, b) = pressure_moments(sim, self.dx, v * t, &self.dir, &self.n);
                    self.moments.0 += a;
                    self.moments.1 += b;
                }
            }
        }
        while let Some(&pen) = self.targets.last() {
            if sim.time < self.t_touch + pen / v {
                break;
            }
            self.targets.pop();
            let t = sim.time - self.t_touch;
            let (m0, m1) = std::mem::take(&mut self.moments);
            // The centre of pressure s_cp gives the Wagner-equivalent wetted length c = (π/2) s_cp (for
            // p ∝ 1/√(c² − s²)), and the pile-up height c sinβ above the apex.
            let c_over_vt = std::f64::consts::FRAC_PI_2 * m1 / m0.max(1e-300);
            self.out.push(WedgeSample {
                penetration: v * t,
                pileup_over_vt: c_over_vt * self.dir.y,
                force_coefficient: 2.0 * self.impulse / (v * v * v * t * t),
            });
        }
        Ok(if self.targets.is_empty() {
            Flow::Stop
        } else {
            Flow::Step
        })
    }
}

/// Zeroth and first moments (∫p dσ, ∫p σ dσ with σ = s/(V t)) of the pressure along the wedge side, one
/// spacing into the fluid, from the apex up to s = 3 V t / sinβ; `vt` is the penetration.
fn pressure_moments(sim: &Simulation<2>, dx: f64, vt: f64, dir: &V2, n: &V2) -> (f64, f64) {
    let ds = 0.25 * dx;
    let (mut m0, mut m1) = (0.0, 0.0);
    let steps = (3.0 * vt / (dir.y * ds)) as usize + 1;
    for k in 0..steps {
        let s = (k as f64 + 0.5) * ds;
        let p = V2::new(0.0, -vt) + dir * s + n * dx;
        let pr = sim.sensor_pressure_at(&p).max(0.0);
        m0 += pr * ds / vt;
        m1 += pr * (s / vt) * ds / vt;
    }
    (m0, m1)
}

/// Runs both and returns the comparison.
pub fn compare(spec: &WedgeSpec, at: &[f64]) -> anyhow::Result<WedgeComparison> {
    let cot = 1.0 / spec.tan_beta();
    Ok(WedgeComparison {
        spec_deadrise_deg: spec.deadrise_deg,
        dx: spec.dx,
        twodt: run_wedge(spec, false, at)?,
        rigid: run_wedge(spec, true, at)?,
        wagner_pileup_over_vt: std::f64::consts::FRAC_PI_2,
        wagner_force_coefficient: std::f64::consts::PI.powi(3) / 8.0 * cot * cot,
    })
}

/// Prints the comparison as a table with the differences.
pub fn print(c: &WedgeComparison) {
    println!(
        "wedge β = {}°, dx/L = {:.2e}; Wagner: pile-up z/(Vt) = {:.3}, half-wedge force F/(ρV³t) = {:.3}",
        c.spec_deadrise_deg, c.dx, c.wagner_pileup_over_vt, c.wagner_force_coefficient
    );
    println!("  Vt/L    pile-up 2D+t  rigid   diff     force 2D+t  rigid   diff    vs Wagner (2D+t)");
    for (a, b) in c.twodt.iter().zip(&c.rigid) {
        println!(
            "  {:.4}  {:.3}        {:.3}   {:+.1}%   {:.3}      {:.3}  {:+.1}%   pile-up {:+.1}%, force {:+.1}%",
            a.penetration,
            a.pileup_over_vt,
            b.pileup_over_vt,
            100.0 * (a.pileup_over_vt / b.pileup_over_vt - 1.0),
            a.force_coefficient,
            b.force_coefficient,
            100.0 * (a.force_coefficient / b.force_coefficient - 1.0),
            100.0 * (a.pileup_over_vt / c.wagner_pileup_over_vt - 1.0),
            100.0 * (a.force_coefficient / c.wagner_force_coefficient - 1.0),
        );
    }
}
