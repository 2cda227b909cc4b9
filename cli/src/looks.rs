//! One table of looks: what every kind of series looks like, in the explorer (a colour and a
//! terminal glyph) and in SVG/PNG files (the same colour and a point shape), so a model has
//! one colour in the explorer, in its `s` exports and in `asperity figure`.
//!
//! A series' line style (solid, dashed, dotted, points) is the chart builder's
//! ([`crate::chart::SeriesStyle`]); the table gives the rest. Within one chart no two series share a colour
//! and glyph, and no two share a glyph and line style (so they stay apart under `NO_COLOR`):
//!
//! | role | colour | glyph | drawn |
//! |---|---|---|---|
//! | model 1, 2, 3, 4 | orange, bluish green, blue, vermillion | `•` `▄` `⣿` `█` | solid |
//! | custom, YP08, Xu24 | reddish purple, brown, purple | `▀` `▚` `+` | solid |
//! | theory (the current scene) | its model's | `⣿` | solid |
//! | unloading branch | the theory's | `◦` | dashed |
//! | adhesionless comparison | light grey | `·` | solid |
//! | closed form (eq. (18), σ → 0, t = ∞, fit) | sky blue | `⣿` | dashed |
//! | second closed form (large σ) | lavender | `•` | dashed |
//! | GFMD / theory on the GFMD map | yellow / olive | `×` / `▚` | points / dashed |
//! | reference points (k-th source) | the text colour (black) | `◆` `■` `▲` `▼` `◇` `□` | points |
//! | current point | rose | `●` | points |
//! | pins 1–6 | sand, green, wine, indigo, grey, teal | `⣿` `•` `▄` `█` `▀` `▚` | dotted |
//! | guide, −σ_a* wall, jump-in, pull-off | grey, magenta, teal, steel blue | `┊` `┃` `╏` `┇` | vertical |
//! | gap bracket | slate | `░` | points (a shaded band) |
//!
//! The theory and the models never share a chart (with `M` the current model is drawn as a
//! model). `cli/tests/looks.rs` checks every chart kind with every overlay.

use crate::chart::style::{Rgb, Shape};
use asperity::input::model::{Model, ModelKind};

/// What a series is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Role {
    /// The theory of the current scene (in its model's colour).
    Theory,
    /// Model slot 0–3 (models 1–4), 4 (custom), 5 (YP08), 6 (Xu24).
    Model(usize),
    /// The adhesionless comparison (or, in the scale view, the final resolution).
    Compare,
    /// A closed form (eq. (18), the small-stress asymptote, t = ∞, a fit).
    Closed,
    /// A second closed form (the large-stress asymptote).
    Closed2,
    /// Reference points: a preset's or the paper's values.
    Reference,
    /// GFMD results.
    Gfmd,
    /// The theory on the GFMD map (a second system, beside the scene's curve).
    GfmdTheory,
    /// The current point.
    Current,
    /// A guide line (σ* = 0, current p*, q_r).
    Guide,
    /// The −σ_a* wall (and the spectrum's cut-offs).
    Wall,
    /// The unloading branch of a hysteresis.
    Unloading,
    /// The jump-in load: above it the loading branch no longer exists.
    JumpIn,
    /// The pull-off load: below it the unloading branch no longer exists.
    PullOff,
    /// A pinned curve (`P`), the pin's index.
    Pin(usize),
    /// A shaded range (the bracket of the mean gap): drawn as a fill of points.
    Band,
}

/// A colour: an RGB, or the terminal's own text colour (black in files).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Ink {
    /// The text colour.
    Text,
    /// A colour.
    Rgb(Rgb),
}

impl Ink {
    /// The colour in a file (white background).
    pub fn rgb(self) -> Rgb {
        match self {
            Ink::Text => Rgb(0, 0, 0),
            Ink::Rgb(c) => c,
        }
    }
}

/// How a series marks the terminal cells it passes (ratatui's markers, or one character
/// per cell).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Glyph {
    /// Braille dots, 2 × 4 per cell.
    Braille,
    /// `•`
    Dot,
    /// `▄`
    Bar,
    /// `█`
    Block,
    /// Half blocks, 1 × 2 per cell.
    HalfBlock,
    /// Quadrants, 2 × 2 per cell.
    Quadrant,
    /// This character in every cell.
    Char(char),
}

impl Glyph {
    /// The legend's symbol.
    pub fn symbol(self) -> char {
        match self {
            Glyph::Braille => '⣿',
            Glyph::Dot => '•',
            Glyph::Bar => '▄',
            Glyph::Block => '█',
            Glyph::HalfBlock => '▀',
            Glyph::Quadrant => '▚',
            Glyph::Char(c) => c,
        }
    }
}

/// The look of one series.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Look {
    /// Colour.
    pub ink: Ink,
    /// Terminal glyph.
    pub glyph: Glyph,
    /// Point shape in files.
    pub shape: Shape,
    /// Bold in the terminal.
    pub bold: bool,
}

/// The colours of model slots 0–7: models 1–4, custom, YP08, Xu24, model 5 (Okabe–Ito, then
/// two earth tones and a pink that none of the other roles uses, so model 5 is told apart from
/// the GFMD points it is compared with).
pub const MODEL_COLOURS: [Rgb; 8] = [
    Rgb(230, 159, 0),
    Rgb(0, 158, 115),
    Rgb(0, 114, 178),
    Rgb(213, 94, 0),
    Rgb(204, 121, 167),
    Rgb(140, 86, 75),
    Rgb(127, 60, 141),
    Rgb(255, 170, 187),
];

/// The glyphs of model slots 0–7.
pub const MODEL_GLYPHS: [Glyph; 8] = [
    Glyph::Dot,
    Glyph::Bar,
    Glyph::Braille,
    Glyph::Block,
    Glyph::HalfBlock,
    Glyph::Quadrant,
    Glyph::Char('+'),
    Glyph::Char('∗'),
];

/// The colours of the pins (apart from the models' and the roles').
pub const PIN_COLOURS: [Rgb; 6] = [
    Rgb(221, 204, 119),
    Rgb(34, 136, 51),
    Rgb(170, 51, 119),
    Rgb(102, 102, 204),
    Rgb(128, 128, 128),
    Rgb(0, 153, 136),
];

/// The glyphs of the pins (dotted lines).
pub const PIN_GLYPHS: [Glyph; 6] = [
    Glyph::Braille,
    Glyph::Dot,
    Glyph::Bar,
    Glyph::Block,
    Glyph::HalfBlock,
    Glyph::Quadrant,
];

/// The glyphs and file shapes of the k-th reference source of a chart.
pub const REFERENCE_MARKS: [(char, Shape); 6] = [
    ('◆', Shape::Diamond),
    ('■', Shape::Square),
    ('▲', Shape::Triangle),
    ('▼', Shape::TriangleDown),
    ('◇', Shape::Plus),
    ('□', Shape::Cross),
];

/// Model slot of a model: 0–3 for models 1–4, 4 custom, 5 YP08, 6 Xu24, 7 model 5.
pub fn model_slot(m: &Model) -> usize {
    kind_slot(m.kind)
}

/// Model slot of a kind of model ([`model_slot`]).
pub fn kind_slot(kind: ModelKind) -> usize {
    match kind {
        ModelKind::Custom => 4,
        ModelKind::Yp08 => 5,
        ModelKind::Xu24 => 6,
        ModelKind::Five => 7,
        _ => kind.number().map_or(4, |n| usize::from(n) - 1),
    }
}

/// The colour of model slot `slot`.
pub fn model_colour(slot: usize) -> Rgb {
    MODEL_COLOURS[slot.min(MODEL_COLOURS.len() - 1)]
}

/// The names of the colours of the table, as a caption says them (`{look:NAME}`, see
/// [`describe`]).
pub const COLOUR_NAMES: [(Rgb, &str); 25] = [
    (Rgb(230, 159, 0), "orange"),
    (Rgb(0, 158, 115), "bluish green"),
    (Rgb(0, 114, 178), "blue"),
    (Rgb(213, 94, 0), "vermillion"),
    (Rgb(204, 121, 167), "reddish purple"),
    (Rgb(140, 86, 75), "brown"),
    (Rgb(127, 60, 141), "purple"),
    (Rgb(221, 204, 119), "sand"),
    (Rgb(34, 136, 51), "green"),
    (Rgb(170, 51, 119), "wine"),
    (Rgb(102, 102, 204), "indigo"),
    (Rgb(128, 128, 128), "grey"),
    (Rgb(0, 153, 136), "teal"),
    (Rgb(187, 187, 187), "light grey"),
    (Rgb(86, 180, 233), "sky blue"),
    (Rgb(153, 136, 238), "lavender"),
    (Rgb(240, 228, 66), "yellow"),
    (Rgb(153, 153, 51), "olive"),
    (Rgb(238, 102, 119), "rose"),
    (Rgb(150, 150, 150), "grey"),
    (Rgb(204, 51, 153), "magenta"),
    (Rgb(68, 170, 153), "teal"),
    (Rgb(102, 153, 204), "steel blue"),
    (Rgb(119, 136, 153), "slate"),
    (Rgb(255, 170, 187), "pink"),
];

/// Words that name a colour: a caption may say them only through a `{look:NAME}` reference.
pub const COLOUR_WORDS: [&str; 24] = [
    "orange",
    "green",
    "blue",
    "vermillion",
    "purple",
    "brown",
    "sand",
    "wine",
    "indigo",
    "grey",
    "gray",
    "teal",
    "sky",
    "lavender",
    "yellow",
    "olive",
    "rose",
    "magenta",
    "steel",
    "slate",
    "red",
    "black",
    "white",
    "pink",
];

/// The name of a colour ("text colour" for [`Ink::Text`]).
pub fn colour_name(ink: Ink) -> &'static str {
    match ink {
        Ink::Text => "black",
        Ink::Rgb(c) => COLOUR_NAMES
            .iter()
            .find(|(rgb, _)| *rgb == c)
            .map_or("unnamed", |(_, n)| n),
    }
}

impl Role {
    /// The roles a caption can name (`{look:NAME}`), and their names.
    pub const NAMED: [(&'static str, Role); 17] = [
        ("theory", Role::Theory),
        ("model1", Role::Model(0)),
        ("model2", Role::Model(1)),
        ("model3", Role::Model(2)),
        ("model4", Role::Model(3)),
        ("model5", Role::Model(7)),
        ("adhesionless", Role::Compare),
        ("closed-form", Role::Closed),
        ("closed-form-2", Role::Closed2),
        ("reference", Role::Reference),
        ("gfmd", Role::Gfmd),
        ("current", Role::Current),
        ("wall", Role::Wall),
        ("unloading", Role::Unloading),
        ("jump-in", Role::JumpIn),
        ("pull-off", Role::PullOff),
        ("band", Role::Band),
    ];

    /// The role a caption names `name`.
    pub fn named(name: &str) -> Option<Role> {
        Role::NAMED.iter().find(|(n, _)| *n == name).map(|(_, r)| *r)
    }
}

/// How a caption says the look of `role` (the first series of its kind in a chart whose
/// current model is slot `model`): its colour and glyph, e.g. `light grey ·`; a look in the
/// text colour is its glyph alone.
pub fn describe(role: Role, model: usize) -> String {
    let l = look(role, model, 0);
    let g = l.glyph.symbol();
    match l.ink {
        Ink::Text => g.to_string(),
        ink => format!("{} {g}", colour_name(ink)),
    }
}

fn rgb(r: u8, g: u8, b: u8) -> Ink {
    Ink::Rgb(Rgb(r, g, b))
}

/// The look of `role` in a chart whose current model is slot `model`; `nth` counts the
/// chart's earlier series of the same role (reference sources).
pub fn look(role: Role, model: usize, nth: usize) -> Look {
    let plain = |ink: Ink, glyph: Glyph, shape: Shape| Look {
        ink,
        glyph,
        shape,
        bold: false,
    };
    let theory = Ink::Rgb(model_colour(model));
    match role {
        Role::Theory => plain(theory, Glyph::Braille, Shape::Circle),
        Role::Model(i) => {
            let i = i.min(MODEL_COLOURS.len() - 1);
            plain(Ink::Rgb(MODEL_COLOURS[i]), MODEL_GLYPHS[i], Shape::Circle)
        }
        Role::Unloading => plain(theory, Glyph::Char('◦'), Shape::Circle),
        Role::Compare => plain(rgb(187, 187, 187), Glyph::Char('·'), Shape::Circle),
        Role::Closed => plain(rgb(86, 180, 233), Glyph::Braille, Shape::Circle),
        Role::Closed2 => plain(rgb(153, 136, 238), Glyph::Dot, Shape::Circle),
        Role::Reference => {
            let (c, shape) = REFERENCE_MARKS[nth % REFERENCE_MARKS.len()];
            Look {
                ink: Ink::Text,
                glyph: Glyph::Char(c),
                shape,
                bold: true,
            }
        }
        Role::Gfmd => plain(rgb(240, 228, 66), Glyph::Char('×'), Shape::Circle),
        Role::GfmdTheory => plain(rgb(153, 153, 51), Glyph::Quadrant, Shape::Cross),
        Role::Current => plain(rgb(238, 102, 119), Glyph::Char('●'), Shape::Circle),
        Role::Guide => plain(rgb(150, 150, 150), Glyph::Char('┊'), Shape::Circle),
        Role::Wall => plain(rgb(204, 51, 153), Glyph::Char('┃'), Shape::Circle),
        Role::JumpIn => plain(rgb(68, 170, 153), Glyph::Char('╏'), Shape::Circle),
        Role::PullOff => plain(rgb(102, 153, 204), Glyph::Char('┇'), Shape::Circle),
        Role::Pin(i) => plain(
            Ink::Rgb(PIN_COLOURS[i % PIN_COLOURS.len()]),
            PIN_GLYPHS[i % PIN_GLYPHS.len()],
            Shape::Circle,
        ),
        Role::Band => plain(rgb(119, 136, 153), Glyph::Char('░'), Shape::Circle),
    }
}
