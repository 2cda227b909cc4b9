//! Word wrap of the caption and help text, the most rows a caption can take (which bounds
//! its scroll, a state the update keeps), and which chart panels a terminal shows (the
//! layout's decision, [`shown_charts`], which the update also needs: only the charts shown
//! are computed).

use ratatui::text::Span;

/// Smallest usable terminal (columns, rows).
pub const MIN_SIZE: (u16, u16) = (60, 20);
/// Rows of the caption box's borders.
pub const CAPTION_BORDER_ROWS: u16 = 2;
/// Rows of plot a chart keeps (between its title border and its x axis).
pub const MIN_PLOT_ROWS: u16 = 8;
/// Rows a chart panel adds around its plot: the title border, the x axis line, its tick
/// labels and the bottom border with the legend.
pub const PANEL_CHROME_ROWS: u16 = 4;
/// Smallest chart panel (rows).
pub const MIN_PANEL_ROWS: u16 = MIN_PLOT_ROWS + PANEL_CHROME_ROWS;
/// Narrowest chart panel when two stand side by side (columns).
pub const MIN_PANEL_COLS: u16 = 40;

/// Width of the parameter panel on a terminal `cols` wide.
pub fn panel_cols(cols: u16) -> u16 {
    match cols {
        120.. => 34,
        80.. => 28,
        _ => 24,
    }
}

/// Rows of the caption box for `lines` wrapped caption lines, with `free` rows between the
/// title and the status rows: every line it needs unless the charts would then fall below one
/// panel ([`MIN_PANEL_ROWS`]); 0 without a caption.
pub fn caption_box_rows(free: u16, lines: usize) -> u16 {
    if lines == 0 {
        return 0;
    }
    let want = (lines as u16).saturating_add(CAPTION_BORDER_ROWS);
    let room = free.saturating_sub(MIN_PANEL_ROWS).max(CAPTION_BORDER_ROWS + 1);
    want.min(room).min(free)
}

/// The charts (0: the big panel's, 1, 2: the lower ones') a body of `body_rows` rows and
/// `chart_cols` columns beside the parameter panel shows, in screen order: all three where
/// it holds two rows of panels, else the focused one and the next side by side where each is
/// at least [`MIN_PANEL_COLS`] wide, else the focused one alone.
pub fn chart_panels(body_rows: u16, chart_cols: u16, focus: usize) -> Vec<usize> {
    let focus = focus.min(2);
    if body_rows >= 2 * MIN_PANEL_ROWS {
        vec![0, 1, 2]
    } else if chart_cols >= 2 * MIN_PANEL_COLS {
        let (a, b) = (focus, (focus + 1) % 3);
        vec![a.min(b), a.max(b)]
    } else {
        vec![focus]
    }
}

/// The charts a terminal of `cols`×`rows` shows with the tour's `caption` (unwrapped; empty
/// without a tour) and one status row; with `zoom` the focused one alone. A longer status
/// message can only take rows from the charts, so this is every chart the screen can show.
pub fn shown_charts(cols: u16, rows: u16, caption: &[String], focus: usize, zoom: bool) -> Vec<usize> {
    if zoom {
        return vec![focus.min(2)];
    }
    let free = rows.saturating_sub(2);
    let lines: usize = caption
        .iter()
        .map(|l| wrap(l, usize::from(cols.saturating_sub(CAPTION_BORDER_ROWS))).len())
        .sum();
    let body = free - caption_box_rows(free, lines);
    chart_panels(body, cols.saturating_sub(panel_cols(cols)), focus)
}

/// Display width of a text.
fn width(s: &str) -> usize {
    Span::raw(s).width()
}

/// Greedy word wrap to `cols` columns (a word longer than a row is cut into rows).
pub fn wrap(text: &str, cols: usize) -> Vec<String> {
    let cols = cols.max(1);
    let mut out = Vec::new();
    for para in text.lines() {
        let mut line = String::new();
        for word in para.split_whitespace() {
            let w = width(word);
            let need = if line.is_empty() { w } else { width(&line) + 1 + w };
            if need <= cols {
                if !line.is_empty() {
                    line.push(' ');
                }
                line.push_str(word);
                continue;
            }
            if !line.is_empty() {
                out.push(std::mem::take(&mut line));
            }
            // a word wider than the row: cut it
            let mut rest = word.to_string();
            while width(&rest) > cols {
                let cut: String = rest
                    .chars()
                    .scan(0, |acc, c| {
                        *acc += width(&c.to_string());
                        (*acc <= cols).then_some(c)
                    })
                    .collect();
                rest = rest[cut.len()..].to_string();
                out.push(cut);
            }
            line = rest;
        }
        out.push(line);
    }
    out
}

/// Most rows the caption `text` can take at any terminal width the explorer runs at (it
/// bounds the caption's scroll).
pub fn caption_rows_at_most(text: &[String]) -> usize {
    let cols = usize::from(MIN_SIZE.0 - CAPTION_BORDER_ROWS);
    text.iter().map(|l| wrap(l, cols).len()).sum()
}
