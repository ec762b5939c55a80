//! The picture every drawing builds: a [`Frame`], sizes chosen from the input's size,
//! layers of one style each, labels, a legend, and the SVG text.
//!
//! A picture is a list of layers, each one SVG group `<g class="NAME" ...>` whose attributes
//! carry the style once (colour, width, dashes) and whose children carry only geometry:
//! points and segments are subpaths of a few `<path>` elements, so the file grows by a few
//! bytes per point or edge and by nothing per attribute. Coordinates are printed with two
//! decimals when labels are shown and one otherwise (a tenth of a unit is far below a
//! point's spacing in a picture too dense for labels).

use super::frame::{Frame, FAR};
use super::labels::Placer;
use crate::geometry::{BoundingBox, ConstructedPoint};
use std::fmt::Write as _;
use std::io;

/// Pictures of at most this many points number their points (or vertices); larger ones have
/// no labels and thinner strokes.
pub const LABEL_LIMIT: usize = 300;

/// The fill colours of classes of points (a graph's colour classes): class k is filled with
/// `CLASS_COLOURS[k % 8]`, outlined in near black. The first seven are the Okabe–Ito
/// palette's colours, the eighth a mid grey.
pub const CLASS_COLOURS: [&str; 8] = [
    "#e69f00", "#56b4e9", "#009e73", "#f0e442", "#0072b2", "#d55e00", "#cc79a7", "#999999",
];

/// The side of the drawing area grows as `40 √n` between these bounds (so the typical gap
/// between two of n spread-out points stays about 40 units until the largest side).
const MIN_SIDE: f64 = 480.0;
const MAX_SIDE: f64 = 2400.0;
const SIDE_PER_ROOT_POINT: f64 = 40.0;

/// Subpaths per `<path>` element: long paths are split so that no attribute grows to
/// megabytes.
const SUBPATHS_PER_PATH: usize = 4096;

/// A circle whose centre or radius is beyond this many sides of the picture is left out: in
/// the picture it would be a straight line.
const CIRCLE_SIDES: f64 = 100.0;

/// What a layer shows; each role has one colour (and default dashes) in every picture, chosen
/// to stay apart for colour-blind readers and in grey print (the Okabe–Ito palette).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Role {
    /// The input points: near-black dots.
    Input,
    /// The answer: a hull, a spanning tree, a polygon (blue; polygons lightly filled).
    Result,
    /// A second answer beside the first, such as another enclosing rectangle (sky blue,
    /// dashed).
    Alternative,
    /// A distinguished pair, point or measure: the diameter, the closest pair, the width, a
    /// centre (vermillion, thick).
    Highlight,
    /// Triangulation edges (grey, thin).
    Triangulation,
    /// Voronoi edges and cells (bluish green).
    Voronoi,
    /// Circles: circumcircles, the largest empty circle (reddish purple).
    Circle,
    /// Secondary and construction lines: antipodal pairs, radii, the clipping box (orange,
    /// dashed).
    Construction,
    /// Text labels (near black).
    Label,
}

/// How a stroke is broken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dash {
    /// A continuous stroke.
    Solid,
    /// Long dashes.
    Dashed,
    /// Short dashes, dot-like.
    Dotted,
}

/// A role and its dashes: the complete style of a layer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Style {
    /// The role, which fixes the colour, the width and the fill.
    pub role: Role,
    /// The dashes.
    pub dash: Dash,
}

impl Role {
    /// Every role, in the order of the legend's palette.
    pub const ALL: [Role; 9] = [
        Role::Input,
        Role::Result,
        Role::Alternative,
        Role::Highlight,
        Role::Triangulation,
        Role::Voronoi,
        Role::Circle,
        Role::Construction,
        Role::Label,
    ];

    /// The role's colour, as SVG writes it.
    ///
    /// ```
    /// use compgeo::draw::Role;
    ///
    /// assert_eq!(Role::Result.colour(), "#0072b2");
    /// ```
    pub const fn colour(self) -> &'static str {
        match self {
            Role::Input | Role::Label => "#1a1a1a",
            Role::Result => "#0072b2",
            Role::Alternative => "#56b4e9",
            Role::Highlight => "#d55e00",
            Role::Triangulation => "#8c8c8c",
            Role::Voronoi => "#009e73",
            Role::Circle => "#cc79a7",
            Role::Construction => "#e69f00",
        }
    }

    /// The role's default dashes: dashed for [`Role::Alternative`] and
    /// [`Role::Construction`], solid otherwise.
    pub const fn default_dash(self) -> Dash {
        match self {
            Role::Alternative | Role::Construction => Dash::Dashed,
            _ => Dash::Solid,
        }
    }

    /// The role with dashes.
    pub const fn dashed(self) -> Style {
        Style {
            role: self,
            dash: Dash::Dashed,
        }
    }

    /// The role with dot-like dashes.
    pub const fn dotted(self) -> Style {
        Style {
            role: self,
            dash: Dash::Dotted,
        }
    }

    /// The role drawn solid.
    pub const fn solid(self) -> Style {
        Style {
            role: self,
            dash: Dash::Solid,
        }
    }

    /// The stroke width relative to the picture's base width.
    fn weight(self) -> f64 {
        match self {
            Role::Result => 1.6,
            Role::Alternative => 1.4,
            Role::Highlight => 2.4,
            Role::Triangulation | Role::Construction => 0.8,
            Role::Circle => 0.9,
            Role::Input | Role::Voronoi | Role::Label => 1.0,
        }
    }
}

impl From<Role> for Style {
    /// The role with its [`default_dash`](Role::default_dash).
    fn from(role: Role) -> Style {
        Style {
            role,
            dash: role.default_dash(),
        }
    }
}

/// A layer's name (its SVG `class`), style and legend text.
///
/// ```
/// use compgeo::draw::{Layer, Role};
///
/// let hull = Layer::new("hull", Role::Result).legend("convex hull");
/// assert_eq!(hull.name(), "hull");
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Layer {
    name: String,
    style: Style,
    legend: Option<String>,
}

impl Layer {
    /// A layer called `name` (written as the group's `class`, so keep it to letters, digits
    /// and hyphens) in `style`, without a legend entry.
    pub fn new(name: &str, style: impl Into<Style>) -> Layer {
        Layer {
            name: name.to_string(),
            style: style.into(),
            legend: None,
        }
    }

    /// The layer with an entry in the legend (shown when the layer draws something).
    pub fn legend(mut self, text: impl Into<String>) -> Layer {
        self.legend = Some(text.into());
        self
    }

    /// The layer's name.
    pub fn name(&self) -> &str {
        &self.name
    }
}

/// The swatch a legend entry shows.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Mark {
    Dot,
    Line,
    Area,
    Ring,
    Text,
    Filled(&'static str),
}

/// The sizes of a picture, from the number of points it shows.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Sizes {
    side: f64,
    stroke: f64,
    dot: f64,
    font: f64,
    legend_font: f64,
    margin: f64,
    labels: bool,
    decimals: u32,
}

impl Sizes {
    fn for_count(n: usize) -> Sizes {
        let root = (n.max(1) as f64).sqrt();
        let side = (SIDE_PER_ROOT_POINT * root).clamp(MIN_SIDE, MAX_SIDE);
        let spacing = side / root;
        let labels = n <= LABEL_LIMIT;
        let font = 11.0;
        Sizes {
            side,
            stroke: (spacing / 30.0).clamp(0.3, 1.5),
            dot: (spacing / 6.0).clamp(1.2, 6.0),
            font,
            legend_font: (side / 45.0).max(13.0),
            margin: 0.04 * side + 2.5 * font,
            labels,
            decimals: if labels { 2 } else { 1 },
        }
    }
}

/// One entry of the legend.
#[derive(Debug, Clone, PartialEq)]
struct Entry {
    style: Style,
    mark: Mark,
    text: String,
}

/// An SVG picture under construction: a [`Frame`], sizes chosen from the number of points,
/// and layers added one by one (each drawn over the earlier ones).
///
/// The drawing functions of this module ([`hull`](super::hull), [`delaunay`](super::delaunay),
/// ...) return one, so a caller can add layers before writing it; a new kind of picture
/// builds its own from [`Picture::new`].
///
/// **Sizes.** The larger side of the drawing area grows as `40 √n` for n points (from 480 to
/// 2400 units); stroke widths and dots shrink as the points get denser. Pictures of at most
/// [`LABEL_LIMIT`] points show labels ([`Picture::labels`]), placed where they overlap
/// neither each other nor a point when there is room; larger ones show none.
///
/// ```
/// use compgeo::draw::{Layer, Picture, Role};
/// use compgeo::geometry::{BoundingBox, Point2};
///
/// let pts = [(0.0, 0.0), (3.0, 1.0), (1.0, 2.0)].map(Point2::from);
/// let mut picture = Picture::new("a triangle", BoundingBox::of(&pts).unwrap(), pts.len());
/// picture.polygons(&Layer::new("triangle", Role::Result).legend("triangle"), [pts]);
/// picture.points(&Layer::new("points", Role::Input), pts);
/// picture.labels(&Layer::new("labels", Role::Label), pts.iter().enumerate().map(|(i, &p)| (p, i.to_string())));
/// let svg = picture.to_svg();
/// assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
/// assert!(svg.contains("<g class=\"triangle\"") && svg.contains(">2</text>"));
/// assert!(svg.ends_with("</svg>\n"));
/// ```
#[derive(Debug, Clone)]
pub struct Picture {
    frame: Frame,
    sizes: Sizes,
    title: String,
    body: String,
    legend: Vec<Entry>,
    layers: Vec<(String, usize)>,
    placer: Placer,
}

impl Picture {
    /// An empty picture of the world box `bounds`, sized for `count` points (which decides
    /// the picture's size, its strokes and whether it shows labels), titled `title` (written
    /// as the SVG `<title>` and the legend's first line).
    pub fn new(title: &str, bounds: BoundingBox, count: usize) -> Picture {
        let sizes = Sizes::for_count(count);
        let frame = Frame::new(bounds, sizes.side, sizes.margin);
        Picture {
            frame,
            sizes,
            title: title.to_string(),
            body: String::new(),
            legend: Vec::new(),
            layers: Vec::new(),
            placer: Placer::new(sizes.font, sizes.dot),
        }
    }

    /// The world → picture transform.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    /// Whether this picture shows labels (at most [`LABEL_LIMIT`] points).
    pub fn shows_labels(&self) -> bool {
        self.sizes.labels
    }

    /// The title.
    pub fn title(&self) -> &str {
        &self.title
    }

    /// Replaces the title (say, to name the algorithm that computed the result).
    pub fn set_title(&mut self, title: &str) {
        self.title = title.to_string();
    }

    /// The layers drawn so far, with how many items each drew (points, polygons, segments,
    /// circles or labels).
    pub fn layers(&self) -> impl Iterator<Item = (&str, usize)> + '_ {
        self.layers
            .iter()
            .map(|(name, count)| (name.as_str(), *count))
    }

    /// Draws `points` as dots; returns how many.
    pub fn points<P: Into<ConstructedPoint>>(
        &mut self,
        layer: &Layer,
        points: impl IntoIterator<Item = P>,
    ) -> usize {
        let mut d = PathData::new(self.sizes.decimals);
        for p in points {
            let at = self.frame.to_picture_constructed(p.into());
            self.placer.avoid(at);
            d.dot(at);
        }
        let attrs = format!(
            " fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linecap=\"round\"",
            layer.style.role.colour(),
            short(self.sizes.dot)
        );
        self.paths(layer, Mark::Dot, &attrs, d)
    }

    /// Draws closed polygons, one subpath each (a polygon of one point is skipped); returns
    /// how many.
    pub fn polygons<P, Q>(&mut self, layer: &Layer, polygons: impl IntoIterator<Item = Q>) -> usize
    where
        P: Into<ConstructedPoint>,
        Q: IntoIterator<Item = P>,
    {
        let mut d = PathData::new(self.sizes.decimals);
        for polygon in polygons {
            let corners: Vec<[f64; 2]> = polygon
                .into_iter()
                .map(|p| self.frame.to_picture_constructed(p.into()))
                .collect();
            if corners.len() >= 2 {
                d.chain(&corners, true);
            }
        }
        let fill = if layer.style.role == Role::Result {
            format!(
                " fill=\"{}\" fill-opacity=\"0.08\"",
                layer.style.role.colour()
            )
        } else {
            " fill=\"none\"".to_string()
        };
        let attrs = fill + &self.stroke(layer.style, 0.0);
        self.paths(layer, Mark::Area, &attrs, d)
    }

    /// Draws open polylines, one subpath each (a polyline of one point is skipped); returns
    /// how many.
    pub fn polylines<P, Q>(&mut self, layer: &Layer, lines: impl IntoIterator<Item = Q>) -> usize
    where
        P: Into<ConstructedPoint>,
        Q: IntoIterator<Item = P>,
    {
        let mut d = PathData::new(self.sizes.decimals);
        for line in lines {
            let vertices: Vec<[f64; 2]> = line
                .into_iter()
                .map(|p| self.frame.to_picture_constructed(p.into()))
                .collect();
            if vertices.len() >= 2 {
                d.chain(&vertices, false);
            }
        }
        let attrs = format!(" fill=\"none\"{}", self.stroke(layer.style, 0.0));
        self.paths(layer, Mark::Line, &attrs, d)
    }

    /// Draws segments, one subpath each; returns how many.
    pub fn segments<P: Into<ConstructedPoint>>(
        &mut self,
        layer: &Layer,
        segments: impl IntoIterator<Item = [P; 2]>,
    ) -> usize {
        let mut d = PathData::new(self.sizes.decimals);
        for [a, b] in segments {
            let a = self.frame.to_picture_constructed(a.into());
            let b = self.frame.to_picture_constructed(b.into());
            d.chain(&[a, b], false);
        }
        let attrs = format!(" fill=\"none\"{}", self.stroke(layer.style, 0.0));
        self.paths(layer, Mark::Line, &attrs, d)
    }

    /// Draws the lines parallel to `direction` (from its first point towards its second)
    /// through each point of `through`, cut to the picture's drawing area and a quarter of
    /// its margin; nothing if the direction's points coincide in the picture, and nothing for a
    /// line that misses the area. Returns how many lines were drawn.
    pub fn parallels<P: Into<ConstructedPoint>>(
        &mut self,
        layer: &Layer,
        direction: [P; 2],
        through: impl IntoIterator<Item = P>,
    ) -> usize {
        let [l, t, r, b] = self.frame.area();
        // A quarter of the margin around the area: a line along the content's edge stays in.
        let pad = self.sizes.margin / 4.0;
        let window = [l - pad, t - pad, r + pad, b + pad];
        let [from, to] = direction.map(|p| self.frame.to_picture_constructed(p.into()));
        let dir = [to[0] - from[0], to[1] - from[1]];
        let mut d = PathData::new(self.sizes.decimals);
        for p in through {
            let a = self.frame.to_picture_constructed(p.into());
            if let Some(ends) = clip_line(a, dir, window) {
                d.chain(&ends, false);
            }
        }
        let attrs = format!(" fill=\"none\"{}", self.stroke(layer.style, 0.0));
        self.paths(layer, Mark::Line, &attrs, d)
    }

    /// Draws circles given by their centre and a point on them; a circle whose centre or
    /// radius is beyond a hundred sides of the picture (a straight line across it) is left
    /// out, and the legend entry says how many were. Returns how many were drawn.
    pub fn circles<P: Into<ConstructedPoint>, Q: Into<ConstructedPoint>>(
        &mut self,
        layer: &Layer,
        circles: impl IntoIterator<Item = (P, Q)>,
    ) -> usize {
        let limit = CIRCLE_SIDES * self.sizes.side;
        let mut body = String::new();
        let (mut count, mut skipped) = (0, 0);
        for (centre, on) in circles {
            let c = self.frame.to_picture_constructed(centre.into());
            let p = self.frame.to_picture_constructed(on.into());
            let r = (p[0] - c[0]).hypot(p[1] - c[1]);
            if c[0].abs() > limit || c[1].abs() > limit || r > limit {
                skipped += 1;
                continue;
            }
            self.circle_element(&mut body, c, r);
            count += 1;
        }
        let attrs = format!(" fill=\"none\"{}", self.stroke(layer.style, 0.0));
        let mut layer = layer.clone();
        if let (Some(text), true) = (&mut layer.legend, skipped > 0) {
            let _ = write!(text, " ({skipped} too large to draw)");
        }
        self.group_with_legend(
            &layer,
            Mark::Ring,
            &attrs,
            &body,
            count,
            count + skipped > 0,
        )
    }

    /// Draws discs twice a dot wide filled with `fill` (one of [`CLASS_COLOURS`], say) and
    /// outlined in near black, centred on `points`; returns how many. The legend entry shows
    /// the fill.
    pub fn filled_points<P: Into<ConstructedPoint>>(
        &mut self,
        layer: &Layer,
        fill: &'static str,
        points: impl IntoIterator<Item = P>,
    ) -> usize {
        let r = self.sizes.dot;
        let mut body = String::new();
        let mut count = 0;
        for p in points {
            let c = self.frame.to_picture_constructed(p.into());
            self.placer.avoid(c);
            self.circle_element(&mut body, c, r);
            count += 1;
        }
        let attrs = format!(
            " fill=\"{fill}\" stroke=\"{}\" stroke-width=\"{}\"",
            Role::Input.colour(),
            short((0.5 * self.sizes.stroke).max(0.2))
        );
        self.group(layer, Mark::Filled(fill), &attrs, &body, count)
    }

    /// Draws a ring of a fixed size (three dots wide) around each point, to find a few
    /// points at a glance in a dense picture; returns how many.
    pub fn rings<P: Into<ConstructedPoint>>(
        &mut self,
        layer: &Layer,
        points: impl IntoIterator<Item = P>,
    ) -> usize {
        let r = 1.5 * self.sizes.dot + 1.5;
        let mut body = String::new();
        let mut count = 0;
        for p in points {
            let c = self.frame.to_picture_constructed(p.into());
            self.circle_element(&mut body, c, r);
            count += 1;
        }
        let attrs = format!(" fill=\"none\"{}", self.stroke(layer.style, 0.0));
        self.group(layer, Mark::Ring, &attrs, &body, count)
    }

    /// Writes each text next to its point, where it overlaps no other label and no dot
    /// when one of eight places around the point is free (else the least crowded), if the
    /// picture [shows labels](Self::shows_labels); otherwise the layer is empty. At most
    /// `4 · LABEL_LIMIT` labels are placed. Returns how many were written.
    pub fn labels<P: Into<ConstructedPoint>>(
        &mut self,
        layer: &Layer,
        labels: impl IntoIterator<Item = (P, String)>,
    ) -> usize {
        let mut body = String::new();
        let mut count = 0;
        let shown = if self.sizes.labels {
            4 * LABEL_LIMIT
        } else {
            0
        };
        for (p, text) in labels.into_iter().take(shown) {
            let at = self.frame.to_picture_constructed(p.into());
            let (x, y, anchor) = self.placer.place(at, text.chars().count());
            body.push_str("<text x=\"");
            push_number(&mut body, x, self.sizes.decimals);
            body.push_str("\" y=\"");
            push_number(&mut body, y, self.sizes.decimals);
            body.push('"');
            if anchor != "start" {
                let _ = write!(body, " text-anchor=\"{anchor}\"");
            }
            let _ = writeln!(body, ">{}</text>", escape(&text));
            count += 1;
        }
        let attrs = format!(
            " font-size=\"{}\" fill=\"{}\"",
            short(self.sizes.font),
            layer.style.role.colour()
        );
        self.group(layer, Mark::Text, &attrs, &body, count)
    }

    /// The picture as SVG text.
    pub fn to_svg(&self) -> String {
        let mut out = Vec::with_capacity(self.body.len() + 4096);
        self.write_svg(&mut out)
            .expect("writing to a vector does not fail");
        String::from_utf8(out).expect("the picture is UTF-8")
    }

    /// Writes the picture as SVG text to `out`.
    ///
    /// # Errors
    /// Those of `out`.
    pub fn write_svg<W: io::Write>(&self, out: &mut W) -> io::Result<()> {
        let [_, _, right, bottom] = self.frame.area();
        // Wide enough for the longest legend entry: a narrow drawing (a vertical segment)
        // widens the picture to its right.
        let font = self.sizes.legend_font;
        let entry = |text: &str| 2.0 * self.legend_left() + 2.7 * font + text_width(text, font);
        let widest = self
            .legend
            .iter()
            .map(|e| entry(&e.text))
            .fold(0.0, f64::max);
        let width = (right + self.sizes.margin).max(widest);
        let (legend, legend_height) = self.legend_text(width, bottom + self.sizes.margin * 0.6);
        let height = bottom + self.sizes.margin * 0.6 + legend_height;
        let origin = self.frame.origin();
        let [left, base] = self.frame.anchor();
        let (w, h) = (short(width), short(height));
        writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" \
             viewBox=\"0 0 {w} {h}\" font-family=\"sans-serif\" \
             data-frame=\"{} {} {} {} {}\">",
            origin.x,
            origin.y,
            self.frame.shift(),
            left,
            base
        )?;
        writeln!(out, "<title>{}</title>", escape(&self.title))?;
        writeln!(out, "<rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>")?;
        out.write_all(self.body.as_bytes())?;
        out.write_all(legend.as_bytes())?;
        writeln!(out, "</svg>")
    }

    /// The stroke attributes of a style, at least `min_width` wide.
    fn stroke(&self, style: Style, min_width: f64) -> String {
        let width = (self.sizes.stroke * style.role.weight()).max(min_width);
        let mut s = format!(
            " stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
            style.role.colour(),
            short(width)
        );
        let unit = width.max(1.0);
        match style.dash {
            Dash::Solid => {}
            Dash::Dashed => {
                let _ = write!(
                    s,
                    " stroke-dasharray=\"{} {}\"",
                    short(5.0 * unit),
                    short(3.0 * unit)
                );
            }
            Dash::Dotted => {
                let _ = write!(
                    s,
                    " stroke-dasharray=\"{} {}\"",
                    short(unit),
                    short(2.0 * unit)
                );
            }
        }
        s
    }

    /// Appends one `<circle>`.
    fn circle_element(&self, body: &mut String, c: [f64; 2], r: f64) {
        let k = self.sizes.decimals;
        body.push_str("<circle cx=\"");
        push_number(body, c[0], k);
        body.push_str("\" cy=\"");
        push_number(body, c[1], k);
        body.push_str("\" r=\"");
        push_number(body, r, k);
        body.push_str("\"/>\n");
    }

    /// Appends a layer of paths.
    fn paths(&mut self, layer: &Layer, mark: Mark, attrs: &str, d: PathData) -> usize {
        let count = d.subpaths;
        let mut body = String::with_capacity(d.text.iter().map(String::len).sum::<usize>() + 64);
        for text in &d.text {
            let _ = writeln!(body, "<path d=\"{text}\"/>");
        }
        self.group(layer, mark, attrs, &body, count)
    }

    /// Appends a layer's group and records it (and its legend entry, if it drew anything).
    fn group(&mut self, layer: &Layer, mark: Mark, attrs: &str, body: &str, count: usize) -> usize {
        self.group_with_legend(layer, mark, attrs, body, count, count > 0)
    }

    /// Appends a layer's group and records it, with its legend entry if `legend`.
    fn group_with_legend(
        &mut self,
        layer: &Layer,
        mark: Mark,
        attrs: &str,
        body: &str,
        count: usize,
        legend: bool,
    ) -> usize {
        let _ = writeln!(self.body, "<g class=\"{}\"{attrs}>", escape(&layer.name));
        self.body.push_str(body);
        self.body.push_str("</g>\n");
        self.layers.push((layer.name.clone(), count));
        if let (Some(text), true) = (&layer.legend, legend) {
            self.legend.push(Entry {
                style: layer.style,
                mark,
                text: text.clone(),
            });
        }
        count
    }

    /// The legend (title, then one swatch and text per entry, in rows) at `top`, for a
    /// picture `width` wide, and its height.
    fn legend_text(&self, width: f64, top: f64) -> (String, f64) {
        let font = self.sizes.legend_font;
        let line = 1.6 * font;
        let left = self.legend_left();
        let mut out = format!(
            "<g class=\"legend\" font-size=\"{}\" fill=\"{}\">\n",
            short(font),
            Role::Label.colour()
        );
        let mut y = top;
        for (k, line_text) in wrap(&self.title, font * 1.1, width - 2.0 * left)
            .iter()
            .enumerate()
        {
            y += if k == 0 { font } else { line };
            let _ = writeln!(
                out,
                "<text x=\"{}\" y=\"{}\" font-weight=\"bold\">{}</text>",
                short(left),
                short(y),
                escape(line_text)
            );
        }
        let swatch = 2.2 * font;
        let mut x = left;
        if !self.legend.is_empty() {
            y += line;
        }
        for entry in &self.legend {
            let needed = swatch + 0.5 * font + text_width(&entry.text, font) + 1.5 * font;
            if x > left && x + needed > width - left {
                x = left;
                y += line;
            }
            let mid = y - 0.35 * font;
            out.push_str(&self.swatch(entry, x, mid, swatch));
            let _ = writeln!(
                out,
                "<text x=\"{}\" y=\"{}\">{}</text>",
                short(x + swatch + 0.5 * font),
                short(y),
                escape(&entry.text)
            );
            x += needed;
        }
        out.push_str("</g>\n");
        (out, y - top + font)
    }

    /// The legend's left edge.
    fn legend_left(&self) -> f64 {
        self.sizes.margin.min(2.0 * self.sizes.legend_font)
    }

    /// The legend swatch of an entry, `length` wide, centred vertically on `mid`.
    fn swatch(&self, entry: &Entry, x: f64, mid: f64, length: f64) -> String {
        let colour = entry.style.role.colour();
        // A swatch stays visible however thin the picture's strokes are.
        let stroke = self.stroke(entry.style, 0.1 * self.sizes.legend_font);
        let font = self.sizes.legend_font;
        match entry.mark {
            Mark::Dot => format!(
                "<path d=\"M{} {}h0\" stroke=\"{colour}\" stroke-width=\"{}\" stroke-linecap=\"round\"/>\n",
                short(x + length / 2.0),
                short(mid),
                short(self.sizes.dot.max(0.4 * font))
            ),
            Mark::Line => format!(
                "<path d=\"M{} {}h{}\" fill=\"none\"{stroke}/>\n",
                short(x),
                short(mid),
                short(length)
            ),
            Mark::Area => {
                let fill = if entry.style.role == Role::Result {
                    format!("fill=\"{colour}\" fill-opacity=\"0.08\"")
                } else {
                    "fill=\"none\"".to_string()
                };
                format!(
                    "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" {fill}{stroke}/>\n",
                    short(x),
                    short(mid - 0.4 * font),
                    short(length),
                    short(0.8 * font)
                )
            }
            Mark::Ring => format!(
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"none\"{stroke}/>\n",
                short(x + length / 2.0),
                short(mid),
                short(0.45 * font)
            ),
            Mark::Filled(fill) => format!(
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{fill}\" stroke=\"{}\"/>\n",
                short(x + length / 2.0),
                short(mid),
                short(0.45 * font),
                Role::Input.colour()
            ),
            Mark::Text => format!(
                "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"{}\">12</text>\n",
                short(x + length / 2.0),
                short(mid + 0.35 * font),
                short(self.sizes.font)
            ),
        }
    }
}

/// The `d` attributes of a layer's paths, split every [`SUBPATHS_PER_PATH`] subpaths.
struct PathData {
    text: Vec<String>,
    subpaths: usize,
    decimals: u32,
}

impl PathData {
    fn new(decimals: u32) -> PathData {
        PathData {
            text: Vec::new(),
            subpaths: 0,
            decimals,
        }
    }

    /// The path text to append the next subpath to.
    fn next(&mut self) -> &mut String {
        if self.subpaths % SUBPATHS_PER_PATH == 0 {
            self.text.push(String::new());
        }
        self.subpaths += 1;
        self.text.last_mut().expect("a path was just started")
    }

    /// A dot: a subpath of length zero, drawn by the round cap.
    fn dot(&mut self, at: [f64; 2]) {
        let k = self.decimals;
        let d = self.next();
        d.push('M');
        push_pair(d, at, k);
        d.push_str("h0");
    }

    /// A polyline (closed with `Z` if asked): `Mx yLx y x y ...`.
    fn chain(&mut self, vertices: &[[f64; 2]], closed: bool) {
        let k = self.decimals;
        let d = self.next();
        for (i, &v) in vertices.iter().enumerate() {
            d.push_str(match i {
                0 => "M",
                1 => "L",
                _ => " ",
            });
            push_pair(d, v, k);
        }
        if closed {
            d.push('Z');
        }
    }
}

/// The part of the line `a + t·dir` inside the window `[left, top, right, bottom]`, or
/// `None` if the direction is zero or the line misses the window (Liang–Barsky).
fn clip_line(a: [f64; 2], dir: [f64; 2], window: [f64; 4]) -> Option<[[f64; 2]; 2]> {
    if dir[0] == 0.0 && dir[1] == 0.0 {
        return None;
    }
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for axis in 0..2 {
        let (min, max) = (window[axis], window[axis + 2]);
        if dir[axis] == 0.0 {
            if a[axis] < min || a[axis] > max {
                return None;
            }
        } else {
            let (t0, t1) = ((min - a[axis]) / dir[axis], (max - a[axis]) / dir[axis]);
            lo = lo.max(t0.min(t1));
            hi = hi.min(t0.max(t1));
        }
    }
    // Neither bound is NaN: the direction is nonzero and every coordinate finite.
    if lo >= hi || !lo.is_finite() || !hi.is_finite() {
        return None;
    }
    let at = |t: f64| [a[0] + t * dir[0], a[1] + t * dir[1]].map(|v| v.clamp(-FAR, FAR));
    Some([at(lo), at(hi)])
}

/// `text` broken at spaces into lines of at most `width` (estimated at `font` size); a
/// word longer than a line gets a line of its own.
fn wrap(text: &str, font: f64, width: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut current = String::new();
    for word in text.split(' ') {
        let candidate = if current.is_empty() {
            word.to_string()
        } else {
            format!("{current} {word}")
        };
        if !current.is_empty() && text_width(&candidate, font) > width {
            lines.push(std::mem::replace(&mut current, word.to_string()));
        } else {
            current = candidate;
        }
    }
    lines.push(current);
    lines
}

/// The estimated width of `text` at `font` size (sans-serif digits and letters average
/// about 0.6 em).
fn text_width(text: &str, font: f64) -> f64 {
    0.6 * font * text.chars().count() as f64
}

/// Appends `x y`.
fn push_pair(out: &mut String, [x, y]: [f64; 2], decimals: u32) {
    push_number(out, x, decimals);
    out.push(' ');
    push_number(out, y, decimals);
}

/// Appends `v` (a picture coordinate, within `±10⁶`) rounded to `decimals` (at most 3)
/// decimals, without trailing zeros or a negative zero.
fn push_number(out: &mut String, v: f64, decimals: u32) {
    let scale = 10u64.pow(decimals.min(3));
    let r = (v.clamp(-FAR, FAR) * scale as f64).round();
    let a = r.abs() as u64;
    if r < 0.0 && a != 0 {
        out.push('-');
    }
    let _ = write!(out, "{}", a / scale);
    let mut frac = a % scale;
    if frac != 0 {
        let mut digits = decimals.min(3) as usize;
        while frac % 10 == 0 {
            frac /= 10;
            digits -= 1;
        }
        let _ = write!(out, ".{frac:0digits$}");
    }
}

/// A size or coordinate of the picture's frame and legend, with at most two decimals.
fn short(v: f64) -> String {
    let mut s = String::new();
    push_number(&mut s, v, 2);
    s
}

/// `text` for XML character data or an attribute value: `&`, `<`, `>`, `"` and `'` as
/// entities, and the characters XML 1.0 forbids (control characters other than tab, line
/// feed and carriage return) as U+FFFD.
///
/// ```
/// use compgeo::draw::escape;
///
/// assert_eq!(escape("a < b & \"c\""), "a &lt; b &amp; &quot;c&quot;");
/// assert_eq!(escape("bell\u{7}"), "bell\u{fffd}");
/// ```
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' | '\r' => out.push(c),
            c if (c as u32) < 0x20 || c == '\u{fffe}' || c == '\u{ffff}' => out.push('\u{fffd}'),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn number(v: f64, decimals: u32) -> String {
        let mut s = String::new();
        push_number(&mut s, v, decimals);
        s
    }

    #[test]
    fn numbers_have_bounded_digits_and_no_negative_zero() {
        assert_eq!(number(12.345, 2), "12.35");
        assert_eq!(number(12.3, 2), "12.3");
        assert_eq!(number(12.0, 2), "12");
        assert_eq!(number(-0.001, 2), "0");
        assert_eq!(number(-0.05, 1), "-0.1");
        assert_eq!(number(-3.04, 2), "-3.04");
        assert_eq!(number(1e300, 2), "1000000");
        assert_eq!(number(-1e300, 1), "-1000000");
        assert_eq!(number(0.5, 0), "1");
    }

    #[test]
    fn sizes_shrink_with_density_and_labels_stop_at_the_limit() {
        let small = Sizes::for_count(10);
        let big = Sizes::for_count(100_000);
        assert!(small.labels && !big.labels);
        assert!(Sizes::for_count(LABEL_LIMIT).labels && !Sizes::for_count(LABEL_LIMIT + 1).labels);
        assert!(big.stroke < small.stroke && big.dot < small.dot);
        assert!(big.side > small.side && big.side <= MAX_SIDE);
    }

    #[test]
    fn lines_are_cut_to_the_window() {
        let w = [0.0, 0.0, 10.0, 10.0];
        assert_eq!(
            clip_line([5.0, 5.0], [1.0, 0.0], w),
            Some([[0.0, 5.0], [10.0, 5.0]])
        );
        assert_eq!(
            clip_line([0.0, 0.0], [1.0, 1.0], w),
            Some([[0.0, 0.0], [10.0, 10.0]])
        );
        assert_eq!(clip_line([20.0, 0.0], [0.0, 1.0], w), None);
        assert_eq!(clip_line([5.0, 5.0], [0.0, 0.0], w), None);
        assert_eq!(clip_line([0.0, 30.0], [1.0, 1.0], w), None);
    }

    #[test]
    fn every_role_has_its_own_colour_but_the_label() {
        let mut colours: Vec<&str> = Role::ALL
            .iter()
            .filter(|&&r| r != Role::Label)
            .map(|r| r.colour())
            .collect();
        colours.sort_unstable();
        colours.dedup();
        assert_eq!(colours.len(), Role::ALL.len() - 1);
    }
}
