//! Wave gauges (`[[probes.gauge]]`).

use bowwave::cases::{self, case_file::CaseFile, run};

/// Regression: a gauge without `bottom` stood on the domain's bottom (0.5 m below the hydrostatic tank's floor),
/// so its depth read 1.5 H in water 1 H deep, and a `connected` gauge, whose stack must start at its bottom,
/// read nothing at all. It now stands on the wall under it.
#[test]
fn a_gauge_without_bottom_stands_on_the_tank_floor_not_the_domain_bottom() {
    let text = cases::builtin::builtin_text("hydrostatic").unwrap().replace(
        "[output]",
        "[[probes.gauge]]\nname = \"g\"\nx = 1.0\n\n[[probes.gauge]]\nname = \"gc\"\nx = 1.0\nconnected = true\n\n[output]",
    );
    let case = CaseFile::parse(&text, "gauge test").unwrap();
    assert_eq!(case.floor_under(1.0), 0.0);
    assert_eq!(
        case.floor_under(2.4),
        case.domain.min[1],
        "no wall under x = 2.4: the domain's bottom"
    );
    let r = run::run(
        &case,
        &run::RunOptions {
            res: Some(10.0),
            end_time: Some(0.05),
            ..Default::default()
        },
    )
    .unwrap();
    for g in ["g", "gc"] {
        let depth = r.series.column(&format!("depthstar_{g}")).unwrap();
        // The top row's centre is at H − dx/2; the level adds dx/2: H within the rows' settling.
        assert!((depth[0] - 1.0).abs() < 0.01, "{g}: depth {} H", depth[0]);
    }
}
