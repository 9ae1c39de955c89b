//! `study`: a Froude sweep from a study file, resumable, gathered into tables, figures and a report.

use crate::options::CheckpointArgs;
use bowwave::studies;
use clap::Args;
use std::path::PathBuf;

#[derive(Args)]
pub struct StudyArgs {
    /// Study file, e.g. studies/quick.toml.
    pub file: PathBuf,
    /// Output folder (default out/study-NAME).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Run only case N (1-based, in the order of `froude`), e.g. a batch array index; then collect
    /// whatever is finished.
    #[arg(long)]
    pub case: Option<usize>,
    /// Do not run anything: gather the finished cases into the tables and figures.
    #[arg(long)]
    pub collect: bool,
    /// Recompute finished cases, and start a case in progress afresh (its checkpoint ignored).
    #[arg(long)]
    pub force: bool,
    /// Print each case's particle count, estimated steps and run time, and run nothing.
    #[arg(long)]
    pub dry_run: bool,
    /// Print where each case stands in the output folder (finished with its outcome; stopped part-way with
    /// the x/L its checkpoint reached, its steps, the time spent and the time left to its stop point at its
    /// pace so far; or not started), and run nothing.
    #[arg(long)]
    pub status: bool,
    /// Checkpoints of the case in progress (CASE/checkpoint.bin: an interrupted study loses at most
    /// `--checkpoint-every` of it), and when to stop saved; `--force` ignores checkpoints too.
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
    /// Cases run at the same time, each with threads/jobs worker threads (default 1: every thread inside
    /// one case, measured faster on 2 cores, see docs/reference/studies.md).
    #[arg(long, default_value_t = 1)]
    pub jobs: usize,
    /// No progress bars.
    #[arg(long, short)]
    pub quiet: bool,
}

impl StudyArgs {
    /// Runs the unfinished cases (or only `--case N`), then gathers every finished one and prints the report.
    /// Exit status 3 when a case halted with a checkpoint (run the same command again to go on).
    pub fn run(self) -> anyhow::Result<std::process::ExitCode> {
        let study = studies::study_file::Study::read(&self.file)?;
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from("out").join(format!("study-{}", study.spec.name)));
        if self.dry_run {
            print_dry_run(&study)?;
            return Ok(std::process::ExitCode::SUCCESS);
        }
        if self.status {
            print_status(&study, &out)?;
            return Ok(std::process::ExitCode::SUCCESS);
        }
        let (mut halted_cases, mut not_started) = (vec![], 0);
        if !self.collect {
            let opts = studies::runner::StudyOptions {
                out_dir: out.clone(),
                force: self.force,
                case: self.case,
                jobs: self.jobs,
                threads: rayon::current_num_threads(),
                progress: !self.quiet,
                // `resume` is set per case by the runner (not with --force).
                checkpoint: self.checkpoint.passage_policy(true)?,
            };
            let ran = studies::runner::run_cases(&study, &opts)?;
            println!("{} case(s) run", ran.finished);
            (halted_cases, not_started) = (ran.halted, ran.not_started);
        }
        let n = studies::collect_all(&study, &out)?;
        println!(
            "{n} of {} case(s) finished; tables, report and figures in {}",
            study.cases.len(),
            out.display()
        );
        print!("{}", std::fs::read_to_string(out.join("report.md")).unwrap_or_default());
        if not_started > 0 {
            eprintln!(
                "{not_started} case(s) not started: the wall-time limit had passed; run the same command again to \
                 go on"
            );
        }
        Ok(match halted_cases.first() {
            Some(first) => {
                for h in &halted_cases[1..] {
                    eprintln!("{h}");
                }
                crate::options::halted(first)
            }
            None if not_started > 0 => std::process::ExitCode::from(3),
            None => std::process::ExitCode::SUCCESS,
        })
    }
}

/// `--dry-run`: each case's particle count, estimated steps and run time.
fn print_dry_run(study: &studies::study_file::Study) -> anyhow::Result<()> {
    let est = studies::runner::dry_run(study)?;
    println!(
        "study {} ({} cases), {}",
        study.spec.name,
        est.len(),
        study.hull_path.display()
    );
    println!("case  Fr      dx/L       particles  est. steps  est. time (s)");
    for e in &est {
        println!(
            "{:4}  {:<6}  {:.3e}  {:9}  {:10.0}  {:13.0}",
            e.spec.index,
            e.spec.fr(),
            e.spec.dx(),
            e.particles,
            e.steps,
            e.seconds
        );
        if let Some(p) = &e.ship3d {
            let rate = bowwave::compare3d::towed_ship::MEASURED_THROUGHPUT;
            println!(
                "      3D: {} particles, {} hull ghosts, {:.0}–{:.0} steps, {:.1}–{:.1} h at {rate:.1e} particle-steps/s \
                 (the towed ship's measured rate on 2 threads)",
                p.particles,
                p.hull_ghosts,
                p.steps_min,
                p.steps_max,
                p.particles as f64 * p.steps_min / rate / 3600.0,
                p.particles as f64 * p.steps_max / rate / 3600.0
            );
        }
    }
    println!(
        "total {:.0} s at {:.1e} particle-steps/s (the measured 2D+t throughput on 2 cores; a plunge search \
         is counted to its give-up point, the worst case)",
        est.iter().map(|e| e.seconds).sum::<f64>(),
        studies::runner::REFERENCE_THROUGHPUT
    );
    Ok(())
}

/// `--status`: one line per case.
fn print_status(study: &studies::study_file::Study, out: &std::path::Path) -> anyhow::Result<()> {
    use studies::status::CaseState;
    println!("study {} in {}", study.spec.name, out.display());
    println!("case  Fr      dx/L       state");
    for c in studies::status::status(study, out)? {
        let state = match &c.state {
            CaseState::Finished(rec) => {
                let r = &rec.result;
                let outcome = match (&r.blowup, &r.plunge) {
                    (Some(b), _) => format!("stopped early ({b})"),
                    (None, Some(p)) if r.plunged => format!("plunged at x/L {:.4}", p.x_plunge_over_l),
                    _ => format!("no plunge up to x/L {:.4}", r.x_end_over_l),
                };
                format!(
                    "finished: {outcome}; {} particles, {} steps, {:.0} s wall, build {}",
                    r.particles,
                    r.steps,
                    r.wall_seconds,
                    rec.git_commit.as_deref().unwrap_or("not recorded")
                )
            }
            CaseState::InProgress(p) => {
                let s = &p.saved;
                let pace = if s.setup_seconds > 0.0 {
                    format!(
                        "the pace of its passage so far ({:.2} h of packing and settling before it)",
                        s.setup_seconds / 3600.0
                    )
                } else {
                    "its pace so far (packing included: an older checkpoint)".to_string()
                };
                // A plunge search stops at its give-up point only if nothing plunges: the hours are an upper bound.
                let bound = if c.spec.config.until == bowwave::twodt::config::Until::Plunge && !s.plunged {
                    " (its give-up point: a plunge ends it sooner)"
                } else {
                    ""
                };
                let left = studies::status::remaining_seconds(p)
                    .map(|left| {
                        format!(
                            ", about {:.1} h more to x/L {:.3}{bound} at {pace}",
                            left / 3600.0,
                            s.x_stop
                        )
                    })
                    .unwrap_or_default();
                format!(
                    "{}: checkpoint at x/L {:.4} (from {:.3}), {} steps, {:.2} h wall{}{}",
                    if p.same_configuration {
                        "in progress"
                    } else {
                        "checkpoint of another configuration (a run starts afresh)"
                    },
                    p.x_over_l,
                    p.x_start,
                    s.steps,
                    s.wall_seconds / 3600.0,
                    if s.plunged { ", plunge found" } else { "" },
                    if p.same_configuration { left } else { String::new() },
                )
            }
            CaseState::Ship3dInProgress(p) => format!(
                "{}: {} steps, {:.2} L travelled at the last bow sample, {:.2} h wall",
                if p.same_configuration {
                    "3D run in progress (its 2D+t partner runs again first, to the same bits)"
                } else {
                    "3D checkpoint of another configuration (a run starts afresh)"
                },
                p.steps,
                p.travel_over_l,
                p.wall_seconds / 3600.0
            ),
            CaseState::OtherConfiguration => "finished with another configuration: runs again".into(),
            CaseState::NotStarted => "not started".into(),
        };
        println!("{:4}  {:<6}  {:.3e}  {state}", c.spec.index, c.spec.fr(), c.spec.dx());
    }
    Ok(())
}
