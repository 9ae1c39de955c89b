//! Progress of a run: a bar on a terminal, plain lines in a log. A batch job's log is a file, where a bar
//! draws nothing; there the run writes a line when it starts, every 60 s (a
//! few hundred lines for a day's run) with where it stands, the steps, the time spent and the time left,
//! and one when it ends.

use super::{Flow, Observer, Outcome};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// Where a run stands: the fraction done, in [0, 1], and a short text (`x/L = 0.2100`, `t* = 1.23`).
pub struct Status {
    pub fraction: f64,
    pub text: String,
    pub steps: u64,
}

enum Display {
    None,
    Bar(indicatif::ProgressBar),
    Lines { last: Instant },
}

/// The progress observer of a run; `status` reads where the run stands.
pub struct Progress<F> {
    label: String,
    status: F,
    display: Display,
    start: Instant,
    /// Interval between two plain lines.
    every: Duration,
}

impl<F> Progress<F> {
    /// `show`: whether to show anything (`--quiet` turns it off); a bar when stderr is a terminal (attached to
    /// `multi` when given, a study's bars), plain lines otherwise.
    pub fn new(label: &str, show: bool, multi: Option<&indicatif::MultiProgress>, status: F) -> Self {
        let display = match (show, std::io::stderr().is_terminal()) {
            (false, _) => Display::None,
            (true, true) => {
                let b = indicatif::ProgressBar::new(1000);
                let b = match multi {
                    Some(m) => m.add(b),
                    None => b,
                };
                b.set_style(
                    indicatif::ProgressStyle::with_template(&format!(
                        "{label}{{bar:40}} {{msg}} [{{elapsed_precise}} / eta {{eta_precise}}]"
                    ))
                    .expect("valid template"),
                );
                Display::Bar(b)
            }
            (true, false) => Display::Lines { last: Instant::now() },
        };
        let p = Progress {
            label: label.trim_end().to_string(),
            status,
            display,
            start: Instant::now(),
            every: Duration::from_secs(60),
        };
        if matches!(p.display, Display::Lines { .. }) {
            eprintln!("{}: started", p.label_or_run());
        }
        p
    }

    fn label_or_run(&self) -> &str {
        if self.label.is_empty() {
            "run"
        } else {
            &self.label
        }
    }
}

/// A duration as `1 h 02 min`, `3 min 05 s` or `12 s`.
pub fn human(d: Duration) -> String {
    let s = d.as_secs();
    match s {
        0..60 => format!("{s} s"),
        60..3600 => format!("{} min {:02} s", s / 60, s % 60),
        _ => format!("{} h {:02} min", s / 3600, (s % 3600) / 60),
    }
}

/// One progress line: where the run stands, its steps, the time spent and, once it is a little way in,
/// the time left at its pace so far.
pub fn line(label: &str, s: &Status, elapsed: Duration) -> String {
    let f = s.fraction.clamp(0.0, 1.0);
    let left = if f > 1e-3 {
        format!(", about {} left", human(elapsed.mul_f64((1.0 - f) / f)))
    } else {
        String::new()
    };
    format!(
        "{label}: {}, {:.1} %, {} steps, {}{left}",
        s.text,
        100.0 * f,
        s.steps,
        human(elapsed)
    )
}

impl<R, F: FnMut(&R) -> Status> Observer<R> for Progress<F> {
    fn observe(&mut self, run: &mut R) -> anyhow::Result<Flow> {
        match &mut self.display {
            Display::None => {}
            Display::Bar(b) => {
                let s = (self.status)(run);
                b.set_position((1000.0 * s.fraction).clamp(0.0, 1000.0) as u64);
                b.set_message(s.text);
            }
            Display::Lines { last } => {
                if last.elapsed() >= self.every {
                    *last = Instant::now();
                    let s = (self.status)(run);
                    eprintln!("{}", line(self.label_or_run(), &s, self.start.elapsed()));
                }
            }
        }
        Ok(Flow::Step)
    }

    fn finish(&mut self, run: &mut R, outcome: &Outcome) -> anyhow::Result<()> {
        match &self.display {
            Display::None => {}
            Display::Bar(b) => b.finish_and_clear(),
            Display::Lines { .. } => {
                let s = (self.status)(run);
                let how = match outcome {
                    Outcome::Finished => "finished".to_string(),
                    Outcome::Halted(h) => format!("halted ({h})"),
                    Outcome::BlewUp(b) => format!("stopped early ({b})"),
                };
                eprintln!(
                    "{}: {how} at {}, {} steps, {}",
                    self.label_or_run(),
                    s.text,
                    s.steps,
                    human(self.start.elapsed())
                );
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_says_where_the_run_is_and_the_time_left() {
        let s = Status {
            fraction: 0.25,
            text: "x/L = 0.1000".into(),
            steps: 1200,
        };
        assert_eq!(
            line("athena Fr 0.500", &s, Duration::from_secs(600)),
            "athena Fr 0.500: x/L = 0.1000, 25.0 %, 1200 steps, 10 min 00 s, about 30 min 00 s left"
        );
        assert_eq!(human(Duration::from_secs(3725)), "1 h 02 min");
    }
}
