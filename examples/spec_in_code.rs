//! A mechanism built in Rust with `torseur::spec::Builder`, validated as a spec file is: a
//! pendulum on a cart pushed by F, checked against a derivation by hand. Run: `cargo run
//! --release --example spec_in_code`
use torseur::spec::Builder;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let m = Builder::new("Pendule sur chariot")
        .parameters("kg", &["M", "m"])
        .parameters("kg m^2", &["A", "B", "J"])
        .parameters("m", &["l"])
        .parameter("g", "m/s^2")
        .parameter("F", "N")
        .length("x")
        .angle("theta")
        .frame("1", "0", "P")
        .rotating_frame("2", "1", "z", "theta", "P")
        .point("P", "O0", "x*x0")
        .point("G", "P", "-l*y2")
        .solid("1", "M", "P")
        .solid("2", "m", "G")
        .principal_inertia("G", "2", ["A", "B", "J"])
        .set_of("E", &["1", "2"])
        .gravity("-g*y0")
        .slider("01", ["0", "1"], "P", "x0")
        .pivot("12", ["1", "2"], "P", "z0")
        .force("poussee", "0", "1", "P", "F*x0")
        .resultant("E", "x0")
        .eom("x")
        .moment("2", "P", "z0")
        .eom("theta")
        .build()?;
    // By hand: (M + m) ẍ + m l (θ̈ cos θ − θ̇² sin θ) − F = 0, (J + m l²) θ̈ + m l ẍ cos θ + m g l sin θ = 0.
    let eom_x = "(M + m)*ddot(x) + m*l*(ddot(theta)*cos(theta) - dot(theta)^2*sin(theta)) - F";
    torseur::assert_equivalent!(m, "eom(x)", eom_x);
    let eom_theta = "(J + m*l^2)*ddot(theta) + m*l*ddot(x)*cos(theta) + m*g*l*sin(theta)";
    torseur::assert_equivalent!(m, "eom(theta)", eom_theta);
    println!("eom(x) and eom(theta) as derived by hand");
    Ok(())
}
