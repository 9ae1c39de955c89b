"""The dam break of bowwave's `dam-break` case (Buchner 2002 / Marrone et al. 2011 geometry), run in PySPH.

An independent code for issue #2's P1 question (session 21): does another SPH code, with the same geometry,
resolution, sound speed and a hydrostatic start, show the jump of P1 to 0.6 rho g H that Marrone et al. and
Buchner's experiment show right after the impact, or the slow rise bowwave shows?

Two schemes of PySPH 1.0b2:
  --scheme wcsph  weakly compressible SPH with Antuono's density diffusion (PySPH's `delta_sph`), Tait EOS,
                  dummy wall particles whose density follows the continuity equation;
  --scheme edac   the entropically damped artificial compressibility scheme with Adami et al.'s (2012)
                  generalized wall boundary condition (the wall pressure extrapolated from the fluid).
Both: Wendland quintic kernel, h = 1.33 dx, c0 = 20 sqrt(gH), artificial viscosity alpha = 0.02, no XSPH.

Geometry in metres: H = 0.6, column 1.2 x 0.6 from the left wall, tank 3.2196 long, walls 2 m high,
4 layers of wall particles. Run: python dam_break_buchner.py --res 40 --scheme edac -d OUT --tf 1.0
Outputs every 0.005 s; read them with p1_from_outputs.py.
"""
import numpy as np
from pysph.base.kernels import WendlandQuintic
from pysph.base.utils import get_particle_array
from pysph.solver.application import Application
from pysph.sph.scheme import WCSPHScheme, SchemeChooser
from pysph.sph.wc.edac import EDACScheme
from pysph.sph.basic_equations import XSPHCorrection
from pysph.sph.integrator import PECIntegrator

H = 0.6          # m, column height
W = 1.2          # m, column width
L = 3.2196       # m, tank length (5.366 H)
TOP = 2.0        # m, wall height
G = 9.81         # m/s^2
RHO0 = 1000.0    # kg/m^3
C0 = 20.0 * np.sqrt(G * H)
GAMMA = 7.0
B = C0 * C0 * RHO0 / GAMMA
LAYERS = 4
OUTPUT_EVERY = 0.005  # s


class DamBreakBuchner(Application):
    def add_user_options(self, group):
        group.add_argument('--res', type=float, default=40.0, dest='res', help='H/dx')
        group.add_argument('--hdx', type=float, default=1.33, dest='hdx', help='h/dx')

    def consume_user_options(self):
        self.dx = H / self.options.res
        self.h = self.options.hdx * self.dx

    def create_scheme(self):
        wcsph = WCSPHScheme(['fluid'], ['boundary'], dim=2, rho0=RHO0, c0=C0, h0=0.02, hdx=1.33, gy=-G,
                            alpha=0.02, beta=0.0, gamma=GAMMA, hg_correction=True, delta_sph=True,
                            delta=0.1)
        edac = EDACScheme(fluids=['fluid'], solids=['boundary'], dim=2, c0=C0, nu=0.0, rho0=RHO0, h=0.02,
                          pb=0.0, gy=-G, eps=0.0, clamp_p=True, alpha=0.02)
        return SchemeChooser(default='edac', wcsph=wcsph, edac=edac)

    def configure_scheme(self):
        dt = 0.125 * self.h / C0
        pfreq = max(1, int(round(OUTPUT_EVERY / dt)))
        kernel = WendlandQuintic(dim=2)
        if self.options.scheme == 'wcsph':
            self.scheme.configure(h0=self.h, hdx=self.options.hdx)
            self.scheme.configure_solver(integrator_cls=PECIntegrator, kernel=kernel, dt=dt, tf=1.0,
                                         adaptive_timestep=False, pfreq=pfreq)
        else:
            self.scheme.configure(h=self.h)
            self.scheme.configure_solver(kernel=kernel, dt=dt, tf=1.0, pfreq=pfreq)

    def create_equations(self):
        eqns = self.scheme.get_equations()
        # XSPH off (eps = 0): particles move with their velocity, as in bowwave and in delta-SPH.
        for grp in eqns:
            for i, e in enumerate(grp.equations):
                if isinstance(e, XSPHCorrection):
                    grp.equations[i] = XSPHCorrection(dest=e.dest, sources=e.sources, eps=0.0)
        return eqns

    def create_particles(self):
        dx = self.dx
        nx, ny = int(round(W / dx)), int(round(H / dx))
        xf, yf = np.meshgrid((np.arange(nx) + 0.5) * dx, (np.arange(ny) + 0.5) * dx)
        xf, yf = xf.ravel(), yf.ravel()
        xs, ys = [], []
        for k in range(LAYERS):
            off = (k + 0.5) * dx
            yy = (np.arange(-LAYERS, int(TOP / dx)) + 0.5) * dx
            xs += [np.full_like(yy, -off), np.full_like(yy, L + off)]
            ys += [yy, yy]
            xx = (np.arange(int(np.ceil(L / dx))) + 0.5) * dx
            xx = xx[xx < L]
            xs.append(xx)
            ys.append(np.full_like(xx, -off))
        xb, yb = np.concatenate(xs), np.concatenate(ys)

        def hydrostatic(y):  # Tait density and pressure of water at rest, H deep
            p = RHO0 * G * np.clip(H - y, 0.0, None)
            return RHO0 * (1.0 + p / B) ** (1.0 / GAMMA), p

        rf, pf = hydrostatic(yf)
        rb, pb = hydrostatic(yb)
        fluid = get_particle_array(name='fluid', x=xf, y=yf, h=self.h, m=rf * dx * dx, rho=rf, p=pf)
        boundary = get_particle_array(name='boundary', x=xb, y=yb, h=self.h, m=RHO0 * dx * dx, rho=rb, p=pb)
        self.scheme.setup_properties([fluid, boundary])
        fluid.rho[:], fluid.p[:] = rf, pf
        boundary.rho[:], boundary.p[:] = rb, pb
        return [fluid, boundary]


if __name__ == '__main__':
    DamBreakBuchner().run()
