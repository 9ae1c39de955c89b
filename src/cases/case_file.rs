//! The case file: a TOML description of a 2D SPH run (walls, fluid blocks, body force, numerics, probes,
//! outputs). Units are SI and given in the comments of the built-in cases (`cases/*.toml`).
//! Every error names the file, the field and what was expected.

use crate::input_error::{parse_toml, read_text, InputError};
use crate::sph::{
    density_diffusion::DensityDiffusion, eos::EosKind, integrator::Integrator, kernel::KernelKind,
    polyline_wall::FluidSide, viscosity::Viscosity,
};
use serde::{Deserialize, Serialize};

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseFile {
    pub name: String,
    #[serde(default)]
    pub description: String,
    /// Spatial dimension; only 2 is accepted by case files for now.
    #[serde(default = "two")]
    pub dimension: usize,
    pub scales: Scales,
    /// The fluid; with `[[phases]]`, the first phase (phase 0).
    pub fluid: FluidSpec,
    /// Further phases for the multi-fluid δ-SPH of Hammani et al. (`sph::multi_fluid`); none (the default):
    /// one phase, the single-phase solver.
    #[serde(default)]
    pub phases: Vec<PhaseSpec>,
    /// Constants of the multi-fluid model (read only with `[[phases]]`).
    #[serde(default)]
    pub multi_fluid: MultiFluidSpec,
    #[serde(default)]
    pub numerics: Numerics,
    pub body_force: BodyForceSpec,
    pub domain: Domain,
    #[serde(default)]
    pub walls: Vec<WallSpec>,
    pub blocks: Vec<BlockSpec>,
    #[serde(default)]
    pub probes: Probes,
    pub output: Output,
    /// Measurements to compare a series column with (`validation::references`).
    #[serde(default)]
    pub references: Vec<ReferenceSpec>,
    /// The folder of the case file, against which reference files are resolved (set by [`CaseFile::read`];
    /// the working directory for a case given as text).
    #[serde(skip)]
    pub dir: Option<std::path::PathBuf>,
}

/// A measured series to compare one of the case's series columns with: a CSV whose first two numeric
/// columns are time and value (header and `#` lines skipped).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReferenceSpec {
    /// The series column compared (`pstar_NAME`, `p_NAME`, `eta_NAME`, `depth_NAME`, `depthstar_NAME`,
    /// `front`, `front_star`, ...).
    pub column: String,
    /// The CSV file, relative to the case file.
    pub file: String,
    /// The reference's time: `"t_star"` (t √(g/length), the default) or `"t"` (s).
    #[serde(default = "t_star")]
    pub time: String,
    /// Added to the reference's times before comparing (in `time`'s unit): an experiment's time origin.
    #[serde(default)]
    pub shift: f64,
    /// The reference's values are multiplied by this to be in the column's unit.
    #[serde(default = "one")]
    pub scale: f64,
    /// Time window of the comparison (in `time`'s unit); default: the reference's whole span.
    #[serde(default)]
    pub window: Option<[f64; 2]>,
    /// Largest mean |ours − reference| over the window that passes (in the column's unit); none: reported.
    #[serde(default)]
    pub tolerance: Option<f64>,
}

fn t_star() -> String {
    "t_star".into()
}

fn one() -> f64 {
    1.0
}

impl ReferenceSpec {
    /// The reference file's path.
    pub fn path(&self, case: &CaseFile) -> std::path::PathBuf {
        case.beside(&self.file)
    }
}

fn two() -> usize {
    2
}

/// Reference scales: `length` (m) sets the resolution (dx = length / resolution) and the non-dimensional
/// outputs t* = t √(g/length), p* = p/(ρ0 g length), x* = x/length (g = |body force| or 1 without one).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scales {
    pub length: f64,
    /// Default length/dx (overridden by `--res`).
    pub resolution: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FluidSpec {
    /// ρ0 (kg/m³).
    pub rho0: f64,
    /// Speed of sound c0 (m/s); give this or `c0_over_sqrt_g_length`.
    pub c0: Option<f64>,
    /// c0 / √(g length) (dimensionless), e.g. 20 for the dam break.
    pub c0_over_sqrt_g_length: Option<f64>,
    #[serde(default)]
    pub eos: EosKind,
    /// Its name, which blocks use to choose it when there are `[[phases]]`; default "water".
    #[serde(default = "water")]
    pub name: String,
}

fn water() -> String {
    "water".into()
}

/// A further phase (`[[phases]]`), e.g. air over the water.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhaseSpec {
    /// The name blocks choose it by (`blocks.phase`).
    pub name: String,
    /// ρ0 (kg/m³), e.g. 1 for air at a density ratio of 1000.
    pub rho0: f64,
    /// State equation; default `tait` (γ below).
    #[serde(default = "tait")]
    pub eos: EosKind,
    /// The Tait exponent; default 1.4 (air, Grenier et al. §4.2).
    #[serde(default = "air_gamma")]
    pub gamma: f64,
    /// Speed of sound (m/s). Default: the value that gives this phase the stiffness ρ0c0²/γ of `[fluid]`
    /// (Hammani et al. eq. 23; 14.14 times the water's for air at a ratio of 1000), so that the interface
    /// does not move under pressure differences the heavier phase hardly feels.
    #[serde(default)]
    pub c0: Option<f64>,
}

fn tait() -> EosKind {
    EosKind::Tait
}

fn air_gamma() -> f64 {
    1.4
}

/// `[multi_fluid]`: constants of the multi-fluid model.
#[derive(Clone, Debug, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct MultiFluidSpec {
    /// Background pressure p_b (Pa), added in the forces of every phase; default 0. Hammani et al. use 0.1 of
    /// the largest hydrostatic pressure in a closed tank; it needs a closed domain (it pulls a free surface in).
    #[serde(default)]
    pub background_pressure: f64,
    /// ε_I of Grenier et al. (2009) eq. 23, a repulsion between phases; default 0 (off).
    #[serde(default)]
    pub interface_repulsion: f64,
    /// The volume-diffusion term's form: `factor-two` (the default, the δ-SPH term mapped to volumes) or
    /// `as-printed` (Hammani et al. eq. 20 as printed, without the factor 2).
    #[serde(default)]
    pub diffusion: crate::sph::multi_fluid::VolumeDiffusion,
    /// Take the multi-fluid path even with the `[fluid]` alone (default false: one phase runs the
    /// single-phase solver): to compare the two on the same case.
    #[serde(default)]
    pub with_one_phase: bool,
    /// The density the state equation reads: `shepard` (Hammani et al. eq. 13 over the particle's phase) or
    /// `integrated` (m/V of the particle itself).
    #[serde(default)]
    pub density: crate::sph::multi_fluid::StateDensity,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Numerics {
    #[serde(default = "default_kernel")]
    pub kernel: KernelKind,
    /// h/dx; default 1.33 (Gaussian) or 2.0 (Wendland).
    pub h_over_dx: Option<f64>,
    #[serde(default)]
    pub integrator: Integrator,
    /// CFL of eq. (4.22); default per integrator (2.0 RK4, 0.5 predictor–corrector; `Integrator::default_cfl`).
    pub cfl: Option<f64>,
    #[serde(default)]
    pub density_diffusion: DensityDiffusion,
    /// δ (dimensionless), default 0.1.
    #[serde(default = "default_delta")]
    pub delta: f64,
    #[serde(default)]
    pub viscosity: Viscosity,
    /// "mls" (first order, eq. 7.6; default) or "shepard".
    #[serde(default)]
    pub ghost_interpolation: crate::sph::solver::GhostInterpolation,
    /// Tabulate the Gaussian's gradient in r² (`sph::kernel_table`); default true: the same accuracy as the
    /// exact kernel on the dam break and the 2D+t chart for 10–25 % less CPU (docs/reference/speed-accuracy.md).
    #[serde(default = "default_kernel_table")]
    pub kernel_table: bool,
    /// "sun2017-walls", "sun2017-leaving", "sun2017" or "none": particle shifting after each step only within two
    /// kernel supports of a wall and away from the free surface, the same only where the flow leaves a wall,
    /// everywhere, or not at all (the thesis's δ-SPH)
    /// (`sph::particle_shifting`). Unset: "sun2017-leaving" with one phase, "none" with `[[phases]]`
    /// ([`CaseFile::shifting`], docs/decisions/wall-leaving-shifting.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shifting: Option<crate::sph::particle_shifting::ParticleShifting>,
    /// "free-slip" (the default, the thesis's for impact flows) or "no-slip": every wall holds the fluid in the
    /// viscous term (thesis §7.1.3), meant with `viscosity = { kind = "physical", nu = … }`.
    #[serde(default)]
    pub wall_slip: crate::sph::equations::ghost_conditions::WallSlip,
    /// "own" (the default, the thesis's) or "previous": the state each RK stage's renormalised density
    /// gradient is taken at; "previous" takes the previous stage's after a step's first stage, one pass over
    /// the pairs a stage instead of two (`sph::main_loop::GradientStage`).
    #[serde(default)]
    pub gradient_stage: crate::sph::main_loop::GradientStage,
    /// The form of the normal-flux walls' terms (`ghosts = "normal-flux"`): `shepard` (the default, divided by
    /// the Shepard sum near the wall, De Leffe et al. 2009) or `thesis` (as printed in thesis §7.1.2).
    #[serde(default)]
    pub normal_flux: crate::sph::normal_flux::NormalFluxForm,
}

fn default_kernel_table() -> bool {
    true
}

fn default_kernel() -> KernelKind {
    KernelKind::RenormalizedGaussian
}
fn default_delta() -> f64 {
    0.1
}

impl Default for Numerics {
    fn default() -> Self {
        Numerics {
            kernel: default_kernel(),
            h_over_dx: None,
            integrator: Integrator::default(),
            cfl: None,
            density_diffusion: DensityDiffusion::default(),
            delta: default_delta(),
            viscosity: Viscosity::default(),
            ghost_interpolation: Default::default(),
            kernel_table: true,
            shifting: Default::default(),
            wall_slip: Default::default(),
            gradient_stage: Default::default(),
            normal_flux: Default::default(),
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum BodyForceSpec {
    /// Uniform gravity g (m/s²).
    Gravity {
        g: Vec<f64>,
    },
    /// Central force −Ω² (x − centre), Ω in 1/s.
    Central {
        omega: f64,
        centre: Vec<f64>,
    },
    None,
}

/// Particles leaving [min, max] (m) stop the run as a blow-up.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Domain {
    pub min: Vec<f64>,
    pub max: Vec<f64>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WallSpec {
    pub name: String,
    /// Polyline vertices (m).
    pub points: Vec<Vec<f64>>,
    /// Side of the polyline (walking from first to last point) on which the fluid lies.
    pub fluid_side: FluidSide,
    /// Constant translation velocity (m/s); omitted: fixed.
    pub velocity: Option<Vec<f64>>,
    /// Ghosts of the straight sides: "fixed" (MLS-valued lattice, thesis §7.1.1; the default) or "images"
    /// (mirror images of the fluid particles, Colagrossi & Landrini 2003; corners keep fixed ghosts).
    #[serde(default)]
    pub ghosts: crate::sph::polyline_wall::GhostKind,
    /// Prescribed sway, heave and roll (`cases::wall_motion`); omitted: still (or `velocity`).
    #[serde(default)]
    pub motion: Option<super::wall_motion::MotionSpec>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "shape", rename_all = "kebab-case", deny_unknown_fields)]
pub enum BlockSpec {
    /// Particles on the lattice ((i + ½) dx) inside [min, max] (m).
    Rectangle {
        min: Vec<f64>,
        max: Vec<f64>,
        /// The phase's name (`[fluid]` or one of `[[phases]]`); default the `[fluid]`.
        #[serde(default)]
        phase: Option<String>,
        #[serde(default)]
        pressure: PressureSpec,
        #[serde(default)]
        velocity: Option<Vec<f64>>,
        #[serde(default)]
        velocity_gradient: Option<Vec<Vec<f64>>>,
        /// Keep only the lattice points on one side of a sinusoidal curve: an interface that is not flat.
        #[serde(default)]
        cut: Option<CutSpec>,
    },
    /// Particles on concentric rings of spacing dx inside a disc (m), or inside the annulus between
    /// `inner_radius` and `radius`.
    Disc {
        centre: Vec<f64>,
        radius: f64,
        /// Inner radius (m) of an annulus; default 0, a whole disc.
        #[serde(default)]
        inner_radius: f64,
        /// The phase's name; default the `[fluid]`.
        #[serde(default)]
        phase: Option<String>,
        #[serde(default)]
        pressure: PressureSpec,
        #[serde(default)]
        velocity: Option<Vec<f64>>,
        /// Initial velocity u = G (x − centre), G in 1/s.
        #[serde(default)]
        velocity_gradient: Option<Vec<Vec<f64>>>,
    },
}

/// The curve y = y + amplitude sin(2π x / wavelength) (m) that cuts a rectangular block, and which side of it
/// the block keeps: the Rayleigh–Taylor set-up's interface y = 1 − 0.15 sin 2πx is `y = 1.0, amplitude = -0.15,
/// wavelength = 1.0`, the light fluid's block keeping `below`, the heavy one's `above`. Two blocks cut by the same
/// curve on opposite sides do not overlap. Under a cut kept `below`, the block's top (where a hydrostatic
/// pressure's `top` applies) is the curve.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CutSpec {
    pub y: f64,
    pub amplitude: f64,
    pub wavelength: f64,
    pub keep: CutSide,
}

/// The side of a [`CutSpec`]'s curve a block keeps.
#[derive(Clone, Copy, Debug, Serialize, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum CutSide {
    Below,
    Above,
}

impl CutSpec {
    /// The curve's height at `x` (m).
    pub fn height(&self, x: f64) -> f64 {
        self.y + self.amplitude * (2.0 * std::f64::consts::PI * x / self.wavelength).sin()
    }

    /// Whether the block keeps the point (x, y).
    pub fn keeps(&self, x: f64, y: f64) -> bool {
        match self.keep {
            CutSide::Below => y < self.height(x),
            CutSide::Above => y >= self.height(x),
        }
    }
}

#[derive(Clone, Debug, Serialize, Deserialize, Default, PartialEq)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
pub enum PressureSpec {
    /// p = 0.
    #[default]
    Zero,
    /// Hydrostatic in the block's phase (gravity along −y), `top` (Pa, default 0: a free surface) at the
    /// block's top: the weight of the layers above, e.g. of the air over the water.
    Hydrostatic {
        #[serde(default)]
        top: f64,
        /// The weight of another fluid above the block's top, up to a level: `{ rho0 = 1.8, up_to = 2.0 }` adds
        /// ρ0 g (up_to − y_top) to `top`, where y_top may vary along a cut block's curve (kg/m³, m).
        #[serde(default)]
        overburden: Option<Overburden>,
    },
    /// p = p_rim + (p_centre − p_rim)(1 − |x − c|²/R²) (Pa), R the block's radius (half diagonal for a
    /// rectangle): the initial pressure of the drops; `p_rim` default 0 (a free surface at R).
    Paraboloid {
        p_centre: f64,
        #[serde(default)]
        p_rim: f64,
    },
}

/// A layer of another fluid above a block ([`PressureSpec::Hydrostatic`]).
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Overburden {
    pub rho0: f64,
    pub up_to: f64,
}

#[derive(Clone, Debug, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Probes {
    #[serde(default)]
    pub pressure: Vec<PressureProbe>,
    #[serde(default)]
    pub gauge: Vec<Gauge>,
    /// Record the front (largest x of the fluid).
    #[serde(default)]
    pub front: bool,
    /// Record the tips of an unstable interface between the `[fluid]` (heavy, above) and the first of
    /// `[[phases]]` (light, below), as Rayleigh–Taylor studies read it: `spike_y`, the lowest particle of the
    /// `[fluid]` minus dx/2, and `bubble_y`, the highest particle of the light phase plus dx/2 (m).
    #[serde(default)]
    pub interface_tips: bool,
    /// Watch for the first air cavity closed by a plunging jet (`cases::cavity_probe`).
    #[serde(default)]
    pub cavity: Option<CavityProbeSpec>,
}

/// The cavity probe: from time `after` (s) on, the fluid is checked at every series sample for a newly
/// closed air cavity; the run records the first one.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CavityProbeSpec {
    pub after: f64,
}

/// A pressure sensor. By default a face on a wall: `size` wide (m; 0 for a point) centred at `position` (m),
/// on the wall `wall` names (or the nearest), the whole face on one straight side of it; it reads the wall
/// pressure averaged over the face, and records its peak and impulse between outputs from every step
/// (`sph::wall_sensor`; placement rules in `cases::sensor_placement`). `direction` (the wall's tangent) may be
/// omitted. With `in_fluid = true` it is a probe inside the fluid instead (a symmetry plane, say): the kernel
/// (Shepard) average of the pressure at 5 points over `size` along `direction`, which it then needs.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PressureProbe {
    pub name: String,
    pub position: Vec<f64>,
    #[serde(default)]
    pub direction: Option<Vec<f64>>,
    #[serde(default)]
    pub size: f64,
    /// The wall the sensor is on (a `walls` name); default: the nearest.
    #[serde(default)]
    pub wall: Option<String>,
    /// A probe in the fluid, not on a wall.
    #[serde(default)]
    pub in_fluid: bool,
}

/// A wave gauge at abscissa `x` (m): the water level (`eta_NAME`, m), the depth above the gauge's `bottom`
/// (`depth_NAME`, m) and that depth over the case's length scale (`depthstar_NAME`); a dry gauge reads zero
/// depth. `connected`: count only water reached from the bottom without crossing air (not spray, not a jet
/// over a trough); otherwise the highest particle within dx of x (`sph::diagnostics::water_level`).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gauge {
    pub name: String,
    pub x: f64,
    /// Height of the floor under the gauge (m); default: the lowest point where a wall crosses the vertical
    /// through `x` ([`CaseFile::floor_under`]), or the domain's bottom if none does.
    #[serde(default)]
    pub bottom: Option<f64>,
    #[serde(default)]
    pub connected: bool,
    /// The wall whose motion carries the gauge (a gauge in a moving tank): `x` is its abscissa at t = 0 and it
    /// follows the wall's horizontal displacement (a roll does not tilt it).
    #[serde(default)]
    pub moves_with: Option<String>,
}

#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Output {
    /// End time (in `time_unit`).
    pub end_time: f64,
    /// Time-series sampling interval (in `time_unit`).
    pub series_every: f64,
    /// VTK snapshot interval (in `time_unit`); 0 turns snapshots off.
    #[serde(default)]
    pub vtk_every: f64,
    /// The unit of the times of the case file (these three and `probes.cavity.after`): seconds (`"s"`, the
    /// default) or t* = t √(g/length) (`"t_star"`), the case's own non-dimensional time. They are converted to
    /// seconds when the case is read.
    #[serde(default)]
    pub time_unit: TimeUnit,
}

/// The unit of a case file's times.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum TimeUnit {
    #[default]
    #[serde(rename = "s")]
    Seconds,
    #[serde(rename = "t_star")]
    TStar,
}

impl CaseFile {
    /// The particle shifting the case runs with: `numerics.shifting`, or when unset the default for its
    /// number of phases ([`crate::sph::particle_shifting::default_for`]).
    pub fn shifting(&self) -> crate::sph::particle_shifting::ParticleShifting {
        self.numerics
            .shifting
            .unwrap_or_else(|| crate::sph::particle_shifting::default_for(!self.phases.is_empty()))
    }

    /// Gives every wall ghosts of kind `kind` (the CLI's `--ghosts`).
    pub fn set_ghosts(&mut self, kind: crate::sph::polyline_wall::GhostKind) {
        for w in &mut self.walls {
            w.ghosts = kind;
        }
    }

    /// Parses and checks a case from TOML text; `file` names it in errors.
    pub fn parse(text: &str, file: &str) -> Result<Self, InputError> {
        let mut case: CaseFile = parse_toml(text, file)?;
        case.check(file)?;
        case.times_in_seconds();
        Ok(case)
    }

    /// Converts the case's times to seconds (`output.time_unit`), after the checks.
    fn times_in_seconds(&mut self) {
        if self.output.time_unit == TimeUnit::TStar {
            let f = (self.scales.length / self.gravity_magnitude()).sqrt();
            self.output.end_time *= f;
            self.output.series_every *= f;
            self.output.vtk_every *= f;
            if let Some(c) = &mut self.probes.cavity {
                c.after *= f;
            }
            for m in self.walls.iter_mut().filter_map(|w| w.motion.as_mut()) {
                for s in [&mut m.sway, &mut m.heave, &mut m.roll].into_iter().flatten() {
                    s.period *= f;
                }
            }
            self.output.time_unit = TimeUnit::Seconds;
        }
    }

    /// Reads a case file from disk.
    pub fn read(path: &std::path::Path) -> Result<Self, InputError> {
        let mut case = Self::parse(&read_text(path)?, &path.display().to_string())?;
        case.dir = path.parent().map(|p| p.to_path_buf());
        super::reference_file::check_files(&case, &path.display().to_string())?;
        super::wall_motion::check_tables(&case, &path.display().to_string())?;
        Ok(case)
    }

    /// A file the case names, relative to the case file's folder (the working directory for a case given as
    /// text).
    pub fn beside(&self, file: &str) -> std::path::PathBuf {
        self.dir.clone().unwrap_or_default().join(file)
    }

    /// The index of the wall called `name`, or what a field naming a wall expects (the case's wall names).
    pub fn wall_named(&self, name: &str) -> Result<usize, String> {
        self.walls.iter().position(|w| w.name == name).ok_or_else(|| {
            let names: Vec<&str> = self.walls.iter().map(|w| w.name.as_str()).collect();
            format!("the name of one of the case's walls ({})", names.join(", "))
        })
    }

    /// The lowest height at which one of the case's walls (as drawn, at t = 0) crosses the vertical through
    /// `x`, or the domain's bottom if none does: a gauge's default floor.
    pub fn floor_under(&self, x: f64) -> f64 {
        let mut floor = f64::INFINITY;
        for w in &self.walls {
            for seg in w.points.windows(2) {
                let (a, b) = (&seg[0], &seg[1]);
                let (lo, hi) = (a[0].min(b[0]), a[0].max(b[0]));
                if x < lo || x > hi {
                    continue;
                }
                let y = if hi > lo {
                    a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0])
                } else {
                    a[1].min(b[1]) // a vertical side through x: its foot
                };
                floor = floor.min(y);
            }
        }
        if floor.is_finite() {
            floor
        } else {
            self.domain.min[self.dimension.max(2) - 1]
        }
    }

    /// The series columns a probe, gauge or the front writes (those a reference may name).
    pub fn probe_columns(&self) -> Vec<String> {
        let mut c = vec![];
        if self.probes.front {
            c.extend(["front".to_string(), "front_star".to_string()]);
        }
        if self.probes.interface_tips {
            c.extend(["spike_y".to_string(), "bubble_y".to_string()]);
        }
        for p in &self.probes.pressure {
            c.extend(pressure_columns(p));
        }
        for g in &self.probes.gauge {
            c.extend([
                format!("eta_{}", g.name),
                format!("depth_{}", g.name),
                format!("depthstar_{}", g.name),
            ]);
        }
        c
    }

    /// The names of the phases in their order: `[fluid]` (phase 0), then `[[phases]]`.
    pub fn phase_names(&self) -> Vec<&str> {
        std::iter::once(self.fluid.name.as_str())
            .chain(self.phases.iter().map(|p| p.name.as_str()))
            .collect()
    }

    /// The phase index a block's `phase` names (0, the `[fluid]`, when it names none).
    pub fn phase_index(&self, name: Option<&str>) -> Result<u8, String> {
        let names = self.phase_names();
        match name {
            None => Ok(0),
            Some(n) => names
                .iter()
                .position(|m| *m == n)
                .map(|k| k as u8)
                .ok_or_else(|| format!("the name of a phase ({})", names.join(", "))),
        }
    }

    fn check_phases(&self, file: &str) -> Result<(), InputError> {
        let err = |field: &str, expected: &str| InputError::field(file, field, expected);
        if self.phases.len() > 254 {
            return Err(err("phases", "at most 254 further phases"));
        }
        for (k, p) in self.phases.iter().enumerate() {
            if p.name.is_empty() || self.phase_names()[..=k].contains(&p.name.as_str()) {
                return Err(err(
                    &format!("phases[{k}].name"),
                    "a name of its own (not the `[fluid]`'s nor another phase's)",
                ));
            }
            if !(p.rho0.is_finite() && p.rho0 > 0.0) {
                return Err(err(&format!("phases[{k}].rho0"), "a positive density in kg/m³"));
            }
            if !(p.gamma.is_finite() && p.gamma >= 1.0) {
                return Err(err(
                    &format!("phases[{k}].gamma"),
                    "a Tait exponent of at least 1 (air: 1.4)",
                ));
            }
            if let Some(c) = p.c0 {
                if !(c.is_finite() && c > 0.0) {
                    return Err(err(&format!("phases[{k}].c0"), "a positive speed of sound in m/s"));
                }
            }
        }
        let m = &self.multi_fluid;
        if !(m.background_pressure.is_finite() && m.background_pressure >= 0.0) {
            return Err(err("multi_fluid.background_pressure", "a non-negative pressure in Pa"));
        }
        if !(m.interface_repulsion.is_finite() && m.interface_repulsion >= 0.0) {
            return Err(err(
                "multi_fluid.interface_repulsion",
                "a non-negative ε_I (Grenier et al.: 0.01–0.1; 0 is off)",
            ));
        }
        if !self.phases.is_empty()
            && self
                .numerics
                .shifting
                .is_some_and(|s| s != crate::sph::particle_shifting::ParticleShifting::None)
        {
            return Err(err("numerics.shifting", crate::sph::particle_shifting::WITH_PHASES));
        }
        if self.probes.interface_tips && self.phases.is_empty() {
            return Err(err(
                "probes.interface_tips",
                "a case with `[[phases]]`: the tips are those of the interface between the `[fluid]` and the first phase",
            ));
        }
        let mut used = vec![false; self.phases.len() + 1];
        for (k, b) in self.blocks.iter().enumerate() {
            let (BlockSpec::Rectangle { phase, .. } | BlockSpec::Disc { phase, .. }) = b;
            match self.phase_index(phase.as_deref()) {
                Ok(i) => used[i as usize] = true,
                Err(expected) => return Err(err(&format!("blocks[{k}].phase"), &expected)),
            }
        }
        if self.phases.is_empty() {
            return Ok(());
        }
        if let Some(k) = used.iter().skip(1).position(|u| !u) {
            return Err(err(
                &format!("phases[{k}]"),
                "a phase that at least one block fills (`blocks.phase`)",
            ));
        }
        // Two blocks of different phases must not overlap: a particle of each at the same place.
        for (a, ba) in self.blocks.iter().enumerate() {
            for (b, bb) in self.blocks.iter().enumerate().skip(a + 1) {
                let (BlockSpec::Rectangle { phase: pa, .. } | BlockSpec::Disc { phase: pa, .. }) = ba;
                let (BlockSpec::Rectangle { phase: pb, .. } | BlockSpec::Disc { phase: pb, .. }) = bb;
                if self.phase_index(pa.as_deref()) != self.phase_index(pb.as_deref()) && blocks_overlap(ba, bb) {
                    return Err(err(
                        &format!("blocks[{b}]"),
                        &format!("a block that does not overlap blocks[{a}], which holds another phase"),
                    ));
                }
            }
        }
        // Ranges the model is meant for (Hammani et al. run 2–1000): a density ratio to the `[fluid]` and a
        // stiffness ρ0c0²/γ ratio (1 by the default rule) within a factor 1e4 and 1e3.
        let law = |kind, rho0, c0, gamma| crate::sph::eos::Eos { kind, rho0, c0, gamma };
        let b_fluid = law(
            self.fluid.eos,
            self.fluid.rho0,
            self.c0(),
            crate::sph::eos::TAIT_GAMMA_WATER,
        )
        .stiffness();
        for (k, p) in self.phases.iter().enumerate() {
            let ratio = p.rho0 / self.fluid.rho0;
            if !(1e-4..=1e4).contains(&ratio) {
                return Err(err(
                    &format!("phases[{k}].rho0"),
                    "a density within a factor 1e4 of the `[fluid]`'s (air/water: 1e-3)",
                ));
            }
            if let Some(c) = p.c0 {
                let r = law(p.eos, p.rho0, c, p.gamma).stiffness() / b_fluid;
                if !(1e-3..=1e3).contains(&r) {
                    return Err(err(
                        &format!("phases[{k}].c0"),
                        "a sound speed giving a stiffness ρ0c0²/γ within a factor 1e3 of the `[fluid]`'s (leave it out \
                         for the equal-stiffness rule, Hammani et al. eq. 23)",
                    ));
                }
            }
        }
        // A background pressure needs a closed tank (at a free surface it pushes the particles out); a closed
        // tank with phases of very different densities needs one (else the light phase's negative pressures
        // open a void at the interface, Hammani et al. Fig. 1).
        let closed = self.walls.iter().any(|w| {
            let (a, b) = (&w.points[0], &w.points[w.points.len() - 1]);
            w.points.len() > 3 && (a[0] - b[0]).hypot(a[1] - b[1]) == 0.0
        });
        let contrast = self.phases.iter().any(|p| {
            let r = p.rho0 / self.fluid.rho0;
            !(0.1..=10.0).contains(&r)
        });
        let pb = self.multi_fluid.background_pressure;
        if pb > 0.0 && !closed {
            return Err(err(
                "multi_fluid.background_pressure",
                "0 without a closed wall (a polyline whose last point is its first): at a free surface a \
                 background pressure pushes the particles out",
            ));
        }
        if pb == 0.0 && closed && contrast {
            return Err(err(
                "multi_fluid.background_pressure",
                "a positive background pressure in a closed tank holding phases of density ratio above 10 \
                 (Hammani et al. use 0.1 of the largest hydrostatic pressure; without it the light phase's \
                 negative pressures open a void at the interface)",
            ));
        }
        Ok(())
    }

    fn check(&self, file: &str) -> Result<(), InputError> {
        let err = |field: &str, expected: &str| InputError::field(file, field, expected);
        let d = self.dimension;
        if d != 2 {
            return Err(err(
                "dimension",
                "2 (case files describe 2D runs; 3D comes with the comparison mode)",
            ));
        }
        let pos = |x: f64| x.is_finite() && x > 0.0;
        let vec_ok = |v: &Vec<f64>| v.len() == d && v.iter().all(|x| x.is_finite());
        if !pos(self.scales.length) {
            return Err(err("scales.length", "a positive length in metres"));
        }
        if !pos(self.scales.resolution) {
            return Err(err(
                "scales.resolution",
                "a positive number of particles per reference length",
            ));
        }
        if !pos(self.fluid.rho0) {
            return Err(err("fluid.rho0", "a positive density in kg/m³"));
        }
        match (self.fluid.c0, self.fluid.c0_over_sqrt_g_length) {
            (Some(c), None) | (None, Some(c)) if pos(c) => {}
            (Some(_), Some(_)) => return Err(err("fluid.c0", "either `c0` or `c0_over_sqrt_g_length`, not both")),
            _ => {
                return Err(err(
                    "fluid.c0",
                    "a positive speed of sound: `c0` (m/s) or `c0_over_sqrt_g_length`",
                ))
            }
        }
        if let Some(r) = self.numerics.h_over_dx {
            if !(r.is_finite() && (0.5..=4.0).contains(&r)) {
                return Err(err("numerics.h_over_dx", "a ratio between 0.5 and 4"));
            }
        }
        if let Some(c) = self.numerics.cfl {
            if !pos(c) {
                return Err(err("numerics.cfl", "a positive CFL number"));
            }
        }
        if !(self.numerics.delta.is_finite() && self.numerics.delta >= 0.0) {
            return Err(err("numerics.delta", "a non-negative δ (0.1 is the default)"));
        }
        match self.numerics.viscosity {
            Viscosity::Artificial { alpha } if !(alpha.is_finite() && alpha >= 0.0) => {
                return Err(err("numerics.viscosity.alpha", "a non-negative α"))
            }
            Viscosity::Physical { nu } if !(nu.is_finite() && nu >= 0.0) => {
                return Err(err("numerics.viscosity.nu", "a non-negative ν in m²/s"))
            }
            _ => {}
        }
        match &self.body_force {
            BodyForceSpec::Gravity { g } if !vec_ok(g) => {
                return Err(err("body_force.g", "a 2-component acceleration in m/s²"))
            }
            BodyForceSpec::Central { omega, centre } if !(omega.is_finite() && vec_ok(centre)) => {
                return Err(err(
                    "body_force",
                    "a finite `omega` (1/s) and a 2-component `centre` (m)",
                ))
            }
            _ => {}
        }
        if !vec_ok(&self.domain.min)
            || !vec_ok(&self.domain.max)
            || (0..d).any(|k| self.domain.min[k] >= self.domain.max[k])
        {
            return Err(err(
                "domain",
                "`min` and `max` as 2-component points with min < max (m)",
            ));
        }
        // The domain is where particles may be: what starts outside it would stop the run at once, and its
        // extent sizes the neighbour search (a block placed at 1e6 m passed and failed to allocate).
        let inside = |p: &[f64], margin: f64| {
            (0..d).all(|i| p[i] - margin >= self.domain.min[i] && p[i] + margin <= self.domain.max[i])
        };
        for (k, w) in self.walls.iter().enumerate() {
            if w.points.len() < 2 || !w.points.iter().all(vec_ok) {
                return Err(err(
                    &format!("walls[{k}].points"),
                    "at least two 2-component points (m)",
                ));
            }
            if !w.points.iter().all(|p| inside(p, 0.0)) {
                return Err(err(&format!("walls[{k}].points"), "points inside the domain (m)"));
            }
            if w.points
                .windows(2)
                .any(|p| (p[0][0] - p[1][0]).hypot(p[0][1] - p[1][1]) == 0.0)
            {
                return Err(err(&format!("walls[{k}].points"), "no repeated consecutive points"));
            }
            if let Some(v) = &w.velocity {
                if !vec_ok(v) {
                    return Err(err(&format!("walls[{k}].velocity"), "a 2-component velocity in m/s"));
                }
            }
            if let Err((field, expected)) = super::wall_motion::check(k, w) {
                return Err(err(&field, &expected));
            }
        }
        self.check_phases(file)?;
        if self.blocks.is_empty() {
            return Err(err("blocks", "at least one fluid block"));
        }
        for (k, b) in self.blocks.iter().enumerate() {
            let (vel, grad) = match b {
                BlockSpec::Rectangle {
                    min,
                    max,
                    velocity,
                    velocity_gradient,
                    cut,
                    ..
                } => {
                    if !vec_ok(min) || !vec_ok(max) || (0..d).any(|i| min[i] >= max[i]) {
                        return Err(err(
                            &format!("blocks[{k}]"),
                            "`min` < `max`, 2-component points in metres",
                        ));
                    }
                    if !inside(min, 0.0) || !inside(max, 0.0) {
                        return Err(err(&format!("blocks[{k}]"), "a rectangle inside the domain (m)"));
                    }
                    if let Some(c) = cut {
                        if !(c.y.is_finite()
                            && c.amplitude.is_finite()
                            && c.wavelength.is_finite()
                            && c.wavelength > 0.0)
                        {
                            return Err(err(
                                &format!("blocks[{k}].cut"),
                                "finite `y` and `amplitude` (m) and a `wavelength` > 0 (m)",
                            ));
                        }
                    }
                    (velocity, velocity_gradient)
                }
                BlockSpec::Disc {
                    centre,
                    radius,
                    inner_radius,
                    velocity,
                    velocity_gradient,
                    ..
                } => {
                    if !vec_ok(centre) || !pos(*radius) {
                        return Err(err(
                            &format!("blocks[{k}]"),
                            "a 2-component `centre` and a positive `radius` (m)",
                        ));
                    }
                    if !(inner_radius.is_finite() && *inner_radius >= 0.0 && inner_radius < radius) {
                        return Err(err(
                            &format!("blocks[{k}].inner_radius"),
                            "a non-negative inner radius below `radius` (m)",
                        ));
                    }
                    if !inside(centre, *radius) {
                        return Err(err(&format!("blocks[{k}]"), "a disc inside the domain (m)"));
                    }
                    (velocity, velocity_gradient)
                }
            };
            if let Some(v) = vel {
                if !vec_ok(v) {
                    return Err(err(&format!("blocks[{k}].velocity"), "a 2-component velocity (m/s)"));
                }
            }
            if let Some(g) = grad {
                if g.len() != d || !g.iter().all(vec_ok) {
                    return Err(err(
                        &format!("blocks[{k}].velocity_gradient"),
                        "a 2×2 matrix [[a, b], [c, d]] in 1/s",
                    ));
                }
            }
        }
        for (k, p) in self.probes.pressure.iter().enumerate() {
            let direction_ok = match &p.direction {
                Some(d) => vec_ok(d) && (d[0].hypot(d[1]) - 1.0).abs() <= 1e-6,
                None => !p.in_fluid,
            };
            if !vec_ok(&p.position) || !direction_ok {
                return Err(err(
                    &format!("probes.pressure[{k}]"),
                    "a 2-component `position` (m) and a unit `direction` (which a probe `in_fluid` needs)",
                ));
            }
            if !(p.size.is_finite() && p.size >= 0.0) {
                return Err(err(
                    &format!("probes.pressure[{k}].size"),
                    "a non-negative sensor size (m)",
                ));
            }
        }
        for (k, g) in self.probes.gauge.iter().enumerate() {
            if !(g.x.is_finite() && g.x > self.domain.min[0] && g.x < self.domain.max[0]) {
                return Err(err(
                    &format!("probes.gauge[{k}].x"),
                    &format!(
                        "an abscissa inside the domain, between {} and {} m",
                        self.domain.min[0], self.domain.max[0]
                    ),
                ));
            }
            if let Some(Err(expected)) = g.moves_with.as_ref().map(|w| self.wall_named(w)) {
                return Err(err(&format!("probes.gauge[{k}].moves_with"), &expected));
            }
            let (lo, hi) = (self.domain.min[d - 1], self.domain.max[d - 1]);
            if let Some(b) = g.bottom {
                if !(b.is_finite() && b >= lo && b < hi) {
                    return Err(err(
                        &format!("probes.gauge[{k}].bottom"),
                        &format!("a floor height inside the domain, between {lo} and {hi} m"),
                    ));
                }
            }
        }
        for (k, p) in self.probes.pressure.iter().enumerate() {
            if !inside(&p.position, 0.0) {
                return Err(err(
                    &format!("probes.pressure[{k}].position"),
                    "a point inside the domain (m), on a wall",
                ));
            }
            if !p.in_fluid {
                if let Err((field, expected)) = super::sensor_placement::place(self, k, p) {
                    return Err(err(&field, &expected));
                }
            }
        }
        let columns = self.probe_columns();
        for (k, r) in self.references.iter().enumerate() {
            if !columns.contains(&r.column) {
                return Err(err(
                    &format!("references[{k}].column"),
                    &format!(
                        "a series column of one of the case's probes or gauges ({})",
                        if columns.is_empty() {
                            "the case has none".to_string()
                        } else {
                            columns.join(", ")
                        }
                    ),
                ));
            }
            if r.file.trim().is_empty() {
                return Err(err(&format!("references[{k}].file"), "a CSV file name"));
            }
            if r.time != "t" && r.time != "t_star" {
                return Err(err(&format!("references[{k}].time"), "\"t\" (s) or \"t_star\""));
            }
            if !(r.shift.is_finite() && r.scale.is_finite() && r.scale != 0.0) {
                return Err(err(
                    &format!("references[{k}]"),
                    "a finite `shift` and a finite, non-zero `scale`",
                ));
            }
            if let Some([a, b]) = r.window {
                if !(a.is_finite() && b.is_finite() && a < b) {
                    return Err(err(&format!("references[{k}].window"), "[start, end] with start < end"));
                }
            }
            if let Some(t) = r.tolerance {
                if !(t.is_finite() && t >= 0.0) {
                    return Err(err(&format!("references[{k}].tolerance"), "a non-negative number"));
                }
            }
        }
        if let Some(c) = &self.probes.cavity {
            if !(c.after.is_finite() && c.after >= 0.0) {
                return Err(err("probes.cavity.after", "a non-negative time (in output.time_unit)"));
            }
        }
        if !pos(self.output.end_time) {
            return Err(err(
                "output.end_time",
                "a positive end time (in output.time_unit: seconds, or t_star)",
            ));
        }
        if !pos(self.output.series_every) {
            return Err(err(
                "output.series_every",
                "a positive sampling interval (in output.time_unit)",
            ));
        }
        if !(self.output.vtk_every.is_finite() && self.output.vtk_every >= 0.0) {
            return Err(err(
                "output.vtk_every",
                "a non-negative interval (in output.time_unit; 0: no snapshots)",
            ));
        }
        Ok(())
    }

    /// |g| for the non-dimensional scales (1 without gravity).
    pub fn gravity_magnitude(&self) -> f64 {
        match &self.body_force {
            BodyForceSpec::Gravity { g } => g.iter().map(|x| x * x).sum::<f64>().sqrt(),
            _ => 1.0,
        }
    }

    /// Speed of sound c0 (m/s).
    pub fn c0(&self) -> f64 {
        match (self.fluid.c0, self.fluid.c0_over_sqrt_g_length) {
            (Some(c), _) => c,
            (None, Some(f)) => f * (self.gravity_magnitude() * self.scales.length).sqrt(),
            _ => unreachable!("checked in parse"),
        }
    }
}

/// The series columns of a pressure probe: the reading (`p_`, Pa; `pstar_`, over ρgL), and for a wall sensor
/// the peak since the previous row (`ppeak_`, `pstarpeak_`) and the impulse ∫ p dt over that interval
/// (`pimpulse_`, Pa s), from every time step.
pub fn pressure_columns(p: &PressureProbe) -> Vec<String> {
    let mut c = vec![format!("p_{}", p.name), format!("pstar_{}", p.name)];
    if !p.in_fluid {
        c.extend([
            format!("ppeak_{}", p.name),
            format!("pstarpeak_{}", p.name),
            format!("pimpulse_{}", p.name),
        ]);
    }
    c
}

/// Whether two blocks share area (rectangles and discs or annuli; a disc inside an annulus's hole does not).
fn blocks_overlap(a: &BlockSpec, b: &BlockSpec) -> bool {
    // A rectangle as (min, max), a disc as (centre, inner radius, radius).
    enum Shape {
        Rect([f64; 2], [f64; 2]),
        Disc([f64; 2], f64, f64),
    }
    let shape = |s: &BlockSpec| match s {
        BlockSpec::Rectangle { min, max, .. } => Shape::Rect([min[0], min[1]], [max[0], max[1]]),
        BlockSpec::Disc {
            centre,
            radius,
            inner_radius,
            ..
        } => Shape::Disc([centre[0], centre[1]], *inner_radius, *radius),
    };
    // Two rectangles cut by the same curve, one kept below it and one above, share no area.
    if let (BlockSpec::Rectangle { cut: Some(ca), .. }, BlockSpec::Rectangle { cut: Some(cb), .. }) = (a, b) {
        if (ca.y, ca.amplitude, ca.wavelength) == (cb.y, cb.amplitude, cb.wavelength) && ca.keep != cb.keep {
            return false;
        }
    }
    let eps = 1e-12;
    match (shape(a), shape(b)) {
        (Shape::Rect(lo1, hi1), Shape::Rect(lo2, hi2)) => (0..2).all(|k| lo1[k].max(lo2[k]) < hi1[k].min(hi2[k]) - eps),
        (Shape::Disc(c1, i1, r1), Shape::Disc(c2, i2, r2)) => {
            let d = (c1[0] - c2[0]).hypot(c1[1] - c2[1]);
            // Concentric rings overlap when their radial ranges do; others when the discs meet and neither
            // lies inside the other's hole.
            if d < eps {
                i1.max(i2) < r1.min(r2) - eps
            } else {
                d < r1 + r2 - eps && d + r2 > i1 + eps && d + r1 > i2 + eps
            }
        }
        (Shape::Rect(lo, hi), Shape::Disc(c, inner, r)) | (Shape::Disc(c, inner, r), Shape::Rect(lo, hi)) => {
            let near = [c[0].clamp(lo[0], hi[0]), c[1].clamp(lo[1], hi[1])];
            let far = [
                if c[0] - lo[0] > hi[0] - c[0] { lo[0] } else { hi[0] },
                if c[1] - lo[1] > hi[1] - c[1] { lo[1] } else { hi[1] },
            ];
            (near[0] - c[0]).hypot(near[1] - c[1]) < r - eps && (far[0] - c[0]).hypot(far[1] - c[1]) > inner + eps
        }
    }
}

#[cfg(test)]
mod tests {
    /// Regression: `#[serde(default)]` on `kernel_table` gave `false` to every case file that did not name it,
    /// so the built-in cases kept the exact kernel after the table became the default.
    #[test]
    fn case_file_without_kernel_table_gets_the_tabulated_default() {
        for name in crate::cases::builtin::builtin_names() {
            let c = crate::cases::load(name).unwrap();
            assert!(c.numerics.kernel_table, "{name}");
            assert_eq!(c.numerics.kernel_table, super::Numerics::default().kernel_table);
        }
    }
}
