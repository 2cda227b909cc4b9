//! The one chart model: a [`Chart`] (title, axis titles, [`Scale`]s, named series in data
//! units, vertical markers) that every renderer draws — the explorer's terminal view, the
//! plain-text chart ([`super::render_text`]) and the SVG/PNG files ([`super::write_svg`],
//! [`super::write_png`]) — and that every producer builds: the explorer's chart builders,
//! `asperity figure`, `gauge --svg/--png` and `surface psd`.
//!
//! A series says what it is ([`Role`]) and how it is drawn ([`SeriesStyle`]); its look (colour,
//! terminal glyph, file marker) is its role's from the table of looks ([`crate::looks`]) unless
//! the producer fixed one ([`Series::painted`]: a figure's curves in their models' colours).

use super::scale::Scale;
use super::style::{Rgb, SeriesStyle, Shape};
use crate::looks::{look, Glyph, Ink, Look, Role};

/// One series, in data units (NaN marks a gap).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend name.
    pub name: String,
    /// Points (data units).
    pub points: Vec<(f64, f64)>,
    /// What it is (its look, unless [`Series::look`] fixes one).
    pub role: Role,
    /// How it is drawn.
    pub style: SeriesStyle,
    /// A look fixed by the producer (None: the role's in this chart, [`Chart::series_look`]).
    pub look: Option<Look>,
}

impl Series {
    /// A series of `role` drawn as `style`, its look the role's.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>, role: Role, style: SeriesStyle) -> Series {
        Series {
            name: name.into(),
            points,
            role,
            style,
            look: None,
        }
    }

    /// A series in a fixed colour and file marker (a figure's curve in its model's colour): a
    /// theory curve as far as its role goes.
    pub fn painted(
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        style: SeriesStyle,
        colour: Rgb,
        shape: Shape,
    ) -> Series {
        Series {
            look: Some(Look {
                ink: Ink::Rgb(colour),
                glyph: Glyph::Braille,
                shape,
                bold: false,
            }),
            ..Series::new(name, points, Role::Theory, style)
        }
    }
}

/// A vertical marker across the whole y range.
#[derive(Debug, Clone, PartialEq)]
pub struct VLine {
    /// x (data units).
    pub x: f64,
    /// What it is ([`Role::Guide`], [`Role::Wall`], [`Role::JumpIn`], [`Role::PullOff`]).
    pub role: Role,
    /// Legend name (empty: no legend entry).
    pub name: String,
}

/// A chart ready to draw.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// Title (the quantity and the load it is drawn at).
    pub title: String,
    /// x axis title, with units.
    pub x_label: String,
    /// y axis title, with units.
    pub y_label: String,
    /// x scale.
    pub xs: Scale,
    /// y scale.
    pub ys: Scale,
    /// Plane bounds of x before rounding: the terminal rounds them to round ticks; the text
    /// and file renderers fit the drawable data instead.
    pub xb: [f64; 2],
    /// Plane bounds of y before rounding.
    pub yb: [f64; 2],
    /// Series, drawn in this order (the legend lists them in the same order).
    pub series: Vec<Series>,
    /// Vertical markers.
    pub vlines: Vec<VLine>,
    /// Why there is nothing to draw.
    pub empty: Option<String>,
    /// The data belong to an earlier scene (a newer one is being computed).
    pub stale: bool,
    /// Points of the y data outside [`Chart::yb`] are dropped (log axes spanning many
    /// decades).
    pub clip_y: bool,
    /// Model slot of the current scene (the theory's colour).
    pub model: usize,
    /// The y axis hugs the data (two labels, a fine step) instead of three round labels
    /// that may double its span (σ̄_c*: the models' differences stay visible).
    pub fit_y: bool,
}

impl Chart {
    /// An empty chart with these titles and scales (bounds [0, 1], the theory model 3's).
    pub fn new(title: impl Into<String>, x: &str, y: &str, xs: Scale, ys: Scale) -> Chart {
        Chart {
            title: title.into(),
            x_label: x.into(),
            y_label: y.into(),
            xs,
            ys,
            xb: [0.0, 1.0],
            yb: [0.0, 1.0],
            series: Vec::new(),
            vlines: Vec::new(),
            empty: None,
            stale: false,
            clip_y: false,
            model: 2,
            fit_y: false,
        }
    }

    /// The order every renderer draws the series in: shaded bands under everything, then
    /// lines, then the closed forms (dashed: the curve they lie on shows between their dashes,
    /// so an asymptote or a fit that a model follows stays visible), then points, which no
    /// line may cover.
    pub fn draw_order(&self) -> Vec<usize> {
        let rank = |s: &Series| match (s.style, s.role) {
            (_, Role::Band) | (SeriesStyle::Band, _) => 0,
            (SeriesStyle::Points, _) => 3,
            (_, Role::Closed | Role::Closed2) => 2,
            _ => 1,
        };
        let mut order: Vec<usize> = (0..self.series.len()).collect();
        order.sort_by_key(|&i| rank(&self.series[i]));
        order
    }

    /// The look of series `i`: the one its producer fixed, else its role's, the k-th
    /// reference source of the chart its k-th marker.
    pub fn series_look(&self, i: usize) -> Look {
        let s = &self.series[i];
        if let Some(l) = s.look {
            return l;
        }
        let nth = self.series[..i]
            .iter()
            .filter(|e| e.role == s.role && e.look.is_none())
            .count();
        look(s.role, self.model, nth)
    }

    /// The look of a vertical marker.
    pub fn vline_look(&self, v: &VLine) -> Look {
        look(v.role, self.model, 0)
    }

    /// The lowest y a renderer draws: with [`Chart::clip_y`], the low end of
    /// [`Chart::yb`] in data units; else −∞.
    pub fn y_floor(&self) -> f64 {
        if self.clip_y {
            self.ys.inverse(self.yb[0])
        } else {
            f64::NEG_INFINITY
        }
    }

    /// Fixes every series' look (its role's where the producer fixed none) and tells apart
    /// the series that share a colour ([`super::tell_apart`]).
    pub fn tell_apart(&mut self) {
        for i in 0..self.series.len() {
            self.series[i].look = Some(self.series_look(i));
        }
        super::tell_apart(&mut self.series);
    }
}
