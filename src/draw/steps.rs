//! Step pages: an algorithm's run as one self-contained HTML page, a picture per step.
//!
//! A [`StepPage`] holds frames, each a [`Picture`] with a caption and the operation counts
//! the run had made by then (a [`trace`](crate::trace) frame's `counts`). The page shows one
//! frame at a time under a slider; the ← and → keys (or Page Up / Page Down, Home and End)
//! and the two buttons step through it. Everything is inline — the SVG of every frame, the
//! style and a short script — so the file opens anywhere, offline, and prints (printing shows
//! the current frame).
//!
//! The page is also well-formed XML (tags closed, the script inside a commented CDATA
//! section), so tests read it with an XML parser: each frame is a `<section class="frame">`
//! with `data-step` (its index) and `data-kind` (the step's name), holding a caption, the
//! picture's `<svg>` and a table of counts.

use std::fmt::Write as _;

use super::svg::{escape, Picture};
use crate::count::{Counts, Operation};
use crate::limits::STEP_PAGE_FRAMES;
use crate::Result;

/// One frame of a [`StepPage`].
#[derive(Debug, Clone)]
pub struct StepFrame {
    /// What the step is, in a word or two (`push`, `pop`, `flip`): written as the frame's
    /// `data-kind`.
    pub kind: &'static str,
    /// A sentence saying what happened.
    pub caption: String,
    /// The state after the step.
    pub picture: Picture,
    /// The operations made so far.
    pub counts: Counts,
}

impl StepFrame {
    /// A frame of kind `kind` with its caption, picture and counts so far.
    pub fn new(kind: &'static str, caption: String, picture: Picture, counts: Counts) -> StepFrame {
        StepFrame {
            kind,
            caption,
            picture,
            counts,
        }
    }
}

/// An algorithm's run, a picture per step, as one HTML page.
///
/// ```
/// use compgeo::count::Counts;
/// use compgeo::draw::{Layer, Picture, Role, StepFrame, StepPage};
/// use compgeo::geometry::{BoundingBox, Point2};
///
/// let pts = [Point2::new(0.0, 0.0), Point2::new(2.0, 1.0), Point2::new(1.0, 2.0)];
/// let bounds = BoundingBox::of(&pts).unwrap();
/// let mut page = StepPage::new("three points, one at a time");
/// for k in 1..=3 {
///     let mut picture = Picture::new("points", bounds, 3);
///     picture.points(&Layer::new("points", Role::Input), pts[..k].iter().copied());
///     let counts = Counts { comparisons: k as u64, ..Counts::default() };
///     page.push(StepFrame { kind: "add", caption: format!("{k} points"), picture, counts })?;
/// }
/// let html = page.to_html();
/// assert_eq!(html.matches("<section class=\"frame\"").count(), 3);
/// assert!(html.contains("id=\"slider\"") && html.contains("max=\"2\""));
/// # Ok::<(), compgeo::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct StepPage {
    title: String,
    about: String,
    frames: Vec<StepFrame>,
}

impl StepPage {
    /// An empty page titled `title`.
    pub fn new(title: &str) -> StepPage {
        StepPage {
            title: title.to_string(),
            about: String::new(),
            frames: Vec::new(),
        }
    }

    /// A paragraph under the title (the input, the algorithm's source).
    pub fn about(mut self, text: &str) -> StepPage {
        self.about = text.to_string();
        self
    }

    /// Adds a frame.
    ///
    /// # Errors
    /// [`Error::LimitExceeded`](crate::Error::LimitExceeded) beyond
    /// [`STEP_PAGE_MAX_FRAMES`](crate::limits::STEP_PAGE_MAX_FRAMES) frames.
    pub fn push(&mut self, frame: StepFrame) -> Result<()> {
        STEP_PAGE_FRAMES.check(self.frames.len() as u128 + 1)?;
        self.frames.push(frame);
        Ok(())
    }

    /// The frames so far.
    pub fn frames(&self) -> &[StepFrame] {
        &self.frames
    }

    /// The page as HTML.
    ///
    /// # Complexity
    /// Linear in the frames' pictures.
    pub fn to_html(&self) -> String {
        let mut h = String::with_capacity(8192);
        let last = self.frames.len().saturating_sub(1);
        let title = escape(&self.title);
        let _ = write!(
            h,
            "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n\
             <meta charset=\"utf-8\"/>\n<title>{title}</title>\n<style>{STYLE}</style>\n</head>\n\
             <body data-current=\"0\">\n<h1>{title}</h1>\n"
        );
        if !self.about.is_empty() {
            let _ = writeln!(h, "<p class=\"about\">{}</p>", escape(&self.about));
        }
        let _ = write!(
            h,
            "<nav class=\"controls\">\n<button type=\"button\" id=\"previous\" \
             title=\"previous step (←)\">← previous</button>\n\
             <input type=\"range\" id=\"slider\" min=\"0\" max=\"{last}\" value=\"0\" step=\"1\" \
             aria-label=\"step\"/>\n<button type=\"button\" id=\"next\" title=\"next step (→)\">\
             next →</button>\n<output id=\"position\">{} / {}</output>\n</nav>\n\
             <div id=\"frames\">\n",
            usize::from(!self.frames.is_empty()),
            self.frames.len()
        );
        for (i, frame) in self.frames.iter().enumerate() {
            let hidden = if i == 0 { "" } else { " hidden=\"hidden\"" };
            let _ = write!(
                h,
                "<section class=\"frame\" id=\"frame-{i}\" data-step=\"{i}\" \
                 data-kind=\"{}\"{hidden}>\n<p class=\"caption\"><span class=\"number\">step \
                 {} of {}</span> {}</p>\n",
                escape(frame.kind),
                i + 1,
                self.frames.len(),
                escape(&frame.caption)
            );
            h.push_str(&frame.picture.to_svg());
            h.push_str(&counts_table(&frame.counts));
            h.push_str("</section>\n");
        }
        let _ = write!(
            h,
            "</div>\n<script>//<![CDATA[\n{SCRIPT}\n//]]></script>\n</body>\n</html>\n"
        );
        h
    }
}

/// The non-zero counts as a table (a note when nothing has been counted yet).
fn counts_table(counts: &Counts) -> String {
    let mut t = String::from(
        "<table class=\"counts\">\n<tr><th>operations so far</th><th>count</th></tr>\n",
    );
    let mut any = false;
    for op in Operation::ALL {
        let value = counts.get(op);
        if value > 0 {
            any = true;
            let _ = writeln!(
                t,
                "<tr data-operation=\"{}\"><td>{}</td><td>{value}</td></tr>",
                op.name(),
                op.name().replace('_', " ")
            );
        }
    }
    if !any {
        t.push_str("<tr><td colspan=\"2\">none yet</td></tr>\n");
    }
    t.push_str("</table>\n");
    t
}

/// The page's style: readable on screen and printed (only the current frame prints).
const STYLE: &str = "
body { font-family: sans-serif; margin: 1.5em auto; max-width: 60em; color: #1a1a1a; }
h1 { font-size: 1.3em; }
.controls { display: flex; gap: 0.8em; align-items: center; margin: 1em 0; }
#slider { flex: 1; }
.caption { font-size: 1.05em; min-height: 2.6em; }
.caption .number { color: #666; margin-right: 0.6em; }
.frame svg { max-width: 100%; height: auto; border: 1px solid #ddd; }
table.counts { border-collapse: collapse; margin-top: 0.6em; }
table.counts td, table.counts th { border: 1px solid #ccc; padding: 0.2em 0.6em; text-align: left; }
@media print { .controls { display: none; } }
";

/// Shows one frame at a time: the slider, the buttons and the keys move between frames. It
/// writes the current index to `body[data-current]` (what the browser test reads).
const SCRIPT: &str = "
(function () {
  var frames = document.querySelectorAll('section.frame');
  var slider = document.getElementById('slider');
  var position = document.getElementById('position');
  var current = 0;
  function show(i) {
    if (frames.length === 0) { return; }
    i = Math.max(0, Math.min(frames.length - 1, i));
    frames[current].hidden = true;
    frames[i].hidden = false;
    current = i;
    slider.value = String(i);
    position.textContent = (i + 1) + ' / ' + frames.length;
    document.body.setAttribute('data-current', String(i));
  }
  slider.addEventListener('input', function () { show(Number(slider.value)); });
  document.getElementById('previous').addEventListener('click', function () { show(current - 1); });
  document.getElementById('next').addEventListener('click', function () { show(current + 1); });
  document.addEventListener('keydown', function (e) {
    if (e.target === slider) { return; }
    var moves = { ArrowRight: 1, PageDown: 1, ArrowLeft: -1, PageUp: -1 };
    if (e.key in moves) { show(current + moves[e.key]); e.preventDefault(); }
    else if (e.key === 'Home') { show(0); e.preventDefault(); }
    else if (e.key === 'End') { show(frames.length - 1); e.preventDefault(); }
  });
  show(0);
})();";
