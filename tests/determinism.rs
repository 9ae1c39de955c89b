//! Results are bit-identical for any thread count (gather loops, fixed neighbour order, sequential sums).

use bowwave::cases::{
    self,
    run::{run, RunOptions},
};
use bowwave::sph::polyline_wall::GhostKind;

fn positions_with_threads(n: usize, ghosts: GhostKind) -> (Vec<u64>, Vec<u64>) {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().unwrap();
    pool.install(|| {
        let mut case = cases::load("dam-break").unwrap();
        case.set_ghosts(ghosts);
        let r = run(
            &case,
            &RunOptions {
                res: Some(20.0),
                end_time: Some(0.25),
                ..Default::default()
            },
        )
        .unwrap();
        let f = &r.sim.fluid;
        let mut order: Vec<usize> = (0..f.len()).collect();
        order.sort_by_key(|&i| f.id[i]);
        let bits: Vec<u64> = order
            .iter()
            .flat_map(|&i| {
                [
                    f.pos[i].x.to_bits(),
                    f.pos[i].y.to_bits(),
                    f.vel[i].x.to_bits(),
                    f.rho[i].to_bits(),
                ]
            })
            .collect();
        let series: Vec<u64> = r
            .series
            .rows
            .iter()
            .flat_map(|row| row.iter().map(|x| x.to_bits()))
            .collect();
        (bits, series)
    })
}

#[test]
fn one_and_two_threads_give_identical_bits() {
    for ghosts in [GhostKind::Fixed, GhostKind::Images] {
        let (a, sa) = positions_with_threads(1, ghosts);
        let (b, sb) = positions_with_threads(2, ghosts);
        assert_eq!(a.len(), b.len());
        assert!(
            a == b,
            "particle state differs between 1 and 2 threads ({ghosts:?} ghosts)"
        );
        assert!(
            sa == sb,
            "time series differ between 1 and 2 threads ({ghosts:?} ghosts)"
        );
    }
}
