//! The method's own measurements, apart from any ship: convergence with resolution (appendix C orders and
//! Richardson extrapolation, for the validation cases and for the 2D+t jet metrics), speed against accuracy
//! over method variants with the Pareto front, stability maps, and the throughput benchmark.

pub mod bench;
pub mod charts;
pub mod convergence;
pub mod sensitivity;
pub mod twodt_chart;
pub mod twodt_convergence;
