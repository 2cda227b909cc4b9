//! The screen's layout, as plain rectangles (a pure function of the terminal's size, the
//! caption and the focus, unit-tested at the sizes a class meets: 60×20, 80×24, 160×48):
//!
//! - a title row, the tour's caption box, the status rows; the body between them holds the
//!   parameter panel on the left and the chart panels;
//! - the caption is word-wrapped to the box's width and gets every row it needs, unless the
//!   body would then fall below one chart panel ([`MIN_PANEL_ROWS`]): then it shows what fits
//!   and scrolls (J/K), saying where it is in its bottom border;
//! - chart panels keep at least [`MIN_PLOT_ROWS`] rows of plot: three panels (one big on top,
//!   two below) where the body holds two rows of panels, else one row: two panels side by side
//!   where each is at least [`MIN_PANEL_COLS`] wide, else the focused chart alone (`f` shows
//!   the next). Fewer panels, never unreadable ones.

use crate::tui::base::wrap::{caption_box_rows, chart_panels, CAPTION_BORDER_ROWS};
pub use crate::tui::base::wrap::{wrap, MIN_PANEL_COLS, MIN_PANEL_ROWS, MIN_PLOT_ROWS, MIN_SIZE, PANEL_CHROME_ROWS};
use ratatui::layout::Rect;

/// Where everything goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Screen {
    /// The title row.
    pub title: Rect,
    /// The parameter panel.
    pub panel: Rect,
    /// The chart panels and the index (0–2) of the chart each shows.
    pub charts: Vec<(Rect, usize)>,
    /// The caption box (height 0 without a caption).
    pub caption: Rect,
    /// The caption's lines, wrapped to the box.
    pub caption_lines: Vec<String>,
    /// The first caption line shown (scrolled).
    pub caption_top: usize,
    /// The status rows.
    pub status: Rect,
}

impl Screen {
    /// The caption lines the box shows.
    pub fn caption_visible(&self) -> &[String] {
        let rows = usize::from(self.caption.height.saturating_sub(CAPTION_BORDER_ROWS));
        let end = (self.caption_top + rows).min(self.caption_lines.len());
        &self.caption_lines[self.caption_top.min(end)..end]
    }

    /// Whether the caption is cut (it scrolls).
    pub fn caption_scrolls(&self) -> bool {
        self.caption_visible().len() < self.caption_lines.len()
    }
}

/// Splits `area` (the whole terminal) for a caption (empty: none), `status_rows` of status,
/// a panel `panel_cols` wide, the focused chart `focus` and the caption's scroll.
pub fn screen(
    area: Rect,
    caption: &[String],
    caption_scroll: usize,
    status_rows: u16,
    panel_cols: u16,
    focus: usize,
) -> Screen {
    let title = Rect::new(area.x, area.y, area.width, 1.min(area.height));
    let status_rows = status_rows.min(area.height.saturating_sub(1));
    let status = Rect::new(area.x, area.y + area.height - status_rows, area.width, status_rows);
    let free = area.height.saturating_sub(1 + status_rows);
    let lines: Vec<String> = caption
        .iter()
        .flat_map(|l| wrap(l, usize::from(area.width.saturating_sub(CAPTION_BORDER_ROWS))))
        .collect();
    let cap_rows = caption_box_rows(free, lines.len());
    let shown = usize::from(cap_rows.saturating_sub(CAPTION_BORDER_ROWS));
    let caption_top = caption_scroll.min(lines.len().saturating_sub(shown));
    let body_h = free - cap_rows;
    let body = Rect::new(area.x, area.y + 1, area.width, body_h);
    let cap = Rect::new(area.x, body.y + body_h, area.width, cap_rows);
    let panel_w = panel_cols.min(area.width);
    let panel = Rect::new(body.x, body.y, panel_w, body_h);
    let cx = body.x + panel_w;
    let cw = body.width - panel_w;
    let charts = match chart_panels(body_h, cw, focus)[..] {
        [_, _, _] => {
            let top_h = body_h / 2;
            let bottom_h = body_h - top_h;
            let left_w = cw / 2;
            vec![
                (Rect::new(cx, body.y, cw, top_h), 0),
                (Rect::new(cx, body.y + top_h, left_w, bottom_h), 1),
                (Rect::new(cx + left_w, body.y + top_h, cw - left_w, bottom_h), 2),
            ]
        }
        // the focused chart and the next one
        [a, b] => {
            let left_w = cw / 2;
            vec![
                (Rect::new(cx, body.y, left_w, body_h), a),
                (Rect::new(cx + left_w, body.y, cw - left_w, body_h), b),
            ]
        }
        _ => vec![(Rect::new(cx, body.y, cw, body_h), focus.min(2))],
    };
    Screen {
        title,
        panel,
        charts,
        caption: cap,
        caption_lines: lines,
        caption_top,
        status,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn caption() -> Vec<String> {
        vec![
            "Fig. 1: a_r/p* against p*; dashed: eq. (18), a fit to exact simulations, 2.14 at small p*.".into(),
            "Model 1 (W = 1, the original theory) undershoots it: 1.60; model 2 (c1 = 0.55) overshoots: 2.37;".into(),
            "model 3 (c1 = −2/9, c2 = 2/3 in W(a_r) [S-17]) follows it.".into(),
            "Turn p* with h and l: the ratio falls once contact spreads.".into(),
        ]
    }

    #[test]
    fn every_chart_keeps_eight_plot_rows_and_the_caption_loses_nothing() {
        for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (160, 48), (200, 60)] {
            for cap in [Vec::new(), caption()] {
                let s = screen(Rect::new(0, 0, w, h), &cap, 0, 1, 28, 0);
                assert!(!s.charts.is_empty());
                for (r, i) in &s.charts {
                    assert!(r.height >= MIN_PANEL_ROWS, "{w}×{h}: chart {i} has {} rows", r.height);
                    assert!(r.width >= 20, "{w}×{h}: chart {i} has {} columns", r.width);
                }
                // everything fits: rows add up to the terminal's
                let rows = 1 + s.panel.height + s.caption.height + s.status.height;
                assert_eq!(rows, h, "{w}×{h}");
                // every caption line is shown or reachable by scrolling
                let all = s.caption_lines.len();
                let mut seen = 0;
                let mut top = 0;
                loop {
                    let t = screen(Rect::new(0, 0, w, h), &cap, top, 1, 28, 0);
                    seen = seen.max(t.caption_top + t.caption_visible().len());
                    if !t.caption_scrolls() || t.caption_top + t.caption_visible().len() >= all {
                        break;
                    }
                    top += 1;
                }
                assert_eq!(seen, all, "{w}×{h}: caption lines reachable");
                let words: usize = cap.iter().map(|l| l.split_whitespace().count()).sum();
                let kept: usize = s.caption_lines.iter().map(|l| l.split_whitespace().count()).sum();
                assert_eq!(words, kept, "{w}×{h}: wrapping keeps every word");
            }
        }
    }

    #[test]
    fn three_panels_where_there_is_room_fewer_where_not() {
        assert_eq!(
            screen(Rect::new(0, 0, 160, 48), &caption(), 0, 1, 34, 0).charts.len(),
            3
        );
        // 80×24 with the tour's caption: one row of panels, one chart (52 columns)
        let s = screen(Rect::new(0, 0, 80, 24), &caption(), 0, 1, 28, 2);
        assert_eq!(s.charts.len(), 1);
        assert_eq!(s.charts[0].1, 2, "the focused chart is the one shown");
        // a wide, short terminal: two side by side, the focused one among them
        let s = screen(Rect::new(0, 0, 200, 24), &[], 0, 1, 34, 1);
        assert_eq!(s.charts.iter().map(|c| c.1).collect::<Vec<_>>(), [1, 2]);
    }

    #[test]
    fn a_long_word_is_cut_not_lost() {
        let w = wrap("abcdefghij klm", 4);
        assert_eq!(w, ["abcd", "efgh", "ij", "klm"]);
        assert!(wrap("", 10).is_empty());
    }
}
