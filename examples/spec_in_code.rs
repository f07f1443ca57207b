//! A mechanism built in Rust rather than JSON: a pendulum on a cart (a slider along x0 carrying
//! a pivot of axis z0), with gravity −g y0. The typed spec goes through the same validation as
//! a file; the example prints the equations of motion, their small-motion linearisation, and
//! checks the results against the independent float backend.
//!
//! Run: `cargo run --example spec_in_code`

use torseur::derivation::derive;
use torseur::quantity::Quantity;
use torseur::spec::wire::*;

fn param(name: &str, unit: &str) -> ParameterSpec {
    ParameterSpec {
        name: name.into(),
        description: None,
        unit: Some(unit.into()),
        kind: ParameterKind::Scalar,
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let spec = SpecFile {
        title: "Pendule sur chariot (construit en Rust)".into(),
        parameters: vec![
            param("M", "kg"),
            param("m", "kg"),
            param("l", "m"),
            param("A", "kg m^2"),
            param("B", "kg m^2"),
            param("J", "kg m^2"),
            param("g", "m/s^2"),
            param("F", "N"),
        ],
        coordinates: vec![
            CoordinateSpec {
                name: "x".into(),
                kind: CoordinateKind::Length,
                description: Some("position du chariot".into()),
                rate: None,
            },
            CoordinateSpec {
                name: "theta".into(),
                kind: CoordinateKind::Angle,
                description: Some("angle du pendule".into()),
                rate: None,
            },
        ],
        frames: vec![
            FrameSpec {
                name: "1".into(),
                parent: "0".into(),
                rotation: None,
                origin: Some("A".into()),
                basis: None,
            },
            FrameSpec {
                name: "2".into(),
                parent: "1".into(),
                rotation: Some(RotationSpec {
                    axis: "z".into(),
                    angle: "theta".into(),
                }),
                origin: Some("A".into()),
                basis: None,
            },
        ],
        points: vec![
            PointSpec {
                name: "A".into(),
                from: None,
                position: "x*x0".into(),
            },
            PointSpec {
                name: "G".into(),
                from: Some("A".into()),
                position: "-l*y2".into(),
            },
        ],
        solids: vec![
            SolidSpec {
                name: "1".into(),
                frame: "1".into(),
                mass: Some("M".into()),
                massless: false,
                centre: Some("A".into()),
                inertia: None,
                symmetries: vec![],
            },
            SolidSpec {
                name: "2".into(),
                frame: "2".into(),
                mass: Some("m".into()),
                massless: false,
                centre: Some("G".into()),
                inertia: Some(InertiaSpec {
                    point: "G".into(),
                    basis: "2".into(),
                    // A real body's moments (J ≤ A + B): A and B do not enter the plane
                    // motion about z0, but a body with A = B = 0 and J ≠ 0 does not exist, and
                    // the float backend, which draws real bodies, refuses it.
                    matrix: [
                        ["A".into(), "0".into(), "0".into()],
                        ["0".into(), "B".into(), "0".into()],
                        ["0".into(), "0".into(), "J".into()],
                    ],
                }),
                symmetries: vec![],
            },
        ],
        sets: [("E".to_string(), vec!["1".to_string(), "2".to_string()])].into(),
        gravity: Some("-g*y0".into()),
        links: vec![
            LinkSpec {
                name: "01".into(),
                kind: LinkKind::Slider,
                between: ["0".into(), "1".into()],
                point: "A".into(),
                axis: Some("x0".into()),
                direction: None,
                pitch: None,
                dependent: None,
                friction: None,
                coulomb: None,
                spring: None,
                label: None,
            },
            LinkSpec {
                name: "12".into(),
                kind: LinkKind::Pivot,
                between: ["1".into(), "2".into()],
                point: "A".into(),
                axis: Some("z0".into()),
                direction: None,
                pitch: None,
                dependent: None,
                friction: None,
                coulomb: None,
                spring: None,
                label: None,
            },
        ],
        actions: vec![ActionSpec {
            name: "poussee".into(),
            from: "0".into(),
            on: "1".into(),
            point: "A".into(),
            resultant: Some("F*x0".into()),
            moment: None,
            unknowns: vec![],
            label: Some("la poussée".into()),
        }],
        pfd: vec![
            TheoremSpec {
                isolate: "E".into(),
                theorem: TheoremKind::Resultant,
                point: None,
                on: Some("x0".into()),
                eom: Some("x".into()),
            },
            TheoremSpec {
                isolate: "2".into(),
                theorem: TheoremKind::Moment,
                point: Some("A".into()),
                on: Some("z0".into()),
                eom: Some("theta".into()),
            },
        ],
        small: vec![SmallSpec {
            coordinate: "theta".into(),
            around: None,
        }],
        quantities: vec!["eom(x)".into(), "eom(theta)".into()],
        ..SpecFile::default()
    };
    let m = torseur::spec::build(&spec)?;
    for q in ["eom(x)", "eom(theta)", "lin(eom(theta))"] {
        let d = derive(&m, &Quantity::parse(q)?)?;
        println!("{q} = {}", d.value.exprs()[0].presentation());
    }
    // By hand: (M + m) ẍ + m l (θ̈ cos θ − θ̇² sin θ) − F = 0 and
    // (J + m l²) θ̈ + m l ẍ cos θ + m g l sin θ = 0.
    torseur::assert_equivalent!(
        m,
        "eom(x)",
        "(M + m)*ddot(x) + m*l*(ddot(theta)*cos(theta) - dot(theta)^2*sin(theta)) - F"
    );
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        "(J + m*l^2)*ddot(theta) + m*l*ddot(x)*cos(theta) + m*g*l*sin(theta)"
    );
    let report = torseur::check::check(&m, 10, 1)?;
    assert!(report.passed(), "{report}");
    println!("float backend: {} rows agree", report.rows.len());
    Ok(())
}
