//! One sampling function for every curve type: a natural cubic spline, the polynomial in
//! Lagrange form and a Bézier curve through the same points, sampled with their tangents by
//! code written once over the curve traits.
//!
//! Run with `cargo run --example curves`.

use compgeo::spline::{
    cubic_spline, lagrange, Bezier, CurveDerivative, EndCondition, Point, Subsegment,
};

/// Prints `count + 1` points of `curve` over [a, b] with the tangent at each.
fn print_samples<C: CurveDerivative<f64, 2>>(name: &str, curve: &C, a: f64, b: f64, count: u32) {
    println!("{name}:");
    for k in 0..=count {
        let u = a + (b - a) * f64::from(k) / f64::from(count);
        let p = curve.eval(&u).expect("u is in the domain");
        let d = curve.derivative_at(&u, 1).expect("u is in the domain");
        println!(
            "  u = {u:5.2}  point ({:7.3}, {:7.3})  tangent ({:7.3}, {:7.3})",
            p[0], p[1], d[0], d[1]
        );
    }
}

fn main() -> Result<(), compgeo::Error> {
    let knots = [0.0, 1.0, 2.0, 3.0];
    let points = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 4.0]].map(Point::new);

    let spline = cubic_spline(&knots, &points, &EndCondition::Natural)?;
    print_samples("natural cubic spline", &spline, 0.0, 3.0, 6);

    let polynomial = lagrange(&knots, &points)?;
    print_samples("interpolating polynomial", &polynomial, 0.0, 3.0, 6);

    // The same four points as a Bézier control polygon, and its piece over [1/4, 3/4]: the
    // piece keeps the parameter, so it samples the same points as the curve there.
    let bezier = Bezier::new(points.to_vec())?;
    print_samples("Bézier curve", &bezier, 0.0, 1.0, 4);
    let piece = bezier.subsegment(&0.25, &0.75)?;
    print_samples("its piece over [1/4, 3/4]", &piece, 0.25, 0.75, 2);
    Ok(())
}
