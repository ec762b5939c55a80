//! The worked examples of [FJ-surfaces, §4–§6] and [PPB, §9.4–§9.6] on Bézier patches,
//! checked exactly on the rational back end against the answers printed in the texts
//! (copied into `tests/fixtures/fj_surfaces_restrict_elevate_join.txt` and
//! `tests/fixtures/ppb_ch9_de_casteljau.txt`, with their lines): restriction to a
//! sub-rectangle (and its rows-first intermediate net), degree elevation in u and in v (with
//! the erratum of line 320), the C⁰-but-not-C¹ join of two biquadratic patches with their
//! parametrisations, edge differences, partials and normals; the subdivision of
//! [PPB, §9.5, Obs. 9]; bilinear precision [PPB, §9.4, Obs. 5]; the twist at a corner
//! [PPB, §9.6].

use crate::spline_common::{q, qi, Q};
use compgeo::spline::{Point, Scalar};
use compgeo::surface::{normal, BezierPatch, ControlNet, Normal, Surface, SurfaceDerivative};

/// A fixture, as (key, rest of the line) pairs, comments skipped.
fn fixture(name: &str) -> Vec<(String, String)> {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures")
            .join(name),
    )
    .unwrap();
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (key, rest) = l.split_once(' ').unwrap();
            (key.to_string(), rest.to_string())
        })
        .collect()
}

/// "a" or "a/b" as a rational.
fn rational(text: &str) -> Q {
    match text.trim().split_once('/') {
        Some((n, d)) => q(n.parse().unwrap(), d.parse().unwrap()),
        None => qi(text.trim().parse().unwrap()),
    }
}

/// The "(x, y, z)" groups of a line.
fn triples(line: &str) -> Vec<Point<Q, 3>> {
    line.split('(')
        .skip(1)
        .map(|group| {
            let xs: Vec<Q> = group[..group.find(')').unwrap()]
                .split(',')
                .map(rational)
                .collect();
            Point::new([xs[0].clone(), xs[1].clone(), xs[2].clone()])
        })
        .collect()
}

/// The rows of the lines with this key, as a net.
fn net(lines: &[(String, String)], key: &str) -> ControlNet<Q, 3> {
    ControlNet::new(
        lines
            .iter()
            .filter(|(k, _)| k == key)
            .map(|(_, rest)| triples(rest))
            .collect(),
    )
    .unwrap()
}

fn patch(lines: &[(String, String)], key: &str) -> BezierPatch<Q, 3> {
    BezierPatch::new(net(lines, key)).unwrap()
}

const FJ: &str = "fj_surfaces_restrict_elevate_join.txt";

#[test]
fn restriction_to_a_sub_rectangle_is_the_printed_net() {
    let lines = fixture(FJ);
    let s = patch(&lines, "restrict.net");
    let bounds: Vec<Q> = lines
        .iter()
        .find(|(k, _)| k == "restrict.rectangle")
        .unwrap()
        .1
        .split_whitespace()
        .map(rational)
        .collect();
    let (a, b, c, d) = (&bounds[0], &bounds[1], &bounds[2], &bounds[3]);
    let r = s.restrict(a, b, c, d).unwrap();
    assert_eq!(r.net(), &net(&lines, "restrict.want"));
    // The text's two steps: rows to [1/3, 1] first (u untouched), then the columns.
    let rows_only = s.restrict(&qi(0), &qi(1), c, d).unwrap();
    assert_eq!(rows_only.net(), &net(&lines, "restrict.rows_only"));
    assert_eq!(rows_only.restrict(a, b, &qi(0), &qi(1)).unwrap(), r);
    // Eq. (13): the new net is the blossom at a's and b's, c's and d's.
    for i in 0..=2 {
        for j in 0..=2 {
            let us: Vec<Q> = (0..2)
                .map(|k| if k < 2 - i { a.clone() } else { b.clone() })
                .collect();
            let vs: Vec<Q> = (0..2)
                .map(|k| if k < 2 - j { c.clone() } else { d.clone() })
                .collect();
            assert_eq!(&s.blossom(&us, &vs).unwrap(), r.net().get(i, j));
        }
    }
}

#[test]
fn elevation_in_u_and_in_v_is_the_printed_net_with_the_erratum() {
    let lines = fixture(FJ);
    let s = patch(&lines, "restrict.net");
    let up = s.elevate_u().unwrap();
    assert_eq!(up.bidegree(), (3, 2));
    assert_eq!(up.net(), &net(&lines, "elevate_u.want"));
    // Line 320 prints (0, 4/3, 11/3) for c_{1,2}^{1,0}; (2c_{1,2} + c_{0,2})/3 is
    // (2, 4/3, 11/3), as line 339 prints it.
    assert_eq!(up.net().get(1, 2), &Point::new([qi(2), q(4, 3), q(11, 3)]));
    let right = s.elevate_v().unwrap();
    assert_eq!(right.bidegree(), (2, 3));
    assert_eq!(right.net(), &net(&lines, "elevate_v.want"));
    assert_eq!(s.elevate_to(3, 3).unwrap(), up.elevate_v().unwrap());
}

/// Σ coefficient·u^a·v^b over the terms of one patch of the fixture.
fn parametrisation(lines: &[(String, String)], which: i64, u: &Q, v: &Q) -> Point<Q, 3> {
    let mut xs = [qi(0), qi(0), qi(0)];
    for (_, rest) in lines.iter().filter(|(k, _)| k == "term") {
        let t: Vec<i64> = rest
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect();
        if t[0] == which {
            xs[t[1] as usize] += qi(t[4]) * u.pow(t[2] as i32) * v.pow(t[3] as i32);
        }
    }
    Point::new(xs)
}

/// The polynomials in v of an "edge." line at v.
fn edge(lines: &[(String, String)], key: &str, v: &Q) -> Point<Q, 3> {
    let groups = triples(&lines.iter().find(|(k, _)| k == key).unwrap().1);
    let value = |g: &Point<Q, 3>| g[0].clone() + g[1].clone() * v + g[2].clone() * v * v;
    Point::new([value(&groups[0]), value(&groups[1]), value(&groups[2])])
}

#[test]
fn the_two_biquadratic_patches_meet_c0_but_not_c1() {
    let lines = fixture(FJ);
    let first = patch(&lines, "join.first");
    let second = patch(&lines, "join.second");
    // Their parametrisations, printed in the monomial basis.
    for (a, b) in [(0, 0), (1, 2), (3, 1), (-2, 5), (7, 9)] {
        let (u, v) = (q(a, 3), q(b, 4));
        assert_eq!(
            first.eval(&u, &v).unwrap(),
            parametrisation(&lines, 1, &u, &v)
        );
        assert_eq!(
            second.eval(&u, &v).unwrap(),
            parametrisation(&lines, 2, &u, &v)
        );
    }
    let coefficients = |which: i64| {
        let mut rows = vec![vec![Point::zero(); 3]; 3];
        for (_, rest) in lines.iter().filter(|(k, _)| k == "term") {
            let t: Vec<i64> = rest
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            if t[0] == which {
                let p: &mut Point<Q, 3> = &mut rows[t[2] as usize][t[3] as usize];
                let mut xs = p.coords().clone();
                xs[t[1] as usize] += qi(t[4]);
                *p = Point::new(xs);
            }
        }
        ControlNet::new(rows).unwrap()
    };
    assert_eq!(first.to_monomial().unwrap(), coefficients(1));
    assert_eq!(second.to_monomial().unwrap(), coefficients(2));
    assert_eq!(
        BezierPatch::from_monomial(&coefficients(2)).unwrap(),
        second
    );
    // The differences of the rows next to the edge, from the u-derivative nets (÷ m = 2).
    let half = q(1, 2);
    let du1 = first.derivative_net(1, 0).unwrap();
    let du2 = second.derivative_net(1, 0).unwrap();
    let scaled = |row: &[Point<Q, 3>]| row.iter().map(|p| p.clone() * &half).collect::<Vec<_>>();
    assert_eq!(
        scaled(du1.net().row(1)),
        triples(
            &lines
                .iter()
                .find(|(k, _)| k == "join.first_differences")
                .unwrap()
                .1
        )
    );
    assert_eq!(
        scaled(du2.net().row(0)),
        triples(
            &lines
                .iter()
                .find(|(k, _)| k == "join.second_differences")
                .unwrap()
                .1
        )
    );
    // C⁰ and not C¹ over [0, 1, 2].
    let knots = [qi(0), qi(1), qi(2)];
    assert_eq!(first.join_u(&second, &knots, &qi(0)).unwrap(), Some(0));
    // The partials and normals along the edge, and the two normals are not parallel.
    for k in 0..=8 {
        let v = q(k, 8);
        let (one, zero) = (qi(1), qi(0));
        assert_eq!(
            first.partial_at(&one, &v, 1, 0).unwrap(),
            edge(&lines, "edge.first_cu", &v)
        );
        assert_eq!(
            second.partial_at(&zero, &v, 1, 0).unwrap(),
            edge(&lines, "edge.second_cu", &v)
        );
        assert_eq!(
            first.partial_at(&one, &v, 0, 1).unwrap(),
            edge(&lines, "edge.cv", &v)
        );
        assert_eq!(
            second.partial_at(&zero, &v, 0, 1).unwrap(),
            edge(&lines, "edge.cv", &v)
        );
        let n1 = edge(&lines, "edge.first_normal", &v);
        let n2 = edge(&lines, "edge.second_normal", &v);
        assert_eq!(
            normal(&first, &one, &v).unwrap(),
            Normal::Regular(n1.clone())
        );
        assert_eq!(
            normal(&second, &zero, &v).unwrap(),
            Normal::Regular(n2.clone())
        );
        // Parallel only at the ends of the edge, v = 0 and v = 1 (line 440).
        let cross = [
            n1[1].clone() * &n2[2] - n1[2].clone() * &n2[1],
            n1[2].clone() * &n2[0] - n1[0].clone() * &n2[2],
            n1[0].clone() * &n2[1] - n1[1].clone() * &n2[0],
        ];
        assert_eq!(
            cross.iter().all(Scalar::is_zero),
            k == 0 || k == 8,
            "v = {v}"
        );
    }
}

#[test]
fn the_subdivision_of_ppb_9_5_observation_9() {
    let lines = fixture("ppb_ch9_de_casteljau.txt");
    // Each printed matrix transposed: entry (r, c) is b_{c, r}.
    let read = |key: &str| {
        let rows: Vec<Vec<i64>> = lines
            .iter()
            .filter(|(k, _)| k == key)
            .map(|(_, rest)| {
                rest.split_whitespace()
                    .map(|x| x.parse().unwrap())
                    .collect()
            })
            .collect();
        let net = (0..4)
            .map(|i| (0..3).map(|j| Point::new([qi(rows[j][i])])).collect())
            .collect();
        BezierPatch::new(ControlNet::new(net).unwrap()).unwrap()
    };
    let (low, high) = (read("low"), read("high"));
    assert_eq!(low.bidegree(), (3, 2));
    // The whole polynomial over [0, 1]²: the low piece restricted to v in [0, 2].
    let whole = low.restrict(&qi(0), &qi(1), &qi(0), &qi(2)).unwrap();
    assert_eq!(
        whole.split_v(&q(1, 2)).unwrap(),
        (low.clone(), high.clone())
    );
    // Obs. 8: the pieces are read off de Casteljau's scheme, so they meet along v = 1/2.
    assert_eq!(
        low.curve_at_v(&qi(1)).unwrap(),
        whole.curve_at_v(&q(1, 2)).unwrap()
    );
    // Obs. 7: rows first, columns first and the tensor scheme agree at (2/3, 1/2).
    let (u, v) = (q(2, 3), q(1, 2));
    let point = whole.rows_first(&u, &v).unwrap();
    assert_eq!(whole.columns_first(&u, &v).unwrap(), point);
    assert_eq!(whole.de_casteljau(&u, &v).unwrap(), point);
    assert_eq!(low.eval(&u, &qi(1)).unwrap(), point);
}

#[test]
fn bilinear_precision_and_the_corner_twist() {
    // [PPB, §9.4, Obs. 5]: a bilinear map elevated to (m, n) has b_{i,j} = b(i/m, j/n).
    let p = |x: i64, y: i64, z: i64| Point::new([qi(x), qi(y), qi(z)]);
    let bilinear = BezierPatch::new(
        ControlNet::new(vec![
            vec![p(0, 0, 1), p(1, 3, 0)],
            vec![p(4, 1, -2), p(2, 2, 7)],
        ])
        .unwrap(),
    )
    .unwrap();
    let (m, n) = (4usize, 3usize);
    let e = bilinear.elevate_to(m, n).unwrap();
    for i in 0..=m {
        for j in 0..=n {
            let want = bilinear
                .eval(&q(i as i64, m as i64), &q(j as i64, n as i64))
                .unwrap();
            assert_eq!(e.net().get(i, j), &want);
        }
    }
    // [PPB, §9.6]: b_st(0, 0) = mn (b_11 − b_10 − b_01 + b_00), on the elevated net too.
    let c = e.net();
    let twist =
        (c.get(1, 1).clone() - c.get(1, 0) - c.get(0, 1) + c.get(0, 0)) * qi((m * n) as i64);
    assert_eq!(e.partial_at(&qi(0), &qi(0), 1, 1).unwrap(), twist);
    assert_eq!(e.twist_net().unwrap().net().get(0, 0), &twist);
}
