"""bowwave's dam-break cases run in PySPH, an independent code for issue #2's two failing checks (session 21).

--case buchner (default): bowwave's `dam-break` (Buchner 2002 / Marrone et al. 2011): H = 0.6 m, column 2H x H,
  tank 5.366H, walls 2 m high, c0 = 20 sqrt(gH), to 1 s (t* 4.04). Does another code show the jump of P1 to
  0.6 rho g H that Marrone et al. and Buchner's experiment show right after the impact, or bowwave's slow rise?
--case mm: bowwave's `dam-break-mm` (Martin & Moyce 1952, n^2 = 2): column a x 2a, a = 0.05715 m, back wall
  and a floor 8a long, c0 = 30 sqrt(g a), to T = n t sqrt(g/a) = 3.4. Does another code's front run ahead of
  the experiment as bowwave's does?

Two schemes of PySPH 1.0b2:
  --scheme edac   (default) the entropically damped artificial compressibility scheme with Adami et al.'s
                  (2012) generalized wall boundary condition (the wall pressure extrapolated from the fluid);
  --scheme wcsph  weakly compressible SPH with Antuono's density diffusion (PySPH's `delta_sph`), Tait EOS,
                  dummy wall particles whose density follows the continuity equation.
Both: Wendland quintic kernel, h = 1.33 dx, artificial viscosity alpha = 0.02, no XSPH, hydrostatic start,
4 layers of wall particles.

Run: python dam_break.py --case buchner --res 40 -d OUT     (--res: H/dx, or a/dx for mm)
Outputs every 0.005 s (buchner) or 0.001 s (mm); read them with p1_from_outputs.py or front_from_outputs.py.
"""
import numpy as np
from pysph.base.kernels import WendlandQuintic
from pysph.base.utils import get_particle_array
from pysph.solver.application import Application
from pysph.sph.scheme import WCSPHScheme, SchemeChooser
from pysph.sph.wc.edac import EDACScheme
from pysph.sph.basic_equations import XSPHCorrection
from pysph.sph.integrator import PECIntegrator

G = 9.81         # m/s^2
RHO0 = 1000.0    # kg/m^3
GAMMA = 7.0
LAYERS = 4
A_MM = 0.05715   # m, Martin & Moyce's a
# column width, column height, tank floor length, right wall?, wall height (m); c0 / sqrt(g * reference length);
# reference length (m); end time (s); output interval (s)
CASES = {
    'buchner': dict(w=1.2, h=0.6, floor=3.2196, right_wall=True, top=2.0, c0=20.0, ref=0.6, tf=1.0, every=0.005),
    'mm': dict(w=A_MM, h=2 * A_MM, floor=8 * A_MM, right_wall=False, top=3.5 * A_MM, c0=30.0, ref=A_MM,
               tf=0.1835, every=0.001),
}


class DamBreak(Application):
    def add_user_options(self, group):
        group.add_argument('--case', choices=sorted(CASES), default='buchner', dest='case')
        group.add_argument('--res', type=float, default=40.0, dest='res', help='reference length / dx')
        group.add_argument('--hdx', type=float, default=1.33, dest='hdx', help='h/dx')

    def consume_user_options(self):
        self.c = CASES[self.options.case]
        self.dx = self.c['ref'] / self.options.res
        self.h = self.options.hdx * self.dx
        self.c0 = self.c['c0'] * np.sqrt(G * self.c['ref'])
        self.b = self.c0 ** 2 * RHO0 / GAMMA

    def create_scheme(self):
        c0 = 1.0  # set in configure_scheme
        wcsph = WCSPHScheme(['fluid'], ['boundary'], dim=2, rho0=RHO0, c0=c0, h0=0.02, hdx=1.33, gy=-G,
                            alpha=0.02, beta=0.0, gamma=GAMMA, hg_correction=True, delta_sph=True,
                            delta=0.1)
        edac = EDACScheme(fluids=['fluid'], solids=['boundary'], dim=2, c0=c0, nu=0.0, rho0=RHO0, h=0.02,
                          pb=0.0, gy=-G, eps=0.0, clamp_p=True, alpha=0.02)
        return SchemeChooser(default='edac', wcsph=wcsph, edac=edac)

    def configure_scheme(self):
        dt = 0.125 * self.h / self.c0
        pfreq = max(1, int(round(self.c['every'] / dt)))
        tf = self.c['tf']
        kernel = WendlandQuintic(dim=2)
        if self.options.scheme == 'wcsph':
            self.scheme.configure(h0=self.h, hdx=self.options.hdx, c0=self.c0)
            self.scheme.configure_solver(integrator_cls=PECIntegrator, kernel=kernel, dt=dt, tf=tf,
                                         adaptive_timestep=False, pfreq=pfreq)
        else:
            self.scheme.configure(h=self.h, c0=self.c0)
            self.scheme.configure_solver(kernel=kernel, dt=dt, tf=tf, pfreq=pfreq)

    def create_equations(self):
        eqns = self.scheme.get_equations()
        # XSPH off (eps = 0): particles move with their velocity, as in bowwave and in delta-SPH.
        for grp in eqns:
            for i, e in enumerate(grp.equations):
                if isinstance(e, XSPHCorrection):
                    grp.equations[i] = XSPHCorrection(dest=e.dest, sources=e.sources, eps=0.0)
        return eqns

    def create_particles(self):
        dx, c = self.dx, self.c
        nx, ny = int(round(c['w'] / dx)), int(round(c['h'] / dx))
        xf, yf = np.meshgrid((np.arange(nx) + 0.5) * dx, (np.arange(ny) + 0.5) * dx)
        xf, yf = xf.ravel(), yf.ravel()
        xs, ys = [], []
        for k in range(LAYERS):
            off = (k + 0.5) * dx
            yy = (np.arange(-LAYERS, int(c['top'] / dx)) + 0.5) * dx
            xs.append(np.full_like(yy, -off))
            ys.append(yy)
            if c['right_wall']:
                xs.append(np.full_like(yy, c['floor'] + off))
                ys.append(yy)
            xx = (np.arange(int(np.ceil(c['floor'] / dx))) + 0.5) * dx
            xx = xx[xx < c['floor']]
            xs.append(xx)
            ys.append(np.full_like(xx, -off))
        xb, yb = np.concatenate(xs), np.concatenate(ys)

        def hydrostatic(y):  # Tait density and pressure of water at rest, the column's height deep
            p = RHO0 * G * np.clip(c['h'] - y, 0.0, None)
            return RHO0 * (1.0 + p / self.b) ** (1.0 / GAMMA), p

        rf, pf = hydrostatic(yf)
        rb, pb = hydrostatic(yb)
        fluid = get_particle_array(name='fluid', x=xf, y=yf, h=self.h, m=rf * dx * dx, rho=rf, p=pf)
        boundary = get_particle_array(name='boundary', x=xb, y=yb, h=self.h, m=RHO0 * dx * dx, rho=rb, p=pb)
        self.scheme.setup_properties([fluid, boundary])
        fluid.rho[:], fluid.p[:] = rf, pf
        boundary.rho[:], boundary.p[:] = rb, pb
        return [fluid, boundary]


if __name__ == '__main__':
    DamBreak().run()
