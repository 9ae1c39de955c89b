//! The one run driver: steps a simulation and calls its observers, for every kind of run (a case file, a
//! 2D+t passage, the 3D slab and tank, the wedge check). A kind of run is its set-up plus its observers;
//! the driver owns the loop, so stopping, halting with a checkpoint and blowing up mean the same everywhere.
//!
//! One iteration: every observer looks at the state in turn ([`Observer::observe`]) and says how to go on
//! ([`Flow`]); then, unless one asked otherwise, the simulation takes one step. The first iteration observes
//! the initial state, and the state after the last step is observed before the run stops. When the run
//! ends, every observer's [`Observer::finish`] is called with the [`Outcome`], so that what it gathered is
//! kept whatever happened (a blown-up run writes what it had).

pub mod checkpoint;
pub mod progress;

use crate::sph::solver::BlowUp;
use std::path::PathBuf;

/// Anything the driver can step: a `Simulation` or a kind of run's state around one.
pub trait Stepper {
    /// One time step; a blow-up stops the run with its diagnosis (the state before the step is kept).
    fn step(&mut self) -> Result<(), BlowUp>;
}

impl<const D: usize> Stepper for crate::sph::solver::Simulation<D> {
    fn step(&mut self) -> Result<(), BlowUp> {
        crate::sph::solver::Simulation::step(self).map(|_| ())
    }
}

/// How an observer wants the run to go on.
#[derive(Debug)]
pub enum Flow {
    /// Go on: the next observer, then a step.
    Step,
    /// The run is done: the remaining observers still see this state, then the run finishes.
    Stop,
    /// The observer changed the state (went back to an earlier one): observe again from the first observer,
    /// without stepping.
    Again,
    /// Stop now with the state saved (a wall-time limit).
    Halt(Halted),
    /// Stop now: the run is no longer trustworthy (e.g. its energy grows).
    Fail(BlowUp),
}

/// How a run ended.
#[derive(Debug)]
pub enum Outcome {
    Finished,
    /// Stopped on purpose with a checkpoint; the same command goes on from it.
    Halted(Halted),
    /// Stopped by a blow-up or a failed check, with the diagnosis.
    BlewUp(BlowUp),
}

/// A run stopped on purpose with its state saved: not a failure. The CLI says where it stopped and exits
/// with status 3, which tells a batch script to submit it again.
#[derive(Clone, Debug, thiserror::Error)]
#[error("stopped at {at} after {steps} steps, the state saved in {}: run the same command again to go on", .checkpoint.display())]
pub struct Halted {
    /// Where the run stood, in the run's own words (`x/L = 0.2100`).
    pub at: String,
    pub steps: u64,
    pub checkpoint: PathBuf,
}

/// What a kind of run returns: its result (also after a blow-up, which the result records with its
/// diagnosis), or where it halted with a checkpoint.
#[derive(Debug)]
pub enum Ended<T> {
    Ran(T),
    Halted(Halted),
}

impl<T> Ended<T> {
    /// The result, or the halt as an error (for callers that set no wall-time limit).
    pub fn ran(self) -> anyhow::Result<T> {
        match self {
            Ended::Ran(t) => Ok(t),
            Ended::Halted(h) => Err(h.into()),
        }
    }
}

/// Looks at the state of a run before each step.
pub trait Observer<R> {
    /// Called before every step, and once more on the state the run stops at.
    fn observe(&mut self, run: &mut R) -> anyhow::Result<Flow>;
    /// Called once when the run ends, whatever the outcome.
    fn finish(&mut self, _run: &mut R, _outcome: &Outcome) -> anyhow::Result<()> {
        Ok(())
    }
}

/// Steps `run` until an observer stops it, halts it or it blows up; an error of an observer (an output that
/// cannot be written) ends the run with that error.
pub fn drive<R: Stepper>(run: &mut R, observers: &mut [&mut dyn Observer<R>]) -> anyhow::Result<Outcome> {
    let outcome = 'run: loop {
        let mut stop = false;
        for o in observers.iter_mut() {
            match o.observe(run)? {
                Flow::Step => {}
                Flow::Stop => stop = true,
                Flow::Again => continue 'run,
                Flow::Halt(h) => break 'run Outcome::Halted(h),
                Flow::Fail(b) => break 'run Outcome::BlewUp(b),
            }
        }
        if stop {
            break Outcome::Finished;
        }
        if let Err(b) = run.step() {
            break Outcome::BlewUp(b);
        }
    };
    for o in observers.iter_mut() {
        o.finish(run, &outcome)?;
    }
    Ok(outcome)
}

/// An observer made of a closure: `f(run)` says how to go on (an end time, a sampling rule).
pub struct Watch<F>(pub F);

impl<R, F: FnMut(&mut R) -> anyhow::Result<Flow>> Observer<R> for Watch<F> {
    fn observe(&mut self, run: &mut R) -> anyhow::Result<Flow> {
        (self.0)(run)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::solver::BlowUpReason;

    /// A counter that blows up at step `fail_at`.
    struct Counter {
        steps: u64,
        fail_at: u64,
    }

    impl Stepper for Counter {
        fn step(&mut self) -> Result<(), BlowUp> {
            if self.steps == self.fail_at {
                return Err(BlowUp {
                    reason: BlowUpReason::NotFinite,
                    time: self.steps as f64,
                    step: self.steps,
                    particle: None,
                });
            }
            self.steps += 1;
            Ok(())
        }
    }

    #[test]
    fn the_initial_and_the_last_state_are_observed_and_finish_sees_the_outcome() {
        let mut run = Counter { steps: 0, fail_at: 99 };
        let mut seen = vec![];
        let mut stop_at_3 = Watch(|r: &mut Counter| {
            seen.push(r.steps);
            Ok(if r.steps >= 3 { Flow::Stop } else { Flow::Step })
        });
        let outcome = drive(&mut run, &mut [&mut stop_at_3]).unwrap();
        assert!(matches!(outcome, Outcome::Finished));
        assert_eq!(seen, vec![0, 1, 2, 3]);
    }

    #[test]
    fn a_blow_up_ends_the_run_with_its_diagnosis_and_the_state_before_it() {
        let mut run = Counter { steps: 0, fail_at: 2 };
        let mut never = Watch(|_: &mut Counter| Ok(Flow::Step));
        let outcome = drive(&mut run, &mut [&mut never]).unwrap();
        assert!(
            matches!(outcome, Outcome::BlewUp(BlowUp { step: 2, .. })),
            "{outcome:?}"
        );
        assert_eq!(run.steps, 2);
    }

    #[test]
    fn again_observes_from_the_first_observer_without_stepping() {
        let mut run = Counter { steps: 0, fail_at: 99 };
        let (mut firsts, mut rewound) = (0, false);
        let mut first = Watch(|_: &mut Counter| {
            firsts += 1;
            Ok(Flow::Step)
        });
        let mut rewind_once = Watch(|r: &mut Counter| {
            if r.steps == 2 && !rewound {
                rewound = true;
                r.steps = 1;
                return Ok(Flow::Again);
            }
            Ok(if r.steps >= 3 { Flow::Stop } else { Flow::Step })
        });
        drive(&mut run, &mut [&mut first, &mut rewind_once]).unwrap();
        // Observed at 0, 1, 2 (rewound to 1), 1, 2, 3.
        assert_eq!(firsts, 6);
    }
}
