//! Helpers shared by the integration tests: running the `compgeo` binary (with the `cli`
//! feature) and spade's triangles as a peer oracle.

#[cfg(feature = "cli")]
use assert_cmd::cargo::cargo_bin_cmd;
#[cfg(feature = "cli")]
use serde_json::Value;

/// Runs the binary with `args` and optional `stdin`; returns (exit code, stdout, stderr).
#[cfg(feature = "cli")]
pub fn run(args: &[&str], stdin: Option<&str>) -> (i32, String, String) {
    let mut cmd = cargo_bin_cmd!("compgeo");
    cmd.args(args);
    if let Some(input) = stdin {
        cmd.write_stdin(input.as_bytes().to_vec());
    }
    let out = cmd.output().unwrap();
    (
        out.status.code().unwrap(),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// Runs a command that must succeed and print one JSON line; returns it parsed.
#[cfg(feature = "cli")]
pub fn run_json(args: &[&str], stdin: Option<&str>) -> Value {
    let (code, out, err) = run(args, stdin);
    assert_eq!(code, 0, "{args:?}: {err}");
    assert!(err.is_empty(), "{args:?}: {err}");
    assert_eq!(out.lines().count(), 1, "{args:?}: one line of JSON");
    serde_json::from_str(&out).unwrap()
}

/// Asserts the bad-input contract (exit code 2, nothing on stdout, exactly one line on stderr
/// starting `error: `) and returns the error line.
#[cfg(feature = "cli")]
pub fn assert_rejected(args: &[&str], stdin: Option<&str>) -> String {
    let (code, out, err) = run(args, stdin);
    assert_eq!(code, 2, "{args:?}: stderr {err}");
    assert!(out.is_empty(), "{args:?}: stdout must be empty, got {out}");
    assert_eq!(
        err.lines().count(),
        1,
        "{args:?}: exactly one line, got {err:?}"
    );
    assert!(err.starts_with("error: "), "{args:?}: {err}");
    err.trim_end().to_string()
}

/// The triangles spade's bulk load finds for `pts` (distinct points), each as a sorted triple
/// of indices into `pts`, the list sorted: the peer oracle the Delaunay tests compare with.
pub fn spade_triangles(pts: &[compgeo::geometry::Point2]) -> Vec<[usize; 3]> {
    use spade::{DelaunayTriangulation, Point2, Triangulation};
    let index: std::collections::HashMap<(u64, u64), usize> = pts
        .iter()
        .enumerate()
        .map(|(i, p)| ((p.x.to_bits(), p.y.to_bits()), i))
        .collect();
    let input: Vec<Point2<f64>> = pts.iter().map(|p| Point2::new(p.x, p.y)).collect();
    let dt: DelaunayTriangulation<Point2<f64>> =
        DelaunayTriangulation::bulk_load(input).expect("spade takes these coordinates");
    let mut out: Vec<[usize; 3]> = dt
        .inner_faces()
        .map(|face| {
            let mut tri = face.vertices().map(|v| {
                let p = v.position();
                index[&(p.x.to_bits(), p.y.to_bits())]
            });
            tri.sort_unstable();
            tri
        })
        .collect();
    out.sort_unstable();
    out
}

/// A triangulation's triangles as a sorted list of sorted vertex triples, to compare the
/// results of different builders.
pub fn triangle_set(t: &compgeo::delaunay::Triangulation) -> Vec<[usize; 3]> {
    let mut out: Vec<[usize; 3]> = (0..t.triangle_count())
        .map(|k| {
            let mut tri = t.triangle(k);
            tri.sort_unstable();
            tri
        })
        .collect();
    out.sort_unstable();
    out
}

/// Whether the Delaunay triangulation is unique: no interior edge of `t` (a valid Delaunay
/// triangulation) has its opposite vertex exactly on the circumcircle. Then every correct
/// builder must return the same triangle set.
pub fn is_unique_delaunay(
    pts: &[compgeo::geometry::Point2],
    t: &compgeo::delaunay::Triangulation,
) -> bool {
    use compgeo::delaunay::{prev_halfedge, EMPTY};
    use compgeo::geometry::{incircle, InCircle};
    (0..t.triangles.len()).all(|e| {
        let f = t.halfedges[e];
        if f == EMPTY {
            return true;
        }
        let [a, b, c] = t.triangle(e / 3);
        let d = t.triangles[prev_halfedge(f)];
        incircle(pts[a], pts[b], pts[c], pts[d]) != InCircle::On
    })
}

/// The validated set of `pts`, which the tests' inputs always are.
pub fn set(pts: &[compgeo::geometry::Point2]) -> compgeo::geometry::PointSet<'_> {
    compgeo::geometry::PointSet::new(pts).expect("the tests' points are finite")
}

/// The exact value of a `WideFloat`, for comparisons in rational arithmetic.
pub fn wide_q(w: compgeo::geometry::WideFloat) -> num_rational::BigRational {
    use num_rational::BigRational;
    let (significand, exponent) = w.to_parts();
    let two = BigRational::from_integer(2.into());
    let power = num_traits::pow(two, exponent.unsigned_abs() as usize);
    let m = BigRational::from_float(significand).expect("a finite significand");
    if exponent >= 0 {
        m * power
    } else {
        m / power
    }
}

/// A fresh empty directory under the system's temporary directory, removed when dropped.
#[cfg(feature = "cli")]
pub struct TempDir(pub std::path::PathBuf);

#[cfg(feature = "cli")]
impl TempDir {
    /// A new directory whose name has `tag`, the process id and the time.
    pub fn new(tag: &str) -> TempDir {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .unwrap()
            .as_nanos();
        let dir =
            std::env::temp_dir().join(format!("compgeo-{tag}-{}-{nanos}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }

    /// The path of `name` inside the directory.
    pub fn path(&self, name: &str) -> std::path::PathBuf {
        self.0.join(name)
    }
}

#[cfg(feature = "cli")]
impl Drop for TempDir {
    fn drop(&mut self) {
        // Best effort: a leftover temporary directory harms nothing.
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
