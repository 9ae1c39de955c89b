//! Free-surface detection, level set, cavities, circulation and jet metrics on synthetic particle sets
//! with known answers.

use bowwave::analysis::{cavity, jet, level_set, Snapshot};
use bowwave::sph::free_surface::{detect, Thresholds};
use bowwave::sph::kernel::{Kernel, KernelKind};
use bowwave::sph::neighbours::CellList;
use nalgebra::Vector2;

type V2 = Vector2<f64>;

fn lattice(dx: f64, lo: V2, hi: V2, keep: impl Fn(&V2) -> bool) -> Vec<V2> {
    let ny = ((hi.x - lo.x) / dx).round() as usize;
    let nz = ((hi.y - lo.y) / dx).round() as usize;
    let mut out = vec![];
    for i in 0..ny {
        for j in 0..nz {
            let p = lo + V2::new((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx);
            if keep(&p) {
                out.push(p);
            }
        }
    }
    out
}

fn snapshot(pos: Vec<V2>, vel: Vec<V2>, dx: f64) -> Snapshot {
    let h = 1.33 * dx;
    let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, h);
    let vol = vec![dx * dx; pos.len()];
    let cells = CellList::build(&pos, kernel.support);
    let fs = detect(&kernel, &cells, &pos, &vol, pos.len(), Thresholds::default());
    Snapshot {
        pos,
        vel,
        vol,
        on_surface: fs.on_surface,
        normal: fs.normal,
        lambda: fs.lambda,
        h,
        dx,
        index: vec![],
    }
}

/// A square pool with a circular hole around a clockwise point vortex of circulation Γ: the hole is the
/// one cavity found, and the circulation along its staircase boundary is Γ.
#[test]
fn cavity_around_a_point_vortex_has_its_circulation() {
    let dx = 0.02;
    let radius = 0.15; // 7.5 dx: larger than the 2h the detection resolves
    let centre = V2::new(0.5, 0.5);
    let pos = lattice(dx, V2::zeros(), V2::new(1.0, 1.0), |p| (p - centre).norm() > radius);
    let gamma = 0.3;
    let vel = pos
        .iter()
        .map(|p| {
            let d = p - centre;
            V2::new(d.y, -d.x) * (gamma / (2.0 * std::f64::consts::PI * d.norm_squared()))
        })
        .collect();
    let s = snapshot(pos, vel, dx);
    let ls = level_set::level_set(&s, V2::new(-0.1, -0.1), V2::new(1.1, 1.1), dx);
    let cavities = cavity::find_cavities(&ls, &cavity::atmosphere_mask(&ls), (2.0 * s.h).powi(2), |_| true);
    assert_eq!(cavities.len(), 1, "one enclosed cavity expected");
    let c = &cavities[0];
    assert!((c.centroid - centre).norm() < dx, "centroid {:?}", c.centroid);
    // The free surface lies half a spacing inside the ring of particle centres: area π (R − dx/2)² to a cell.
    let expected = std::f64::consts::PI * (radius - 0.5 * dx).powi(2);
    assert!((c.area / expected - 1.0).abs() < 0.15, "area {} vs {expected}", c.area);
    let g = cavity::circulation(&s, &ls, c);
    assert!((g / gamma - 1.0).abs() < 0.02, "Γ = {g}, expected {gamma}");
}

/// An overturned wave of rectangles: pool, a face column rising from it, a horizontal slab (the jet) and a
/// tip column falling back to the pool. The cavity is the rectangle under the slab, and the jet metrics are
/// those of the slab: area a·b, I_OG/S² = (a² + b²)/(12 a b), horizontal axis, known centre and velocity.
#[test]
fn rectangular_jet_over_a_cavity_has_the_slab_metrics() {
    let dx = 0.01;
    let (y0, y1, z0, z1) = (0.5, 1.4, 0.6, 0.8); // the slab
    let in_wave = |p: &V2| {
        let pool = p.y < 0.0;
        let face = p.x > 0.2 && p.x < y0 && p.y < z1;
        let slab = p.x >= y0 && p.x <= y1 && p.y > z0 && p.y < z1;
        let tip = p.x > y1 && p.x < 1.6 && p.y < z1;
        pool || face || slab || tip
    };
    let pos = lattice(dx, V2::new(0.0, -0.5), V2::new(2.0, 0.8), in_wave);
    let u_jet = V2::new(0.7, -0.4);
    let vel = pos.iter().map(|p| if p.y > z0 { u_jet } else { V2::zeros() }).collect();
    let s = snapshot(pos, vel, dx);
    let ls = level_set::level_set(&s, V2::new(-0.05, -0.55), V2::new(2.05, 1.0), dx);
    let cavities = cavity::find_cavities(&ls, &cavity::atmosphere_mask(&ls), (2.0 * s.h).powi(2), |_| true);
    assert_eq!(cavities.len(), 1);
    let c = &cavities[0];
    let idx = jet::jet_particles(&s, &ls, c);
    let m = jet::metrics(&s, &ls, &idx).expect("jet found");
    let (a, b) = (y1 - y0, z1 - z0);
    let rel = |x: f64, e: f64| (x / e - 1.0).abs();
    assert!(rel(m.area, a * b) < 0.03, "S = {} vs {}", m.area, a * b);
    assert!(rel(m.i_og / (m.area * m.area), (a * a + b * b) / (12.0 * a * b)) < 0.05);
    assert!(rel(m.length, a) < 0.03, "L = {} vs {a}", m.length);
    assert!(m.alpha_g_deg.abs() < 1.0, "α_G = {}", m.alpha_g_deg);
    assert!((m.y_g - 0.5 * (y0 + y1)).abs() < dx && (m.z_g - 0.5 * (z0 + z1)).abs() < dx);
    assert!((m.v_g - u_jet.x).abs() < 1e-12 && (m.w_g - u_jet.y).abs() < 1e-12);
    let expected_vg = (0.4f64).atan2(0.7).to_degrees();
    assert!((m.alpha_vg_deg - expected_vg).abs() < 1e-9);
    // The impact point (rightmost cavity node) is at the tip column's face.
    assert!((c.rightmost.x - y1).abs() < 2.0 * dx, "impact y {}", c.rightmost.x);
}

/// Particles on the curves parallel to the ellipse at depths (k + ½) dx, evenly spaced along each at about
/// dx, each with the volume of its strip (a body-fitted "uniform distribution" as in thesis §7.2.1), with
/// the layer index and the exact outward normal of each (all layers share the normal at the same θ).
fn ellipse_layers(a: f64, b: f64, dx: f64) -> (Vec<V2>, Vec<f64>, Vec<usize>, Vec<V2>) {
    let (mut pos, mut vol, mut layer, mut normal) = (vec![], vec![], vec![], vec![]);
    let mut k = 0;
    loop {
        let depth = (k as f64 + 0.5) * dx;
        // Stay well inside the smallest radius of curvature b²/a (the parallel curve folds beyond it).
        if depth > 0.5 * b * b / a {
            break;
        }
        let m = 4000;
        let nrm = |t: f64| V2::new(b * t.cos(), a * t.sin()).normalize();
        let pts: Vec<V2> = (0..=m)
            .map(|j| {
                let t = std::f64::consts::TAU * j as f64 / m as f64;
                V2::new(a * t.cos(), b * t.sin()) - nrm(t) * depth
            })
            .collect();
        let mut cum = vec![0.0];
        for w in pts.windows(2) {
            cum.push(cum.last().unwrap() + (w[1] - w[0]).norm());
        }
        let per = *cum.last().unwrap();
        let n = (per / dx).round() as usize;
        for i in 0..n {
            let target = per * i as f64 / n as f64;
            let j = cum.partition_point(|&c| c < target).clamp(1, m);
            let f = (target - cum[j - 1]) / (cum[j] - cum[j - 1]);
            pos.push(pts[j - 1] + (pts[j] - pts[j - 1]) * f);
            vol.push(dx * per / n as f64);
            layer.push(k);
            let t = std::f64::consts::TAU * (j as f64 - 1.0 + f) / m as f64;
            normal.push(nrm(t));
        }
        k += 1;
    }
    (pos, vol, layer, normal)
}

/// Mean angle (degrees) between the detected normals of the outer-layer particles of an ellipse
/// (eccentricity 0.661, as in thesis Fig. 7.11) and the analytic normals, and the share of them detected.
fn ellipse_normal_error(h_over_a: f64) -> (f64, f64) {
    let a = 1.0;
    let b = a * (1.0f64 - 0.661 * 0.661).sqrt();
    let h = h_over_a * a;
    let dx = h / 1.33;
    let (pos, vol, layer, exact) = ellipse_layers(a, b, dx);
    let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, h);
    let cells = CellList::build(&pos, kernel.support);
    let fs = detect(&kernel, &cells, &pos, &vol, pos.len(), Thresholds::default());
    let (mut sum, mut n, mut found) = (0.0, 0, 0);
    for k in (0..pos.len()).filter(|&k| layer[k] == 0) {
        n += 1;
        if fs.on_surface[k] {
            found += 1;
            sum += fs.normal[k].dot(&exact[k]).clamp(-1.0, 1.0).acos().to_degrees();
        }
    }
    (sum / found.max(1) as f64, found as f64 / n as f64)
}

/// Thesis Table 7.1: the error of the normals (7.23) on the ellipse converges nearly quadratically
/// (2.16, 1.23, 0.68 at h/a = 7.52, 3.76, 1.88 × 10⁻²; the thesis does not state its unit). We require
/// an observed order above 1.5 over the same three resolutions and every outer-layer particle detected.
#[test]
fn ellipse_normals_converge_near_quadratically() {
    let hs = [0.0752, 0.0376, 0.0188];
    let thesis = [2.16, 1.23, 0.68];
    let errs: Vec<(f64, f64)> = hs.iter().map(|&h| ellipse_normal_error(h)).collect();
    for ((h, (e, share)), t) in hs.iter().zip(&errs).zip(thesis) {
        println!("h/a = {h:.4}: mean normal angle error {e:.3}° (thesis ε = {t}), first row detected {share:.3}");
    }
    for w in errs.windows(2) {
        let order = (w[0].0 / w[1].0).log2();
        println!("observed order {order:.2}");
        assert!(order > 1.5, "order {order}");
    }
    assert!(errs.iter().all(|e| e.1 > 0.999), "first-row particles missed: {errs:?}");
}

/// Thesis Fig. 7.11 (right): an elliptic cavity of minor axis 2h inside the ellipse is detected: the level
/// set built from the detected free surface encloses one air region there. No particle farther than 3h
/// from both surfaces is detected.
#[test]
fn elliptic_cavity_of_minor_axis_2h_is_detected() {
    let (a, b) = (1.0, 0.7504);
    let h = 0.0376;
    let dx = h / 1.33;
    let (ca, cb) = (2.0 * h, h); // cavity semi-axes: minor axis 2h
    let in_cavity = |p: &V2| (p.x / ca).powi(2) + (p.y / cb).powi(2) < 1.0;
    let inside = |p: &V2| (p.x / a).powi(2) + (p.y / b).powi(2) < 1.0 && !in_cavity(p);
    let pos = lattice(dx, V2::new(-a, -b), V2::new(a, b), inside);
    let s = snapshot(pos, Vec::new(), dx);
    let (mut rim, mut rim_found, mut deep_found) = (0, 0, 0);
    for k in 0..s.len() {
        let p = s.pos[k];
        let fc = (p.x / ca).powi(2) + (p.y / cb).powi(2) - 1.0;
        let gc = V2::new(2.0 * p.x / (ca * ca), 2.0 * p.y / (cb * cb));
        let d_cav = fc / gc.norm();
        let fo = (p.x / a).powi(2) + (p.y / b).powi(2) - 1.0;
        let go = V2::new(2.0 * p.x / (a * a), 2.0 * p.y / (b * b));
        let d_out = -fo / go.norm();
        if d_cav < 0.75 * dx {
            rim += 1;
            rim_found += s.on_surface[k] as usize;
        }
        if d_cav > 3.0 * h && d_out > 3.0 * h && s.on_surface[k] {
            deep_found += 1;
        }
    }
    println!("cavity rim: {rim_found} of {rim} particles detected; interior false detections {deep_found}");
    assert_eq!(deep_found, 0);
    let ls = level_set::level_set(&s, V2::new(-1.1, -0.9), V2::new(1.1, 0.9), dx);
    let cavities = cavity::find_cavities(&ls, &cavity::atmosphere_mask(&ls), 0.0, |_| true);
    assert_eq!(cavities.len(), 1, "cavities found: {}", cavities.len());
    assert!(cavities[0].centroid.norm() < dx, "cavity at {:?}", cavities[0].centroid);
}

/// Level sets of a pool (dx 0.02) with a round hole of radius 0.12 in it, of the same pool full, and of the
/// pool with a notch open to the air where the hole is.
fn pools_with_a_hole() -> [level_set::LevelSet; 3] {
    let dx = 0.02;
    let centre = V2::new(0.5, 0.3);
    let hole = |p: &V2| (p - centre).norm() < 0.12;
    let notch = |p: &V2| (p.x - centre.x).abs() < 0.12 && p.y > centre.y - 0.12;
    let pool = |keep: &dyn Fn(&V2) -> bool| {
        let pos = lattice(dx, V2::zeros(), V2::new(1.0, 0.5), |p| keep(p));
        let s = snapshot(pos, Vec::new(), dx);
        level_set::level_set(&s, V2::new(-0.1, -0.1), V2::new(1.1, 0.7), dx)
    };
    [pool(&|p| !hole(p)), pool(&|_| true), pool(&|p| !notch(p))]
}

/// Regression: a run at dx/L = 1e-3 reported a "plunge" that was a hole opening inside a stretched sheet
/// of particles. A plunge traps air that was atmosphere before; such a hole was fluid. Here the same
/// cavity (a hole in a pool) is scored against an earlier state where it was fluid (fraction 0) and one
/// where the pool was open above it, a notch reaching the atmosphere (fraction 1).
#[test]
fn hole_in_a_stretched_sheet_is_not_a_plunge() {
    let [now, full, open] = pools_with_a_hole();
    let cavities = cavity::find_cavities(&now, &cavity::atmosphere_mask(&now), 0.0, |_| true);
    assert_eq!(cavities.len(), 1);
    let f_full = cavity::trapped_fraction(&now, &cavities[0], &full, &cavity::atmosphere_mask(&full));
    let f_open = cavity::trapped_fraction(&now, &cavities[0], &open, &cavity::atmosphere_mask(&open));
    assert_eq!(f_full, 0.0);
    assert!(f_open > 0.9, "fraction {f_open}");
}

/// The premise of plunge criterion 5 (docs/reference/jet-metrics.md): at dx/L = 7e-4, Athena Fr 0.55 reported a
/// "plunge" at x/L 0.227 that was a sliver of air between the top particle row peeling off the sheet that
/// climbs the hull and the sheet below it, both moving up together (Γ/(UD) = −0.011). A sliver between
/// layers that move together has next to no circulation, while the same sliver with the fluid turning around
/// it, as an overturning jet's cavity, has the circulation of that turning.
#[test]
fn sliver_between_layers_moving_together_has_no_circulation() {
    let dx = 0.01;
    // A slot 4 dx thick and 40 dx long in a pool, tilted like the sheet on a hull side.
    let (centre, half_len, half_thick) = (V2::new(0.5, 0.3), 0.2, 0.02);
    let (t, n) = (V2::new(0.5, 0.866), V2::new(-0.866, 0.5));
    let slot = |p: &V2| {
        let d = p - centre;
        d.dot(&t).abs() < half_len && d.dot(&n).abs() < half_thick
    };
    let pos = lattice(dx, V2::zeros(), V2::new(1.0, 0.6), |p| !slot(p));
    let u_sheet = V2::new(0.3, 0.5);
    let ls_of = |s: &Snapshot| level_set::level_set(s, V2::new(-0.1, -0.1), V2::new(1.1, 0.8), dx);
    // The fluid beside the slot moves with the sheet, the outer side a little faster (the row peeling off).
    let peeling: Vec<V2> = pos
        .iter()
        .map(|p| u_sheet * (1.0 + 0.05 * ((p - centre).dot(&n) > 0.0) as u8 as f64))
        .collect();
    let s = snapshot(pos.clone(), peeling, dx);
    let ls = ls_of(&s);
    let cavities = cavity::find_cavities(&ls, &cavity::atmosphere_mask(&ls), (2.0 * s.h).powi(2), |_| true);
    assert_eq!(cavities.len(), 1, "the slot is one cavity of at least (2h)²");
    let g_sliver = cavity::circulation(&s, &ls, &cavities[0]);
    // The same slot with the fluid turning clockwise around it at the sheet's speed.
    let turning: Vec<V2> = pos
        .iter()
        .map(|p| {
            let d = p - centre;
            V2::new(d.y, -d.x) / d.norm().max(dx) * u_sheet.norm()
        })
        .collect();
    let s = snapshot(pos, turning, dx);
    let ls = ls_of(&s);
    let cavities = cavity::find_cavities(&ls, &cavity::atmosphere_mask(&ls), (2.0 * s.h).powi(2), |_| true);
    let g_turning = cavity::circulation(&s, &ls, &cavities[0]);
    // Γ of the turning flow: |u| ∮ r dθ around the centre, 2π × the mean radius of the loop (about
    // 0.1 for this slot) × |u| ≈ 0.37, less where the loop runs radially.
    assert!(g_turning > 0.2, "Γ around the turning slot {g_turning}");
    assert!(
        g_sliver.abs() < 0.1 * g_turning,
        "Γ of the sliver {g_sliver} against {g_turning}"
    );
}

/// Between two regular plunge checks the run may check every step (the search for t_p): those checks all
/// compare with the same earlier check and leave it in place, while a regular check moves it forward.
#[test]
fn checks_between_regular_ones_compare_with_the_same_earlier_check() {
    let [closed, _, open] = pools_with_a_hole();
    let mut watch = cavity::ClosureWatch::default();
    assert!(
        watch.closed_since_previous(&closed, 0.0, |_| true).is_none(),
        "no earlier check yet"
    );
    assert!(
        watch.newly_closed(&open, 0.0, |_| true).is_none(),
        "the first regular check"
    );
    for _ in 0..2 {
        let c = watch
            .closed_since_previous(&closed, 0.0, |_| true)
            .expect("an earlier check");
        assert_eq!(c.len(), 1, "the notch closed into the hole since the regular check");
    }
    assert_eq!(watch.newly_closed(&closed, 0.0, |_| true).map(|c| c.len()), Some(1));
    assert_eq!(
        watch.newly_closed(&closed, 0.0, |_| true).map(|c| c.len()),
        Some(0),
        "closed already at the previous regular check"
    );
}

/// With several phases the analyses read the water alone: in the still two-layer tank (water under air) the
/// water's top row is its free surface and the rows under it are not, though air particles cover it; the
/// snapshot the cavity probe and the 2D+t detection read holds the water's particles only.
#[test]
fn water_under_air_has_its_free_surface_where_the_air_begins() {
    let case = bowwave::cases::load("two-layer").expect("built-in");
    let mut sim = bowwave::cases::setup::build(&case, Some(10.0)).expect("builds");
    sim.refresh();
    let fs = sim.free_surface_of_phase(bowwave::sph::free_surface::Thresholds::default(), 0);
    let f = &sim.fluid;
    let dx = sim.cfg.dx;
    let (mut top, mut top_surface, mut below_surface) = (0, 0, 0);
    for i in 0..f.len() {
        if f.phase[i] != 0 {
            continue;
        }
        let y = f.pos[i].y;
        let away_from_walls = f.pos[i].x > 3.0 * dx && f.pos[i].x < 2.0 - 3.0 * dx;
        if (y - (1.0 - 0.5 * dx)).abs() < 1e-9 && away_from_walls {
            top += 1;
            top_surface += fs.on_surface[i] as usize;
        } else if y < 1.0 - 3.5 * dx && y > 3.0 * dx && away_from_walls {
            below_surface += fs.on_surface[i] as usize;
        }
    }
    assert!(top > 10);
    assert_eq!(
        top_surface, top,
        "every particle of the water's top row is on its surface"
    );
    assert_eq!(below_surface, 0, "no water particle three rows down is");
    // Seen with the air as matter, the same row is inside.
    let all = sim.free_surface(bowwave::sph::free_surface::Thresholds::default());
    let top_all = (0..f.len())
        .filter(|&i| f.phase[i] == 0 && (f.pos[i].y - (1.0 - 0.5 * dx)).abs() < 1e-9 && all.on_surface[i])
        .count();
    assert_eq!(top_all, 0);
    let n_water = (0..f.len()).filter(|&i| f.phase[i] == 0).count();
    let snap = Snapshot::from_simulation(&mut sim, dx);
    assert_eq!(snap.len(), n_water);
}

/// Writes a frame series in the format of `bowwave frames` (`twodt::external_frames`): frames.csv and one
/// CSV of water particles per frame.
fn write_frames(dir: &std::path::Path, frames: &[(f64, Vec<V2>, Vec<V2>, f64)]) {
    std::fs::create_dir_all(dir).unwrap();
    let mut index = String::from("x_over_l,file\n");
    for (k, (x, pos, vel, vol)) in frames.iter().enumerate() {
        let name = format!("f{k}.csv");
        index.push_str(&format!("{x},{name}\n"));
        let mut body = String::from("y,z,u,v,volume\n");
        for (p, u) in pos.iter().zip(vel) {
            body.push_str(&format!("{:e},{:e},{:e},{:e},{:e}\n", p.x, p.y, u.x, u.y, vol));
        }
        std::fs::write(dir.join(name), body).unwrap();
    }
    std::fs::write(dir.join("frames.csv"), index).unwrap();
}

/// Another code's frames measured by bowwave's criteria: the rectangular overturned wave beside a Wigley
/// hull (D = 0.1 L, dx = D/20) in two frames, its tip hanging 0.3 D above the pool at x/L 0.05 (the air
/// under the slab open to the atmosphere) and standing in the pool at 0.06 (the cavity closed), the water
/// turning clockwise around the cavity. The plunge is the second frame, at the impact point of the tip's
/// face, with the slab's crest and jet; a cavity that was never open (the second frame alone) is no plunge.
#[test]
fn another_codes_frames_plunge_where_the_cavity_first_closes() {
    use bowwave::geometry::{surface::HullSurface, wigley};
    use bowwave::twodt::external_frames::{measure, FramesSpec};
    let spec_w = wigley::WigleySpec::default();
    let hull = std::sync::Arc::new(HullSurface::new(&wigley::wigley(&spec_w)));
    let dx = 0.005;
    let (y0, y1, z0, z1) = (0.35, 0.6, 0.08, 0.12);
    let frame = |x: f64, tip_foot: f64| {
        let wave = |p: &V2| {
            let hull_side = p.x > wigley::half_breadth(&spec_w, x, p.y) + dx;
            let pool = p.y < 0.0 && hull_side;
            let face = p.x > 0.25 && p.x < y0 && p.y < z1;
            let slab = p.x >= y0 && p.x <= y1 && p.y > z0 && p.y < z1;
            let tip = p.x > y1 && p.x < 0.65 && p.y > tip_foot && p.y < z1;
            pool || face || slab || tip
        };
        let pos = lattice(dx, V2::new(0.0, -0.2), V2::new(0.8, z1), wave);
        let centre = V2::new(0.5 * (y0 + y1), 0.5 * z0);
        let vel = pos.iter().map(|p| V2::new(p.y - centre.y, -(p.x - centre.x))).collect();
        (x, pos, vel, dx * dx)
    };
    let spec = FramesSpec {
        fr: 0.5,
        dx,
        width_over_beam: 4.0,
        depth_over_draft: 2.0,
        plunge_depth: None,
        plunge_circulation: Some(0.02),
    };
    let dir = std::env::temp_dir().join(format!("bowwave-frames-{}", std::process::id()));
    write_frames(&dir, &[frame(0.05, 0.03), frame(0.06, -1.0)]);
    let r = measure(hull.clone(), &spec, &dir).expect("frames measured");
    assert_eq!(r.crest.rows.len(), 2);
    let p = r.plunge.expect("the closed cavity is a plunge");
    assert_eq!(p.x_plunge_over_l, 0.06);
    assert!(
        (p.y_plunge_over_l - y1).abs() < 2.0 * dx,
        "impact y {}",
        p.y_plunge_over_l
    );
    // The crest: the slab's top row at z1 − dx/2, plus dx/2; D = 0.1.
    assert!((p.h_pj_over_d - z1 / 0.1).abs() < 1e-9, "H_pj/D {}", p.h_pj_over_d);
    assert!((r.crest.rows[1][1] - z1 / 0.1).abs() < 1e-9);
    assert!(p.gamma_over_ud > 0.02, "Γ/(UD) {}", p.gamma_over_ud);
    let slab = ((y1 - y0) / dx) * ((z1 - z0) / dx);
    assert!(
        (p.jet_particles as f64 / slab - 1.0).abs() < 0.1,
        "jet of {} particles",
        p.jet_particles
    );
    // The closed frame alone: nothing was open before it, so nothing closed.
    let alone = dir.join("alone");
    write_frames(&alone, &[frame(0.06, -1.0)]);
    assert!(measure(hull, &spec, &alone).unwrap().plunge.is_none());
    let _ = std::fs::remove_dir_all(&dir);
}

/// Bad frames are refused with the file and the field named, never a panic.
#[test]
fn bad_frames_name_the_file_and_the_field() {
    use bowwave::twodt::external_frames::{read_frame, read_index};
    let dir = std::env::temp_dir().join(format!("bowwave-bad-frames-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("frames.csv"), "x_over_l,name\n0.1,a.csv\n").unwrap();
    let e = read_index(&dir).unwrap_err().to_string();
    assert!(e.contains("frames.csv") && e.contains("`file`"), "{e}");
    std::fs::write(dir.join("frames.csv"), "x_over_l,file\nabc,a.csv\n").unwrap();
    let e = read_index(&dir).unwrap_err().to_string();
    assert!(e.contains("frames.csv") && e.contains("x_over_l (row 1)"), "{e}");
    std::fs::write(dir.join("a.csv"), "y,z,u,v\n0.1,0.0,0.0,0.0\n").unwrap();
    let e = read_frame(&dir.join("a.csv")).unwrap_err().to_string();
    assert!(e.contains("a.csv") && e.contains("`volume`"), "{e}");
    std::fs::write(dir.join("a.csv"), "y,z,u,v,volume\n0.1,0.0,0.0,0.0,-1\n").unwrap();
    let e = read_frame(&dir.join("a.csv")).unwrap_err().to_string();
    assert!(e.contains("a.csv") && e.contains("volume (row 1)"), "{e}");
    std::fs::write(dir.join("a.csv"), "y,z,u,v,volume\n0.1,x,0.0,0.0,1\n").unwrap();
    let e = read_frame(&dir.join("a.csv")).unwrap_err().to_string();
    assert!(e.contains("a.csv") && e.contains("row 1") && e.contains("`z`"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}
