//! `run`, `validate` and `cases`: the solver's cases (built-in or TOML), run, validated or listed.

use crate::options::GhostsArg;
use bowwave::cases::overrides::CaseOverrides;
use bowwave::sph::equations::ghost_conditions::WallSlip;
use bowwave::sph::particle_shifting::ParticleShifting;
use bowwave::{cases, validation};
use clap::Args;
use std::path::PathBuf;

#[derive(Args)]
pub struct RunArgs {
    /// Built-in case name (see `bowwave cases`) or path to a case TOML file.
    #[arg(default_value = "dam-break")]
    pub case: String,
    /// Resolution: reference length / particle spacing (e.g. H/dx for the dam break). Default: the case's.
    #[arg(long)]
    pub res: Option<f64>,
    /// Output folder (default: out/CASE_NAME).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// End time in seconds (default: the case's).
    #[arg(long)]
    pub end: Option<f64>,
    /// Do not write VTK snapshots.
    #[arg(long)]
    pub no_vtk: bool,
    /// No progress bar.
    #[arg(long, short)]
    pub quiet: bool,
    /// Ghosts of every wall's straight sides, overriding the case file: `fixed` (a lattice valued by MLS at
    /// the mirror points, thesis §7.1.1), `images` (mirror images of the fluid particles, Colagrossi &
    /// Landrini 2003; corners keep fixed ghosts) or `normal-flux` (no ghosts: boundary terms on the wall's
    /// surface, thesis §7.1.2 divided by the Shepard sum, free slip, single phase). Default: the case's (fixed
    /// unless it says otherwise).
    #[arg(long, value_enum)]
    pub ghosts: Option<GhostsArg>,
    /// Particle shifting after each step, overriding the case file: `sun2017-walls` (the δ⁺-SPH shift of Sun et
    /// al. 2017 only within two kernel supports of the fixed wall ghosts and away from the free surface, which
    /// removes the ghosts' over-pressure at stagnation points and corners where it comes from), `sun2017-leaving`
    /// (the default of a single-phase case: that band only where the flow leaves a wall, not where it arrives),
    /// `sun2017` (the same shift everywhere) or `none` (the thesis's δ-SPH; the default, and the only choice, with
    /// several phases; docs/reference/method.md, "Particle shifting").
    #[arg(long)]
    pub shifting: Option<ParticleShifting>,
    /// A physical kinematic viscosity ν in m²/s (eq. 5.3) in place of the case's viscosity; e.g. the dam break
    /// at the Reynolds number √(gH) H/ν = 1e4 of thesis §9.3 takes 1.456e-4.
    #[arg(long, value_parser = crate::options::viscosity_nu)]
    pub nu: Option<f64>,
    /// What every wall imposes on the tangential velocity, overriding the case file: `free-slip` (the default,
    /// the thesis's for impact flows) or `no-slip` (the viscous term sees the velocity relative to the wall
    /// reversed, thesis §7.1.3; use it with `--nu`, since the artificial viscosity's ν is thousands of times
    /// water's at laboratory scale).
    #[arg(long)]
    pub wall_slip: Option<WallSlip>,
    /// A method variant applied to the case before the options above, by the names of `chart speed-accuracy
    /// --variants`: delta-sph, molteni, wcsph, wendland (Wendland C2 at h = 2 dx), pc, rk4, table, exact-kernel,
    /// images, fixed-ghosts, normal-flux, normal-flux-thesis, sun2017, sun2017-walls, sun2017-leaving, no-shifting, lagged-gradient, alpha=A, delta=D, cfl=C, h=H
    /// (h/dx), joined by `+` to combine (e.g. `wendland+h=1.4`: Wendland C2 with a 2.8 dx support, half the Gaussian's neighbours).
    #[arg(long)]
    pub variant: Option<String>,
    /// Do not stop the run when its mechanical energy rises by more than 1e-3 of its scale with fixed walls
    /// (by default such a rise is diagnosed as an unstable time integration or a non-conservative term).
    #[arg(long)]
    pub allow_energy_growth: bool,
}

impl RunArgs {
    /// Runs the case; its exit status is non-zero after a blow-up.
    pub fn run(self) -> anyhow::Result<std::process::ExitCode> {
        let mut case = cases::load(&self.case)?;
        CaseOverrides {
            variant: self.variant,
            ghosts: self.ghosts.map(Into::into),
            shifting: self.shifting,
            nu: self.nu,
            wall_slip: self.wall_slip,
        }
        .apply(&mut case)?;
        let out = self.out.unwrap_or_else(|| PathBuf::from("out").join(&case.name));
        let opts = cases::run::RunOptions {
            res: self.res,
            end_time: self.end,
            progress: !self.quiet,
            vtk: !self.no_vtk,
            allow_energy_growth: self.allow_energy_growth,
            ..Default::default()
        };
        let code = validation::run_and_report(&case, &out, opts)?;
        Ok(std::process::ExitCode::from(u8::try_from(code).unwrap_or(1)))
    }
}

#[derive(Args)]
pub struct ValidateArgs {
    /// A built-in case to validate (default: all of them), or `tank-3d`: the still tank in 3D (water H deep in
    /// a 1 × 0.5 H box, to t√(g/H) = 20; default resolution 20, `--ghosts images` for image faces), or
    /// `hull-at-rest`: the Wigley hull as a 3D wall in still water (the 3D ship's tank, U = 0, to t√(g/D) = 20;
    /// `--res` is D/dx, default 8; `--ghosts images` for the tank's faces).
    pub case: Option<String>,
    /// Resolution (reference length / dx); default: each case's validation resolution.
    #[arg(long)]
    pub res: Option<f64>,
    /// Write series and plots of each validation run under this folder.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Ghosts of every wall's straight sides, overriding the case files (see `run --help`).
    #[arg(long, value_enum)]
    pub ghosts: Option<GhostsArg>,
    /// Particle shifting, overriding the case files (see `run --help`).
    #[arg(long)]
    pub shifting: Option<ParticleShifting>,
    /// A physical kinematic viscosity ν (m²/s) in place of the case files' viscosity (see `run --help`).
    #[arg(long, value_parser = crate::options::viscosity_nu)]
    pub nu: Option<f64>,
    /// Free or no slip at every wall, overriding the case files (see `run --help`).
    #[arg(long)]
    pub wall_slip: Option<WallSlip>,
    /// A method variant applied to every 2D case before the options above (see `run --help`), e.g.
    /// `wendland+h=1.4`; the 3D cases refuse it.
    #[arg(long)]
    pub variant: Option<String>,
}

impl ValidateArgs {
    /// Prints the validation table; exit status 1 when a tolerance is missed.
    pub fn run(self) -> anyhow::Result<std::process::ExitCode> {
        let ok = validation::validate_cli(
            self.case.as_deref(),
            self.res,
            self.out.as_deref(),
            &CaseOverrides {
                variant: self.variant,
                ghosts: self.ghosts.map(Into::into),
                shifting: self.shifting,
                nu: self.nu,
                wall_slip: self.wall_slip,
            },
        )?;
        Ok(if ok {
            std::process::ExitCode::SUCCESS
        } else {
            std::process::ExitCode::FAILURE
        })
    }
}

#[derive(Args)]
pub struct CasesArgs {
    /// Print this built-in case's TOML.
    pub name: Option<String>,
}

impl CasesArgs {
    pub fn run(self) -> anyhow::Result<()> {
        match self.name {
            None => {
                for (n, text) in cases::builtin::BUILTIN {
                    let c = cases::CaseFile::parse(text, n)?;
                    println!("{n:18} {}", c.description);
                }
            }
            Some(n) => match cases::builtin::builtin_text(&n) {
                Some(t) => print!("{t}"),
                None => anyhow::bail!(
                    "no built-in case `{n}`; built-ins: {}",
                    cases::builtin::builtin_names().join(", ")
                ),
            },
        }
        Ok(())
    }
}
