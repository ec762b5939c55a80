//! The world → picture transform: y up in the world, y down in SVG, one scale for both axes,
//! a power of two so that every finite input maps without overflow or underflow.

use crate::geometry::{BoundingBox, ConstructedPoint, Point2, WideFloat};

/// Picture coordinates are clamped to `±FAR`: a point far outside the frame (a clamped
/// circumcentre, say) still prints as a finite, bounded number.
pub(super) const FAR: f64 = 1e6;

/// How world coordinates become picture coordinates.
///
/// A world point `(x, y)` is drawn at
///
/// ```text
/// px = left   + (x − origin.x) · 2^−shift
/// py = bottom − (y − origin.y) · 2^−shift
/// ```
///
/// with the differences rounded once (as [`WideFloat`]s, so neither `f64::MAX − (−f64::MAX)`
/// nor a difference of subnormals loses its value) and the result clamped to `±10⁶`. The
/// scale is a power of two chosen so that the larger side of the content's bounding box
/// is between half the picture's side and the side: both axes share it, so angles and
/// circles keep their shape, and y grows upwards as in the rest of the crate. The
/// content is centred in a drawing area at least half the side wide and a quarter
/// high, so a single point or a vertical segment still gets a sensible frame.
///
/// Every picture records its frame in the root element as
/// `data-frame="origin.x origin.y shift left bottom"` (the coordinates in Rust's shortest
/// round-trip form), so a reader can map the picture back to the world.
///
/// ```
/// use compgeo::draw::Frame;
/// use compgeo::geometry::{BoundingBox, Point2};
///
/// let b = BoundingBox::of(&[Point2::new(0.0, 0.0), Point2::new(4.0, 1.0)]).unwrap();
/// let f = Frame::new(b, 600.0, 20.0);
/// let [x0, y0] = f.to_picture(Point2::new(0.0, 0.0));
/// let [x1, y1] = f.to_picture(Point2::new(4.0, 1.0));
/// assert_eq!(x1 - x0, 4.0 * (y0 - y1)); // one scale for both axes
/// assert!(y1 < y0); // y up: the larger y is drawn higher
/// assert!(x1 - x0 > 300.0 && x1 - x0 <= 600.0);
///
/// // Extreme magnitudes map to ordinary picture coordinates.
/// let b = BoundingBox::of(&[Point2::new(-f64::MAX, 5e-324), Point2::new(f64::MAX, 1e300)]).unwrap();
/// let f = Frame::new(b, 600.0, 20.0);
/// let [x, y] = f.to_picture(Point2::new(f64::MAX, 1e300));
/// assert!(x.is_finite() && y.is_finite());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    origin: Point2,
    shift: i32,
    left: f64,
    bottom: f64,
    area: [f64; 4],
}

impl Frame {
    /// The frame that draws `bounds` with its larger side between `side / 2` and `side`
    /// picture units, centred in a drawing area `margin` units from the picture's left and
    /// top edges. `side` and `margin` are clamped to `[1, 10⁵]` and `[0, 10⁵]`.
    ///
    /// The origin is `bounds.min`; a box with no extent (one point) is drawn at the centre
    /// of the drawing area with scale 1.
    pub fn new(bounds: BoundingBox, side: f64, margin: f64) -> Frame {
        let side = if side.is_nan() {
            1.0
        } else {
            side.clamp(1.0, 1e5)
        };
        let margin = if margin.is_nan() {
            0.0
        } else {
            margin.clamp(0.0, 1e5)
        };
        let (width, height) = (bounds.width(), bounds.height());
        let extent = width.max(height);
        let shift = if extent.is_zero() {
            0
        } else {
            // extent = m · 2^e with m in [1, 2): the content's side m · 2^(e − shift) lies in
            // (side / 2, side] for shift = e − ⌊log₂(side / m)⌋.
            let (m, e) = extent.to_parts();
            let fits = (side / m).log2().floor() as i32;
            e.saturating_sub(fits)
        };
        let mut frame = Frame {
            origin: bounds.min,
            shift,
            left: 0.0,
            bottom: 0.0,
            area: [0.0; 4],
        };
        let (content_w, content_h) = (frame.length(width), frame.length(height));
        let area_w = content_w.max(side / 2.0);
        let area_h = content_h.max(side / 4.0);
        frame.left = margin + (area_w - content_w) / 2.0;
        frame.bottom = margin + area_h - (area_h - content_h) / 2.0;
        frame.area = [margin, margin, margin + area_w, margin + area_h];
        frame
    }

    /// Where the world point `p` is drawn, `[px, py]`, each clamped to `±10⁶`.
    pub fn to_picture(&self, p: Point2) -> [f64; 2] {
        [
            self.left + self.length(WideFloat::difference(p.x, self.origin.x)),
            self.bottom - self.length(WideFloat::difference(p.y, self.origin.y)),
        ]
        .map(clamp)
    }

    /// Where a constructed point is drawn, from its value even beyond the range of `f64`.
    pub fn to_picture_constructed(&self, p: ConstructedPoint) -> [f64; 2] {
        match p {
            ConstructedPoint::Finite(q) => self.to_picture(q),
            ConstructedPoint::BeyondRange([x, y]) => {
                let dx = x.add(WideFloat::from(-self.origin.x));
                let dy = y.add(WideFloat::from(-self.origin.y));
                [self.left + self.length(dx), self.bottom - self.length(dy)].map(clamp)
            }
        }
    }

    /// A world length (or signed difference) in picture units, clamped to `±10⁶`.
    pub fn length(&self, w: WideFloat) -> f64 {
        let (m, e) = w.to_parts();
        let e = i64::from(e) - i64::from(self.shift);
        if m == 0.0 || e < -1100 {
            return 0.0;
        }
        if e > 40 {
            return FAR.copysign(m);
        }
        clamp(m * 2f64.powi(e as i32))
    }

    /// The drawing area `[left, top, right, bottom]` in picture units: the content's
    /// bounding box, centred, with room to spare on a narrow side.
    pub fn area(&self) -> [f64; 4] {
        self.area
    }

    /// The world point drawn at `[left, bottom]`: the minimum corner of the bounds.
    pub fn origin(&self) -> Point2 {
        self.origin
    }

    /// The scale's exponent: a world length `d` is drawn `d · 2^−shift` long.
    pub fn shift(&self) -> i32 {
        self.shift
    }

    /// The picture coordinates `[left, bottom]` of the origin.
    pub fn anchor(&self) -> [f64; 2] {
        [self.left, self.bottom]
    }
}

/// `v` clamped to `±FAR` (NaN cannot occur: every input is finite).
fn clamp(v: f64) -> f64 {
    v.clamp(-FAR, FAR)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(points: &[(f64, f64)]) -> Frame {
        let pts: Vec<Point2> = points.iter().map(|&p| Point2::from(p)).collect();
        Frame::new(BoundingBox::of(&pts).unwrap(), 600.0, 10.0)
    }

    #[test]
    fn the_content_fills_between_half_and_all_of_the_side() {
        for scale in [1e-320, 1e-300, 1e-5, 1.0, 3.0, 1e5, 1e300, f64::MAX / 4.0] {
            let f = frame(&[(0.0, 0.0), (scale, scale / 2.0)]);
            let [x0, y0] = f.to_picture(Point2::new(0.0, 0.0));
            let [x1, y1] = f.to_picture(Point2::new(scale, scale / 2.0));
            let w = x1 - x0;
            assert!(w > 300.0 && w <= 600.0, "{scale}: {w}");
            // The same scale on both axes, up to the subnormals' own rounding.
            assert!((w / (y0 - y1) - 2.0).abs() < 0.05, "{scale}");
        }
    }

    #[test]
    fn the_whole_range_maps_to_finite_coordinates() {
        let m = f64::MAX;
        let f = frame(&[(-m, -m), (m, m)]);
        let [a, b] = f.to_picture(Point2::new(-m, m));
        let [c, d] = f.to_picture(Point2::new(m, -m));
        assert!(c - a > 300.0 && d - b > 300.0);
        let far = ConstructedPoint::BeyondRange([WideFloat::from(m).mul(WideFloat::from(8.0)); 2]);
        let [x, y] = f.to_picture_constructed(far);
        assert!(x.is_finite() && y.is_finite() && x > c && y < b);
    }

    #[test]
    fn a_single_point_sits_in_the_middle_of_its_area() {
        for p in [(0.0, 0.0), (1e300, -1e300), (5e-324, 0.0)] {
            let f = frame(&[p]);
            let [x, y] = f.to_picture(Point2::from(p));
            let [l, t, r, b] = f.area();
            assert_eq!((x, y), ((l + r) / 2.0, (t + b) / 2.0));
        }
    }

    #[test]
    fn a_vertical_segment_gets_a_wide_enough_area() {
        let f = frame(&[(1.0, 0.0), (1.0, 10.0)]);
        let [l, t, r, b] = f.area();
        assert!(r - l >= 200.0 && b - t > 300.0);
        let [x, _] = f.to_picture(Point2::new(1.0, 5.0));
        assert_eq!(x, (l + r) / 2.0);
    }
}
