//! Tests of the `simulate` module: accuracy against closed forms, breakpoints, error paths,
//! CSV and plot files.

use std::f64::consts::PI;
use std::path::Path;

use super::*;

type Rhs = fn(f64, &[f64], &mut [f64]) -> Result<(), String>;

/// Largest |y_j(t) - exact(t)| over the output instants.
fn max_error(traj: &Trajectory, j: usize, exact: impl Fn(f64) -> f64) -> f64 {
    traj.times()
        .iter()
        .zip(traj.states())
        .map(|(&t, y)| (y[j] - exact(t)).abs())
        .fold(0.0, f64::max)
}

// ---------------------------------------------------------------- integration

#[test]
fn harmonic_oscillator_matches_closed_form() {
    let w = 2.0 * PI * 1.3;
    let (x0, v0) = (1.0, 0.3);
    let traj = integrate(
        |_t, y, dy| {
            dy[0] = y[1];
            dy[1] = -w * w * y[0];
            Ok(())
        },
        &[x0, v0],
        10.0,
        &Options::default(),
    )
    .expect("integrates");

    // 1 ms grid, exactly k·dt, closed by t_end.
    assert_eq!(traj.len(), 10_001);
    assert_eq!(traj.dim(), 2);
    for (k, &t) in traj.times().iter().enumerate() {
        assert_eq!(t, k as f64 * 1e-3);
    }
    assert_eq!(traj.last().map(|(t, _)| t), Some(10.0));

    let ex = max_error(&traj, 0, |t| x0 * (w * t).cos() + v0 / w * (w * t).sin());
    let ev = max_error(&traj, 1, |t| -x0 * w * (w * t).sin() + v0 * (w * t).cos());
    assert!(ex < 1e-8, "position error {ex:e}");
    assert!(ev / w < 1e-8, "velocity error {ev:e}");
    let stats = traj.stats();
    assert_eq!(stats.pieces, 1);
    assert!(stats.accepted_steps > 100 && stats.evaluations > 6 * stats.accepted_steps);
}

fn pendulum_energy_drift(rtol: f64, atol: f64) -> f64 {
    const G_OVER_L: f64 = 9.81;
    let energy = |y: &[f64]| 0.5 * y[1] * y[1] - G_OVER_L * y[0].cos();
    let opts = Options {
        rtol,
        atol,
        output: Output::Steps,
        ..Options::default()
    };
    let traj = integrate(
        |_t, y, dy| {
            dy[0] = y[1];
            dy[1] = -G_OVER_L * y[0].sin();
            Ok(())
        },
        &[2.0, 0.0], // 115°: far from the small-angle regime
        10.0,
        &opts,
    )
    .expect("integrates");
    let e0 = energy(&[2.0, 0.0]);
    traj.states()
        .map(|y| (energy(y) - e0).abs() / e0.abs())
        .fold(0.0, f64::max)
}

#[test]
fn pendulum_conserves_energy_to_the_tolerance() {
    // About 800 steps over 5 periods: the relative drift stays within a few tens of rtol.
    let tight = pendulum_energy_drift(1e-10, 1e-12);
    assert!(
        tight < 1e-8,
        "relative energy drift {tight:e} at rtol 1e-10"
    );
    // And it follows the tolerance: a looser one drifts proportionally more.
    let loose = pendulum_energy_drift(1e-6, 1e-8);
    assert!(loose < 1e-4, "relative energy drift {loose:e} at rtol 1e-6");
    assert!(
        loose > 100.0 * tight,
        "drift {loose:e} vs {tight:e}: not tolerance-driven"
    );
}

#[test]
fn steps_output_starts_at_t0_and_increases() {
    let opts = Options {
        t0: 1.0,
        output: Output::Steps,
        ..Options::default()
    };
    let traj = integrate(
        |_t, y, dy| {
            dy[0] = -y[0];
            Ok(())
        },
        &[1.0],
        3.0,
        &opts,
    )
    .expect("integrates");
    assert_eq!(traj.times()[0], 1.0);
    assert_eq!(traj.state(0), Some(&[1.0][..]));
    assert!(traj.times().windows(2).all(|w| w[0] < w[1]));
    let (t, y) = traj.last().expect("non-empty");
    assert_eq!(t, 3.0);
    assert!((y[0] - (-2f64).exp()).abs() < 1e-11);
    assert_eq!(traj.len(), traj.stats().accepted_steps as usize + 1);
}

/// x' = t for t < 0.5, x' = 0.5 after: a rate ramp then a constant (a kink in x').
fn ramp(t: f64, _y: &[f64], dy: &mut [f64]) -> Result<(), String> {
    dy[0] = if t < 0.5 { t } else { 0.5 };
    Ok(())
}

fn ramp_exact(t: f64) -> f64 {
    if t < 0.5 {
        t * t / 2.0
    } else {
        0.125 + 0.5 * (t - 0.5)
    }
}

/// x'' = 1 for t < 0.5, -1 after: an imposed acceleration that jumps.
fn bang(t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), String> {
    dy[0] = y[1];
    dy[1] = if t < 0.5 { 1.0 } else { -1.0 };
    Ok(())
}

fn bang_exact(t: f64) -> f64 {
    if t < 0.5 {
        t * t / 2.0
    } else {
        0.125 + 0.5 * (t - 0.5) - (t - 0.5).powi(2) / 2.0
    }
}

fn run(f: Rhs, y0: &[f64], breakpoints: Vec<f64>, rtol: f64, atol: f64) -> Trajectory {
    let opts = Options {
        rtol,
        atol,
        breakpoints,
        ..Options::default()
    };
    integrate(f, y0, 1.5, &opts).expect("integrates")
}

#[test]
fn breakpoint_restores_accuracy_of_a_piecewise_law() {
    for (rtol, atol) in [(1e-10, 1e-12), (1e-6, 1e-8)] {
        // Ramp then constant: with the breakpoint, each piece is a polynomial that the
        // 5th-order method integrates exactly.
        let with = run(ramp, &[0.0], vec![0.5], rtol, atol);
        let without = run(ramp, &[0.0], vec![], rtol, atol);
        let (e_with, e_without) = (
            max_error(&with, 0, ramp_exact),
            max_error(&without, 0, ramp_exact),
        );
        assert!(
            e_with < 1e-14,
            "ramp, rtol {rtol:e}: error {e_with:e} with the breakpoint"
        );
        assert!(
            e_without > 1e3 * e_with.max(1e-15),
            "ramp, rtol {rtol:e}: error {e_without:e} without the breakpoint"
        );
        assert_eq!(with.stats().rejected_steps, 0);
        assert!(without.stats().rejected_steps > 0);
        assert!(without.stats().evaluations > with.stats().evaluations);
        assert_eq!((with.stats().pieces, without.stats().pieces), (2, 1));
        assert_eq!(with.len(), without.len());

        // A jump in the imposed acceleration: worse without, still exact with.
        let with = run(bang, &[0.0, 0.0], vec![0.5], rtol, atol);
        let without = run(bang, &[0.0, 0.0], vec![], rtol, atol);
        let (e_with, e_without) = (
            max_error(&with, 0, bang_exact),
            max_error(&without, 0, bang_exact),
        );
        assert!(
            e_with < 1e-14,
            "jump, rtol {rtol:e}: error {e_with:e} with the breakpoint"
        );
        assert!(
            e_without > 1e3 * e_with.max(1e-15),
            "jump: {e_without:e} without"
        );
        assert!(without.stats().rejected_steps > with.stats().rejected_steps);
    }
}

#[test]
fn each_piece_sees_its_own_side_of_a_breakpoint() {
    // A law written with `<=` (left-continuous) and one written with `<` (right-continuous)
    // give the same, exact result, and f is never called across the breakpoint from a piece.
    for left_closed in [false, true] {
        let mut calls: Vec<f64> = Vec::new();
        let opts = Options {
            breakpoints: vec![0.5, 0.5, 7.0, -1.0],
            ..Options::default()
        };
        let traj = integrate(
            |t, y, dy| {
                calls.push(t);
                let before = if left_closed { t <= 0.5 } else { t < 0.5 };
                dy[0] = y[1];
                dy[1] = if before { 1.0 } else { -1.0 };
                Ok(())
            },
            &[0.0, 0.0],
            1.5,
            &opts,
        )
        .expect("integrates");
        let err = max_error(&traj, 0, bang_exact);
        assert!(err < 1e-14, "left_closed = {left_closed}: error {err:e}");
        assert_eq!(
            traj.stats().pieces,
            2,
            "0.5 twice, 7 and -1 outside: one breakpoint"
        );
        assert!(!calls.contains(&0.5), "f called exactly at the breakpoint");
        assert!(calls.iter().all(|t| (0.0..=1.5).contains(t)));
        // The output grid still has 0.5 itself, and the state there is exact.
        let i = traj
            .times()
            .iter()
            .position(|&t| t == 0.5)
            .expect("0.5 on the grid");
        assert!((traj.state(i).expect("state")[0] - 0.125).abs() < 1e-15);
    }
}

#[test]
fn output_grid_ends_exactly_at_t_end() {
    let opts = Options {
        output: Output::Interval(0.3),
        ..Options::default()
    };
    let traj = integrate(ramp, &[0.0], 1.0, &opts).expect("integrates");
    assert_eq!(traj.times(), &[0.0, 0.3, 0.6, 0.8999999999999999, 1.0]);
    let opts = Options {
        output: Output::Interval(0.25),
        ..Options::default()
    };
    let traj = integrate(ramp, &[0.0], 1.0, &opts).expect("integrates");
    assert_eq!(traj.times(), &[0.0, 0.25, 0.5, 0.75, 1.0]);
    assert!(max_error(&traj, 0, ramp_exact) < 1e-9);
}

// ---------------------------------------------------------------- errors

#[test]
fn rhs_error_propagates() {
    let mut evaluations = 0u32;
    let result = integrate(
        |t, y, dy| {
            evaluations += 1;
            if t > 0.3 {
                return Err(format!("model undefined at t = {t}"));
            }
            dy[0] = -y[0];
            Ok(())
        },
        &[1.0],
        1.0,
        &Options::default(),
    );
    match result {
        Err(SimError::Rhs { t, message }) => {
            assert!(t > 0.3 && t < 0.4, "t = {t}");
            assert!(
                message.starts_with("model undefined at t = 0.3"),
                "{message}"
            );
        }
        other => panic!("expected SimError::Rhs, got {other:?}"),
    }
    // The integration stopped at the failure instead of going on to t = 1.
    assert!(evaluations < 200, "{evaluations} evaluations");
}

#[test]
fn rhs_error_in_a_later_piece_propagates() {
    let opts = Options {
        breakpoints: vec![0.2, 0.4],
        ..Options::default()
    };
    let result = integrate(
        |t, _y, dy| {
            dy[0] = 1.0;
            if t > 0.4 {
                Err("boom".to_string())
            } else {
                Ok(())
            }
        },
        &[0.0],
        1.0,
        &opts,
    );
    assert!(
        matches!(&result, Err(SimError::Rhs { t, message }) if *t > 0.4 && message == "boom"),
        "{result:?}"
    );
    let text = result.map(|_| ()).expect_err("fails").to_string();
    assert!(
        text.contains("boom") && text.contains("right-hand side"),
        "{text}"
    );
}

#[test]
fn non_finite_derivative_is_an_error() {
    let result = integrate(
        |t, y, dy| {
            dy[0] = if t < 0.25 { -y[0] } else { f64::NAN };
            Ok(())
        },
        &[1.0],
        1.0,
        &Options::default(),
    );
    assert!(
        matches!(result, Err(SimError::NonFinite { t, index: 0, value }) if t >= 0.25 && value.is_nan()),
        "{result:?}"
    );
}

#[test]
fn step_budget_is_enforced() {
    let opts = Options {
        max_steps: 10,
        ..Options::default()
    };
    let result = integrate(
        |_t, y, dy| {
            dy[0] = y[1];
            dy[1] = -y[0];
            Ok(())
        },
        &[1.0, 0.0],
        100.0,
        &opts,
    );
    assert!(
        matches!(result, Err(SimError::MaxSteps { .. })),
        "{result:?}"
    );
}

#[test]
fn invalid_inputs_are_rejected() {
    let ok = |_t: f64, _y: &[f64], dy: &mut [f64]| {
        dy.fill(0.0);
        Ok(())
    };
    let base = Options::default();
    let cases: Vec<(&[f64], f64, Options)> = vec![
        (&[], 1.0, base.clone()),
        (&[f64::NAN], 1.0, base.clone()),
        (&[0.0], 0.0, base.clone()),
        (&[0.0], f64::INFINITY, base.clone()),
        (
            &[0.0],
            1.0,
            Options {
                rtol: -1.0,
                ..base.clone()
            },
        ),
        (
            &[0.0],
            1.0,
            Options {
                atol: 0.0,
                ..base.clone()
            },
        ),
        (
            &[0.0],
            1.0,
            Options {
                max_steps: 0,
                ..base.clone()
            },
        ),
        (
            &[0.0],
            1.0,
            Options {
                max_step: Some(0.0),
                ..base.clone()
            },
        ),
        (
            &[0.0],
            1.0,
            Options {
                breakpoints: vec![f64::NAN],
                ..base.clone()
            },
        ),
        (
            &[0.0],
            1.0,
            Options {
                output: Output::Interval(0.0),
                ..base.clone()
            },
        ),
        (
            &[0.0],
            1.0,
            Options {
                output: Output::Interval(1e-12),
                ..base.clone()
            },
        ),
    ];
    for (i, (y0, t_end, opts)) in cases.into_iter().enumerate() {
        let result = integrate(ok, y0, t_end, &opts);
        assert!(
            matches!(result, Err(SimError::InvalidInput(_))),
            "case {i}: {result:?}"
        );
    }
}

// ---------------------------------------------------------------- CSV

#[test]
fn csv_has_units_header_and_round_trips() {
    let traj = integrate(
        |_t, y, dy| {
            dy[0] = y[1];
            dy[1] = -y[0];
            Ok(())
        },
        &[1.0, 0.0],
        0.01,
        &Options::default(),
    )
    .expect("integrates");
    let mut table = traj
        .to_table("t (s)", &["x (m)", "v (m/s)"])
        .expect("table");
    table
        .push_column("note, \"quoted\"", vec![0.5; traj.len()])
        .expect("column");
    let csv = table.to_csv();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("t (s),x (m),v (m/s),\"note, \"\"quoted\"\"\"")
    );
    assert_eq!(lines.next(), Some("0e0,1e0,0e0,5e-1"));
    let mut n = 0;
    for (line, (t, y)) in csv
        .lines()
        .skip(1)
        .zip(traj.times().iter().zip(traj.states()))
    {
        let values: Vec<f64> = line
            .split(',')
            .map(|v| v.parse().expect("number"))
            .collect();
        assert_eq!(
            values,
            [*t, y[0], y[1], 0.5],
            "shortest form reads back exactly"
        );
        n += 1;
    }
    assert_eq!(n, 11);
    assert!(csv.ends_with('\n') && !csv.contains('\r'));

    let fixed = table
        .clone()
        .with_format(NumberFormat::Scientific(9))
        .to_csv();
    assert_eq!(
        fixed.lines().nth(2).map(|l| l.split(',').next()),
        Some(Some("1.000000000e-3"))
    );
    assert_eq!(NumberFormat::Shortest.format(f64::NEG_INFINITY), "-inf");
    assert_eq!(NumberFormat::Scientific(3).format(f64::NAN), "nan");

    assert!(matches!(
        traj.to_table("t (s)", &["x (m)"]),
        Err(SimError::InvalidInput(_))
    ));
    assert!(matches!(
        table.push_row(&[1.0]),
        Err(SimError::InvalidInput(_))
    ));
    assert!(matches!(
        table.push_column("y", vec![1.0]),
        Err(SimError::InvalidInput(_))
    ));
}

/// Names of the files in `dir`, sorted.
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("readable")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn csv_is_written_atomically() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("out.csv");
    let mut table = Table::new(&["t (s)", "θ2 (rad)"]);
    table.push_row(&[0.0, 0.1]).expect("row");
    table.write_csv(&path).expect("written");
    assert_eq!(
        std::fs::read_to_string(&path).expect("read"),
        "t (s),θ2 (rad)\n0e0,1e-1\n"
    );
    // Overwrite: the new content replaces the old, and no temporary file is left behind.
    table.push_row(&[1.0, 0.2]).expect("row");
    table.write_csv(&path).expect("rewritten");
    assert_eq!(
        std::fs::read_to_string(&path)
            .expect("read")
            .lines()
            .count(),
        3
    );
    assert_eq!(listing(dir.path()), ["out.csv"]);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(&path)
            .expect("metadata")
            .permissions()
            .mode();
        assert_eq!(mode & 0o600, 0o600);
        assert_ne!(
            mode & 0o044,
            0,
            "readable by others like File::create, not 0600"
        );
    }
    // An unwritable destination is an error, not a panic.
    let bad = dir.path().join("missing-dir").join("out.csv");
    assert!(matches!(table.write_csv(&bad), Err(SimError::Io { .. })));
}

// ---------------------------------------------------------------- plots

fn sample_figure() -> Figure {
    let traj = integrate(
        |t, y, dy| {
            let w = if t < 0.5 { 24.0 * t } else { 12.0 };
            dy[0] = y[1];
            dy[1] = (w * w * y[0].cos() - 49.05) * y[0].sin() - 0.4 * y[1];
            Ok(())
        },
        &[0.1, 0.0],
        2.0,
        &Options {
            output: Output::Interval(2e-3),
            breakpoints: vec![0.5],
            ..Options::default()
        },
    )
    .expect("integrates");
    let torque: Vec<f64> = traj
        .states()
        .map(|y| 0.01 * (2.0 * y[0]).sin() * y[1])
        .collect();
    let mut with_gap = traj.series(1, "θ2' (rad/s)").expect("component 1");
    with_gap.points[100].1 = f64::NAN; // breaks the line, must not break the plot
    Figure::new("Regulator: θ2(t) and Cm(t)", "t (s)")
        .panel(Panel::new("θ2 (rad)").series(traj.series(0, "θ2").expect("component 0")))
        .panel(
            Panel::new("Cm (N·m)")
                .series(Series::from_xy("Cm", traj.times(), &torque).expect("same lengths"))
                .series(Series::new("", vec![(0.0, 0.0), (2.0, 0.0)])),
        )
        .panel(
            Panel::new("θ2' (rad/s)")
                .series(with_gap)
                .y_range(-20.0, 20.0),
        )
}

/// Width and height from the IHDR chunk, after checking the PNG signature.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "PNG signature");
    assert_eq!(&bytes[12..16], b"IHDR");
    let be = |b: &[u8]| u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
    (be(&bytes[16..20]), be(&bytes[20..24]))
}

#[test]
fn svg_and_png_files_are_produced_and_deterministic() {
    let dir = tempfile::tempdir().expect("temp dir");
    let figure = sample_figure();
    let (svg1, svg2) = (dir.path().join("a.svg"), dir.path().join("b.svg"));
    let (png1, png2) = (dir.path().join("a.png"), dir.path().join("b.png"));
    figure.save_svg(&svg1).expect("svg");
    sample_figure().save_svg(&svg2).expect("svg again");
    figure.save_png(&png1, 2).expect("png");
    sample_figure().save_png(&png2, 2).expect("png again");

    let svg = std::fs::read(&svg1).expect("read");
    assert!(svg.len() > 10_000);
    assert_eq!(
        svg,
        std::fs::read(&svg2).expect("read"),
        "SVG not deterministic"
    );
    let text = String::from_utf8(svg).expect("utf-8");
    assert!(text.starts_with("<svg width=\"800\" height=\"960\""));
    for needle in [
        "Regulator: θ2(t) and Cm(t)",
        "t (s)",
        "θ2 (rad)",
        "Cm (N·m)",
        ">\nθ2\n<",
    ] {
        assert!(text.contains(needle), "SVG lacks {needle:?}");
    }
    // Text stays text, in a generic family: no font file or font path is referenced.
    assert!(!text.contains("@font-face") && !text.contains(".ttf"));
    assert!(text.contains("font-family=\"sans-serif\""));

    let png = std::fs::read(&png1).expect("read");
    assert_eq!(
        png,
        std::fs::read(&png2).expect("read"),
        "PNG not deterministic"
    );
    assert_eq!(png_size(&png), (1600, 1920));
    // Full decode: CRCs, zlib stream, every row.
    let mut reader = png::Decoder::new(std::io::Cursor::new(&png))
        .read_info()
        .expect("header");
    let mut pixels = vec![0; reader.output_buffer_size().expect("size")];
    let frame = reader.next_frame(&mut pixels).expect("decodes");
    assert_eq!((frame.width, frame.height), (1600, 1920));
    assert_eq!(frame.color_type, png::ColorType::Rgb);
    let info = reader.info();
    let dims = info.pixel_dims.expect("pHYs");
    assert_eq!((dims.xppu, dims.unit), (7559, png::Unit::Meter)); // 192 dpi
    // Not blank: there is ink (curves, text) on the white page.
    let dark = pixels
        .chunks_exact(3)
        .filter(|p| p.iter().all(|&c| c < 100))
        .count();
    assert!(dark > 10_000, "{dark} dark pixels");
    assert_eq!(listing(dir.path()), ["a.png", "a.svg", "b.png", "b.svg"]);
}

#[test]
fn plot_writes_both_files() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (svg, png) = (dir.path().join("x.svg"), dir.path().join("x.png"));
    let series = [
        Series::new(
            "cos",
            (0..=200)
                .map(|i| (i as f64 * 0.01, (i as f64 * 0.01).cos()))
                .collect(),
        ),
        Series::new(
            "sin",
            (0..=200)
                .map(|i| (i as f64 * 0.01, (i as f64 * 0.01).sin()))
                .collect(),
        ),
    ];
    plot(&series, "Two curves", "t (s)", "x (m)", &svg, Some(&png)).expect("plotted");
    assert!(std::fs::metadata(&svg).expect("svg").len() > 1000);
    assert_eq!(png_size(&std::fs::read(&png).expect("png")), (2400, 1080));
    plot(
        &series,
        "SVG only",
        "t (s)",
        "x (m)",
        &dir.path().join("y.svg"),
        None,
    )
    .expect("svg");
}

#[test]
fn degenerate_figures_are_errors_or_still_drawn() {
    // No panel, silly sizes and ranges: errors.
    assert!(matches!(
        Figure::new("t", "x").to_svg(),
        Err(SimError::InvalidInput(_))
    ));
    let one = || Figure::new("t", "x").panel(Panel::new("y"));
    assert!(matches!(
        one().size(10, 10).to_svg(),
        Err(SimError::InvalidInput(_))
    ));
    assert!(matches!(one().to_png(0), Err(SimError::InvalidInput(_))));
    assert!(matches!(one().to_png(100), Err(SimError::InvalidInput(_))));
    assert!(matches!(
        one().x_range(1.0, 1.0).to_svg(),
        Err(SimError::InvalidInput(_))
    ));
    assert!(matches!(
        Series::from_xy("s", &[1.0], &[]),
        Err(SimError::InvalidInput(_))
    ));
    // Empty panel, constant or all-NaN series: drawn.
    assert!(one().to_svg().is_ok());
    let flat = Panel::new("y").series(Series::new("c", vec![(0.0, 3.0), (1.0, 3.0)]));
    assert!(Figure::new("t", "x").panel(flat).to_png(1).is_ok());
    let nan = Panel::new("y").series(Series::new("n", vec![(f64::NAN, 1.0), (0.0, f64::NAN)]));
    assert!(Figure::new("t", "x").panel(nan).to_svg().is_ok());
}
