//! Surface construction, checked exactly on the rational back end: the worked examples of
//! [FJ-surfaces, §7] (tensor interpolation of bidegree (2, 3), least squares of bidegree
//! (1, 1)) from `tests/fixtures/`; tensor interpolation reproduces its data; least squares on
//! data sampled from a surface on the fitted knots returns that surface; lofting passes
//! through its curves (of different degrees and knots); the bilinear patch is the formula of
//! [RD, §3.3]; the piecewise bicubic interpolant of [PPB, §9.8] interpolates and is C¹; bad
//! input gives named errors.

use crate::spline_common::{q, qi, Q};
use compgeo::spline::{BSpline, Curve, CurveDerivative, KnotVector, Parameterisation, Point};
use compgeo::surface::{
    BSplineSurface, BezierPatch, BezierPatchGrid, ControlNet, Direction, Surface, SurfaceDerivative,
};
use compgeo::Error;
use proptest::prelude::*;

fn fixture(name: &str) -> String {
    std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures")
            .join(name),
    )
    .unwrap()
}

fn rational(s: &str) -> Q {
    match s.split_once('/') {
        Some((n, d)) => q(n.parse().unwrap(), d.parse().unwrap()),
        None => qi(s.parse().unwrap()),
    }
}

fn point3(words: &[&str]) -> Point<Q, 3> {
    Point::new([rational(words[0]), rational(words[1]), rational(words[2])])
}

/// The lines of a fixture starting with `tag`, split into words after the tag.
fn lines<'a>(text: &'a str, tag: &str) -> Vec<Vec<&'a str>> {
    text.lines()
        .filter_map(|l| {
            l.strip_prefix(tag)
                .map(|rest| rest.split_whitespace().collect())
        })
        .collect()
}

#[test]
fn worked_example_of_tensor_interpolation() {
    let text = fixture("fj_surfaces_interpolation_2_3.txt");
    let (us, vs) = (
        [q(0, 1), q(1, 2), q(1, 1)],
        [q(0, 1), q(1, 3), q(2, 3), q(1, 1)],
    );
    let mut data = vec![vec![Point::zero(); 4]; 3];
    let conditions = lines(&text, "at ");
    assert_eq!(conditions.len(), 12);
    for w in conditions {
        let (u, v) = (rational(w[0]), rational(w[1]));
        let i = us.iter().position(|x| *x == u).unwrap();
        let j = vs.iter().position(|x| *x == v).unwrap();
        data[i][j] = point3(&w[2..]);
    }
    let want: Vec<Vec<Point<Q, 3>>> = lines(&text, "net ")
        .iter()
        .map(|w| {
            w.join(" ")
                .split('|')
                .map(|p| point3(&p.split_whitespace().collect::<Vec<_>>()))
                .collect()
        })
        .collect();
    let data = ControlNet::new(data).unwrap();
    let patch = BezierPatch::interpolate(&data, &us, &vs).unwrap();
    assert_eq!(patch.net().to_rows(), want);
    // The same net as a B-spline surface on the Bézier knots, columns first by transposing.
    let t = |n: usize| KnotVector::clamped_uniform(n - 1, n, qi(0), qi(1)).unwrap();
    let s = BSplineSurface::interpolate_at(&data.transposed(), &vs, &us, t(4), t(3)).unwrap();
    assert_eq!(s.net().transposed().to_rows(), want);
    // And the printed parametrisation's z at a point off the grid: c(u, v)_z with u = 1/4,
    // v = 1/2 from 27/2(uv³ − uv²) + 9v³ + 18(u²v² − v² − u²v³) + 3uv + 8v + 4(u − u² − u²v).
    let (u, v) = (q(1, 4), q(1, 2));
    let z = q(27, 2) * (u.clone() * v.pow(3) - u.clone() * v.pow(2))
        + qi(9) * v.pow(3)
        + qi(18) * (u.pow(2) * v.pow(2) - v.pow(2) - u.pow(2) * v.pow(3))
        + qi(3) * &u * &v
        + qi(8) * &v
        + qi(4) * (u.clone() - u.pow(2) - u.pow(2) * &v);
    assert_eq!(patch.eval(&u, &v).unwrap()[2], z);
}

#[test]
fn worked_example_of_least_squares() {
    let text = fixture("fj_surfaces_least_squares_1_1.txt");
    let data = lines(&text, "at ");
    let us: Vec<Q> = data.iter().map(|w| rational(w[0])).collect();
    let vs: Vec<Q> = data.iter().map(|w| rational(w[1])).collect();
    let points: Vec<Point<Q, 3>> = data.iter().map(|w| point3(&w[2..])).collect();
    let patch = BezierPatch::fit(&points, &us, &vs, (1, 1)).unwrap();
    for w in lines(&text, "c ") {
        let (i, j): (usize, usize) = (w[0].parse().unwrap(), w[1].parse().unwrap());
        assert_eq!(patch.net().get(i, j), &point3(&w[2..]), "c_{i},{j}");
    }
}

/// A random grid of (2..=5) × (2..=5) integer points in R³ with increasing rational
/// parameters in [0, 1] (0 and 1 included).
fn grid() -> impl Strategy<Value = (ControlNet<Q, 3>, Vec<Q>, Vec<Q>)> {
    (2usize..=5, 2usize..=5)
        .prop_flat_map(|(m, n)| {
            (
                prop::collection::vec((-9i64..=9, -9i64..=9, -9i64..=9), m * n),
                Just((m, n)),
                prop::collection::btree_set(1i64..24, m - 2),
                prop::collection::btree_set(1i64..24, n - 2),
            )
        })
        .prop_map(|(pts, (m, n), iu, iv)| {
            let points = pts
                .into_iter()
                .map(|(x, y, z)| Point::new([qi(x), qi(y), qi(z)]))
                .collect();
            let params = |inner: std::collections::BTreeSet<i64>| {
                let mut p = vec![qi(0)];
                p.extend(inner.into_iter().map(|k| q(k, 24)));
                p.push(qi(1));
                p
            };
            (
                ControlNet::from_rows(m, n, points).unwrap(),
                params(iu),
                params(iv),
            )
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn interpolation_reproduces_its_data((data, us, vs) in grid(), p in 1usize..=3, qd in 1usize..=3) {
        let (p, qd) = (p.min(us.len() - 1), qd.min(vs.len() - 1));
        let tu = KnotVector::averaged(p, &us).unwrap();
        let tv = KnotVector::averaged(qd, &vs).unwrap();
        let s = BSplineSurface::interpolate_at(&data, &us, &vs, tu, tv).unwrap();
        let b = BezierPatch::interpolate(&data, &us, &vs).unwrap();
        for (i, u) in us.iter().enumerate() {
            for (j, v) in vs.iter().enumerate() {
                prop_assert_eq!(&s.eval(u, v).unwrap(), data.get(i, j));
                prop_assert_eq!(&b.eval(u, v).unwrap(), data.get(i, j));
            }
        }
        // Computed parameters: uniform ones are i/(M − 1).
        let s = BSplineSurface::interpolate(&data, (p, qd), Parameterisation::Uniform).unwrap();
        for i in 0..data.rows() {
            for j in 0..data.columns() {
                let (u, v) = (q(i as i64, data.rows() as i64 - 1), q(j as i64, data.columns() as i64 - 1));
                prop_assert_eq!(&s.eval(&u, &v).unwrap(), data.get(i, j));
            }
        }
    }

    #[test]
    fn least_squares_returns_the_sampled_surface((data, _, _) in grid(), p in 1usize..=2, qd in 1usize..=2, cut_u in 1i64..=3, cut_v in 1i64..=3) {
        let (m, n) = (data.rows(), data.columns());
        let (p, qd) = (p.min(m - 1), qd.min(n - 1));
        let knots = |d: usize, count: usize, cut: i64| {
            let mut t = vec![qi(0); d + 1];
            t.extend((1..count - d).map(|k| q(k as i64 * cut, (count - d) as i64 * 3)));
            t.extend(vec![qi(1); d + 1]);
            KnotVector::new(d, t).unwrap()
        };
        let s = BSplineSurface::new(data.clone(), knots(p, m, cut_u), knots(qd, n, cut_v)).unwrap();
        // Samples on a grid fine enough for every basis product: 3 per knot span and more.
        let (mut pts, mut us, mut vs) = (vec![], vec![], vec![]);
        let steps = 3 * (m.max(n) as i64 + 1);
        for a in 0..=steps {
            for b in 0..=steps {
                let (u, v) = (q(a, steps), q(b, steps));
                pts.push(s.eval(&u, &v).unwrap());
                us.push(u);
                vs.push(v);
            }
        }
        let f = BSplineSurface::fit(&pts, &us, &vs, s.u_knots().clone(), s.v_knots().clone()).unwrap();
        prop_assert_eq!(f.net(), s.net());
        // A Bézier patch of the bidegree, sampled and fitted.
        let b = BezierPatch::new(data.clone()).unwrap();
        let pts: Vec<_> = us.iter().zip(&vs).map(|(u, v)| b.eval(u, v).unwrap()).collect();
        let f = BezierPatch::fit(&pts, &us, &vs, b.bidegree()).unwrap();
        prop_assert_eq!(f.net(), b.net());
    }

    #[test]
    fn lofting_passes_through_its_curves(
        degrees in prop::collection::vec(1usize..=3, 2..=4),
        inner in prop::collection::vec(prop::collection::btree_set(1i64..6, 0..=2), 4),
        coords in prop::collection::vec((-9i64..=9, -9i64..=9), 40),
    ) {
        let mut next = coords.iter();
        let curves: Vec<BSpline<Q, 2>> = degrees
            .iter()
            .zip(&inner)
            .map(|(d, interior)| {
                let mut t = vec![qi(0); d + 1];
                t.extend(interior.iter().map(|k| qi(*k)));
                t.extend(vec![qi(6); d + 1]);
                let t = KnotVector::new(*d, t).unwrap();
                let c = (0..t.control_points()).map(|_| {
                    let (x, y) = next.next().unwrap();
                    Point::new([qi(*x), qi(*y)])
                }).collect();
                BSpline::new(c, t).unwrap()
            })
            .collect();
        let k = curves.len();
        let params: Vec<Q> = (0..k).map(|i| q(i as i64, k as i64 - 1)).collect();
        let degree = (k - 1).min(2);
        let knots = KnotVector::averaged(degree, &params).unwrap();
        let along_v = BSplineSurface::loft(&curves, Direction::V, &params, knots.clone()).unwrap();
        let along_u = BSplineSurface::loft(&curves, Direction::U, &params, knots).unwrap();
        for (c, t) in curves.iter().zip(&params) {
            for x in (0..=12).map(|a| q(a, 2)) {
                let want = c.eval(&x).unwrap();
                prop_assert_eq!(along_v.eval(&x, t).unwrap(), want.clone());
                prop_assert_eq!(along_u.eval(t, &x).unwrap(), want);
            }
        }
    }

    #[test]
    fn bicubic_interpolation_interpolates_and_is_c1((data, us, vs) in grid()) {
        let g = BezierPatchGrid::bicubic_c1(&data, &us, &vs).unwrap();
        for (i, u) in us.iter().enumerate() {
            for (j, v) in vs.iter().enumerate() {
                prop_assert_eq!(&g.eval(u, v).unwrap(), data.get(i, j));
            }
        }
        let ts: Vec<Q> = (0..=4).map(|k| q(k, 4)).collect();
        let h = |p: &[Q], a: usize| p[a + 1].clone() - &p[a];
        // Across every inner line u = u_a: the value and both first partials agree.
        for a in 1..us.len() - 1 {
            for b in 0..vs.len() - 1 {
                let (left, right) = (g.patch(a - 1, b), g.patch(a, b));
                for t in &ts {
                    let (one, zero) = (qi(1), qi(0));
                    prop_assert_eq!(left.eval(&one, t).unwrap(), right.eval(&zero, t).unwrap());
                    prop_assert_eq!(
                        left.partial_at(&one, t, 1, 0).unwrap() / &h(&us, a - 1),
                        right.partial_at(&zero, t, 1, 0).unwrap() / &h(&us, a)
                    );
                    prop_assert_eq!(left.partial_at(&one, t, 0, 1).unwrap(), right.partial_at(&zero, t, 0, 1).unwrap());
                }
            }
        }
        // Across every inner line v = v_b.
        for b in 1..vs.len() - 1 {
            for a in 0..us.len() - 1 {
                let (low, high) = (g.patch(a, b - 1), g.patch(a, b));
                for t in &ts {
                    let (one, zero) = (qi(1), qi(0));
                    prop_assert_eq!(low.eval(t, &one).unwrap(), high.eval(t, &zero).unwrap());
                    prop_assert_eq!(
                        low.partial_at(t, &one, 0, 1).unwrap() / &h(&vs, b - 1),
                        high.partial_at(t, &zero, 0, 1).unwrap() / &h(&vs, b)
                    );
                    prop_assert_eq!(low.partial_at(t, &one, 1, 0).unwrap(), high.partial_at(t, &zero, 1, 0).unwrap());
                }
            }
        }
    }
}

#[test]
fn bilinear_patch_is_the_formula_of_the_notes() {
    // [RD, §3.3]: P(x, y) = z00 + (z10 − z00)x + (z01 − z00)y + (z00 − z01 − z10 + z11)xy on
    // [0, 1]².
    let z = [qi(2), q(-1, 3), qi(5), q(7, 2)]; // z00, z01, z10, z11
    let p = |x: i64, y: i64, z: &Q| Point::new([qi(x), qi(y), z.clone()]);
    let s = BezierPatch::bilinear(
        p(0, 0, &z[0]),
        p(0, 1, &z[1]),
        p(1, 0, &z[2]),
        p(1, 1, &z[3]),
    )
    .unwrap();
    for x in (0..=5).map(|k| q(k, 5)) {
        for y in (0..=3).map(|k| q(k, 3)) {
            let want = z[0].clone()
                + (z[2].clone() - &z[0]) * &x
                + (z[1].clone() - &z[0]) * &y
                + (z[0].clone() - &z[1] - &z[2] + &z[3]) * &x * &y;
            let got = s.eval(&x, &y).unwrap();
            assert_eq!(got, Point::new([x.clone(), y.clone(), want]));
        }
    }
}

#[test]
fn lofted_curves_stay_the_curves_after_compatibility() {
    // A quadratic with an interior knot and a line: the loft's u curves share one degree and
    // knot vector, and the isoparametric curves at the parameters are the given curves.
    let line = BSpline::new(
        vec![Point::new([qi(0)]), Point::new([qi(6)])],
        KnotVector::clamped_uniform(1, 2, qi(0), qi(6)).unwrap(),
    )
    .unwrap();
    let t = KnotVector::new(2, [0, 0, 0, 2, 6, 6, 6].map(qi).to_vec()).unwrap();
    let quad = BSpline::new([1, 5, -3, 2].map(|x| Point::new([qi(x)])).to_vec(), t).unwrap();
    let params = [qi(0), qi(1)];
    let s = BSplineSurface::loft(
        &[line.clone(), quad.clone()],
        Direction::V,
        &params,
        KnotVector::clamped_uniform(1, 2, qi(0), qi(1)).unwrap(),
    )
    .unwrap();
    assert_eq!(s.bidegree(), (2, 1));
    assert_eq!(s.u_knots().knots(), [0, 0, 0, 2, 6, 6, 6].map(qi));
    for (c, v) in [(&line, &params[0]), (&quad, &params[1])] {
        let iso = s.isocurve(Direction::V, v).unwrap();
        for u in (0..=12).map(|k| q(k, 2)) {
            assert_eq!(iso.eval(&u).unwrap(), c.eval(&u).unwrap());
            assert_eq!(
                iso.derivative_at(&u, 1).unwrap(),
                c.derivative_at(&u, 1).unwrap()
            );
        }
    }
}

fn invalid_name(e: Error) -> &'static str {
    match e {
        Error::InvalidParameter { name, .. } => name,
        other => panic!("not an invalid parameter: {other:?}"),
    }
}

#[test]
fn bad_construction_input_gives_named_errors() {
    let data = ControlNet::new(
        (0..3)
            .map(|i| (0..3).map(|j| Point::new([i as f64, j as f64])).collect())
            .collect(),
    )
    .unwrap();
    let t = KnotVector::clamped_uniform(2, 3, 0.0, 1.0).unwrap();
    let ok = [0.0, 0.5, 1.0];
    // Repeated, decreasing, NaN, outside the domain, wrong count.
    for bad in [
        [0.0, 0.0, 1.0],
        [0.0, 0.7, 0.5],
        [0.0, f64::NAN, 1.0],
        [0.0, 0.5, 1.5],
    ] {
        let e = BSplineSurface::interpolate_at(&data, &bad, &ok, t.clone(), t.clone()).unwrap_err();
        assert_eq!(invalid_name(e), "u parameters", "{bad:?}");
        let e = BezierPatch::interpolate(&data, &ok, &bad).unwrap_err();
        assert_eq!(invalid_name(e), "v parameters", "{bad:?}");
    }
    let e = BSplineSurface::interpolate_at(&data, &ok[..2], &ok, t.clone(), t.clone()).unwrap_err();
    assert_eq!(invalid_name(e), "u parameters");
    let t4 = KnotVector::clamped_uniform(2, 4, 0.0, 1.0).unwrap();
    let e = BSplineSurface::interpolate_at(&data, &ok, &ok, t4.clone(), t.clone()).unwrap_err();
    assert_eq!(invalid_name(e), "u knots");
    // Schoenberg–Whitney: a cubic's parameters crowded into one span.
    let data4 = ControlNet::new(
        (0..4)
            .map(|i| (0..3).map(|j| Point::new([i as f64, j as f64])).collect())
            .collect(),
    )
    .unwrap();
    let tw = KnotVector::new(1, vec![0.0, 0.0, 0.5, 0.75, 1.0, 1.0]).unwrap();
    let e = BSplineSurface::interpolate_at(&data4, &[0.0, 0.1, 0.2, 1.0], &ok, tw, t.clone())
        .unwrap_err();
    assert_eq!(invalid_name(e), "u parameters");
    // Least squares: mismatched counts, outside the domain, NaN data, too few data.
    let pts = vec![Point::new([0.0, 0.0]); 4];
    let e = BSplineSurface::fit(&pts, &[0.0; 3], &[0.0; 4], t.clone(), t.clone()).unwrap_err();
    assert_eq!(invalid_name(e), "params");
    let e = BSplineSurface::fit(&pts, &[0.0, 0.5, 2.0, 1.0], &[0.0; 4], t.clone(), t.clone())
        .unwrap_err();
    assert_eq!(invalid_name(e), "u parameters");
    let mut nan = pts.clone();
    nan[1] = Point::new([f64::NAN, 0.0]);
    assert!(matches!(
        BSplineSurface::fit(&nan, &[0.0; 4], &[0.0; 4], t.clone(), t.clone()),
        Err(Error::NonFinite { index: 1, .. })
    ));
    let e = BSplineSurface::fit(
        &pts,
        &[0.0, 0.5, 1.0, 0.25],
        &[0.0, 0.5, 1.0, 0.25],
        t.clone(),
        t.clone(),
    )
    .unwrap_err();
    assert_eq!(invalid_name(e), "params");
    assert!(e_contains(
        BSplineSurface::fit(
            &pts,
            &[0.0, 0.5, 1.0, 0.25],
            &[0.0, 0.5, 1.0, 0.25],
            t.clone(),
            t.clone()
        )
        .unwrap_err(),
        "not unique"
    ));
    // A rank-deficient fit whose every basis function sees data: bilinear, data at the
    // corners (0, 0) and (1, 1) and twice at the centre; c_{0,1} and c_{1,0} only meet the
    // centre, with equal weights, so their columns of the collocation matrix coincide.
    let tl = KnotVector::clamped_uniform(1, 2, 0.0, 1.0).unwrap();
    let pts3 = vec![Point::new([0.0, 0.0]); 4];
    let e = BSplineSurface::fit(
        &pts3,
        &[0.0, 1.0, 0.5, 0.5],
        &[0.0, 1.0, 0.5, 0.5],
        tl.clone(),
        tl.clone(),
    )
    .unwrap_err();
    assert!(e_contains(e, "rank"));
    // Lofting: different domains, repeated parameters.
    let c = |end: f64| {
        BSpline::new(
            vec![Point::new([0.0]), Point::new([1.0])],
            KnotVector::clamped_uniform(1, 2, 0.0, end).unwrap(),
        )
        .unwrap()
    };
    let e =
        BSplineSurface::loft(&[c(1.0), c(2.0)], Direction::V, &[0.0, 1.0], tl.clone()).unwrap_err();
    assert_eq!(invalid_name(e), "curves");
    let e =
        BSplineSurface::loft(&[c(1.0), c(1.0)], Direction::U, &[0.0, 0.0], tl.clone()).unwrap_err();
    assert_eq!(invalid_name(e), "u parameters");
    assert!(matches!(
        BSplineSurface::<f64, 1>::loft(&[], Direction::U, &[], tl),
        Err(Error::Empty { .. })
    ));
    // Bicubic: too few rows, repeated parameters.
    let row = ControlNet::new(vec![vec![Point::new([0.0]), Point::new([1.0])]]).unwrap();
    assert!(matches!(
        BezierPatchGrid::bicubic_c1(&row, &[0.0], &[0.0, 1.0]),
        Err(Error::TooFew { .. })
    ));
    let e = BezierPatchGrid::bicubic_c1(&data, &ok, &[0.0, 1.0, 1.0]).unwrap_err();
    assert_eq!(invalid_name(e), "v parameters");
}

fn e_contains(e: Error, text: &str) -> bool {
    e.to_string().contains(text)
}
