//! How a series looks in every renderer: its line style ([`SeriesStyle`]), its colour
//! ([`Rgb`]) and its point marker in files ([`Shape`]). Plain values with no dependencies, so
//! the table of looks ([`crate::looks`]) and the chart model can both use them.

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SeriesStyle {
    /// A solid line through the points (a model curve).
    Line,
    /// Markers only (simulation points, reference values).
    Points,
    /// A dashed line (a closed form, an asymptote, a reference curve).
    Dashed,
    /// A dotted line (a pinned curve of an earlier scene).
    Dotted,
    /// A dash-dotted line (a further curve of a model already drawn).
    DashDot,
    /// A filled band (the bracket of the mean gap): the points are its outline, each run
    /// between gaps one closed polygon ([`super::band_outline`]).
    Band,
}

impl SeriesStyle {
    /// The line styles, solid first.
    pub const LINES: [SeriesStyle; 4] = [
        SeriesStyle::Line,
        SeriesStyle::Dashed,
        SeriesStyle::Dotted,
        SeriesStyle::DashDot,
    ];

    /// The on/off lengths of a broken line, starting with a stroke, in units of about a
    /// line's width (a terminal cell, 2.5 px of a file); `None` for a solid line or points.
    pub fn pattern(self) -> Option<&'static [f64]> {
        match self {
            SeriesStyle::Line | SeriesStyle::Points | SeriesStyle::Band => None,
            SeriesStyle::Dashed => Some(&[3.0, 2.0]),
            SeriesStyle::Dotted => Some(&[1.0, 2.0]),
            SeriesStyle::DashDot => Some(&[3.0, 1.5, 1.0, 1.5]),
        }
    }

    /// Its name in figure files and text charts.
    pub fn name(self) -> &'static str {
        match self {
            SeriesStyle::Line => "line",
            SeriesStyle::Points => "points",
            SeriesStyle::Dashed => "dashed",
            SeriesStyle::Dotted => "dotted",
            SeriesStyle::DashDot => "dash-dot",
            SeriesStyle::Band => "band",
        }
    }
}

/// A colour (sRGB).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Rgb(pub u8, pub u8, pub u8);

/// The marker of a series of points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Shape {
    /// A filled disc.
    Circle,
    /// An open square.
    Square,
    /// A filled diamond.
    Diamond,
    /// A filled triangle, point up.
    Triangle,
    /// A filled triangle, point down.
    TriangleDown,
    /// A diagonal cross.
    Cross,
    /// An upright cross.
    Plus,
}

impl Shape {
    /// Every shape.
    pub const ALL: [Shape; 7] = [
        Shape::Circle,
        Shape::Square,
        Shape::Diamond,
        Shape::Triangle,
        Shape::TriangleDown,
        Shape::Cross,
        Shape::Plus,
    ];
}
