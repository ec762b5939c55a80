//! Pictures of surfaces and meshes as projected wireframes ([`project`]): tensor-product
//! patches (Bézier, B-spline, NURBS) with isoparametric lines over their dashed control net,
//! triangular Bézier patches with the lines of constant barycentric coordinates, and
//! polygon meshes by their edges (a subdivided mesh over the coarse one).

use super::{bounds_of as bounds, project, sample_parameters, Layer, Picture, Role};
use crate::error::{Error, Result};
use crate::geometry::Point2;
use crate::mesh::PolygonMesh;
use crate::spline::{Domain, Scalar};
use crate::surface::{ControlNet, Surface, TriangularPatch};

/// The most isoparametric lines a picture draws each way.
const MAX_LINES: usize = 1024;

/// A tensor-product surface as a projected wireframe: `lines + 1` isoparametric lines
/// u = const (layer `iso-u`) and as many v = const (layer `iso-v`), evenly spaced over the
/// domain (over [0, 1] for a Bézier patch, whose domain is the whole plane) and both ends
/// included, over the control net drawn dashed (layer `control-net`: its rows, then its
/// columns) with its points. `name` names the surface in the title.
///
/// Line i of `iso-u` is the curve v ↦ c(uᵢ, v) at uᵢ = u₀ + (u₁ − u₀) · i / lines, drawn
/// through its points at [`sample_parameters`] of the lines' v values (likewise for `iso-v`);
/// every point is the surface's own [`Surface::eval`], in its own arithmetic, then
/// [projected](project).
///
/// # Errors
/// [`Error::InvalidParameter`] named `"lines"` unless 1 ≤ lines ≤ 1024; those of
/// [`Surface::eval`] and [`project`].
///
/// # Complexity
/// Θ(L² · [`SAMPLES_PER_PIECE`](super::SAMPLES_PER_PIECE)) evaluations and output for L =
/// `lines`, plus O(mn) for an m × n net.
///
/// ```
/// use compgeo::draw;
/// use compgeo::spline::Point;
/// use compgeo::surface::{BezierPatch, ControlNet};
///
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let net = ControlNet::new(vec![
///     vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 1.0), p(2.0, 0.0, 0.0)],
///     vec![p(0.0, 1.0, 1.0), p(1.0, 1.0, 2.0), p(2.0, 1.0, 1.0)],
/// ])?;
/// let patch = BezierPatch::new(net.clone())?;
/// let picture = draw::surface("Bézier patch", &patch, &net, 4)?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("iso-u", 5)) && layers.contains(&("iso-v", 5)));
/// assert!(layers.contains(&("control-net", 2 + 3)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn surface<S: Scalar, const D: usize>(
    name: &str,
    surface: &impl Surface<S, D>,
    net: &ControlNet<S, D>,
    lines: usize,
) -> Result<Picture> {
    if !(1..=MAX_LINES).contains(&lines) {
        return Err(Error::InvalidParameter {
            name: "lines",
            reason: format!("{lines} isoparametric lines; 1 to {MAX_LINES} are drawn"),
        });
    }
    let domain = surface.domain();
    let us = even(&domain.u, lines);
    let vs = even(&domain.v, lines);
    let (u_samples, v_samples) = (sample_parameters(&us), sample_parameters(&vs));
    let iso_u = us
        .iter()
        .map(|u| {
            v_samples
                .iter()
                .map(|v| project(&surface.eval(u, v)?))
                .collect()
        })
        .collect::<Result<Vec<Vec<Point2>>>>()?;
    let iso_v = vs
        .iter()
        .map(|v| {
            u_samples
                .iter()
                .map(|u| project(&surface.eval(u, v)?))
                .collect()
        })
        .collect::<Result<Vec<Vec<Point2>>>>()?;
    let rows = (0..net.rows())
        .map(|i| net.row(i).iter().map(project).collect())
        .collect::<Result<Vec<Vec<Point2>>>>()?;
    let columns: Vec<Vec<Point2>> = (0..net.columns())
        .map(|j| rows.iter().map(|row| row[j]).collect())
        .collect();
    let title = format!(
        "{name}: {} × {} control net, {} isoparametric lines each way",
        net.rows(),
        net.columns(),
        lines + 1
    );
    let all: Vec<Point2> = iso_u.iter().chain(&rows).flatten().copied().collect();
    let mut picture = Picture::new(&title, bounds(&all), net.rows() * net.columns());
    picture.polylines(
        &Layer::new("control-net", Role::Construction).legend("control net"),
        rows.iter().chain(&columns).map(|line| line.iter().copied()),
    );
    picture.polylines(
        &Layer::new("iso-u", Role::Result).legend("u = const"),
        iso_u.iter().map(|line| line.iter().copied()),
    );
    picture.polylines(
        &Layer::new("iso-v", Role::Alternative.solid()).legend("v = const"),
        iso_v.iter().map(|line| line.iter().copied()),
    );
    picture.points(
        &Layer::new("control-points", Role::Input),
        rows.iter().flatten().copied(),
    );
    Ok(picture)
}

/// A triangular Bézier patch as a projected wireframe: the lines of constant barycentric
/// coordinate u = i/s, v = i/s and w = i/s (s = `segments`, i = 0, …, s; layers `iso-u`,
/// `iso-v`, `iso-w`, each line through its points at the s + 1 − i grid points (j/s, k/s)
/// it passes), over the control net drawn dashed: the triangles b_{i+1,j,k}, b_{i,j+1,k},
/// b_{i,j,k+1} for i + j + k = n − 1 (layer `control-net`).
///
/// The grid point with barycentric coordinates (u, v, 1 − u − v) is the patch's own
/// [`Surface::eval`] at (u, v), in its own arithmetic, [projected](project).
///
/// # Errors
/// [`Error::InvalidParameter`] named `"segments"` unless 1 ≤ segments ≤ 1024; those of
/// [`project`].
///
/// # Complexity
/// Θ(s²) evaluations of Θ(n³D) each, Θ(s² + n²) output.
///
/// ```
/// use compgeo::draw;
/// use compgeo::spline::Point;
/// use compgeo::surface::TriangularPatch;
///
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let patch = TriangularPatch::new(vec![
///     p(1.0, 0.0, 0.0), p(0.5, 0.5, 0.5), p(0.0, 1.0, 0.0),
///     p(0.5, 0.0, 0.0), p(0.0, 0.5, 0.0),
///     p(0.0, 0.0, 0.0),
/// ])?;
/// let picture = draw::triangular_patch(&patch, 4)?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("iso-u", 4)) && layers.contains(&("control-net", 3)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn triangular_patch<S: Scalar, const D: usize>(
    patch: &TriangularPatch<S, D>,
    segments: usize,
) -> Result<Picture> {
    if !(1..=MAX_LINES).contains(&segments) {
        return Err(Error::InvalidParameter {
            name: "segments",
            reason: format!("{segments} segments; 1 to {MAX_LINES} are drawn"),
        });
    }
    let s = segments;
    let frac = |i: usize| S::from_ratio(i as i64, s as i64);
    // grid[i][j]: the point at (u, v) = (i/s, j/s), i + j ≤ s.
    let grid = (0..=s)
        .map(|i| {
            (0..=s - i)
                .map(|j| project(&patch.eval(&frac(i), &frac(j))?))
                .collect()
        })
        .collect::<Result<Vec<Vec<Point2>>>>()?;
    // A line stops at the edge u + v = 1; lines of one point (the corners) are skipped.
    let iso_u: Vec<Vec<Point2>> = (0..s).map(|i| grid[i].clone()).collect();
    let iso_v: Vec<Vec<Point2>> = (0..s)
        .map(|j| (0..=s - j).map(|i| grid[i][j]).collect())
        .collect();
    let iso_w: Vec<Vec<Point2>> = (1..=s)
        .map(|m| (0..=m).map(|i| grid[i][m - i]).collect())
        .collect();
    let n = patch.degree();
    let mut net = Vec::new();
    for k in 0..n {
        for j in 0..n - k {
            let i = n - 1 - j - k;
            let corner = |a: usize, b: usize, c: usize| {
                project(patch.get(a, b, c).expect("i + j + k = n indexes the net"))
            };
            net.push([
                corner(i + 1, j, k)?,
                corner(i, j + 1, k)?,
                corner(i, j, k + 1)?,
            ]);
        }
    }
    let control = patch
        .points()
        .iter()
        .map(project)
        .collect::<Result<Vec<_>>>()?;
    let title = format!("triangular Bézier patch of degree {n}, {s} segments a side");
    let all: Vec<Point2> = grid.iter().flatten().chain(&control).copied().collect();
    let mut picture = Picture::new(&title, bounds(&all), control.len());
    picture.polygons(
        &Layer::new("control-net", Role::Construction).legend("control net"),
        net.iter().map(|t| t.iter().copied()),
    );
    for (name, lines, role) in [
        ("iso-u", &iso_u, Role::Result.solid()),
        ("iso-v", &iso_v, Role::Alternative.solid()),
        ("iso-w", &iso_w, Role::Voronoi.solid()),
    ] {
        picture.polylines(
            &Layer::new(name, role).legend(format!("{} = const", &name[4..])),
            lines.iter().map(|line| line.iter().copied()),
        );
    }
    picture.points(
        &Layer::new("control-points", Role::Input),
        control.iter().copied(),
    );
    Ok(picture)
}

/// A polygon mesh as a projected wireframe: every edge once (layer `edges`, blue) and the
/// vertices numbered when the picture shows labels; with `fine` (the mesh after some rounds
/// of subdivision) the fine mesh's edges (layer `edges`) over the coarse mesh's, dashed
/// (layer `coarse`).
///
/// # Errors
/// Those of [`project`].
///
/// # Complexity
/// Θ(V + E) time and output for the meshes' vertices and edges.
///
/// ```
/// use compgeo::draw;
/// use compgeo::mesh::{catmull_clark, PolygonMesh};
/// use compgeo::spline::Point;
///
/// let p = |x: f64, y: f64, z: f64| Point::new([x, y, z]);
/// let square = PolygonMesh::new(
///     vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(1.0, 1.0, 0.0), p(0.0, 1.0, 0.0)],
///     &[[0, 1, 2, 3]],
/// )?;
/// let fine = catmull_clark(&square, 1)?; // one round: four quads
/// let picture = draw::mesh(&square, Some(&fine))?;
/// let layers: Vec<(&str, usize)> = picture.layers().collect();
/// assert!(layers.contains(&("coarse", 4)) && layers.contains(&("edges", 12)));
/// # Ok::<(), compgeo::Error>(())
/// ```
pub fn mesh<S: Scalar, const D: usize>(
    coarse: &PolygonMesh<S, D>,
    fine: Option<&PolygonMesh<S, D>>,
) -> Result<Picture> {
    let coarse_points = coarse
        .positions()
        .iter()
        .map(project)
        .collect::<Result<Vec<_>>>()?;
    let fine_points = match fine {
        Some(f) => f
            .positions()
            .iter()
            .map(project)
            .collect::<Result<Vec<_>>>()?,
        None => Vec::new(),
    };
    let shown = fine.unwrap_or(coarse);
    let title = format!(
        "polygon mesh: {} vertices, {} edges, {} faces{}",
        shown.vertex_count(),
        shown.edge_count(),
        shown.face_count(),
        if fine.is_some() {
            format!(" (subdivided from {} faces)", coarse.face_count())
        } else {
            String::new()
        }
    );
    let all: Vec<Point2> = coarse_points.iter().chain(&fine_points).copied().collect();
    let mut picture = Picture::new(&title, bounds(&all), shown.vertex_count());
    let edges = |m: &PolygonMesh<S, D>, at: &[Point2]| -> Vec<[Point2; 2]> {
        let t = m.topology();
        (0..t.edge_count())
            .map(|e| t.edge_vertices(e).map(|v| at[v]))
            .collect()
    };
    match fine {
        Some(f) => {
            picture.segments(
                &Layer::new("coarse", Role::Construction).legend("coarse mesh"),
                edges(coarse, &coarse_points),
            );
            picture.segments(
                &Layer::new("edges", Role::Result).legend("subdivided mesh"),
                edges(f, &fine_points),
            );
        }
        None => {
            picture.segments(
                &Layer::new("edges", Role::Result).legend("mesh edges"),
                edges(coarse, &coarse_points),
            );
        }
    }
    picture.points(
        &Layer::new("vertices", Role::Input),
        coarse_points.iter().copied(),
    );
    picture.labels(
        &Layer::new("labels", Role::Label).legend("vertex index"),
        coarse_points
            .iter()
            .enumerate()
            .map(|(i, &p)| (p, i.to_string())),
    );
    Ok(picture)
}

/// `lines + 1` evenly spaced parameters over an interval domain, or over [0, 1] for the
/// whole line.
fn even<S: Scalar>(domain: &Domain<S>, lines: usize) -> Vec<S> {
    let (a, b) = match domain.bounds() {
        Some((a, b)) => (a.clone(), b.clone()),
        None => (S::zero(), S::one()),
    };
    let step = b - &a;
    (0..=lines)
        .map(|i| a.clone() + &(step.clone() * &S::from_ratio(i as i64, lines as i64)))
        .collect()
}
