//! Terminal summary of a 2D+t run, beside Table 10.1 of the thesis when the hull and Froude number are there.

use super::run::TwoDtResult;
use std::path::Path;

/// Prints the result and where the outputs went.
pub fn print(r: &TwoDtResult, out: &Path) {
    println!(
        "{} Fr = {}: dx/L = {:.3e} (coarse {:.3e}), {} particles, {} steps, wall {:.1} s, CPU {:.1} s",
        r.hull, r.fr, r.dx_over_l, r.dx_coarse_over_l, r.particles, r.steps, r.wall_seconds, r.cpu_seconds
    );
    println!(
        "  settling left E_K/(M g D) = {:.2e}; far-field |η|/D ≤ {:.2e}; max Mach {:.3}; mass change {:.1e}; pressure noise {:.3e} ρgD",
        r.ke_after_settle, r.far_field_eta_over_d, r.max_mach, r.mass_change, r.pressure_noise_over_rho_g_d
    );
    if let Some(b) = &r.blowup {
        println!("  STOPPED EARLY: {b}");
    }
    match &r.plunge {
        None => println!("  no plunge detected up to x/L = {:.4}", r.x_end_over_l),
        Some(p) => {
            println!(
                "  plunge: x/L = {:.4}, y/L = {:.4}, Fr_x = {:.3}, H_pj/D = {:.3}, fall/D = {:.3}, Γ/(UD) = {:.3}",
                p.x_plunge_over_l, p.y_plunge_over_l, p.fr_x, p.h_pj_over_d, p.fall_over_d, p.gamma_over_ud
            );
            println!(
                "  jet: L/D = {:.3}, S/(DB) = {:.4}, I_OG/S² = {:.3}, G = ({:.3}, {:.3}) D, V_G = ({:.3}, {:.3}) U, α_G = {:.1}°, α_VG = {:.1}°",
                p.l_jet_over_d,
                p.s_jet_over_db,
                p.i_og_over_s2,
                p.y_g_over_d,
                p.z_g_over_d,
                p.v_g_over_u,
                p.w_g_over_u,
                p.alpha_g_deg,
                p.alpha_vg_deg
            );
            match r.air_over_d {
                None => println!(
                    "  air: the jet closes its cavity at the plunge, x/L = {:.4}; what the run shows after it (the \
                     cavity's collapse, the splash-up) is single phase, without the trapped air",
                    p.x_plunge_over_l
                ),
                Some(a) => println!(
                    "  air: modelled ({a} D above the calm level); the jet closes its cavity at the plunge, x/L = \
                     {:.4}, and the air it traps cannot escape sideways as in 3D (an upper bound of its cushioning)",
                    p.x_plunge_over_l
                ),
            }
            if let Some(t) = crate::reference::published_jet(&r.hull, r.fr) {
                println!(
                    "  thesis Table 10.1 ({} Fr {}): dx/L = {:.2e}, x_plunge/L = {}, y_plunge/L = {}, H_pj/D = {}",
                    r.hull, r.fr, t.dx_over_l, t.x_plunge_over_l, t.y_plunge_over_l, t.h_pj_over_d
                );
            }
        }
    }
    println!("  outputs in {}", out.display());
}
