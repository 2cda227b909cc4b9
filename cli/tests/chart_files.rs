//! The chart renderer's files: SVG parses as XML and names every series; PNG is a PNG of the
//! promised size; empty and gappy series do not break either.

mod common;

use asperity_cli::chart::{write_png, write_svg, Chart, Rgb, Scale, Series, SeriesStyle, Shape, PNG_SIZE};
use asperity_cli::looks::{look, model_colour, Role};

fn spec(x_log: bool, y_log: bool) -> Chart {
    let curve: Vec<(f64, f64)> = (0..50)
        .map(|i| {
            let p = 10f64.powf(-3.0 + 3.0 * i as f64 / 49.0);
            (p, 2.0 - p)
        })
        .collect();
    Chart {
        series: vec![
            Series::painted(
                "model 3",
                curve.clone(),
                SeriesStyle::Line,
                model_colour(2),
                Shape::Circle,
            ),
            Series::painted(
                "eq. (18)",
                curve.iter().map(|&(x, y)| (x, 0.9 * y)).collect(),
                SeriesStyle::Dashed,
                look(Role::Closed, 0, 0).ink.rgb(),
                Shape::Circle,
            ),
            Series::painted(
                "GFMD (512²)",
                vec![(1e-2, 1.9), (f64::NAN, 1.0), (1e-1, -1.0), (0.5, 1.5)],
                SeriesStyle::Points,
                look(Role::Gfmd, 0, 0).ink.rgb(),
                Shape::Diamond,
            ),
            Series::painted(
                "failed series",
                vec![],
                SeriesStyle::Dotted,
                Rgb(0, 0, 0),
                Shape::Circle,
            ),
        ],
        ..Chart::new(
            "a_r/p* against p*",
            "p* = p/(E*ḡ)",
            "σ̄_c* ū/h_rms γ̃",
            Scale::of(x_log),
            Scale::of(y_log),
        )
    }
}

fn tmp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("asperity-chart-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn svg_is_xml_and_names_every_series() {
    for (xl, yl) in [(false, false), (true, false), (false, true), (true, true)] {
        let path = tmp(&format!("c-{xl}-{yl}.svg"));
        write_svg(&spec(xl, yl), &path).unwrap();
        let texts = common::svg_texts(&path);
        let text = std::fs::read_to_string(&path).unwrap();
        for name in [
            "model 3",
            "eq. (18)",
            "GFMD (512²)",
            "failed series",
            "a_r/p* against p*",
            "p* = p/(E*ḡ)",
            "σ\u{304}_c* ū/h_rms γ\u{303}",
        ] {
            assert!(texts.iter().any(|t| t == name), "{name} missing from {texts:?}");
        }
        // the text stays Unicode: the PNG's composite glyphs are the PNG's own
        assert!(!text.chars().any(|c| ('\u{E000}'..='\u{F8FF}').contains(&c)), "{text}");
    }
}

#[test]
fn png_has_the_promised_size() {
    let path = tmp("c.png");
    write_png(&spec(true, false), &path).unwrap();
    let bytes = std::fs::read(&path).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    // IHDR: width and height, big-endian, at bytes 16..24
    let w = u32::from_be_bytes(bytes[16..20].try_into().unwrap());
    let h = u32::from_be_bytes(bytes[20..24].try_into().unwrap());
    assert_eq!((w, h), PNG_SIZE);
}

#[test]
fn an_unwritable_path_is_an_io_error_not_a_panic() {
    let bad = std::path::Path::new("/nonexistent-dir/x/y.svg");
    assert!(write_svg(&spec(false, false), bad).is_err());
    assert!(write_png(&spec(false, false), std::path::Path::new("/nonexistent-dir/x/y.png")).is_err());
}

/// On the white page a colour too light to read (the GFMD yellow) draws its lines and its
/// markers' edges in a darker shade of its hue that reaches the least contrast; the markers
/// keep the colour inside, so it stays the colour of the explorer. A colour that reads on
/// white is drawn as it is.
#[test]
fn light_colours_are_drawn_darker_on_white() {
    use asperity_cli::chart::contrast::{contrast_with_white, MIN_CONTRAST_ON_WHITE};
    use asperity_cli::chart::on_white;
    let yellow = look(Role::Gfmd, 0, 0).ink.rgb();
    let ink = on_white(yellow);
    assert!(contrast_with_white(yellow) < MIN_CONTRAST_ON_WHITE);
    assert!(contrast_with_white(ink) >= MIN_CONTRAST_ON_WHITE);
    let blue = model_colour(2);
    assert_eq!(on_white(blue), blue);
    let pts = vec![(0.1, 0.2), (0.5, 0.6), (0.9, 0.4)];
    let series = |name: &str, style, colour| Series::painted(name, pts.clone(), style, colour, Shape::Circle);
    let spec = Chart {
        series: vec![
            series("a light line", SeriesStyle::Line, yellow),
            series("light points", SeriesStyle::Points, yellow),
            series("a dark line", SeriesStyle::Line, blue),
        ],
        ..Chart::new("t", "x", "y", Scale::Linear, Scale::Linear)
    };
    let path = tmp("light.svg");
    write_svg(&spec, &path).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let doc = roxmltree::Document::parse(&text).unwrap();
    let hex = |c: Rgb| format!("#{:02X}{:02X}{:02X}", c.0, c.1, c.2);
    let attrs = |name: &str| -> std::collections::BTreeSet<String> {
        doc.descendants()
            .filter_map(|n| n.attribute(name))
            .map(str::to_uppercase)
            .collect()
    };
    let (strokes, fills) = (attrs("stroke"), attrs("fill"));
    assert!(
        strokes.contains(&hex(ink)),
        "no line or edge in {}: {strokes:?}",
        hex(ink)
    );
    assert!(
        !strokes.contains(&hex(yellow)),
        "a light stroke {} on white",
        hex(yellow)
    );
    assert!(fills.contains(&hex(yellow)), "the markers lost their colour: {fills:?}");
    assert!(strokes.contains(&hex(blue)), "a readable colour changed: {strokes:?}");
}

/// A file's ticks are the one nice-ticks routine's round values, written by the one number
/// formatter (as on screen and in the text chart): 0, 0.2, …, 1 on a linear axis over
/// [0, 1], the decades 0.001 … 1 on a log axis over [10⁻³, 1].
#[test]
fn file_ticks_are_the_shared_round_values() {
    let mut c = Chart::new("t", "x", "y", Scale::Linear, Scale::Log10);
    c.series.push(Series::painted(
        "s",
        vec![(0.0, 1e-3), (1.0, 1.0)],
        SeriesStyle::Line,
        Rgb(0, 0, 0),
        Shape::Circle,
    ));
    let path = tmp("ticks.svg");
    write_svg(&c, &path).unwrap();
    let texts = common::svg_texts(&path);
    let values = asperity_cli::numfmt::nice_ticks(-0.05, 1.05, false, 8);
    assert_eq!(values, [0.0, 0.2, 0.4, 0.6, 0.8, 1.0]);
    for v in values.into_iter().chain([1e-3, 1e-2, 0.1]) {
        let l = asperity_cli::numfmt::tick(v);
        assert!(texts.contains(&l), "{l} not among {texts:?}");
    }
    // nothing else: no 0.1 step on x, no 1e-3 spelling on y
    assert!(!texts.iter().any(|t| t == "0.5" || t == "1e-3"), "{texts:?}");
}
