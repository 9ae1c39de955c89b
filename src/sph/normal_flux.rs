//! The normal-flux walls of a simulation (thesis §7.1.2): every boundary's surface nodes at the current stage, and
//! the two gathers that use them, the boundary terms of eq. (7.14) added to each fluid particle's rates after the
//! main loop, and the force of the fluid on each wall (its wall pressure integrated over the nodes). The terms
//! themselves are in
//! [`super::equations::normal_flux`]. A simulation whose walls are all ghosts has no nodes and pays nothing.

use super::body_force::BodyForce;
use super::boundary::{Boundary, FluxNodes};
use super::equations::normal_flux::{continuity_term, pressure_term, wall_pressure, WallNode};
use super::equations::{continuity, pressure_force};
use super::kernel::Kernel;
use super::neighbours::CellList;
use super::solver::{Gathered, GhostState};
use nalgebra::SVector;
use rayon::prelude::*;

/// How the normal-flux operators of eq. (7.14) treat the kernel's truncation by the wall.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum NormalFluxForm {
    /// For every particle with a wall node in its support, the divergence and the pressure gradient (fluid and
    /// wall parts) divided by the Shepard sum Γ_i = Σ_j W_ij V_j, the particle itself included (De Leffe et al.
    /// 2009, as the thesis reports them). The smoothed gradient of a field cut by a wall is Γ_i times its
    /// gradient (Γ ≈ ½ on a wall), and the wall's terms act along its normal only: undivided, the water beside
    /// a vertical wall is held up by Γ g against g and slides down it. The symmetric (p_k + p_i) form is kept:
    /// its 2 p_i [Σ_j ∇W V_j + Σ_k n W S], zero only in the continuum, is what pushes a particle back from the
    /// wall when it comes closer (the difference form p_k − p_i, free of that lattice error, left the wall
    /// nothing but the acoustic damping of eq. 7.19 and blew the still tank up within 30 steps). The default
    /// (docs/decisions/normal-flux-wall.md).
    #[default]
    Shepard,
    /// As printed in the thesis (§7.1.2), undivided.
    Thesis,
}

/// The nodes of all normal-flux walls at one stage, with their owners and a cell list over them.
#[derive(Clone, Debug, Default)]
pub(super) struct FluxWalls<const D: usize> {
    pub nodes: FluxNodes<D>,
    /// The boundary (index in the simulation's list) each node belongs to.
    pub owner: Vec<usize>,
    cells: CellList<D>,
}

/// What the boundary terms read of a stage's fluid.
pub(super) struct FluidStage<'a, const D: usize> {
    pub pos: &'a [SVector<f64, D>],
    pub vel: &'a [SVector<f64, D>],
    pub rho: &'a [f64],
    pub pressure: &'a [f64],
    pub volume: &'a [f64],
    /// The cell list over `all_pos`, the fluid's positions then the ghosts'.
    pub cells: &'a CellList<D>,
    pub all_pos: &'a [SVector<f64, D>],
    /// The ghosts' values at this stage.
    pub ghosts: &'a GhostState<D>,
}

impl<const D: usize> FluxWalls<D> {
    /// The nodes of `boundaries` at time `t`, for kernel support `support` (m).
    pub fn place(&mut self, boundaries: &[Box<dyn Boundary<D>>], t: f64, support: f64) {
        self.nodes.clear();
        self.owner.clear();
        let mut tmp = FluxNodes::default();
        for (k, b) in boundaries.iter().enumerate() {
            tmp.clear();
            b.flux_nodes(t, &mut tmp);
            self.owner.extend(std::iter::repeat_n(k, tmp.len()));
            self.nodes.append(&tmp);
        }
        self.cells = if self.nodes.is_empty() {
            CellList::default()
        } else {
            CellList::build(&self.nodes.pos, support)
        };
    }

    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    fn node(&self, k: usize) -> WallNode<D> {
        WallNode {
            outward: self.nodes.outward[k],
            vel: self.nodes.wall_vel[k],
            acc: self.nodes.wall_acc[k],
        }
    }

    /// Adds the boundary terms of eq. (7.14) to the main loop's rates: a gather over the nodes within each
    /// particle's support, in the cell list's order (the same bits for any thread count). With
    /// [`NormalFluxForm::Shepard`] a particle that has nodes in its support has its divergence and pressure
    /// gradient, the fluid's part (summed again here, with the exact kernel gradient, over the fluid and the
    /// other walls' ghosts) and the wall's, divided by Γ_i.
    pub fn add_terms(
        &self,
        kernel: &Kernel<D>,
        c0: f64,
        body: BodyForce<D>,
        form: NormalFluxForm,
        f: &FluidStage<'_, D>,
        out: &mut Gathered<D>,
    ) {
        if self.is_empty() {
            return;
        }
        let nf = f.pos.len();
        let (drho, (dvel, _)) = out;
        drho.par_iter_mut()
            .zip(dvel.par_iter_mut())
            .enumerate()
            .for_each(|(i, (drho, dvel))| {
                let (x, u, rho, p) = (f.pos[i], f.vel[i], f.rho[i], f.pressure[i]);
                let g = body.acceleration(&x);
                let (mut wall_drho, mut wall_dvel, mut touched) = (0.0, SVector::<f64, D>::zeros(), false);
                self.cells
                    .for_each_within(&self.nodes.pos, &x, kernel.support, |k, r_ik, r| {
                        let node = self.node(k);
                        let w_s = kernel.w(r) * self.nodes.area[k];
                        let p_k = wall_pressure(p, rho, &u, &r_ik, &node, &g, c0);
                        wall_drho += continuity_term(rho, &u, &node, w_s);
                        wall_dvel += pressure_term(p, p_k, rho, &node, w_s);
                        touched = true;
                    });
                if !touched {
                    return;
                }
                match form {
                    NormalFluxForm::Thesis => {
                        *drho += wall_drho;
                        *dvel += wall_dvel;
                    }
                    NormalFluxForm::Shepard => {
                        // The gather holds the fluid's divergence and pressure sums once: summed again here (over
                        // the fluid and the other walls' ghosts, which stand for the fluid beyond them, a symmetry
                        // plane's), they and the wall's become 1/Γ_i of them.
                        let (mut gamma, mut div, mut grad) = (0.0, 0.0, SVector::<f64, D>::zeros());
                        f.cells.for_each_within(f.all_pos, &x, kernel.support, |j, rij, r| {
                            let (u_j, p_j, v_j) = if j < nf {
                                (f.vel[j], f.pressure[j], f.volume[j])
                            } else {
                                let g = j - nf;
                                (f.ghosts.vel[g], f.ghosts.p[g], f.ghosts.volume[g])
                            };
                            gamma += kernel.w(r) * v_j; // the Shepard sum Γ_i, the particle itself included
                            if j != i {
                                let gw = kernel.grad(&rij, r);
                                div += continuity::velocity_divergence(rho, &(u_j - u), &gw, v_j);
                                grad += pressure_force::pressure_acceleration(p, p_j, rho, &gw, v_j);
                            }
                        });
                        let scale = 1.0 / gamma;
                        *drho += div * (scale - 1.0) + wall_drho * scale;
                        *dvel += grad * (scale - 1.0) + wall_dvel * scale;
                    }
                }
            });
    }

    /// Force of the fluid on each of `n_boundaries` boundaries through its nodes (N; N per unit depth in 2D):
    /// Σ_k p̄_k n_k S_k, the wall pressure integrated over the wetted nodes, p̄_k the Shepard average over the
    /// fluid within the support of node k and in front of its tangent plane of each particle's eq. (7.20)
    /// estimate (a node with no such fluid is dry; the water behind a thin wall, or a hull's mirrored side
    /// across a symmetry plane, is not its). Not the reaction of the boundary terms: with [`NormalFluxForm::Shepard`] the fluid's
    /// own pairs no longer cancel near the wall, and the reaction would miss the weight of a still tank by a
    /// third. Per-node gathers, summed per boundary in node order.
    pub fn forces(
        &self,
        kernel: &Kernel<D>,
        c0: f64,
        body: BodyForce<D>,
        f: &FluidStage<'_, D>,
        n_boundaries: usize,
    ) -> Vec<SVector<f64, D>> {
        let nf = f.pos.len();
        let per_node: Vec<SVector<f64, D>> = (0..self.nodes.len())
            .into_par_iter()
            .map(|k| {
                let node = self.node(k);
                let (mut sum, mut weight) = (0.0, 0.0);
                f.cells
                    .for_each_below_within(f.all_pos, &self.nodes.pos[k], kernel.support, nf, |i, r_ki, r| {
                        if r_ki.dot(&node.outward) < 0.0 {
                            return; // behind the node's tangent plane: the water on the wall's other side
                        }
                        let g = body.acceleration(&f.pos[i]);
                        let p_k = wall_pressure(f.pressure[i], f.rho[i], &f.vel[i], &-r_ki, &node, &g, c0);
                        let wv = kernel.w(r) * f.volume[i];
                        sum += p_k * wv;
                        weight += wv;
                    });
                if weight > 0.0 {
                    node.outward * (sum / weight * self.nodes.area[k])
                } else {
                    SVector::zeros()
                }
            })
            .collect();
        let mut out = vec![SVector::zeros(); n_boundaries];
        for (k, force) in per_node.iter().enumerate() {
            out[self.owner[k]] += force;
        }
        out
    }
}
