//! The one declaration of a 2D+t case (thesis §10.1): every option of a run, its default and its check.
//!
//! The same struct is the `bowwave twodt` options (clap, flattened; each doc comment is its `--help`), a
//! study file's `[config]` table and per-case overrides (serde, unknown keys refused), and what the manifest
//! and a finished case's `case.json` record. A TOML key is the CLI option's name with `-` written `_`
//! (`--give-up-at` is `give_up_at`). Defaults live in [`TwoDtConfig::default`] only; clap reads them from
//! there. Lengths are in units of the ship length L, speeds in √(gL).

use crate::sph::density_diffusion::DensityDiffusion;
use crate::sph::main_loop::GradientStage;
use crate::sph::particle_shifting::ParticleShifting;
use serde::{Deserialize, Serialize};

/// A value written as one of a few words or as a number: [`Until`] and [`PlungeCirculation`], on the
/// command line (`FromStr`, `Display`) and in TOML and JSON (a string or a number).
pub trait WordOrNumber: Sized + Copy + PartialEq + 'static {
    /// The words and their values.
    const WORDS: &'static [(&'static str, Self)];
    /// What a number means, for the error message.
    const NUMBER: &'static str;
    fn from_number(x: f64) -> Self;
    /// The number, when the value is one.
    fn number(self) -> Option<f64>;

    /// One of the words, or a number; the error says which were expected.
    fn parse_word_or_number(s: &str) -> Result<Self, String> {
        let s = s.trim();
        if let Some((_, v)) = Self::WORDS.iter().find(|(w, _)| *w == s) {
            return Ok(*v);
        }
        s.parse::<f64>()
            .map(Self::from_number)
            .map_err(|_| format!("expected {}, got `{s}`", Self::expected("`")))
    }

    /// What is expected, the words quoted with `quote`.
    fn expected(quote: &str) -> String {
        let words: Vec<String> = Self::WORDS.iter().map(|(w, _)| format!("{quote}{w}{quote}")).collect();
        format!("{} or {}", words.join(", "), Self::NUMBER)
    }

    /// The value's word ("" for a number).
    fn word(self) -> &'static str {
        Self::WORDS.iter().find(|(_, v)| *v == self).map_or("", |(w, _)| w)
    }
}

/// The file form of a [`WordOrNumber`].
#[derive(Serialize, Deserialize)]
#[serde(untagged)]
enum Written {
    Number(f64),
    Word(String),
}

/// `FromStr`, `Display`, `Serialize` and `Deserialize` of a [`WordOrNumber`] type.
macro_rules! word_or_number_impls {
    ($t:ty) => {
        impl std::str::FromStr for $t {
            type Err = String;
            fn from_str(s: &str) -> Result<Self, String> {
                <$t>::parse_word_or_number(s)
            }
        }
        impl std::fmt::Display for $t {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                match self.number() {
                    Some(x) => write!(f, "{x}"),
                    None => f.write_str(self.word()),
                }
            }
        }
        impl Serialize for $t {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                match self.number() {
                    Some(x) => Written::Number(x),
                    None => Written::Word(self.word().to_string()),
                }
                .serialize(s)
            }
        }
        impl<'de> Deserialize<'de> for $t {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                let expected = || format!("expected {}", Self::expected("\""));
                match Written::deserialize(d).map_err(|_| serde::de::Error::custom(expected()))? {
                    Written::Number(x) => Ok(Self::from_number(x)),
                    Written::Word(w) => w.parse().map_err(serde::de::Error::custom),
                }
            }
        }
    };
}

/// Where a run stops: `plunge`, `transom` or an x/L value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Until {
    /// Shortly after the plunge is detected ([`TwoDtConfig::after_plunge`] further in x/L).
    Plunge,
    /// At the transom (end of the hull).
    Transom,
    /// At this x/L.
    X(f64),
}

impl WordOrNumber for Until {
    const WORDS: &'static [(&'static str, Self)] = &[("plunge", Until::Plunge), ("transom", Until::Transom)];
    const NUMBER: &'static str = "an x/L value";
    fn from_number(x: f64) -> Self {
        Until::X(x)
    }
    fn number(self) -> Option<f64> {
        match self {
            Until::X(x) => Some(x),
            _ => None,
        }
    }
}

word_or_number_impls!(Until);

/// Whether the initial rows are packed (thesis chapter 6, `sph::packing`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Packing {
    /// Pack graded rows (`ratio` > 1), whose lattice otherwise relaxes with spurious flow; leave uniform
    /// rows, a lattice already at rest.
    #[default]
    Auto,
    On,
    Off,
}

impl Packing {
    /// Whether rows graded by `coarse_ratio` are packed.
    pub fn applies(self, coarse_ratio: f64) -> bool {
        match self {
            Packing::Auto => coarse_ratio > 1.0,
            Packing::On => true,
            Packing::Off => false,
        }
    }
}

impl std::str::FromStr for Packing {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "auto" => Ok(Packing::Auto),
            "on" => Ok(Packing::On),
            "off" => Ok(Packing::Off),
            v => Err(format!("expected `auto`, `on` or `off`, got `{v}`")),
        }
    }
}

impl std::fmt::Display for Packing {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Packing::Auto => "auto",
            Packing::On => "on",
            Packing::Off => "off",
        })
    }
}

/// Plunge criterion 5 of docs/reference/jet-metrics.md: the least circulation Γ/(UD) around a closed
/// cavity, or off.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlungeCirculation {
    Off,
    AtLeast(f64),
}

impl PlungeCirculation {
    /// The threshold, `None` when the criterion is off.
    pub fn threshold(self) -> Option<f64> {
        self.number()
    }
}

impl WordOrNumber for PlungeCirculation {
    const WORDS: &'static [(&'static str, Self)] = &[("off", PlungeCirculation::Off)];
    const NUMBER: &'static str = "a number Γ/(UD)";
    fn from_number(g: f64) -> Self {
        PlungeCirculation::AtLeast(g)
    }
    fn number(self) -> Option<f64> {
        match self {
            PlungeCirculation::AtLeast(g) => Some(g),
            PlungeCirculation::Off => None,
        }
    }
}

word_or_number_impls!(PlungeCirculation);

/// The defaults, for clap's `default_value_t` (the one place they are written is [`TwoDtConfig::default`]).
fn d() -> TwoDtConfig {
    TwoDtConfig::default()
}

/// Every option of a 2D+t case. Lengths in units of L.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, clap::Args)]
#[serde(default, deny_unknown_fields)]
pub struct TwoDtConfig {
    /// Ship Froude number U/√(gL).
    #[arg(long, default_value_t = d().fr)]
    pub fr: f64,
    /// Fine particle spacing dx/L near the free surface (default: from H_pj/dx > 20, eq. 10.9, with the
    /// bow-wave height estimated from Table 10.1; `scene::auto_dx`). Each kind of run declares its own
    /// resolution (`twodt --dx`, `converge twodt --dx` a ladder, a study's `[resolution]`), so it is no
    /// option of the flattened set.
    #[arg(skip)]
    pub dx: Option<f64>,
    /// Coarse spacing below the transition, as a multiple of dx, in [1, 4] (constant h; 1 = uniform).
    /// Default 1.5, packed: 42 % fewer particles for the same crest within 0.5 % (docs/reference/twodt.md).
    #[arg(long = "ratio", value_name = "R", default_value_t = d().coarse_ratio)]
    #[serde(rename = "ratio")]
    pub coarse_ratio: f64,
    /// Domain width W as a multiple of the beam B (thesis §10.1.2: 4).
    #[arg(long = "width", value_name = "W_OVER_B", default_value_t = d().width_over_beam)]
    #[serde(rename = "width")]
    pub width_over_beam: f64,
    /// Water depth Z as a multiple of the draft D (thesis §10.1.2 and appendix D: 2).
    #[arg(long = "depth", value_name = "Z_OVER_D", default_value_t = d().depth_over_draft)]
    #[serde(rename = "depth")]
    pub depth_over_draft: f64,
    /// Depth of the fine layer below the calm level, as a multiple of D (thesis §10.1.2: 0.2).
    #[arg(long = "fine-depth", value_name = "D1_OVER_D", default_value_t = d().fine_depth_over_draft)]
    #[serde(rename = "fine_depth")]
    pub fine_depth_over_draft: f64,
    /// Height of the coarse layer above the bottom, as a multiple of D (thesis §10.1.2: 1).
    #[arg(long = "coarse-height", value_name = "D2_OVER_D", default_value_t = d().coarse_height_over_draft)]
    #[serde(rename = "coarse_height")]
    pub coarse_height_over_draft: f64,
    /// x/L of the section at the start (default: the stem). A value before the stem runs the tank alone
    /// until the stem arrives.
    #[arg(long)]
    pub x0: Option<f64>,
    /// Where to stop: `plunge` (shortly after it), `transom`, or an x/L value (e.g. 1.3 for stern waves).
    #[arg(long, default_value_t = d().until)]
    pub until: Until,
    /// With `until = plunge`: the x/L at which to give up if nothing has plunged (default: the transom).
    #[arg(long)]
    pub give_up_at: Option<f64>,
    /// x/L run on after the plunge when `until = plunge`.
    #[arg(long, default_value_t = d().after_plunge)]
    pub after_plunge: f64,
    /// Sound speed / √(gL) (default: 10 × the expected largest velocity, `scene::expected_max_speed`;
    /// thesis §4.1, Mach ≤ 0.1).
    #[arg(long)]
    pub c0: Option<f64>,
    /// Damped settling before the ship starts, in acoustic crossings of the depth (Z/c0); with `--air`, three
    /// times as many (`scene::AIR_SETTLE_FACTOR`).
    #[arg(long = "settle", value_name = "CROSSINGS", default_value_t = d().settle_crossings)]
    #[serde(rename = "settle")]
    pub settle_crossings: f64,
    /// Free-surface detection and plunge check every this many steps.
    #[arg(long, default_value_t = d().detect_every)]
    pub detect_every: usize,
    /// Optional plunge criterion 3 (ours, off by default): a closed air cavity counts as the plunge only if
    /// its lowest point lies below this fraction of the crest height, e.g. 0.5 (docs/reference/jet-metrics.md).
    #[arg(long)]
    pub plunge_depth: Option<f64>,
    /// Plunge criterion 5: a closed air cavity counts as the plunge only if the circulation around it,
    /// Γ/(UD), is at least this (clockwise positive: a jet overturning away from the hull; the thesis,
    /// §10.1.3, has "a net circulation around this formed closed cavity"), or `off` (docs/reference/jet-metrics.md).
    #[arg(long, default_value_t = d().plunge_circulation)]
    pub plunge_circulation: PlungeCirculation,
    /// x/L between outputs (series row, η(y) profile, VTK frame).
    #[arg(long, default_value_t = d().output_dx)]
    pub output_dx: f64,
    /// Density diffusion: delta-sph (eq. 5.2), molteni-colagrossi (5.4) or none (standard WCSPH), for
    /// method comparisons.
    #[arg(long, default_value_t = d().diffusion)]
    pub diffusion: DensityDiffusion,
    /// The state each RK stage's renormalised density gradient (the δ-term's) is taken at: own (the thesis's)
    /// or previous (after a step's first stage the previous stage's, one pass over the pairs a stage instead of
    /// two; `sph::main_loop::GradientStage`, BENCHMARKS.md session 51).
    #[arg(long, default_value_t = d().gradient_stage)]
    pub gradient_stage: GradientStage,
    /// Particle shifting after each step: sun2017-walls (the shift of Sun et al. 2017 only within two kernel
    /// supports of a wall, away from the free surface: it removes the fixed ghosts' over-pressure where the
    /// flow leaves a wall or turns a corner, as the run-up does at the keel), sun2017-leaving (the same only
    /// where the flow leaves a wall; the default), sun2017 (everywhere, δ⁺-SPH) or none (the thesis's δ-SPH).
    /// Default: sun2017-leaving, or none with --air (docs/reference/method.md,
    /// "Particle shifting"; docs/decisions/wall-leaving-shifting.md).
    #[arg(long)]
    pub shifting: Option<ParticleShifting>,
    /// Evaluate the Gaussian kernel's gradient at every pair instead of from its table in r² (the table
    /// changes positions by about 1e-6 dx for 10–25 % less CPU; docs/reference/speed-accuracy.md).
    #[arg(long)]
    pub exact_kernel: bool,
    /// CFL number of eq. (4.22) (default: the integrator's, RK4 2.0).
    #[arg(long)]
    pub cfl: Option<f64>,
    /// Artificial viscosity α of eq. (4.11), dimensionless: ν = α h c0 / 8 in 2D, so that doubling `--c0`
    /// doubles ν unless α is halved (default: the solver's 0.02, docs/decisions/viscosity.md; the thesis,
    /// §4.1.1, needs α > 0.01 for stability).
    #[arg(long)]
    pub alpha: Option<f64>,
    /// Pack the initial particles (thesis chapter 6: moved along −∇Γ inside the tank closed by a lid at the
    /// calm level) before the damped settling: auto (when ratio > 1), on, or off.
    #[arg(long, default_value_t = d().packing)]
    pub packing: Packing,
    /// An air layer of this height above the calm level, as a multiple of D, up to its own free surface: the
    /// multi-fluid δ-SPH of Hammani et al. (`sph::multi_fluid`), air at the fine spacing. Default: none, one
    /// phase (the thesis's 2D+t). The layer need be no deeper than the jet rises (H_pj, about 0.5–0.9 D):
    /// air matters once the jet traps it, and the air's sound speed (eq. 23: the water's stiffness, 14 c0 at
    /// a density ratio of 1000) makes the time step about 14 times smaller (docs/reference/twodt.md, "Air").
    #[arg(long, value_name = "H_OVER_D")]
    pub air: Option<f64>,
    /// Density of the air layer / that of the water (default 0.001, the ratio Hammani et al. and Grenier et al.
    /// use for air and water; at 15 °C it is 0.00123). Read only with `--air`.
    #[arg(long, value_name = "RATIO", default_value_t = d().air_density)]
    pub air_density: f64,
    /// With `--air`: the background pressure of the multi-fluid model (Hammani et al. eq. 10), as a fraction
    /// of the largest hydrostatic pressure ρ_w g Z (their §III.A: 0.1). Read only with `--air`.
    #[arg(long, value_name = "FRACTION", default_value_t = d().air_background)]
    pub air_background: f64,
    /// Write VTK frames (.vtp + .pvd for ParaView) at every output.
    #[arg(long)]
    pub vtk: bool,
    /// Write a PNG of the bow region at every output.
    #[arg(long)]
    pub frames: bool,
}

impl Default for TwoDtConfig {
    fn default() -> Self {
        TwoDtConfig {
            fr: 0.5,
            dx: None,
            coarse_ratio: 1.5,
            width_over_beam: 4.0,
            depth_over_draft: 2.0,
            fine_depth_over_draft: 0.2,
            coarse_height_over_draft: 1.0,
            x0: None,
            until: Until::Plunge,
            give_up_at: None,
            after_plunge: 0.01,
            c0: None,
            settle_crossings: 1.0,
            detect_every: 10,
            plunge_depth: None,
            plunge_circulation: PlungeCirculation::AtLeast(0.02),
            output_dx: 0.005,
            diffusion: DensityDiffusion::DeltaSph,
            gradient_stage: GradientStage::Own,
            shifting: None,
            exact_kernel: false,
            cfl: None,
            alpha: None,
            packing: Packing::Auto,
            air: None,
            air_density: 1e-3,
            air_background: 0.1,
            vtk: false,
            frames: false,
        }
    }
}

/// The options of [`TwoDtConfig`] that [`TwoDtConfig::check`] checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConfigOption {
    Fr,
    CoarseRatio,
    WidthOverBeam,
    DepthOverDraft,
    C0,
    Cfl,
    Alpha,
    Settle,
    OutputDx,
    AfterPlunge,
    DetectEvery,
    Until,
    Layers,
    GiveUpAt,
    PlungeDepth,
    PlungeCirculation,
    Air,
    AirDensity,
    AirBackground,
}

impl ConfigOption {
    /// The option's key: the TOML key of a study file's `[config]`, and the CLI's `--key` with `_` as `-`.
    pub fn key(self) -> &'static str {
        match self {
            ConfigOption::Fr => "fr",
            ConfigOption::CoarseRatio => "ratio",
            ConfigOption::WidthOverBeam => "width",
            ConfigOption::DepthOverDraft => "depth",
            ConfigOption::C0 => "c0",
            ConfigOption::Cfl => "cfl",
            ConfigOption::Alpha => "alpha",
            ConfigOption::Settle => "settle",
            ConfigOption::OutputDx => "output_dx",
            ConfigOption::AfterPlunge => "after_plunge",
            ConfigOption::DetectEvery => "detect_every",
            ConfigOption::Until => "until",
            ConfigOption::Layers => "fine_depth and coarse_height",
            ConfigOption::GiveUpAt => "give_up_at",
            ConfigOption::PlungeDepth => "plunge_depth",
            ConfigOption::PlungeCirculation => "plunge_circulation",
            ConfigOption::Air => "air",
            ConfigOption::AirDensity => "air_density",
            ConfigOption::AirBackground => "air_background",
        }
    }

    /// What the option is, in words.
    pub fn describe(self) -> &'static str {
        match self {
            ConfigOption::Fr => "Froude number",
            ConfigOption::CoarseRatio => "coarse ratio dx_c/dx_f",
            ConfigOption::WidthOverBeam => "domain width W/B",
            ConfigOption::DepthOverDraft => "water depth Z/D",
            ConfigOption::C0 => "c0/√(gL)",
            ConfigOption::Cfl => "CFL",
            ConfigOption::Alpha => "artificial viscosity α",
            ConfigOption::Settle => "settling",
            ConfigOption::OutputDx => "output spacing x/L",
            ConfigOption::AfterPlunge => "run-on after the plunge x/L",
            ConfigOption::DetectEvery => "detection interval",
            ConfigOption::Until => "end point x/L",
            ConfigOption::Layers => "fine layer depth and coarse layer height / D",
            ConfigOption::GiveUpAt => "give-up point x/L",
            ConfigOption::PlungeDepth => "plunge depth",
            ConfigOption::PlungeCirculation => "plunge circulation Γ/(UD)",
            ConfigOption::Air => "air layer height / D",
            ConfigOption::AirDensity => "air density / water density",
            ConfigOption::AirBackground => "background pressure / ρ_w g Z",
        }
    }
}

/// A [`TwoDtConfig`] value out of range: which option, what was expected, what was given.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("`{}` ({}): expected {expected}, got {got}", option.key(), option.describe())]
pub struct ConfigError {
    pub option: ConfigOption,
    pub expected: &'static str,
    pub got: String,
}

impl TwoDtConfig {
    /// Checks the values that need no hull (the spacing and the tank's size are checked by
    /// the scene's `build`, against the hull's draft and beam): each error names the option and what
    /// was expected. The CLI, study files and the library all pass through here.
    pub fn check(&self) -> Result<(), ConfigError> {
        use ConfigOption as O;
        let positive = |v: f64| v.is_finite() && v > 0.0;
        let non_negative = |v: f64| v.is_finite() && v >= 0.0;
        let fail = |option, expected, got: &dyn std::fmt::Display| {
            Err(ConfigError {
                option,
                expected,
                got: got.to_string(),
            })
        };
        if !(positive(self.fr) && self.fr < 3.0) {
            return fail(O::Fr, "in (0, 3)", &self.fr);
        }
        if !(self.coarse_ratio >= 1.0 && self.coarse_ratio <= 4.0) {
            return fail(O::CoarseRatio, "in [1, 4]", &self.coarse_ratio);
        }
        if !(self.width_over_beam >= 1.0 && self.width_over_beam.is_finite()) {
            return fail(O::WidthOverBeam, "≥ 1", &self.width_over_beam);
        }
        if !(self.depth_over_draft > 1.0 && self.depth_over_draft.is_finite()) {
            return fail(O::DepthOverDraft, "> 1", &self.depth_over_draft);
        }
        if let Some(c0) = self.c0.filter(|&c| !positive(c)) {
            return fail(O::C0, "> 0", &c0);
        }
        if let Some(cfl) = self.cfl.filter(|&c| !positive(c)) {
            return fail(O::Cfl, "> 0", &cfl);
        }
        if let Some(alpha) = self.alpha.filter(|&a| !non_negative(a)) {
            return fail(O::Alpha, "0 or more", &alpha);
        }
        if !non_negative(self.settle_crossings) {
            return fail(O::Settle, "0 or more acoustic crossings", &self.settle_crossings);
        }
        if !positive(self.output_dx) {
            return fail(O::OutputDx, "> 0", &self.output_dx);
        }
        if !non_negative(self.after_plunge) {
            return fail(O::AfterPlunge, "0 or more", &self.after_plunge);
        }
        if self.detect_every == 0 {
            return fail(O::DetectEvery, "at least 1 step", &0);
        }
        if !(positive(self.fine_depth_over_draft) && positive(self.coarse_height_over_draft)) {
            let got = format!("{} and {}", self.fine_depth_over_draft, self.coarse_height_over_draft);
            return fail(O::Layers, "> 0", &got);
        }
        // x/L is measured from the stem, and a run may start before it (a still tank ahead of the ship), so an
        // end point or give-up point below 0 is a valid, if short, run; only a value that is no number is not.
        if let Until::X(x) = self.until {
            if !x.is_finite() {
                return fail(O::Until, "`plunge`, `transom` or an x/L value", &x);
            }
        }
        if let Some(x) = self.give_up_at.filter(|x| !x.is_finite()) {
            return fail(O::GiveUpAt, "an x/L value", &x);
        }
        if let Some(d) = self.plunge_depth.filter(|&d| !(d.is_finite() && d > 0.0 && d <= 1.0)) {
            return fail(O::PlungeDepth, "in (0, 1]", &d);
        }
        if let Some(g) = self.plunge_circulation.threshold().filter(|g| !g.is_finite()) {
            return fail(O::PlungeCirculation, "`off` or a number", &g);
        }
        // Thinner than a few spacings it holds no air worth the name, but the spacing is the scene's: the
        // layer's particle count is checked there.
        if let Some(a) = self.air.filter(|&a| !(positive(a) && a <= 10.0)) {
            return fail(O::Air, "in (0, 10]", &a);
        }
        // A light phase: lighter than half the water (the equal-stiffness sound speed of eq. 23 grows as
        // 1/√ratio, and 1e-4 already makes the step 45 times smaller than one phase's).
        if !(self.air_density >= 1e-4 && self.air_density <= 0.5) {
            return fail(O::AirDensity, "in [1e-4, 0.5]", &self.air_density);
        }
        if !(self.air_background >= 0.0 && self.air_background <= 10.0) {
            return fail(O::AirBackground, "in [0, 10]", &self.air_background);
        }
        if self.air.is_some() && self.shifting.is_some_and(|s| s != ParticleShifting::None) {
            return fail(
                O::Air,
                crate::sph::particle_shifting::WITH_PHASES,
                &"an air layer with particle shifting",
            );
        }
        Ok(())
    }

    /// The particle shifting the run uses: `shifting`, or when unset the default for one phase or, with `air`,
    /// two ([`crate::sph::particle_shifting::default_for`]).
    pub fn shifting(&self) -> ParticleShifting {
        self.shifting
            .unwrap_or_else(|| crate::sph::particle_shifting::default_for(self.air.is_some()))
    }

    /// The same configuration without the packing: for building a scene whose particles come from elsewhere
    /// (a checkpoint) or are only counted (a dry run). The packing moves particles inside the tank; it adds
    /// none and removes none, except for the rare particle it moves across the section's edge when a run
    /// starts inside the hull.
    pub fn unpacked(&self) -> TwoDtConfig {
        TwoDtConfig {
            packing: Packing::Off,
            ..self.clone()
        }
    }

    /// The configuration with the output-only options (VTK, frames) at their defaults: what a checkpoint or
    /// a finished spacing of a convergence ladder must match to be reused (writing frames or not does not
    /// change the run).
    /// The shifting is written resolved (`Some`): a checkpoint of the thesis's method, saved when no shifting
    /// was the default, is not taken for one of today's default.
    pub fn physics(&self) -> TwoDtConfig {
        TwoDtConfig {
            vtk: false,
            frames: false,
            shifting: Some(self.shifting()),
            ..self.clone()
        }
    }

    /// This configuration with the keys of `overrides` (a study file's `[config]` or `[case.N]` table, in
    /// the same keys) replaced; an unknown key or a value of the wrong kind is an error that names it.
    pub fn with_overrides(&self, overrides: &toml::Table) -> Result<TwoDtConfig, String> {
        let mut table = toml::Table::try_from(self).map_err(|e| format!("internal: {e}"))?;
        for (k, v) in overrides {
            table.insert(k.clone(), v.clone());
        }
        TwoDtConfig::deserialize(toml::Value::Table(table)).map_err(|e| e.message().to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_default_survives_a_round_trip_through_toml_and_json() {
        let d = TwoDtConfig::default();
        let t = toml::to_string(&d).unwrap();
        assert_eq!(toml::from_str::<TwoDtConfig>(&t).unwrap(), d, "{t}");
        let j = serde_json::to_string(&d).unwrap();
        assert_eq!(serde_json::from_str::<TwoDtConfig>(&j).unwrap(), d, "{j}");
        let set = TwoDtConfig {
            dx: Some(7e-4),
            until: Until::X(0.3),
            give_up_at: Some(0.6),
            plunge_circulation: PlungeCirculation::Off,
            packing: Packing::On,
            diffusion: DensityDiffusion::MolteniColagrossi,
            gradient_stage: GradientStage::Previous,
            ..d
        };
        let t = toml::to_string(&set).unwrap();
        assert_eq!(toml::from_str::<TwoDtConfig>(&t).unwrap(), set, "{t}");
    }

    /// Regression (session 48): the default shifting became the near-wall band while an unset shifting kept
    /// the Debug text `None`, the text of the old default `ParticleShifting::None`: an unshifted checkpoint would
    /// have been resumed with the band.
    #[test]
    fn a_checkpoint_of_the_old_unshifted_default_is_not_taken_for_todays_default() {
        let old_default = format!("{:?}", ParticleShifting::None);
        let today = format!("{:?}", TwoDtConfig::default().physics().shifting);
        assert_ne!(today, old_default);
        assert!(today.contains("Sun2017Leaving"), "{today}");
        // Nor a checkpoint of the band, the default of sessions 48–49.
        assert_ne!(today, format!("{:?}", Some(ParticleShifting::Sun2017Walls)));
        let explicit = TwoDtConfig {
            shifting: Some(ParticleShifting::Sun2017Leaving),
            ..Default::default()
        };
        assert_eq!(explicit.physics(), TwoDtConfig::default().physics());
        let air = TwoDtConfig {
            air: Some(1.5),
            ..Default::default()
        };
        assert_eq!(air.physics().shifting, Some(ParticleShifting::None));
    }

    #[test]
    fn until_reads_words_and_numbers_and_names_a_bad_value() {
        assert_eq!("plunge".parse::<Until>(), Ok(Until::Plunge));
        assert_eq!("transom".parse::<Until>(), Ok(Until::Transom));
        assert_eq!("0.3".parse::<Until>(), Ok(Until::X(0.3)));
        assert!("plunj".parse::<Until>().unwrap_err().contains("plunj"));
        let c: TwoDtConfig = toml::from_str("until = 1").unwrap();
        assert_eq!(c.until, Until::X(1.0));
        let e = toml::from_str::<TwoDtConfig>("until = \"plunj\"")
            .unwrap_err()
            .to_string();
        assert!(e.contains("plunj"), "{e}");
    }

    #[test]
    fn an_unknown_key_is_refused_by_name() {
        let e = TwoDtConfig::default()
            .with_overrides(&toml::from_str("ratoi = 2").unwrap())
            .unwrap_err();
        assert!(e.contains("ratoi"), "{e}");
        let c = TwoDtConfig::default()
            .with_overrides(&toml::from_str("ratio = 2\nplunge_circulation = \"off\"").unwrap())
            .unwrap();
        assert_eq!((c.coarse_ratio, c.plunge_circulation), (2.0, PlungeCirculation::Off));
    }
}
