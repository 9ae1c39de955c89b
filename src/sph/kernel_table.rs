//! The kernel-gradient factor F(r²) = (dW/dr)/r tabulated in r² and linearly interpolated: a speed variant
//! (`kernel_table = true` in a case's `[numerics]`, variant `table` in the charts) that replaces one
//! exponential per pair and stage by two table reads. Its effect on accuracy is measured in
//! `docs/reference/speed-accuracy.md`, not assumed.
//!
//! Tabulating in r² keeps F a function of |r_ij|² alone, so F_ij = F_ji exactly and the pairwise forces stay
//! antisymmetric (momentum is conserved as with the exact kernel). Only the Gaussian is tabulated: for
//! Wendland C2, F depends on √(r²) and a linear table in r² would be poor near r = 0.

use super::kernel::{Kernel, KernelKind};

/// F(r²) on [0, R²] at [`GradientTable::INTERVALS`] equal intervals.
#[derive(Clone, Debug)]
pub struct GradientTable {
    r2_max: f64,
    inv_ds: f64,
    /// Per interval k: F at its start and the difference to the next sample, (F_k, F_{k+1} − F_k). A
    /// fixed-size array, so the index clamped below `INTERVALS` needs no bounds check in the pair loops.
    intervals: Box<[[f64; 2]; GradientTable::INTERVALS]>,
}

impl GradientTable {
    /// Number of intervals in r² (dimensionless). 4096 intervals of 9h²/4096 bound the relative error of
    /// the linear interpolation of e^{−r²/h²} by (9/4096)²/8 = 6e-7.
    pub const INTERVALS: usize = 4096;

    /// The table of `kernel`'s F, or `None` for a kernel that is not tabulated (Wendland C2).
    pub fn new<const D: usize>(kernel: &Kernel<D>) -> Option<Self> {
        if kernel.kind != KernelKind::RenormalizedGaussian {
            return None;
        }
        let r2_max = kernel.support * kernel.support;
        let ds = r2_max / Self::INTERVALS as f64;
        // The last sample is taken just inside the support (F is cut to zero at R² itself).
        let values: Vec<f64> = (0..=Self::INTERVALS)
            .map(|k| kernel.grad_factor((k as f64 * ds).min(r2_max * (1.0 - 1e-15))))
            .collect();
        let intervals: Box<[[f64; 2]]> = values.windows(2).map(|w| [w[0], w[1] - w[0]]).collect();
        Some(GradientTable {
            r2_max,
            inv_ds: 1.0 / ds,
            intervals: intervals.try_into().expect("INTERVALS intervals"),
        })
    }

    /// Interpolated F(r²); zero outside the support.
    #[inline]
    pub fn factor(&self, r2: f64) -> f64 {
        if r2 >= self.r2_max {
            return 0.0;
        }
        let x = r2 * self.inv_ds;
        // 0 ≤ x < INTERVALS here: a cast to i32 is exact and takes half the instructions of the saturating cast to usize.
        let k = (x as i32).min(Self::INTERVALS as i32 - 1) as usize;
        let f = x - k as f64;
        let [a, slope] = self.intervals[k];
        a + slope * f
    }
}

/// How the gather loops get F(r²): from the kernel or from its table.
#[derive(Clone, Copy, Debug)]
pub enum GradientFactor<'a, const D: usize> {
    Exact(Kernel<D>),
    Table(&'a GradientTable),
}

impl<const D: usize> GradientFactor<'_, D> {
    /// F(r²) (1/m^{D+2}).
    #[inline]
    pub fn at(&self, r2: f64) -> f64 {
        match self {
            GradientFactor::Exact(k) => k.grad_factor(r2),
            GradientFactor::Table(t) => t.factor(r2),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_matches_the_gaussian_to_a_millionth_of_its_peak() {
        let k = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 0.013);
        let t = GradientTable::new(&k).unwrap();
        let peak = k.grad_factor(0.0).abs();
        let mut worst = 0.0f64;
        for i in 0..100_000 {
            let r2 = k.support * k.support * (i as f64 + 0.37) / 100_000.0;
            worst = worst.max((t.factor(r2) - k.grad_factor(r2)).abs() / peak);
        }
        assert!(worst < 1e-6, "worst relative error {worst:e}");
        assert_eq!(t.factor(k.support * k.support), 0.0);
        assert_eq!(t.factor(2.0 * k.support * k.support), 0.0);
    }

    #[test]
    fn wendland_is_not_tabulated() {
        assert!(GradientTable::new(&Kernel::<2>::new(KernelKind::WendlandC2, 0.1)).is_none());
    }
}
