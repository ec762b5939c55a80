//! Placing labels: eight places around a point, the first that overlaps neither a placed
//! label nor a dot, else the least crowded. Only pictures of a few hundred points show
//! labels, so the quadratic search stays small (at most `4 · LABEL_LIMIT` labels and as many
//! dots are remembered).

use super::svg::LABEL_LIMIT;

/// Where a label goes relative to its point: offsets in units of the gap (`gap`) and the
/// font size (`font`), and the text anchor.
const PLACES: [(f64, f64, f64, f64, &str); 8] = [
    // (gap x, gap y, font y, anchor width factor, anchor)
    (1.0, -1.0, 0.0, 0.0, "start"),  // above right
    (-1.0, -1.0, 0.0, 1.0, "end"),   // above left
    (1.0, 1.0, 0.8, 0.0, "start"),   // below right
    (-1.0, 1.0, 0.8, 1.0, "end"),    // below left
    (1.5, 0.0, 0.35, 0.0, "start"),  // right
    (-1.5, 0.0, 0.35, 1.0, "end"),   // left
    (0.0, -1.5, 0.0, 0.5, "middle"), // above
    (0.0, 1.5, 0.8, 0.5, "middle"),  // below
];

/// The labels and dots placed so far.
#[derive(Debug, Clone, Default)]
pub(super) struct Placer {
    font: f64,
    gap: f64,
    boxes: Vec<[f64; 4]>,
    dots: Vec<[f64; 2]>,
    dot_radius: f64,
}

impl Placer {
    /// A placer for labels of `font` size next to dots `dot` wide.
    pub(super) fn new(font: f64, dot: f64) -> Placer {
        Placer {
            font,
            gap: dot / 2.0 + 2.0,
            boxes: Vec::new(),
            dots: Vec::new(),
            dot_radius: dot / 2.0,
        }
    }

    /// Remembers a dot that labels should not cover.
    pub(super) fn avoid(&mut self, at: [f64; 2]) {
        if self.dots.len() < 4 * LABEL_LIMIT {
            self.dots.push(at);
        }
    }

    /// The baseline position and anchor of a label of `chars` characters for the point
    /// `at`, and remembers its box.
    pub(super) fn place(&mut self, at: [f64; 2], chars: usize) -> (f64, f64, &'static str) {
        let width = 0.6 * self.font * chars as f64;
        let mut best: Option<(usize, [f64; 4], f64, f64, &'static str)> = None;
        for &(gx, gy, fy, shift, anchor) in &PLACES {
            let x = at[0] + gx * self.gap;
            let y = at[1] + gy * self.gap + fy * self.font;
            let left = x - shift * width;
            let b = [left, y - 0.8 * self.font, left + width, y + 0.2 * self.font];
            let crowd = self.crowd(b);
            if best.is_none_or(|(c, ..)| crowd < c) {
                best = Some((crowd, b, x, y, anchor));
            }
            if crowd == 0 {
                break;
            }
        }
        let (_, b, x, y, anchor) = best.expect("there are places to try");
        if self.boxes.len() < 4 * LABEL_LIMIT {
            self.boxes.push(b);
        }
        (x, y, anchor)
    }

    /// How many placed labels and dots the box `b` overlaps.
    fn crowd(&self, b: [f64; 4]) -> usize {
        let r = self.dot_radius;
        let labels = self
            .boxes
            .iter()
            .filter(|o| b[0] < o[2] && o[0] < b[2] && b[1] < o[3] && o[1] < b[3])
            .count();
        let dots = self
            .dots
            .iter()
            .filter(|d| b[0] - r < d[0] && d[0] < b[2] + r && b[1] - r < d[1] && d[1] < b[3] + r)
            .count();
        labels + dots
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_labels_at_one_point_do_not_overlap() {
        let mut p = Placer::new(11.0, 4.0);
        p.avoid([100.0, 100.0]);
        p.place([100.0, 100.0], 2);
        p.place([100.0, 100.0], 2);
        let [a, b] = [p.boxes[0], p.boxes[1]];
        assert!(!(a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]));
        // Neither covers the dot.
        for o in [a, b] {
            assert!(!(o[0] < 100.0 && 100.0 < o[2] && o[1] < 100.0 && 100.0 < o[3]));
        }
    }
}
