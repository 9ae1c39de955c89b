"""bowwave's 2D+t bow-wave run in PySPH, an independent code on the same deforming section (issue #30, item 3).

The section sequence comes from bowwave itself, so both codes see the same hull surface:

    bowwave hull sections hulls/athena.csv --to 0.5 --out sections.csv

and the scene from a finished bowwave 2D+t case (its case.json: Fr, dx, c0, tank width and depth in B and D; the
hull file's header: B, D):

    python twodt.py --sections sections.csv --case CASE/case.json --hull hulls/athena.csv -d OUT

Non-dimensional with L, g and rho0 (L = g = rho0 = 1); U = Fr; the section at time t is the hull's at
x = x0 + U t. Half domain: a free-slip symmetry wall y = 0, a bottom at z = -Z (Z = depth * D), a wall at
y = W (W = width * B), open top; fluid at rest below z = 0 outside the section at x0, hydrostatic pressure.
Uniform spacing dx everywhere (bowwave grades its rows below 0.2 D at constant h: PySPH cannot, so it has more
particles, not a different resolution where the jet forms).

Scheme (--scheme edac, the default, or delta_sph): PySPH 1.0b2's EDAC (entropically damped artificial compressibility) with Adami et al.'s (2012) wall
condition: the wall pressure extrapolated from the fluid with the wall's acceleration, which needs no wall
history, so the hull's wall particles can be placed anew at every step. Wendland quintic kernel (support 2h), or
with --sph-kernel gaussian PySPH's Gaussian (support 3h, as bowwave's), h = 1.33 dx; artificial viscosity alpha =
0.02 (bowwave's delta-SPH: alpha 0.02, density diffusion 0.1), no XSPH, c0 from bowwave's case. EDAC's
artificial viscosity also acts between fluid and wall particles, at the wall's velocity: a friction along the
hull that lowered the first crest by 39 % at dx/L 1.4e-3 (issue #30, session 41). --wall-viscosity off limits it
to fluid pairs, so that the walls are free-slip for every term, as bowwave's ghosts (eq. 7.2) and the thesis's
inviscid 2D+t; compare the codes with it off. --scheme delta_sph is the thesis's delta-SPH built from PySPH's
own equations with Adami's walls, free slip (DeltaSphAdami below): the scheme bowwave runs, with another wall
condition and kernel.

The hull: after every step its wall particles are placed on the section at the new time: points at arc-length
spacing dx along the section from the keel (the first dx/2 from it), LAYERS layers inside it along the normal,
each with the section's velocity U (y_x, z_x) and acceleration U^2 (y_xx, z_xx) at its girth position; unused
slots of the array wait below the tank, out of every neighbourhood.

Outputs every --every x/L; read them with crest_from_outputs.py.
"""
import json
import numpy as np
from pysph.base.kernels import Gaussian, WendlandQuintic
from pysph.base.utils import get_particle_array
from pysph.sph.wc.transport_velocity import MomentumEquationArtificialViscosity
from pysph.solver.application import Application
from pysph.sph.wc.edac import EDACScheme
from pysph.sph.basic_equations import XSPHCorrection
from pysph.sph.scheme import Scheme, SchemeChooser
from pysph.sph.equation import Equation

LAYERS = 4
HDX = 1.33


def header(path):
    """The hull file's `# key: value` header."""
    meta = {}
    with open(path) as f:
        for line in f:
            if not line.startswith('#'):
                break
            k, _, v = line[1:].partition(':')
            meta[k.strip()] = v.strip()
    return meta


class Sections:
    """The section sequence written by `bowwave hull sections`: linear in x between its samples."""

    def __init__(self, path):
        a = np.loadtxt(path, delimiter=',', skiprows=1)
        self.xs = np.unique(a[:, 0])
        n = len(self.xs)
        self.npts = len(a) // n
        self.data = a.reshape(n, self.npts, a.shape[1])[:, :, 3:]  # y, z, y_x, z_x, y_xx, z_xx

    def at(self, x):
        if x <= self.xs[0]:
            return self.data[0]
        if x >= self.xs[-1]:
            return self.data[-1]
        i = np.searchsorted(self.xs, x) - 1
        f = (x - self.xs[i]) / (self.xs[i + 1] - self.xs[i])
        return (1 - f) * self.data[i] + f * self.data[i + 1]


class WallViscousVelocity(Equation):
    """A wall particle's velocity in the viscous term of DeltaSphAdami, --wall-viscosity free-slip: the fluid's
    velocity at the wall particle (Shepard average), its normal component relative to the wall reversed, as the
    velocity bowwave's free-slip ghost takes from its mirror point (eq. 7.2). Needs the wall's normal (nx, ny)
    into the fluid on every wall particle."""

    def initialize(self, d_idx, d_uf, d_vf, d_wv):
        d_uf[d_idx] = 0.0
        d_vf[d_idx] = 0.0
        d_wv[d_idx] = 0.0

    def loop(self, d_idx, s_idx, d_uf, d_vf, d_wv, s_u, s_v, WIJ):
        d_uf[d_idx] += s_u[s_idx] * WIJ
        d_vf[d_idx] += s_v[s_idx] * WIJ
        d_wv[d_idx] += WIJ

    def post_loop(self, d_idx, d_uf, d_vf, d_wv, d_u, d_v, d_nx, d_ny, d_ug, d_vg):
        uf = d_u[d_idx]
        vf = d_v[d_idx]
        if d_wv[d_idx] > 1e-14:
            uf = d_uf[d_idx] / d_wv[d_idx]
            vf = d_vf[d_idx] / d_wv[d_idx]
        un = (uf - d_u[d_idx]) * d_nx[d_idx] + (vf - d_v[d_idx]) * d_ny[d_idx]
        d_ug[d_idx] = uf - 2.0 * un * d_nx[d_idx]
        d_vg[d_idx] = vf - 2.0 * un * d_ny[d_idx]


class WallViscosity(Equation):
    """The viscous term of eq. 4.11 (PySPH's MomentumEquationDeltaSPH form) between a fluid particle and wall
    particles, at the wall particle's velocity: its own (free_slip 0: a friction, as EDAC's default) or the
    mirrored fluid velocity of WallViscousVelocity (free_slip 1)."""

    def __init__(self, dest, sources, rho0, c0, alpha, free_slip):
        self.rho0, self.c0, self.alpha, self.free_slip = rho0, c0, alpha, free_slip
        super(WallViscosity, self).__init__(dest, sources)

    def loop(self, d_idx, s_idx, d_rho, d_u, d_v, d_au, d_av, s_m, s_rho, s_u, s_v, s_ug, s_vg,
             XIJ, HIJ, R2IJ, EPS, DWIJ):
        uj = self.free_slip * s_ug[s_idx] + (1.0 - self.free_slip) * s_u[s_idx]
        vj = self.free_slip * s_vg[s_idx] + (1.0 - self.free_slip) * s_v[s_idx]
        vijdotxij = (d_u[d_idx] - uj) * XIJ[0] + (d_v[d_idx] - vj) * XIJ[1]
        tmp = self.alpha * HIJ * self.c0 * self.rho0 * vijdotxij / (R2IJ + EPS) * s_m[s_idx] / s_rho[s_idx] / d_rho[d_idx]
        d_au[d_idx] += tmp * DWIJ[0]
        d_av[d_idx] += tmp * DWIJ[1]


class DeltaSphAdami(Scheme):
    """The thesis's delta-SPH (eq. 5.1: continuity with the density diffusion of eq. 5.2 and its renormalised
    density gradient, momentum with p_i + p_j written as p_i/rho_i^2 + p_j/rho_j^2, the artificial viscosity of
    eq. 4.11 on every fluid pair), linear state equation, assembled from PySPH's own delta-SPH equations; the walls
    are Adami et al.'s (2012): pressure extrapolated from the fluid with the wall's acceleration, density from it
    by the state equation, the wall's prescribed velocity in the continuity equation. The viscous term with the
    walls follows --wall-viscosity: off (none, the default), free-slip (the wall particles at the fluid's velocity
    mirrored through the wall, as bowwave's ghosts) or on (at the wall's own velocity, a friction). With free-slip
    the scheme differs from bowwave's in the wall's pressure condition, the kernel and the integrator."""

    def __init__(self, fluids, solids, dim, rho0, c0, h0, gy, alpha=0.02, delta=0.1):
        self.fluids, self.solids, self.dim = fluids, solids, dim
        self.rho0, self.c0, self.h0, self.gy = rho0, c0, h0, gy
        self.alpha, self.delta = alpha, delta
        self.wall_viscosity = 'off'
        self.solver = None

    def configure(self, h=None, c0=None, **kw):
        if h is not None:
            self.h0 = h
        if c0 is not None:
            self.c0 = c0
        super().configure(**kw)

    def configure_solver(self, kernel=None, integrator_cls=None, extra_steppers=None, **kw):
        from pysph.sph.integrator import PECIntegrator
        from pysph.sph.integrator_step import WCSPHStep
        from pysph.solver.solver import Solver
        steppers = {name: WCSPHStep() for name in self.fluids}
        self.solver = Solver(dim=self.dim, integrator=PECIntegrator(**steppers), kernel=kernel, **kw)

    def get_equations(self):
        from pysph.sph.equation import Group
        from pysph.sph.basic_equations import ContinuityEquation
        from pysph.sph.wc.basic import (TaitEOS, MomentumEquation, ContinuityEquationDeltaSPH,
                                        ContinuityEquationDeltaSPHPreStep, MomentumEquationDeltaSPH)
        from pysph.sph.wc.kernel_correction import GradientCorrectionPreStep, GradientCorrection
        from pysph.sph.wc.transport_velocity import SolidWallPressureBC
        everything = self.fluids + self.solids
        g0 = [TaitEOS(dest=f, sources=None, rho0=self.rho0, c0=self.c0, gamma=1.0) for f in self.fluids]
        g1 = [SolidWallPressureBC(dest=s, sources=self.fluids, rho0=self.rho0, p0=self.rho0 * self.c0 ** 2, b=1.0,
                                  gy=self.gy) for s in self.solids]
        if self.wall_viscosity == 'free-slip':
            g1 += [WallViscousVelocity(dest=s, sources=self.fluids) for s in self.solids]
        g1 += [GradientCorrectionPreStep(dest=f, sources=self.fluids, dim=self.dim) for f in self.fluids]
        g2 = []
        for f in self.fluids:
            g2 += [GradientCorrection(dest=f, sources=self.fluids), ContinuityEquationDeltaSPHPreStep(dest=f, sources=self.fluids)]
        g3 = []
        for f in self.fluids:
            g3 += [ContinuityEquation(dest=f, sources=everything),
                   ContinuityEquationDeltaSPH(dest=f, sources=self.fluids, c0=self.c0, delta=self.delta),
                   MomentumEquation(dest=f, sources=everything, c0=self.c0, alpha=0.0, beta=0.0, gy=self.gy),
                   MomentumEquationDeltaSPH(dest=f, sources=self.fluids, rho0=self.rho0, c0=self.c0,
                                            alpha=self.alpha)]
            if self.wall_viscosity != 'off':
                g3.append(WallViscosity(dest=f, sources=self.solids, rho0=self.rho0, c0=self.c0, alpha=self.alpha,
                                        free_slip=1.0 if self.wall_viscosity == 'free-slip' else 0.0))
            # WCSPHStep moves a particle with (ax, ay, az), which XSPHCorrection sets: eps 0 is u itself.
            g3.append(XSPHCorrection(dest=f, sources=[f], eps=0.0))
        return [Group(equations=g0, real=False), Group(equations=g1, real=False), Group(equations=g2),
                Group(equations=g3)]

    def setup_properties(self, particles, clean=True):
        from pysph.base.utils import get_particle_array_wcsph
        props = list(get_particle_array_wcsph(name='junk').properties.keys())
        props += [{'name': 'm_mat', 'stride': 9}, {'name': 'gradrho', 'stride': 3}, 'wij', 'wv', 'uf', 'vf', 'ug',
                  'vg', 'nx', 'ny']
        for pa in particles:
            self._ensure_properties(pa, props, clean)
            pa.set_output_arrays(['x', 'y', 'u', 'v', 'rho', 'm', 'h', 'p', 'pid', 'gid', 'tag'])


class TwoDt(Application):
    def add_user_options(self, group):
        group.add_argument('--sections', required=True, dest='sections')
        group.add_argument('--case', required=True, dest='case', help="a bowwave 2D+t case's case.json")
        group.add_argument('--hull', required=True, dest='hull', help='the hull file (for B and D)')
        group.add_argument('--x0', type=float, default=None, dest='x0',
                           help='x/L at t = 0 (default: the first x of the case series.csv beside case.json)')
        group.add_argument('--x-end', type=float, default=0.4, dest='x_end')
        group.add_argument('--dx', type=float, default=None, dest='dx_override', help='override the case dx/L')
        group.add_argument('--every', type=float, default=0.005, dest='every', help='output interval in x/L')
        group.add_argument('--sph-kernel', choices=['wendland5', 'gaussian'], default='wendland5', dest='kernel_name',
                           help="wendland5 (PySPH's Wendland quintic, support 2h) or gaussian (PySPH's Gaussian, "
                                "support 3h, as bowwave's kernel: a check of the kernel's part in a difference)")
        group.add_argument('--wall-viscosity', choices=['on', 'off', 'free-slip'], default=None, dest='wall_viscosity',
                           help="on (EDAC's default: the artificial viscosity also acts between a fluid particle "
                                "and the wall particles, at the wall's own velocity, a friction along the hull), "
                                "off (fluid pairs only; delta_sph's default) or, with --scheme delta_sph only, "
                                "free-slip (with the wall particles at the fluid's velocity mirrored through the "
                                "wall, as bowwave's free-slip ghosts carry it, eq. 7.2)")

    def consume_user_options(self):
        o = self.options
        case = json.load(open(o.case))
        cfg, res = case['spec']['config'], case['result']
        meta = header(o.hull)
        lm = float(meta['length_m'])
        self.beam, self.draft = float(meta['beam_m']) / lm, float(meta['draft_m']) / lm
        self.fr = cfg['fr']
        self.dx = o.dx_override or cfg['dx']
        self.h = HDX * self.dx
        self.c0 = res['c0_over_sqrt_gl']
        self.width = cfg['width'] * self.beam
        self.depth = cfg['depth'] * self.draft
        if o.x0 is None:
            import os
            series = os.path.join(os.path.dirname(o.case), 'series.csv')
            o.x0 = float(np.loadtxt(series, delimiter=',', skiprows=1, max_rows=1)[0])
        self.x0 = o.x0
        self.sec = Sections(o.sections)
        # The girth of the largest section, for the size of the hull's array.
        g = max(np.sum(np.hypot(np.diff(d[:, 0]), np.diff(d[:, 1]))) for d in self.sec.data)
        self.nmax = LAYERS * (int(g / self.dx) + 8)
        self.park = (-0.5 * self.width, -2.0 * self.depth)

    def create_scheme(self):
        edac = EDACScheme(fluids=['fluid'], solids=['walls', 'hull'], dim=2, c0=1.0, nu=0.0, rho0=1.0, h=1.0,
                          pb=0.0, gy=-1.0, eps=0.0, clamp_p=True, alpha=0.02)
        delta = DeltaSphAdami(fluids=['fluid'], solids=['walls', 'hull'], dim=2, rho0=1.0, c0=1.0, h0=1.0, gy=-1.0)
        return SchemeChooser(default='edac', edac=edac, delta_sph=delta)

    def configure_scheme(self):
        o = self.options
        if o.wall_viscosity is None:
            o.wall_viscosity = 'off' if o.scheme == 'delta_sph' else 'on'
        if o.scheme == 'delta_sph':
            self.scheme.scheme.wall_viscosity = o.wall_viscosity
        elif o.wall_viscosity == 'free-slip':
            raise SystemExit('--wall-viscosity free-slip needs --scheme delta_sph')
        dt = 0.125 * self.h / self.c0
        self.dt_fixed = dt
        t_end = (self.options.x_end - self.x0) / self.fr
        pfreq = max(1, int(round(self.options.every / self.fr / dt)))
        self.scheme.configure(h=self.h, c0=self.c0)
        kernel = Gaussian(dim=2) if self.options.kernel_name == 'gaussian' else WendlandQuintic(dim=2)
        self.scheme.configure_solver(kernel=kernel, dt=dt, tf=t_end, pfreq=pfreq)

    def create_equations(self):
        eqns = self.scheme.get_equations()
        for grp in eqns:
            for i, e in enumerate(grp.equations):
                if isinstance(e, XSPHCorrection):
                    grp.equations[i] = XSPHCorrection(dest=e.dest, sources=e.sources, eps=0.0)
                if isinstance(e, MomentumEquationArtificialViscosity) and self.options.wall_viscosity == 'off':
                    grp.equations[i] = MomentumEquationArtificialViscosity(dest=e.dest, sources=['fluid'],
                                                                           alpha=e.alpha, c0=e.c0)
        return eqns

    def hull_points(self, t):
        """Wall particles of the section at time t: positions, velocities, accelerations (n x 2 each)."""
        s = self.sec.at(self.x0 + self.fr * t)
        p, v, a = s[:, 0:2], self.fr * s[:, 2:4], self.fr ** 2 * s[:, 4:6]
        seg = np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1]))
        arc = np.concatenate([[0.0], np.cumsum(seg)])
        if arc[-1] < self.dx:
            return np.zeros((0, 2)), np.zeros((0, 2)), np.zeros((0, 2)), np.zeros((0, 2))
        sa = np.arange(0.5 * self.dx, arc[-1], self.dx)
        q = np.column_stack([np.interp(sa, arc, p[:, k]) for k in range(2)])
        vq = np.column_stack([np.interp(sa, arc, v[:, k]) for k in range(2)])
        aq = np.column_stack([np.interp(sa, arc, a[:, k]) for k in range(2)])
        tan = np.column_stack([np.interp(sa, arc, np.gradient(p[:, k], arc, edge_order=1)) for k in range(2)])
        tan /= np.maximum(np.hypot(tan[:, 0], tan[:, 1]), 1e-300)[:, None]
        normal = np.column_stack([tan[:, 1], -tan[:, 0]])  # into the fluid, as bowwave's N_2D (eq. 10.3)
        layers = [q - (k + 0.5) * self.dx * normal for k in range(LAYERS)]
        return (np.vstack(layers), np.vstack([vq] * LAYERS), np.vstack([aq] * LAYERS),
                np.vstack([normal] * LAYERS))

    def place_hull(self, t):
        pa = self._hull
        pos, vel, acc, normal = self.hull_points(t)
        n = min(len(pos), self.nmax)
        if len(pos) > self.nmax:
            print(f'warning: {len(pos)} hull wall particles, {self.nmax} slots')
        pa.x[:] = self.park[0]
        pa.y[:] = self.park[1]
        pa.u[:] = pa.v[:] = pa.au[:] = pa.av[:] = 0.0
        pa.x[:n], pa.y[:n] = pos[:n, 0], pos[:n, 1]
        pa.u[:n], pa.v[:n] = vel[:n, 0], vel[:n, 1]
        pa.au[:n], pa.av[:n] = acc[:n, 0], acc[:n, 1]
        if 'nx' in pa.properties:
            pa.nx[:] = 0.0
            pa.ny[:] = 1.0
            pa.nx[:n], pa.ny[:n] = normal[:n, 0], normal[:n, 1]

    def create_particles(self):
        dx, w, z = self.dx, self.width, self.depth
        ny, nz = int(round(w / dx)), int(round(z / dx))
        yf, zf = np.meshgrid((np.arange(ny) + 0.5) * dx, -z + (np.arange(nz) + 0.5) * dx)
        yf, zf = yf.ravel(), zf.ravel()
        # Outside the section at x0: the section's half-breadth at each height, by interpolation on its curve.
        s = self.sec.at(self.x0)
        inside = np.zeros_like(yf, dtype=bool)
        if np.ptp(s[:, 1]) > 0:
            zs, ys = s[:, 1], s[:, 0]
            order = np.argsort(zs)
            half = np.interp(zf, zs[order], ys[order], left=-1.0, right=-1.0)
            inside = yf < half + 0.5 * dx
        yf, zf = yf[~inside], zf[~inside]
        top = 0.6 * self.draft + 0.5 * z
        ws, zs_, ns = [], [], []
        for k in range(LAYERS):
            off = (k + 0.5) * dx
            zz = -z + (np.arange(-LAYERS, int((z + top) / dx)) + 0.5) * dx
            ws += [np.full_like(zz, -off), np.full_like(zz, w + off)]
            zs_ += [zz, zz]
            ns += [np.tile([1.0, 0.0], (len(zz), 1)), np.tile([-1.0, 0.0], (len(zz), 1))]  # into the fluid
            yy = (np.arange(ny) + 0.5) * dx
            ws.append(yy)
            zs_.append(np.full_like(yy, -z - off))
            ns.append(np.tile([0.0, 1.0], (len(yy), 1)))
        yw, zw, nw = np.concatenate(ws), np.concatenate(zs_), np.vstack(ns)
        m = dx * dx
        fluid = get_particle_array(name='fluid', x=yf, y=zf, h=self.h, m=m, rho=1.0, p=-zf)
        walls = get_particle_array(name='walls', x=yw, y=zw, h=self.h, m=m, rho=1.0, p=0.0)
        hull = get_particle_array(name='hull', x=np.full(self.nmax, self.park[0]),
                                  y=np.full(self.nmax, self.park[1]), h=self.h, m=m, rho=1.0, p=0.0)
        self.scheme.setup_properties([fluid, walls, hull])
        if 'nx' in walls.properties:
            walls.nx[:], walls.ny[:] = nw[:, 0], nw[:, 1]
        fluid.p[:] = -zf
        if self.options.scheme == 'delta_sph':
            # The density that the linear state equation turns into the hydrostatic pressure.
            fluid.rho[:] = 1.0 - zf / self.c0 ** 2
        self._hull = hull
        self.place_hull(0.0)
        return [fluid, walls, hull]

    def pre_step(self, solver):
        if self.options.restart_file is not None and not getattr(self, '_resumed', False):
            # PySPH resumes with the saved run's last step, which its end shortened to land on its tf.
            solver.dt = self.dt_fixed
            self._resumed = True

    def post_step(self, solver):
        if not hasattr(self, '_hull'):
            # A run resumed with --restart-file loads its arrays instead of creating them.
            self._hull = next(pa for pa in self.particles if pa.name == 'hull')
        self.place_hull(solver.t)


if __name__ == '__main__':
    TwoDt().run()
